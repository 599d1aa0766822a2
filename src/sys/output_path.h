/* output_path.h — an output file checked before any work is done: its folder exists and can be
 * written, it is not a folder itself, and its extension is one the command writes. A render of an
 * hour must not end in "cannot write". */
#ifndef PATHLAB_OUTPUT_PATH_H
#define PATHLAB_OUTPUT_PATH_H

/* The size of every path buffer: PATH_MAX (4096) and room for the suffixes pathlab adds to a name
 * (FILE_L12.pfm.meta, NAME.tmp.XXXXXX); a longer path is refused where it is built (snprintf). */
#define PATH_CAP 4352

/* path, given as `flag` to `cmd` ("render", "-o"): 0 if it can be written, else 1 after printing
 * "pathlab CMD: FLAG PATH: why". exts: the extensions allowed, lower case with their dot, ending with
 * NULL (compared without case: .PFM is .pfm); NULL for any. */
int output_path_check(const char *cmd, const char *flag, const char *path, const char *const *exts);
/* The same for a folder that a command creates or fills (compare -o DIR, grade --heatmap DIR):
 * either it is a writable folder, or it does not exist and its parent is a writable folder. */
int output_dir_check(const char *cmd, const char *flag, const char *dir);
#endif
