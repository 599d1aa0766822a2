/* render_merge.h — renders of one scene, flags, camera and seed with disjoint sample ranges
 * (render --samples A:B, on several machines) combined into the render of all their samples: means
 * weighted by samples, variances of the means combined exactly, --split layers too. Inputs that
 * differ are refused, naming the difference. */
#ifndef PATHLAB_RENDER_MERGE_H
#define PATHLAB_RENDER_MERGE_H

/* Merges the renders at paths[0 .. n-1] into out (and its variance into var_out unless NULL), each
 * with its sidecar. 0; 1 when a write failed; 2 when the inputs cannot be merged (said why). */
int render_merge(const char *out, const char *var_out, const char *const *paths, int n);
#endif
