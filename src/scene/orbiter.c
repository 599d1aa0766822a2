/* orbiter.c — gKit orbiter files: the reader, and the camera they describe as a pathlab view. */
#include "scene/orbiter.h"
#include "sys/shown.h"
#include "sys/input_file.h"
#include "scene/camera.h"
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define ORBITER_KEYS "cprsf"
/* what each key's line holds, for messages */
static const char *const KEY_FORM[] = {"c cx cy cz (the centre)", "p px py (the pan)", "r rx ry (the rotation, degrees)",
                                       "s size radius (the distance, > 0, and the scene radius)", "f fov width height (vertical fov in degrees, 0.01 to under 180; whole pixels, at most 1e9 in all)"};

/* The largest size of a number: the camera is made of floats (FLT_MAX is about 3.4e38), and the
 * eye, c + M (px, py, size), adds up to three of them. */
#define ORBITER_MAX_NUMBER 1e30

/* Up to max numbers from s into out; how many, -1 if something that is not a number follows, -2 if
 * a number is beyond ORBITER_MAX_NUMBER in size. */
static int read_numbers(const char *s, double *out, int max)
{
    int n = 0;
    char *end;
    for (;;) {
        while (*s == ' ' || *s == '\t' || *s == '\r' || *s == '\n') s++;
        if (!*s) return n;
        if (n == max) return -1;
        out[n] = strtod(s, &end);
        if (end == s || !isfinite(out[n])) return -1;
        if (fabs(out[n]) > ORBITER_MAX_NUMBER) return -2;
        n++;
        s = end;
    }
}

static int whole(double x) { return x >= 1.0 && x <= 65536.0 && x == floor(x); }

/* Stores the numbers of key k's line; 0, or 1 if they do not fit (count, range). */
static int store_key(orbiter *o, int k, const double *v, int n)
{
    switch (k) {
    case 0: if (n != 3) return 1; memcpy(o->c, v, 3 * sizeof *v); return 0;
    case 1: if (n != 2) return 1; memcpy(o->p, v, 2 * sizeof *v); return 0;
    case 2: if (n != 2) return 1; memcpy(o->r, v, 2 * sizeof *v); return 0;
    case 3:   /* gKit before the radius wrote "s size" alone, and its lookat() sets radius = size;
               * its move() keeps size >= 0.001: the camera is in front of the centre */
        if ((n != 1 && n != 2) || !(v[0] > 0.0)) return 1;
        o->size = v[0];
        o->radius = n == 2 ? v[1] : v[0];
        return 0;
    default:  /* gKit writes width and height with %f: 1024.000000; the bounds are a view file's
               * (camera.h), said here with this file's line rather than by the camera later */
        if (n != 3 || !(v[0] >= VIEW_FOV_MIN && v[0] < 180.0) || !whole(v[1]) || !whole(v[2]) || v[1] * v[2] > VIEW_PIXELS_MAX) return 1;
        o->fov = v[0];
        o->width = (int)v[1];
        o->height = (int)v[2];
        o->has_f = 1;
        return 0;
    }
}

/* One line; 0, or 1 after printing "path:lineno: ...". seen[k] is the line of key k, 0 if none yet. */
static int parse_line(orbiter *o, char *line, const char *path, int lineno, int seen[5])
{
    double v[4];
    const char *key;
    int k, n;
    char *hash = strchr(line, '#');
    if (hash) *hash = '\0';
    line[strcspn(line, "\r\n")] = '\0';
    for (key = line; *key == ' ' || *key == '\t'; key++) continue;
    if (!*key) return 0;
    if (!strchr(ORBITER_KEYS, *key) || (key[1] != ' ' && key[1] != '\t' && key[1] != '\0')) {
        fprintf(stderr, "%s:%d: '%.40s%s' is not a line of a gKit orbiter file (expected c, p, r, s or f lines)\n", shown(path),
                lineno, shown(key), strlen(key) > 40 ? "..." : "");
        return 1;
    }
    k = (int)(strchr(ORBITER_KEYS, *key) - ORBITER_KEYS);
    if (seen[k]) {
        fprintf(stderr, "%s:%d: a second '%c' line (the first is line %d)\n", shown(path), lineno, *key, seen[k]);
        return 1;
    }
    seen[k] = lineno;
    n = read_numbers(key + 1, v, 4);
    if (n == -2) {
        fprintf(stderr, "%s:%d: a number beyond %g in size in '%.40s%s': pathlab's camera is made of floats\n", shown(path),
                lineno, ORBITER_MAX_NUMBER, shown(key), strlen(key) > 40 ? "..." : "");
        return 1;
    }
    if (n < 0 || store_key(o, k, v, n)) {
        fprintf(stderr, "%s:%d: expected '%s', got '%.40s%s'\n", shown(path), lineno, KEY_FORM[k], shown(key), strlen(key) > 40 ? "..." : "");
        return 1;
    }
    return 0;
}

int orbiter_read(orbiter *o, const char *path)
{
    size_t cap = 256;
    char *line = malloc(cap);
    int seen[5] = {0, 0, 0, 0, 0}, lineno = 0, k, err = 0, rc;
    FILE *fp = input_file_open(path, 1);   /* a FIFO must not hang the command */
    memset(o, 0, sizeof *o);
    if (!fp || !line) {
        fprintf(stderr, "%s: cannot open the orbiter file: %s\n", shown(path), fp ? strerror(ENOMEM) : input_file_why(errno));
        free(line);
        if (fp) fclose(fp);
        return 1;
    }
    /* view files' reader: lines of any length, a long comment never read as a line, NUL refused */
    while (!err && (rc = view_read_line(fp, &line, &cap))) {
        lineno++;
        if (rc != 1) fprintf(stderr, "%s:%d: %s\n", shown(path), lineno, rc == 6 ? "a NUL byte: not a text file"
                             : rc == 7 ? "line too long" : "out of memory");
        err = rc != 1 || parse_line(o, line, path, lineno, seen);
    }
    fclose(fp);
    free(line);
    for (k = 0; k < 4 && !err; k++)
        if (!seen[k]) {
            fprintf(stderr, "%s:%d: the file ends without its '%s' line (a gKit orbiter file has c, p, r and s lines)\n",
                    shown(path), lineno > 0 ? lineno : 1, KEY_FORM[k]);
            err = 1;
        }
    return err;
}

/* m = Ry(-ry) Rx(-rx), the camera-to-world rotation (the inverse of the view's Rx(rx) Ry(ry)). */
static void camera_rotation(const orbiter *o, double m[3][3])
{
    double ax = -o->r[0] * PI / 180.0, ay = -o->r[1] * PI / 180.0;
    double cx = cos(ax), sx = sin(ax), cy = cos(ay), sy = sin(ay);
    /* Ry = [cy 0 sy; 0 1 0; -sy 0 cy], Rx = [1 0 0; 0 cx -sx; 0 sx cx], as gKit's mat.cpp */
    m[0][0] = cy; m[0][1] = sy * sx;  m[0][2] = sy * cx;
    m[1][0] = 0;  m[1][1] = cx;       m[1][2] = -sx;
    m[2][0] = -sy; m[2][1] = cy * sx; m[2][2] = cy * cx;
}

static void mul(double m[3][3], const double v[3], double out[3])
{
    int i;
    for (i = 0; i < 3; i++) out[i] = m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2];
}

void orbiter_view(const orbiter *o, view *vw)
{
    double m[3][3], eye[3], up[3], tgt[3];
    const double local_eye[3] = {o->p[0], o->p[1], o->size}, y[3] = {0, 1, 0};
    /* the target: the point at distance size straight ahead, the orbit centre moved by the pan
     * (c + M (px, py, 0)), the middle of gKit's image; a view file shows a point of the scene */
    const double local_tgt[3] = {o->p[0], o->p[1], 0};
    int i;
    camera_rotation(o, m);
    mul(m, local_eye, eye);
    mul(m, local_tgt, tgt);
    mul(m, y, up);
    for (i = 0; i < 3; i++) { eye[i] += o->c[i]; tgt[i] += o->c[i]; }
    vw->eye = v3((float)eye[0], (float)eye[1], (float)eye[2]);
    vw->target = v3((float)tgt[0], (float)tgt[1], (float)tgt[2]);
    vw->up = v3((float)up[0], (float)up[1], (float)up[2]);
    vw->has_eye = vw->has_target = 1;
    if (o->has_f) {
        vw->fov = (float)o->fov;
        vw->width = o->width;
        vw->height = o->height;
    }
}

double orbiter_znear(const orbiter *o)
{
    double dx = o->c[0] - o->p[0], dy = o->c[1] - o->p[1], dz = o->c[2] - o->size;
    double d = sqrt(dx * dx + dy * dy + dz * dz) - o->radius;
    return d > 0.1 ? d : 0.1;
}
