/* merge.h — the command `pathlab merge OUT.pfm IN.pfm... [--variance OUT_var.pfm]`: renders of one
 * scene, flags, camera and seed with disjoint sample ranges (render --samples A:B, on several
 * machines), combined into the render of all their samples: means weighted by samples, variances
 * of the means combined exactly, --split layers too. Inputs that differ are refused, naming the difference. */
#ifndef PATHLAB_MERGE_H
#define PATHLAB_MERGE_H

#define MERGE_USAGE "  pathlab merge OUT.pfm IN.pfm... [--variance OUT_var.pfm]   renders of disjoint --samples A:B,\n" \
                    "                combined into the render of all their samples (see docs/distributed.md)\n"

/* Exit status 0, 1 when a write failed, 2 for bad arguments or inputs that cannot be merged. */
int merge_main(int argc, char **argv);
#endif
