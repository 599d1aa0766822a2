/* render_cmd.h — the command `pathlab render SCENE.obj [flags] -o FILE`: reads its flags
 * (cmd/render_args.h), loads the scene, renders and writes the image, one per bounce with --split
 * and the variance with --variance. */
#ifndef PATHLAB_RENDER_CMD_H
#define PATHLAB_RENDER_CMD_H

/* Exit status 0, 1 when the render or a write failed, 2 for bad arguments or a bad scene. */
int render_main(int argc, char **argv);
#endif
