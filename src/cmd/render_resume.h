/* render_resume.h — `render --resume -o FILE` with nothing else: the scene, camera, size, flags and
 * seed come from FILE's sidecar; a flag given on the command line must agree with it, and a
 * disagreement names the flag and both values. */
#ifndef PATHLAB_RENDER_RESUME_H
#define PATHLAB_RENDER_RESUME_H
#include "cmd/render_args.h"
#include "files/sidecar.h"

#define RESUME_MAX_ARGS 128   /* the arguments of the command line made (argv and the sidecar's) */

/* The arguments to parse: if argv has --resume and -o FILE whose sidecar can be read, argv[0], then
 * what the sidecar says that argv does not (the scene if argv names none, --seed, the sidecar's
 * flags, --eye --target --up --fov --size unless argv gives --view or --orbiter, --split if it has
 * layers), then argv[1..]; else argv itself. text[cap] holds the sidecar's words. 0, or 1 after
 * printing why (too many arguments). */
int render_resume_args(int argc, char **argv, char **out, int *out_argc, char *text, size_t cap);
/* This render's sidecar `now` against had, the sidecar of FILE to resume: 0 if their flags, camera
 * and seed agree, else 1 after "pathlab render: --resume: --rr is 4 on the command line but 3 in
 * FILE's sidecar ...". */
int render_resume_check(const sidecar *now, const sidecar *had, const char *file);
#endif
