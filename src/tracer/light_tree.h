/* light_tree.h — choosing among many lights (--light tree): a binary tree over the emitters, each
 * node bounding those below it by a sphere (position), a cone of their normals (orientation) and
 * their power. From the shading point p of normal n, a node's importance is its power x cos(theta')
 * x cos(theta_i) / d^2, bounds of the angle of emission and of incidence: an upper bound of what
 * its emitters can send to p (Conty Estevez and Kulla 2018; pbrt-v4's LightBounds::Importance), 0
 * when every emitter below shows p its back or lies under p's surface. n = (0, 0, 0): no normal,
 * the factor is 1 (the checks' bare points). The choice descends from the root: at each
 * node the first child with probability I1 / (I1 + I2), and u0 rescaled to stay uniform, so that
 * the leaf's probability is the product of the choices on its path. An emitter that can send light
 * toward p has a nonzero importance at every node above it, hence a nonzero probability: unbiased,
 * provided u0 can fall in a share that small. Far from p a share can be 1e-12 and less, hence u0's
 * 53 random bits (sampler_2d_53bit): with 32, a share under 2^-32 was never drawn. */
#ifndef PATHLAB_LIGHT_TREE_H
#define PATHLAB_LIGHT_TREE_H
#include <stdint.h>
#include "math/vec.h"

/* What the tree knows of an emitter: its bounding box, its front normal, its power (area x
 * luminance of Le), given by light.c. */
typedef struct { vec3 lo, hi, n; float power; } light_bounds;

typedef struct {
    vec3 c;               /* centre of the emitters' bounding box */
    float r;              /* radius of the sphere about c that holds the box */
    vec3 axis;            /* every emitter normal below is within theta_o of axis */
    float cos_o, sin_o;   /* of theta_o (pi: any direction) */
    float power;          /* sum of area x luminance(Le) below */
    int right;            /* the second child (the first is the next node); -1 at a leaf */
    int emitter;          /* a leaf's emitter */
} light_node;

typedef struct {
    light_node *node;     /* depth-first: 2n - 1 nodes, the root first */
    int nnodes;
    uint64_t *path;       /* per emitter: bit k is 1 when the k-th step down to it takes the second child */
    unsigned char *depth; /* per emitter: the steps from the root to its leaf */
} light_tree;

/* Builds the tree over the emitters b[0..n-1] (n > 0), splitting at the median: O(n log n), depth
 * at most ceil(log2 n). 0 on success. */
int light_tree_build(light_tree *t, const light_bounds *b, int n);
void light_tree_free(light_tree *t);
/* What the emitters below nd can send to p of normal n, bounded above (0 only if none faces p
 * from above its surface). */
float light_node_importance(const light_node *nd, vec3 p, vec3 n);
/* Probability of taking the first child of node k from p of normal n. */
double light_tree_first_prob(const light_tree *t, int k, vec3 p, vec3 n);
/* Descends from the root, seen from p of normal n, with *u in [0, 1): returns the emitter, its probability in *prob, and
 * leaves in *u where it fell within that emitter's share, uniform in [0, 1). */
int light_tree_pick(const light_tree *t, vec3 p, vec3 n, double *u, double *prob);
/* The probability that light_tree_pick chooses emitter i from p of normal n (along i's path). */
double light_tree_prob(const light_tree *t, int i, vec3 p, vec3 n);
#endif
