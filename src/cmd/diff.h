/* diff.h — `pathlab diff A.pfm B.pfm [--heatmap out.ppm]`: how far an image is from a reference
 * (the metrics are stats/image_diff.h's; the heatmap image/heatmap.h's). */
#ifndef PATHLAB_DIFF_H
#define PATHLAB_DIFF_H
/* Exit status 0, 1 when the heatmap could not be written, 2 for bad arguments or inputs. */
int diff_main(int argc, char **argv);
#endif
