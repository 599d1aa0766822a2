/* render_adaptive.h — pathlab render's adaptive sampling flags (--target-error, --adaptive,
 * --pilot, --min-spp, --sample-count): their table, the checks of how they go together, and what
 * they add to the sidecar. Only render has them (compare renders uniformly). */
#ifndef PATHLAB_RENDER_ADAPTIVE_H
#define PATHLAB_RENDER_ADAPTIVE_H
#include "cmd/render_args.h"
#include "files/sidecar.h"

#define RENDER_ADAPTIVE_NFLAGS 6   /* the flags and the closing NULL entry */
#define RENDER_ADAPTIVE_DEFAULT_CAP 65536   /* --target-error without --spp: the cap of n(x) */

void render_adaptive_flag_table(render_args *a, cli_flag t[RENDER_ADAPTIVE_NFLAGS]);
/* After the flags were read: 0, or 1 after printing why. Sets a->adaptive (--target-error implies it). */
int render_adaptive_check(render_args *a);
/* The adaptive flags in one canonical form, into m->adaptive (left "" if not adaptive). */
void render_adaptive_describe(const render_args *a, sidecar *m);
#endif
