/* version.c — the revision, passed by the Makefile (-DPATHLAB_REVISION) to this file only, so that
 * a new commit rebuilds one object. */
#include "cmd/version.h"
#ifndef PATHLAB_REVISION
#define PATHLAB_REVISION "unknown"
#endif
const char *pathlab_revision(void) { return PATHLAB_REVISION; }
