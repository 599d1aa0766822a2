/* version.h — which pathlab this is: the git revision it was built from (git describe), written
 * into every sidecar and printed by `pathlab --version`. */
#ifndef PATHLAB_VERSION_H
#define PATHLAB_VERSION_H
const char *pathlab_revision(void);
#endif
