/* fuzz_mtl.c — libFuzzer harness: one MTL file alone (mtl_load into an empty mesh), then a lookup
 * of the first material's name, as obj.c's usemtl does. */
#include <stdlib.h>
#include "fuzz_common.h"
#include "scene/mtl.h"
#include "scene/scene_file.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    mesh m = {0};
    const char *path = fuzz_write(0, "f.mtl", data, size);
    mtl_opts o = {NULL, TEXTURE_RAW, 1};
    char *root = scene_file_folder(path);   /* its map_ files confined to its folder, as an mtllib's */
    m.mats = calloc(1, sizeof *m.mats);   /* mats[0], the default material, as obj.c makes it */
    if (!m.mats || !root) { free(m.mats); free(root); return 0; }
    m.nmats = 1;
    if (mtl_load(path, &m, root, &o) == 0 && m.nmats > 1 && mtl_find(&m, m.mats[1].name) < 1) abort();
    mesh_free(&m);
    free(root);
    return 0;
}
