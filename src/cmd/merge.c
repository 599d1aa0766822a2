/* merge.c — pathlab merge: its flags and its checks of the output, then files/render_merge.h. */
#include "cmd/merge.h"
#include <stdio.h>
#include <stdlib.h>
#include "files/render_merge.h"
#include "image/image.h"
#include "util/cli.h"
#include "sys/output_path.h"

#define MAX_INPUTS 4096

int merge_main(int argc, char **argv)
{
    const char *var_out = NULL, **words;
    const cli_flag flags[] = {{"--variance", CLI_STRING, &var_out, 0, 0, NULL, NULL, NULL},
                              {NULL, CLI_SWITCH, NULL, 0, 0, NULL, NULL, NULL}};
    const cli_flag *tables[] = {flags, NULL};
    int n, rc, k;
    words = malloc(sizeof *words * (MAX_INPUTS + 1));
    if (!words) { fprintf(stderr, "pathlab merge: out of memory\n"); return 2; }
    rc = cli_parse("merge", argc, argv, tables, NULL, words, MAX_INPUTS + 1, &n) ? 2 : 0;
    if (!rc && n < 2) { fprintf(stderr, "pathlab merge: needs an output and at least one input\nusage:\n" MERGE_USAGE); rc = 2; }
    if (!rc && (img_format_of(words[0]) != IMG_PFM || (var_out && img_format_of(var_out) != IMG_PFM))) {
        fprintf(stderr, "pathlab merge: %s: the merged image and its variance are written as .pfm\n", var_out && img_format_of(words[0]) == IMG_PFM ? var_out : words[0]);
        rc = 2;
    }
    for (k = 1; !rc && k < n; k++)
        if (img_format_of(words[k]) == IMG_HDR) {   /* RGBE keeps 8 bits of each channel: no sum of samples survives it */
            fprintf(stderr, "pathlab merge: %s: an .hdr (RGBE) cannot be merged: it keeps 8-bit mantissas, not the samples' sums "
                            "a piece must hold; merge the renders' .pfm files (and their sidecars)\n", words[k]);
            rc = 2;
        }
    if (!rc && (output_path_check("merge", "output", words[0], IMG_PFM_EXTENSION) || (var_out && output_path_check("merge", "--variance", var_out, IMG_PFM_EXTENSION))))
        rc = 2;
    if (!rc) rc = render_merge(words[0], var_out, words + 1, n - 1);
    free(words);
    return rc;
}
