/* bench_rays.h — `pathlab bench-rays MESH.obj [-r RES] [-t THREADS]`: times the BVH build and three
 * fixed ray sets (primary, diffuse bounce, shadow) with the exact ray recipe of the Embree anchor
 * (shared/tools/embree-rays/README.md), and prints lines of the same form, for compare.sh. */
#ifndef PATHLAB_BENCH_RAYS_H
#define PATHLAB_BENCH_RAYS_H
/* argv[0] = "bench-rays". Returns 0 on success, 2 on a usage error, 1 on a load or memory error. */
int bench_rays_main(int argc, char **argv);
#endif
