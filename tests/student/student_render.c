/* tests/student/student_render.c — a renderer of the kind a student writes in gKit's direct-light tutorial,
 * written apart from pathlab (none of its code, its own RNG, camera and RGBE writer) so that the
 * tests grade a whole path from a student's program to a verdict (tests/test_student.sh):
 *   L = Le(first hit) + Kd/pi Le(s) cos(theta_p) cos(theta_s) / |s - p|^2 / pdf(s), one light
 *   triangle picked uniformly (pdf of a triangle 1 / ntriangles), a point uniform on it (pdf 1 /
 *   area); the ray through the pixel's centre, Point(x + .5f, y + .5f) with y up from the bottom
 *   row; gKit's orbiter camera; one-sided emitters (front face by the winding).
 * usage: student_render SCENE.obj ORBITER.txt SPP SEED OUT.pfm|OUT.hdr [mistake...]
 *   mistakes: no-pi (Kd, not Kd/pi), no-light-cos (cos theta_s left out), unclamped (cos theta_s
 *   not clamped at 0: light from the back of the emitter counts, negative), jitter (a random point
 *   in the pixel instead of its centre), via-rgbe (the PFM holds the values of a truncating RGBE
 *   file decoded without the half step, as gKit's and OpenImageIO's decoders do).
 * OUT.hdr: Radiance RGBE, flat, written with a truncating encoder (as gKit's), rows top to bottom.
 * Only what the tests' scenes use of OBJ and MTL: v, f (fans), usemtl, mtllib; newmtl, Kd, Ke. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct { double x, y, z; } vec;
typedef struct { vec a, b, c; int mat; } triangle;
typedef struct { char name[64]; vec kd, ke; } material;

static vec add(vec a, vec b) { vec r = {a.x + b.x, a.y + b.y, a.z + b.z}; return r; }
static vec sub(vec a, vec b) { vec r = {a.x - b.x, a.y - b.y, a.z - b.z}; return r; }
static vec mul(vec a, double s) { vec r = {a.x * s, a.y * s, a.z * s}; return r; }
static double dot(vec a, vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static vec cross(vec a, vec b) { vec r = {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; return r; }
static vec normalize(vec a) { return mul(a, 1.0 / sqrt(dot(a, a))); }

static triangle *tris;
static int ntris, nmats, *lights, nlights;
static material mats[64];
static int no_pi, no_light_cos, unclamped, jitter, via_rgbe;

/* xorshift64*: the student's own generator, seeded per pixel */
static unsigned long long rng_state;
static double uniform01(void)
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return (double)((rng_state * 2685821657736338717ULL) >> 11) / 9007199254740992.0;
}

static void read_mtl(const char *path)
{
    char line[256];
    FILE *f = fopen(path, "r");
    material *m = NULL;
    if (!f) { fprintf(stderr, "student_render: %s: cannot open\n", path); exit(2); }
    while (fgets(line, sizeof line, f)) {
        if (!strncmp(line, "newmtl ", 7) && nmats < 64) {
            m = &mats[nmats++];
            memset(m, 0, sizeof *m);
            sscanf(line + 7, "%63s", m->name);
        } else if (m && !strncmp(line, "Kd ", 3)) sscanf(line + 3, "%lf %lf %lf", &m->kd.x, &m->kd.y, &m->kd.z);
        else if (m && !strncmp(line, "Ke ", 3)) sscanf(line + 3, "%lf %lf %lf", &m->ke.x, &m->ke.y, &m->ke.z);
    }
    fclose(f);
}

static int material_index(const char *name)
{
    int k;
    for (k = 0; k < nmats; k++) if (!strcmp(mats[k].name, name)) return k;
    return 0;
}

/* v, f (a fan 0 1 2, 0 2 3 ... as gKit's read_mesh), usemtl, mtllib (beside the OBJ) */
static void read_obj(const char *path)
{
    static vec v[4096];
    char line[512], word[256], dir[512];
    int nv = 0, mat = 0, cap = 64;
    FILE *f = fopen(path, "r");
    const char *slash = strrchr(path, '/');
    snprintf(dir, sizeof dir, "%.*s", slash ? (int)(slash - path + 1) : 0, path);
    if (!f) { fprintf(stderr, "student_render: %s: cannot open\n", path); exit(2); }
    tris = malloc(cap * sizeof *tris);
    while (fgets(line, sizeof line, f)) {
        if (!strncmp(line, "v ", 2) && nv < 4096) sscanf(line + 2, "%lf %lf %lf", &v[nv].x, &v[nv].y, &v[nv].z), nv++;
        else if (!strncmp(line, "mtllib ", 7) && sscanf(line + 7, "%255s", word) == 1) {
            char mtl[800];
            snprintf(mtl, sizeof mtl, "%s%s", dir, word);
            read_mtl(mtl);
        } else if (!strncmp(line, "usemtl ", 7) && sscanf(line + 7, "%255s", word) == 1) mat = material_index(word);
        else if (!strncmp(line, "f ", 2)) {
            int idx[16], n = 0, k;
            char *s = line + 2, *end;
            for (; n < 16; n++, s = end + strcspn(end, " \t\n")) {   /* "i", "i/t" or "i/t/n": the vertex i */
                idx[n] = (int)strtol(s, &end, 10);
                if (end == s || idx[n] < 1 || idx[n] > nv) break;
            }
            for (k = 1; k + 1 < n; k++) {
                if (ntris == cap) tris = realloc(tris, (cap *= 2) * sizeof *tris);
                tris[ntris].a = v[idx[0] - 1], tris[ntris].b = v[idx[k] - 1], tris[ntris].c = v[idx[k + 1] - 1];
                tris[ntris++].mat = mat;
            }
        }
    }
    fclose(f);
    lights = malloc((ntris + 1) * sizeof *lights);
    for (mat = 0; mat < ntris; mat++) {
        vec ke = mats[tris[mat].mat].ke;
        if (ke.x + ke.y + ke.z > 0.0) lights[nlights++] = mat;
    }
}

/* Moller-Trumbore: the distance along d to triangle t, or 0 */
static double hit_triangle(const triangle *t, vec o, vec d)
{
    vec e1 = sub(t->b, t->a), e2 = sub(t->c, t->a), p = cross(d, e2), s, q;
    double det = dot(e1, p), u, v, dist;
    if (fabs(det) < 1e-12) return 0.0;
    s = sub(o, t->a);
    u = dot(s, p) / det;
    if (u < 0.0 || u > 1.0) return 0.0;
    q = cross(s, e1);
    v = dot(d, q) / det;
    if (v < 0.0 || u + v > 1.0) return 0.0;
    dist = dot(e2, q) / det;
    return dist > 1e-4 ? dist : 0.0;
}

static int intersect(vec o, vec d, double tmax, double *t)
{
    int k, best = -1;
    *t = tmax;
    for (k = 0; k < ntris; k++) {
        double h = hit_triangle(&tris[k], o, d);
        if (h > 0.0 && h < *t) { *t = h; best = k; }
    }
    return best;
}

/* Direct light at p (normal n facing the viewer) from one light triangle picked uniformly */
static vec direct(vec p, vec n, vec kd)
{
    const triangle *l = &tris[lights[(int)(uniform01() * nlights) % nlights]];
    double u = uniform01(), v = uniform01(), su = sqrt(u), t, d2, cos_p, cos_s, area, pdf, g;
    vec s = add(mul(l->a, 1.0 - su), add(mul(l->b, su * (1.0 - v)), mul(l->c, su * v)));
    vec ln = cross(sub(l->b, l->a), sub(l->c, l->a)), w = sub(s, p), zero = {0, 0, 0}, le;
    area = 0.5 * sqrt(dot(ln, ln));
    ln = normalize(ln);
    d2 = dot(w, w);
    w = mul(w, 1.0 / sqrt(d2));
    cos_p = dot(n, w);
    cos_s = dot(ln, mul(w, -1.0));
    if (cos_p <= 0.0) return zero;
    if (!unclamped && cos_s <= 0.0) return zero;   /* the emitter's back: no light */
    if (intersect(add(p, mul(n, 1e-3)), w, sqrt(d2) * (1.0 - 1e-4), &t) >= 0) return zero;
    pdf = 1.0 / (nlights * area);
    g = cos_p * (no_light_cos ? 1.0 : cos_s) / d2 / pdf / (no_pi ? 1.0 : M_PI);
    le = mats[l->mat].ke;
    return (vec){kd.x * le.x * g, kd.y * le.y * g, kd.z * le.z * g};
}

static vec radiance(vec o, vec d)
{
    double t;
    int k = intersect(o, d, 1e30, &t);
    vec n, p, L = {0, 0, 0};
    const material *m;
    if (k < 0) return L;
    m = &mats[tris[k].mat];
    n = normalize(cross(sub(tris[k].b, tris[k].a), sub(tris[k].c, tris[k].a)));
    if (dot(n, d) < 0.0) L = m->ke;       /* the emitting side faces the eye */
    else n = mul(n, -1.0);
    p = add(o, mul(d, t));
    return add(L, direct(p, n, m->kd));
}

/* gKit's orbiter file: eye = c + M (px, py, size), M = Ry(-ry) Rx(-rx); f: fov (vertical), w, h */
typedef struct { vec eye, right, up, forward; double fov; int w, h; } camera;

static vec rotate(vec v, double rx, double ry)   /* Ry(-ry) Rx(-rx) v, degrees */
{
    double a = -rx * M_PI / 180.0, b = -ry * M_PI / 180.0;
    vec x = {v.x, v.y * cos(a) - v.z * sin(a), v.y * sin(a) + v.z * cos(a)};
    vec r = {x.x * cos(b) + x.z * sin(b), x.y, -x.x * sin(b) + x.z * cos(b)};
    return r;
}

static camera read_orbiter(const char *path)
{
    char line[256];
    double c[3] = {0, 0, 0}, p[2] = {0, 0}, r[2] = {0, 0}, size = 1.0;
    camera cam;
    FILE *f = fopen(path, "r");
    vec ex = {1, 0, 0}, ey = {0, 1, 0}, ez = {0, 0, 1}, local;
    memset(&cam, 0, sizeof cam);
    if (!f) { fprintf(stderr, "student_render: %s: cannot open\n", path); exit(2); }
    while (fgets(line, sizeof line, f)) {
        double fw = 0, fh = 0;
        if (line[0] == 'c') sscanf(line + 1, "%lf %lf %lf", &c[0], &c[1], &c[2]);
        if (line[0] == 'p') sscanf(line + 1, "%lf %lf", &p[0], &p[1]);
        if (line[0] == 'r') sscanf(line + 1, "%lf %lf", &r[0], &r[1]);
        if (line[0] == 's') sscanf(line + 1, "%lf", &size);
        if (line[0] == 'f' && sscanf(line + 1, "%lf %lf %lf", &cam.fov, &fw, &fh) == 3) cam.w = (int)fw, cam.h = (int)fh;
    }
    fclose(f);
    local.x = p[0], local.y = p[1], local.z = size;
    cam.eye = add((vec){c[0], c[1], c[2]}, rotate(local, r[0], r[1]));
    cam.right = rotate(ex, r[0], r[1]);
    cam.up = rotate(ey, r[0], r[1]);
    cam.forward = mul(rotate(ez, r[0], r[1]), -1.0);
    return cam;
}

/* RGBE of one pixel as gKit writes it: e from the largest channel, mantissas truncated */
static void rgbe_encode(const float *v, unsigned char out[4])
{
    double m = fmax(v[0], fmax(v[1], v[2])), f;
    int e, k;
    if (m < 1e-32) { out[0] = out[1] = out[2] = out[3] = 0; return; }
    f = frexp(m, &e) * 256.0 / m;
    for (k = 0; k < 3; k++) out[k] = (unsigned char)(v[k] > 0.0f ? v[k] * f : 0.0);
    out[3] = (unsigned char)(e + 128);
}

/* the value of an RGBE pixel decoded without the half step (gKit's, OpenImageIO's decoders) */
static void rgbe_decode_low(const unsigned char in[4], float *v)
{
    int k;
    for (k = 0; k < 3; k++) v[k] = in[3] ? (float)ldexp(in[k], in[3] - 136) : 0.0f;
}

static int write_image(const float *px, int w, int h, const char *path)
{
    FILE *f = fopen(path, "wb");
    int x, y, hdr = strlen(path) > 4 && !strcmp(path + strlen(path) - 4, ".hdr");
    if (!f) return 1;
    if (hdr) fprintf(f, "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n", h, w);
    else fprintf(f, "PF\n%d %d\n-1.0\n", w, h);
    for (y = 0; y < h; y++)   /* px: row 0 = the bottom row (gKit); .hdr from the top, PFM from the bottom */
        for (x = 0; x < w; x++) {
            const float *v = &px[3 * ((size_t)(hdr ? h - 1 - y : y) * w + x)];
            unsigned char e[4];
            float low[3];
            rgbe_encode(v, e);
            rgbe_decode_low(e, low);
            if (hdr) fwrite(e, 1, 4, f);
            else fwrite(via_rgbe ? low : v, sizeof(float), 3, f);   /* little-endian hosts */
        }
    return fclose(f) != 0;
}

static void render(const camera *cam, int spp, unsigned long long seed, float *px)
{
    double th = tan(0.5 * cam->fov * M_PI / 180.0), aspect = (double)cam->w / cam->h;
    int x, y, s;
    for (y = 0; y < cam->h; y++)
        for (x = 0; x < cam->w; x++) {
            vec sum = {0, 0, 0};
            rng_state = (seed * 0x9E3779B97F4A7C15ULL) ^ ((unsigned long long)(y * cam->w + x + 1) * 0xD1B54A32D192ED03ULL);
            if (!rng_state) rng_state = 1;
            for (s = 0; s < spp; s++) {
                double fx = x + (jitter ? uniform01() : 0.5), fy = y + (jitter ? uniform01() : 0.5);
                double nx = (2.0 * fx / cam->w - 1.0) * th * aspect, ny = (2.0 * fy / cam->h - 1.0) * th;
                vec d = normalize(add(cam->forward, add(mul(cam->right, nx), mul(cam->up, ny))));
                sum = add(sum, radiance(cam->eye, d));
            }
            px[3 * (y * cam->w + x)] = (float)(sum.x / spp);
            px[3 * (y * cam->w + x) + 1] = (float)(sum.y / spp);
            px[3 * (y * cam->w + x) + 2] = (float)(sum.z / spp);
        }
}

int main(int argc, char **argv)
{
    camera cam;
    float *px;
    int k;
    if (argc < 6) { fprintf(stderr, "usage: student_render SCENE.obj ORBITER.txt SPP SEED OUT.pfm|OUT.hdr [mistake...]\n"); return 2; }
    for (k = 6; k < argc; k++) {
        no_pi |= !strcmp(argv[k], "no-pi");
        no_light_cos |= !strcmp(argv[k], "no-light-cos");
        unclamped |= !strcmp(argv[k], "unclamped");
        jitter |= !strcmp(argv[k], "jitter");
        via_rgbe |= !strcmp(argv[k], "via-rgbe");
    }
    read_obj(argv[1]);
    cam = read_orbiter(argv[2]);
    if (!nlights || cam.w < 1 || cam.h < 1) { fprintf(stderr, "student_render: no light, or no f line in %s\n", argv[2]); return 2; }
    px = calloc((size_t)3 * cam.w * cam.h, sizeof *px);
    render(&cam, atoi(argv[3]), strtoull(argv[4], NULL, 10), px);
    if (write_image(px, cam.w, cam.h, argv[5])) { fprintf(stderr, "student_render: %s: cannot write\n", argv[5]); return 2; }
    free(px);
    return 0;
}
