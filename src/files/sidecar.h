/* sidecar.h — what made an image, in a small text file beside it (FILE.pfm -> FILE.pfm.meta), since
 * PFM has no metadata: the sample indices rendered, seed, scene, flags, camera, revision. pathlab
 * merge and render --resume read it to refuse pieces that are not of the same render; grade prints it.
 * One "key value" per line, '#' starts a comment, unknown keys are skipped (later versions may add some):
 *   kind mean | variance       samples 0:384[,1000:1200]     seed 1         layer total | L3
 *   scene PATH   scene-id ID   flags ...   camera ...   variance FILE   layers A:B   revision R
 *   sky-id ID (with --sky IMAGE)
 * and for an adaptive render (docs/adaptive.md), whose pixel x holds the samples 0 .. n(x) - 1:
 *   adaptive FLAGS   spp-cap N   spp-mean X   pilot-seed S   sample-count FILE
 * and when the sampler is not independent (docs/sampler.md):
 *   sampler sobol    variance-dof 3     (only when not independent: absent means independent, whatever
 *                                        the default of --sampler, and a variance with many dof) */
#ifndef PATHLAB_SIDECAR_H
#define PATHLAB_SIDECAR_H
#include <stddef.h>
#include <stdint.h>

#define SIDECAR_MAX_RANGES 256
#define SIDECAR_TEXT 1024
/* Room for the samples line's text: 256 ranges of two 19-digit indices (a line of 8192 cut them) */
#define SIDECAR_RANGES_TEXT (SIDECAR_MAX_RANGES * 42)
/* The bounds of a sidecar's numbers, those of the command line: a sample index at most 2^62 (as
 * --samples), a count of samples (the adaptive cap, its mean) at most 2^30 (as --spp), so that no sum
 * of them overflows. A sidecar beyond them is refused as malformed. */
#define SIDECAR_INDEX_MAX (1LL << 62)
#define SIDECAR_SPP_MAX (1LL << 30)

typedef struct {
    char kind[16];                 /* "mean", or "variance" (of the mean) */
    char layer[16];                /* "total", or "L3" for a --split layer */
    int nranges;                   /* sample indices [range[i][0], range[i][1]), sorted, disjoint, not touching */
    int64_t range[SIDECAR_MAX_RANGES][2];
    uint64_t seed;
    char scene[SIDECAR_TEXT];      /* the scene as given (for people; merge compares scene_id) */
    char scene_id[40];             /* a fingerprint of the triangles and materials rendered */
    char sky_id[40];               /* of the --sky image's pixels ("" if none, or written before it) */
    char flags[4 * SIDECAR_TEXT];  /* every flag that changes the samples, in one canonical form (its
                                      paths escaped: up to 4 bytes a character) */
    char camera[SIDECAR_TEXT];     /* the camera used, exactly (%.9g) */
    char variance[SIDECAR_TEXT];   /* the variance image's file name, in the same folder ("" if none) */
    int layers_first, layers_n;    /* --split wrote the layers L_first .. L_(first + n - 1), FILE_Lk.pfm
                                    * ("layers A:B" in the file; n = 0: none) */
    char revision[64];             /* pathlab's version (git describe) */
    char stopped[32];              /* "SIGINT", "SIGTERM" or "time" when stopped before the samples asked */
    char adaptive[SIDECAR_TEXT];   /* the adaptive flags ("--target-error 0.01 --pilot 16 ..."); "" if uniform */
    int64_t spp_cap;               /* adaptive: the --spp cap of n(x) */
    double spp_mean;               /* adaptive: the mean over the pixels of their sample counts */
    uint64_t pilot_seed;           /* adaptive: the seed of the pilot's streams (never kept) */
    char sample_count[SIDECAR_TEXT];   /* adaptive: the sample-count image's file name ("" if none) */
    char sampler[16];              /* --sampler: "" (no line) is independent, in every sidecar ever written */
    int variance_dof;              /* degrees of freedom of the variance of the mean: 0 (no line) many */
} sidecar;

/* A name written in a sidecar: each control character and backslash (and each space with spaces:
 * a path inside the flags line, which is split at its spaces) as \xNN, so that no name writes a
 * line or a word of its own (a newline in a scene's name forged a samples line). Cut at cap, never
 * inside an escape. */
void sidecar_escape(char *dst, size_t cap, const char *src, int spaces);
/* Undoes sidecar_escape in place; 1 if s holds a backslash not followed by xNN. */
int sidecar_unescape(char *s);
/* FILE -> FILE.meta */
void sidecar_path(char *dst, size_t cap, const char *image_path);
/* Writes the sidecar of image_path into the file `file` (a temporary name, renamed later with the
 * image: render_files.h); 0, or 1 after printing why. */
int sidecar_write_to(const sidecar *m, const char *image_path, const char *file);
/* Reads the sidecar of image_path. 0; -1 if it does not exist (nothing printed); 1 after printing
 * "FILE.meta:LINE: why" for a malformed one. */
int sidecar_read(sidecar *m, const char *image_path);
/* 1 if the render was made with --sampler sobol (absent: independent). */
int sidecar_is_sobol(const sidecar *m);
/* The number of samples of the ranges. */
int64_t sidecar_spp(const sidecar *m);
/* "0:384,1000:1200" */
void sidecar_ranges_text(const sidecar *m, char *dst, size_t cap);
/* Adds the ranges of b to a, sorted and joined; 0, or 1 after printing why: a range of b overlaps
 * one of a (the same samples twice), or there are too many ranges. */
int sidecar_add_ranges(sidecar *a, const sidecar *b, const char *a_name, const char *b_name);
/* Compares what must match for two renders to be merged (scene, flags, camera, seed); 0 if they
 * match, else 1 after printing "pathlab CMD: A and B differ in KEY: 'x' vs 'y'". Adaptive renders
 * never match (1, saying so): their pixels hold different sample counts, which merge and --resume
 * do not combine. */
int sidecar_check_same(const sidecar *a, const sidecar *b, const char *cmd, const char *a_name, const char *b_name);
/* The pathlab render command that makes this render again at w x h (0: its own size), with
 * -o STEM.pfm --variance STEM_var.pfm and as many spp as it holds. 0, or 1 if the camera line is unreadable. */
int sidecar_render_command(const sidecar *m, int w, int h, const char *stem, char *out, size_t cap);
#endif
