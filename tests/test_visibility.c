/* test_visibility.c — the pairs of visibility.h (a triangle and an emitter that nothing can come
 * between), against segments traced between them.
 *  1. McGuire's CornellBox-Empty-White (its 12 triangles, as in the file): every wall and the light's
 *     other half see each light triangle wholly (22 of 24 pairs; an emitter does not light itself).
 *     A box of 12 triangles floating under the light: no floor triangle sees the light wholly.
 *     A light just under a huge ground (half-width 1e2 to 1e6, 5e-8 to 1e-3 under it) is hidden from
 *     a panel over the ground; just over it, it is not.
 *  2. 256 random rooms (a box whose corners are moved by up to 2 %, as McGuire's are, so that its
 *     quads are not flat, folded in or out; or not moved), with 0 to 3 triangles hung inside: for
 *     every pair said clear, 4000 (the first 16 rooms) or 250 segments from a random point of the
 *     triangle to a random point of the emitter are tested against every other triangle (the
 *     watertight test, bvh_triangle_hit): none may be blocked at t in (1e-4, 1 - 1e-4).
 *     Deterministic (a fixed LCG): no alpha, a blocked segment is a bug. Pairs found are counted, so
 *     that a table with no pairs cannot pass as correct: in the empty rooms with flat walls every pair
 *     must be clear, with folded walls 95 % (the planes of the triangles alone clear 27 % of those;
 *     the separating axes, all). PATHLAB_TEST_QUICK=1 or PATHLAB_FAST=1 (sanitizer builds): 64 rooms.
 *     A sphere of 364 triangles in a room: the same, 100 segments a pair (it blocks the floor).
 *  3. A scene over VISIBILITY_MAX_TRIS triangles gets no table (and no pairs), without error. */
#include "geometry/visibility.h"
#include "geometry/bvh.h"
#include "geometry/ray.h"
#include "check.h"
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static uint64_t rng_state = 0x2545F4914F6CDD1DULL;
static float rnd(void)   /* [0, 1) */
{
    rng_state = rng_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (float)(rng_state >> 40) * (1.0f / 16777216.0f);
}
static float rnd_range(float lo, float hi) { return lo + (hi - lo) * rnd(); }

#define MAXV 1024
typedef struct { vec3 P[MAXV]; int tri[3 * MAXV]; int nv, nt; int emitters[16], ne; } scene_t;

static int add_v(scene_t *s, vec3 p) { s->P[s->nv] = p; return s->nv++; }
static void add_t(scene_t *s, int a, int b, int c) { s->tri[3 * s->nt] = a; s->tri[3 * s->nt + 1] = b; s->tri[3 * s->nt + 2] = c; s->nt++; }
/* a quad a b c d as OBJ's "f a b c d": triangles (a, b, c) and (a, c, d) */
static void add_quad(scene_t *s, vec3 a, vec3 b, vec3 c, vec3 d, int emits)
{
    int ia = add_v(s, a), ib = add_v(s, b), ic = add_v(s, c), id = add_v(s, d);
    if (emits) s->emitters[s->ne++] = s->nt;
    add_t(s, ia, ib, ic);
    if (emits) s->emitters[s->ne++] = s->nt;
    add_t(s, ia, ic, id);
}

/* McGuire's CornellBox-Empty-White.obj, its vertices and faces in the file's order */
static void empty_white(scene_t *s)
{
    memset(s, 0, sizeof *s);
    add_quad(s, v3(-1.01f, 0, 0.99f), v3(1, 0, 0.99f), v3(1, 0, -1.04f), v3(-0.99f, 0, -1.04f), 0);                 /* floor */
    add_quad(s, v3(-1.02f, 1.99f, 0.99f), v3(-1.02f, 1.99f, -1.04f), v3(1, 1.99f, -1.04f), v3(1, 1.99f, 0.99f), 0);  /* ceiling */
    add_quad(s, v3(-0.99f, 0, -1.04f), v3(1, 0, -1.04f), v3(1, 1.99f, -1.04f), v3(-1.02f, 1.99f, -1.04f), 0);        /* back */
    add_quad(s, v3(1, 0, -1.04f), v3(1, 0, 0.99f), v3(1, 1.99f, 0.99f), v3(1, 1.99f, -1.04f), 0);                    /* right */
    add_quad(s, v3(-1.01f, 0, 0.99f), v3(-0.99f, 0, -1.04f), v3(-1.02f, 1.99f, -1.04f), v3(-1.02f, 1.99f, 0.99f), 0); /* left */
    add_quad(s, v3(-0.24f, 1.98f, 0.16f), v3(-0.24f, 1.98f, -0.22f), v3(0.23f, 1.98f, -0.22f), v3(0.23f, 1.98f, 0.16f), 1); /* light */
}

/* an axis-aligned box of 12 triangles, lo to hi */
static void add_box(scene_t *s, vec3 lo, vec3 hi)
{
    vec3 c[8];
    int k;
    for (k = 0; k < 8; k++) c[k] = v3(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
    add_quad(s, c[0], c[1], c[3], c[2], 0); add_quad(s, c[4], c[6], c[7], c[5], 0);
    add_quad(s, c[0], c[4], c[5], c[1], 0); add_quad(s, c[2], c[3], c[7], c[6], 0);
    add_quad(s, c[0], c[2], c[6], c[4], 0); add_quad(s, c[1], c[5], c[7], c[3], 0);
}

static int build(const scene_t *s, pair_visibility *pv) { return pair_visibility_build(pv, s->P, s->tri, s->nt, s->emitters, s->ne); }

static vec3 corner(const scene_t *s, int t, int k) { return s->P[s->tri[3 * t + k]]; }
static vec3 point_on(const scene_t *s, int t)
{
    float u = rnd(), v = rnd();
    vec3 a = corner(s, t, 0), b = corner(s, t, 1), c = corner(s, t, 2);
    if (u + v > 1) { u = 1 - u; v = 1 - v; }
    return v3_add(a, v3_add(v3_scale(v3_sub(b, a), u), v3_scale(v3_sub(c, a), v)));
}

/* Segments between every pair said clear; returns how many were blocked, and counts the pairs. */
static long blocked_segments(const scene_t *s, const pair_visibility *pv, int per_pair, long *clear_pairs)
{
    long blocked = 0;
    int t, e, i, o;
    *clear_pairs = 0;
    for (t = 0; t < s->nt; t++)
        for (e = 0; e < s->ne; e++) {
            if (!sees_wholly(pv, t, e)) continue;
            ++*clear_pairs;
            for (i = 0; i < per_pair; i++) {
                ray r;
                vec3 p = point_on(s, t), q = point_on(s, s->emitters[e]);
                r.o = p; r.d = v3_sub(q, p); r.tmax = 1.0f;
                for (o = 0; o < s->nt; o++) {
                    hit h;
                    if (o == t || o == s->emitters[e]) continue;
                    if (bvh_triangle_hit(corner(s, o, 0), corner(s, o, 1), corner(s, o, 2), &r, &h) && h.t > 1e-4f && h.t < 1 - 1e-4f) {
                        if (!blocked)
                            printf("  triangle %d blocks a segment from triangle %d to emitter %d (triangle %d) at t = %g\n", o, t, e, s->emitters[e], h.t);
                        blocked++;
                        break;
                    }
                }
            }
        }
    return blocked;
}

/* A ground of half-width g at y = 0 (triangles 0, 1), a panel at y = 1 over it (2, 3) and a light
 * (4, 5) at y = light_y, within a few units of the origin: a light just under a huge ground is hidden
 * from the panel, one just over it is not. */
static void ground_panel_light(scene_t *s, float g, float light_y)
{
    memset(s, 0, sizeof *s);
    add_quad(s, v3(-g, 0, -g), v3(-g, 0, g), v3(g, 0, g), v3(g, 0, -g), 0);
    add_quad(s, v3(-0.5f, 1, -0.5f), v3(0.5f, 1, -0.5f), v3(0.5f, 1, 0.5f), v3(-0.5f, 1, 0.5f), 0);
    add_quad(s, v3(0.25f, light_y, 0.25f), v3(0.25f, light_y, -0.25f), v3(-0.25f, light_y, -0.25f), v3(-0.25f, light_y, 0.25f), 1);
}

/* How many of the panel's pairs with the light are clear. */
static int panel_pairs_clear(const pair_visibility *pv) { return sees_wholly(pv, 2, 0) + sees_wholly(pv, 2, 1) + sees_wholly(pv, 3, 0) + sees_wholly(pv, 3, 1); }

/* 1b: the tolerance of "on a plane" follows the terms computed, not the largest coordinate of the
 * triangles compared: a light 5e-6 under a ground of half-width 1e4 is under it (it was taken as in
 * its plane, 2^-30 of 1e4 = 9.3e-6, and the panel lit). */
static void check_mixed_scales(void)
{
    static const float cases[][2] = {{1e4f, 5e-6f}, {1e5f, 5e-5f}, {1e6f, 1e-3f}, {1e6f, 1e-5f}, {1e2f, 5e-8f}};
    scene_t s;
    pair_visibility pv;
    int i, under = 0, over = 0, n = (int)(sizeof cases / sizeof cases[0]);
    for (i = 0; i < n; i++) {
        ground_panel_light(&s, cases[i][0], -cases[i][1]);
        build(&s, &pv);
        if (panel_pairs_clear(&pv)) printf("  ground %g, light %g under it: %d panel-light pairs clear\n", cases[i][0], cases[i][1], panel_pairs_clear(&pv));
        under += panel_pairs_clear(&pv);
        pair_visibility_free(&pv);
        ground_panel_light(&s, cases[i][0], cases[i][1]);
        build(&s, &pv);
        over += panel_pairs_clear(&pv);
        pair_visibility_free(&pv);
    }
    check(under == 0, "visibility_light_under_huge_ground", "%d panel-light pairs clear through the ground (%d scenes)", under, n);
    check(over == 4 * n, "visibility_light_over_huge_ground", "%d of %d panel-light pairs clear with the light over the ground", over, 4 * n);
}

/* A sphere of 2 nl (nl - 1) triangles (nl >= 3 rings of nl quads, the poles' caps as triangles:
 * no zero-area triangle), centre c, radius r: convex, so its upper triangles see a light above. */
static void add_sphere(scene_t *s, vec3 c, float r, int nl)
{
    int i, j, first = s->nv;
    for (i = 1; i < nl; i++)
        for (j = 0; j < nl; j++) {
            double th = 3.14159265358979 * i / nl, ph = 2 * 3.14159265358979 * j / nl;
            add_v(s, v3_add(c, v3((float)(r * sin(th) * cos(ph)), (float)(r * cos(th)), (float)(r * sin(th) * sin(ph)))));
        }
    for (i = 0; i + 1 < nl - 1; i++)
        for (j = 0; j < nl; j++) {
            int a = first + i * nl + j, b = first + i * nl + (j + 1) % nl;
            add_t(s, a, a + nl, b + nl);
            add_t(s, a, b + nl, b);
        }
    {
        int top = add_v(s, v3_add(c, v3(0, r, 0))), bottom = add_v(s, v3_add(c, v3(0, -r, 0)));
        for (j = 0; j < nl; j++) {
            add_t(s, top, first + (j + 1) % nl, first + j);
            add_t(s, bottom, first + (nl - 2) * nl + j, first + (nl - 2) * nl + (j + 1) % nl);
        }
    }
}

/* A room: a box [-1, 1] x [0, 2] x [-1, 1] open at +z, each corner moved by up to `jitter`, and a
 * light quad facing down under the ceiling; then `inside` random triangles hung in it. */
static void random_room(scene_t *s, float jitter, int inside)
{
    vec3 c[8];
    int k;
    memset(s, 0, sizeof *s);
    for (k = 0; k < 8; k++)
        c[k] = v3((k & 1 ? 1.0f : -1.0f) + rnd_range(-jitter, jitter), (k & 2 ? 2.0f : 0.0f) + rnd_range(-jitter, jitter),
                  (k & 4 ? 1.0f : -1.0f) + rnd_range(-jitter, jitter));
    add_quad(s, c[0], c[4], c[5], c[1], 0);   /* floor, facing up */
    add_quad(s, c[2], c[3], c[7], c[6], 0);   /* ceiling, facing down */
    add_quad(s, c[0], c[1], c[3], c[2], 0);   /* back */
    add_quad(s, c[0], c[2], c[6], c[4], 0);   /* left */
    add_quad(s, c[1], c[5], c[7], c[3], 0);   /* right */
    {
        float y = 1.95f + rnd_range(-jitter, jitter), x0 = rnd_range(-0.6f, 0.0f), z0 = rnd_range(-0.6f, 0.0f);
        add_quad(s, v3(x0, y, z0), v3(x0 + 0.4f, y, z0), v3(x0 + 0.4f, y, z0 + 0.4f), v3(x0, y, z0 + 0.4f), 1);
    }
    for (k = 0; k < inside; k++) {
        vec3 m = v3(rnd_range(-0.8f, 0.8f), rnd_range(0.2f, 1.8f), rnd_range(-0.8f, 0.8f));
        float r = rnd_range(0.05f, 0.5f);
        int a = add_v(s, v3_add(m, v3(rnd_range(-r, r), rnd_range(-r, r), rnd_range(-r, r))));
        int b = add_v(s, v3_add(m, v3(rnd_range(-r, r), rnd_range(-r, r), rnd_range(-r, r))));
        add_t(s, a, b, add_v(s, v3_add(m, v3(rnd_range(-r, r), rnd_range(-r, r), rnd_range(-r, r)))));
    }
}

int main(void)
{
    scene_t s;
    pair_visibility pv;
    long clear, blocked, clear_empty = 0, pairs_empty = 0, clear_full = 0, blocked_all = 0;
    const char *quick = getenv("PATHLAB_TEST_QUICK"), *fast = getenv("PATHLAB_FAST");   /* make test SAN=...: PATHLAB_FAST=1 */
    int floor_clear, i, t, e, rooms = (quick && !strcmp(quick, "1")) || (fast && !strcmp(fast, "1")) ? 64 : 256;

    /* 1 */
    empty_white(&s);
    i = build(&s, &pv);
    check(i == 0 && pv.npairs == 22, "visibility_empty_white", "%ld of 24 pairs clear, expected 22", pv.npairs);
    blocked = blocked_segments(&s, &pv, 4000, &clear);
    check(blocked == 0, "visibility_empty_white_segments", "%ld of %ld segments blocked", blocked, 4000 * clear);
    pair_visibility_free(&pv);
    add_box(&s, v3(-0.3f, 0.8f, -0.3f), v3(0.3f, 1.2f, 0.3f));
    build(&s, &pv);
    for (floor_clear = 0, t = 0; t < 2; t++)
        for (e = 0; e < s.ne; e++) floor_clear += sees_wholly(&pv, t, e);
    check(floor_clear == 0, "visibility_box_under_light", "%d floor-light pairs clear with a box between, expected 0 (%ld pairs in all)",
          floor_clear, pv.npairs);
    blocked = blocked_segments(&s, &pv, 4000, &clear);
    check(blocked == 0 && clear > 0, "visibility_box_under_light_segments", "%ld of %ld segments blocked, %ld pairs clear", blocked, 4000 * clear, clear);
    pair_visibility_free(&pv);
    check_mixed_scales();

    /* 2 */
    for (i = 0; i < rooms; i++) {
        int inside = i % 4;
        random_room(&s, i % 8 < 4 ? 0.02f : 0.0f, inside);
        if (build(&s, &pv)) { check(0, "visibility_random_rooms", "out of memory"); return check_summary(); }
        blocked_all += blocked_segments(&s, &pv, i < 16 ? 4000 : 250, &clear);
        if (!inside && i % 8 < 4) clear_empty += clear, pairs_empty += (long)s.nt * s.ne - s.ne;
        if (!inside && i % 8 >= 4) clear_full += clear == (long)s.nt * s.ne - s.ne;
        pair_visibility_free(&pv);
    }
    check(blocked_all == 0, "visibility_random_rooms", "%ld segments blocked between pairs said clear (%d rooms)", blocked_all, rooms);
    check(clear_empty >= pairs_empty * 19 / 20, "visibility_random_rooms_found", "%ld of %ld pairs clear in the empty rooms with folded walls",
          clear_empty, pairs_empty);
    check(clear_full == rooms / 8, "visibility_exact_boxes_all_clear", "%ld of %d empty rooms with flat walls have every pair clear", clear_full, rooms / 8);

    /* 2b: more than 64 triangles (the tables' words), a sphere hung under the light */
    random_room(&s, 0.0f, 0);
    add_sphere(&s, v3(0.1f, 1.0f, -0.1f), 0.45f, 14);
    build(&s, &pv);
    blocked = blocked_segments(&s, &pv, 100, &clear);
    check(blocked == 0 && clear > 20 && s.nt > 300, "visibility_sphere_in_room", "%d triangles: %ld segments blocked, %ld of %d pairs clear",
          s.nt, blocked, clear, s.nt * s.ne);
    pair_visibility_free(&pv);

    /* 3 */
    {
        static vec3 P[3 * (VISIBILITY_MAX_TRIS + 1)];
        static int tri[3 * (VISIBILITY_MAX_TRIS + 1)];
        int em = 0, n = VISIBILITY_MAX_TRIS + 1;
        for (i = 0; i < 3 * n; i++) { P[i] = v3((float)i, (float)(i % 3), 0.5f * (float)(i % 7)); tri[i] = i; }
        check(pair_visibility_build(&pv, P, tri, n, &em, 1) == 0 && !pv.bits && pv.npairs == 0 && !sees_wholly(&pv, 0, 0),
              "visibility_too_big", "%d triangles: no table", n);
        pair_visibility_free(&pv);
    }
    return check_summary();
}
