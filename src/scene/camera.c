/* camera.c — view files and the pinhole camera. */
#include "scene/camera.h"
#include "sys/shown.h"
#include "sys/input_file.h"
#include "scene/objtext.h"
#include <errno.h>
#include <float.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void view_defaults(view *vw)
{
    memset(vw, 0, sizeof *vw);
    vw->up = v3(0, 1, 0);
    vw->fov = 40.0f;
    vw->width = vw->height = 512;
}


/* Reads n floats from the rest of a line into out; 0 on success, and nothing may follow them.
 * A finite double beyond the float range (1e39) is refused with its own message (code 3): cast
 * to float it is undefined behaviour, and as inf it gave a misleading "up is parallel". */
static int read_floats(const char *s, double *out, int n)
{
    int i;
    char *end;
    for (i = 0; i < n; i++) {
        double d = strtod(s, &end);
        if (end == s || !isfinite(d)) return 1;
        if (fabs(d) > FLT_MAX) return 3;
        out[i] = d;
        s = end;
    }
    while (*s == ' ' || *s == '\t' || *s == '\r' || *s == '\n') s++;
    return *s != '\0';
}

/* size W H: whole numbers checked as doubles, before any conversion to int (a double beyond
 * INT_MAX cast to int is undefined behaviour: "size 2521474836477 256"). */
static int size_ok(const double *f)
{
    return f[0] == floor(f[0]) && f[1] == floor(f[1]) && f[0] >= 1 && f[1] >= 1 && f[0] <= VIEW_SIZE_MAX
        && f[1] <= VIEW_SIZE_MAX && f[0] * f[1] <= VIEW_PIXELS_MAX;
}

/* One line without its comment: 0, or an error code for view_error. */
static int parse_view_line(view *vw, char *line, int lineno)
{
    char key[16];
    double f[3];
    int n = 0, rc;
    if (sscanf(line, " %15s%n", key, &n) != 1) return 0;   /* blank line */
    line += n;
    if (!strcmp(key, "eye") || !strcmp(key, "target") || !strcmp(key, "up")) {
        if ((rc = read_floats(line, f, 3))) return rc;
        if (key[0] == 'e') { vw->eye = v3((float)f[0], (float)f[1], (float)f[2]); vw->has_eye = 1; vw->line_eye = lineno; }
        else if (key[0] == 't') { vw->target = v3((float)f[0], (float)f[1], (float)f[2]); vw->has_target = 1; vw->line_target = lineno; }
        else { vw->up = v3((float)f[0], (float)f[1], (float)f[2]); vw->line_up = lineno; }
    } else if (!strcmp(key, "fov")) {
        if ((rc = read_floats(line, f, 1))) return rc;
        if (!(f[0] >= VIEW_FOV_MIN && f[0] < 180)) return 4;
        vw->fov = (float)f[0];
        vw->line_fov = lineno;
    } else if (!strcmp(key, "size")) {
        if ((rc = read_floats(line, f, 2)) == 1 || (!rc && (f[0] != floor(f[0]) || f[1] != floor(f[1])))) return 1;
        if (rc || !size_ok(f)) return 5;
        vw->width = (int)f[0];
        vw->height = (int)f[1];
        vw->line_size = lineno;
    } else {
        return 2;
    }
    return 0;
}

/* The comment is read and dropped, whatever its length, so that a long one never turns into a
 * new line; reading stops at a NUL byte: /dev/zero has no line end. */
int view_read_line(FILE *fp, char **buf, size_t *cap)
{
    size_t n = 0;
    int c, comment = 0, rc = 1, any = 0;
    char *bigger;
    while ((c = getc(fp)) != EOF && c != '\n') {
        any = 1;
        if (c == '\0') return 6;
        if (c == '#') comment = 1;
        if (comment || rc != 1) continue;
        if (n + 1 == *cap) {
            if (*cap >= VIEW_LINE_MAX) { rc = 7; continue; }
            if (!(bigger = realloc(*buf, 2 * *cap))) return 8;
            *buf = bigger;
            *cap *= 2;
        }
        (*buf)[n++] = (char)c;
    }
    (*buf)[n] = '\0';
    return c == EOF && !any ? 0 : rc;
}

/* Prints "path:lineno: what is wrong" for error code rc of parse_view_line or read_line. */
static void view_error(const char *path, int lineno, int rc, const char *line)
{
    static const char *const what[] = {
        "", "bad values (eye/target/up take 3 numbers, fov 1, size 2 whole numbers)",
        "unknown key (expected eye, target, up, fov or size)",
        "a number too large for a float (the largest is 3.4e38)",
        "fov must be from 0.01 (below it, neighbouring pixels' rays are one float direction) to 180 degrees (exclusive)", "",
        "a NUL byte: not a text file", "",
        "out of memory"};
    fprintf(stderr, "%s:%d: ", shown(path), lineno);
    if (rc == 5) {   /* the numbers as written, after the key (at most 40 characters of them) */
        line += strspn(line, " \t");
        line += strcspn(line, " \t");
        line += strspn(line, " \t");
        fprintf(stderr, "size %.40s%s: out of range (whole numbers from 1 to %d, at most %.0e pixels)\n", shown(line),
                strlen(line) > 40 ? "..." : "", VIEW_SIZE_MAX, VIEW_PIXELS_MAX);
    } else if (rc == 7) {
        fprintf(stderr, "line longer than %d characters before its comment\n", VIEW_LINE_MAX - 1);
    } else {
        fprintf(stderr, "%s\n", what[rc]);
    }
}

int view_read(view *vw, const char *path)
{
    size_t cap = 256;
    char *line = malloc(cap);
    int lineno = 0, rc = 0;
    FILE *fp;
    if (!line) { fprintf(stderr, "%s: out of memory\n", shown(path)); return 1; }
    if (!(fp = input_file_open(path, 0))) {   /* a FIFO named SCENE.view must not hang the render */
        free(line);
        return errno == ENOENT ? -1 : (fprintf(stderr, "%s: cannot open: %s\n", shown(path), strerror(errno)), 1);
    }
    snprintf(vw->file, sizeof vw->file, "%s", path);
    vw->line_eye = vw->line_target = vw->line_up = vw->line_fov = vw->line_size = 0;
    while (!rc && (rc = view_read_line(fp, &line, &cap))) {
        lineno++;
        if (rc == 1) rc = parse_view_line(vw, line, lineno);
        if (rc) view_error(path, lineno, rc, line);
    }
    if (!rc && ferror(fp)) { fprintf(stderr, "%s: read error\n", shown(path)); rc = 1; }
    /* an empty view (/dev/null, a FIFO with no writer: it reads as empty) would silently give the
     * default framing */
    if (!rc && !(vw->line_eye || vw->line_target || vw->line_up || vw->line_fov || vw->line_size)) {
        fprintf(stderr, "%s: no camera in it (lines eye, target, up, fov or size)\n", shown(path));
        rc = 1;
    }
    fclose(fp);
    free(line);
    return rc ? 1 : 0;
}

void view_print(FILE *f, const view *vw)
{
    fprintf(f, "eye %.9g %.9g %.9g\n", vw->eye.x, vw->eye.y, vw->eye.z);
    fprintf(f, "target %.9g %.9g %.9g\n", vw->target.x, vw->target.y, vw->target.z);
    fprintf(f, "up %.9g %.9g %.9g\n", vw->up.x, vw->up.y, vw->up.z);
    fprintf(f, "fov %.9g\n", vw->fov);
    fprintf(f, "size %d %d\n", vw->width, vw->height);
}

/* The distance along +z from the target at which the box lo..hi fills the field of view (tangents
 * tan_v and tan_h of its half angles) but for a 5% margin: every corner's offset across the view,
 * over its depth from the eye, within the tangent. The box's image is the convex hull of its
 * corners', so the whole box is in the picture; tighter than its bounding sphere, which left a mesh
 * in 60% of the width. -1 when up is along the view (the sphere's distance serves then). */
static float fit_distance(const view *vw, vec3 lo, vec3 hi, float tan_v, float tan_h, float radius)
{
    vec3 w = v3(0, 0, 1), u = v3_cross(vw->up, w), v;
    float len = v3_length(u), d = 0.0f;
    int k;
    if (!(len > 1e-6f * v3_length(vw->up))) return -1.0f;
    u = v3_scale(u, 1.0f / len);
    v = v3_cross(w, u);
    for (k = 0; k < 8; k++) {
        vec3 c = v3_sub(v3(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z), vw->target);
        float across = fmaxf(fabsf(v3_dot(c, u)) / tan_h, fabsf(v3_dot(c, v)) / tan_v);
        d = fmaxf(d, c.z + fmaxf(1.05f * across, 0.05f * radius));   /* the eye outside the box */
    }
    return d;
}

void view_frame_bounds(view *vw, vec3 lo, vec3 hi)
{
    vec3 c = v3_scale(v3_add(lo, hi), 0.5f);
    float radius = 0.5f * v3_length(v3_sub(hi, lo)), dist;
    /* far enough along +z that the box fits in the field of view; else its bounding sphere in the narrower one */
    float half = 0.5f * vw->fov * PI_F / 180.0f;
    float aspect = (float)vw->width / (float)vw->height;
    float half_min = aspect < 1.0f ? atanf(tanf(half) * aspect) : half;
    if (!vw->has_target) vw->target = c;
    dist = fit_distance(vw, lo, hi, tanf(half), tanf(half) * aspect, radius);
    if (!(dist > 0.0f && dist < INFINITY)) dist = 1.05f * radius / sinf(half_min);
    if (!vw->has_eye) vw->eye = v3_add(vw->target, v3(0, 0, dist));
    vw->has_eye = vw->has_target = 1;
}

/* Prints a camera error where its value came from: "FILE:LINE: " for a key of a view file (line
 * > 0), "camera: " for a flag or a default; returns 1. */
static int say(const view *vw, int line, const char *fmt, ...)
{
    va_list ap;
    if (line > 0) fprintf(stderr, "%s:%d: ", shown(vw->file), line);
    else fprintf(stderr, "camera: ");
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    return 1;
}

/* "line N" for a key of the view file, "no line" for a flag or a default, into buf. */
static const char *origin(int line, char *buf, size_t cap)
{
    if (line > 0) snprintf(buf, cap, "line %d", line);
    else snprintf(buf, cap, "flag, orbiter or default");
    return buf;
}

/* eye, target and up checked in double: their float differences and products may overflow (eye
 * 1e30, target -1e30) and would give a NaN basis or a misleading message. */
static int check_directions(const view *vw)
{
    double f[3], u[3], x[3], lf, lu, lx;
    char a[32], b[32], c[32];
    int line = vw->line_target > vw->line_eye ? vw->line_target : vw->line_eye;
    f[0] = (double)vw->target.x - vw->eye.x, f[1] = (double)vw->target.y - vw->eye.y, f[2] = (double)vw->target.z - vw->eye.z;
    u[0] = vw->up.x, u[1] = vw->up.y, u[2] = vw->up.z;
    x[0] = f[1] * u[2] - f[2] * u[1], x[1] = f[2] * u[0] - f[0] * u[2], x[2] = f[0] * u[1] - f[1] * u[0];
    lf = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    lu = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    lx = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    if (!(lf > 0)) return say(vw, line, "eye (%s) and target (%s) are the same point", origin(vw->line_eye, a, sizeof a),
                              origin(vw->line_target, b, sizeof b));
    if (!(lf <= FLT_MAX))
        return say(vw, line, "eye (%s) and target (%s) are too far apart for float arithmetic (%.3g)",
                   origin(vw->line_eye, a, sizeof a), origin(vw->line_target, b, sizeof b), lf);
    if (lf < 1e-18)   /* its square, in the float normalisation, would be 0 */
        return say(vw, line, "eye (%s) and target (%s) are too close for float arithmetic (%.3g apart; at least 1e-18)",
                   origin(vw->line_eye, a, sizeof a), origin(vw->line_target, b, sizeof b), lf);
    if (!(lu > 0)) return say(vw, vw->line_up, "up is (0, 0, 0)");
    if (lu < 1e-18 || !(lu <= FLT_MAX)) return say(vw, vw->line_up, "up %g %g %g: too short or too long for float arithmetic (a length "
                                                   "from 1e-18 to 3.4e38)", u[0], u[1], u[2]);
    if (!(lx > 1e-6 * lf * lu))
        return say(vw, vw->line_up > line ? vw->line_up : line, "up %g %g %g (%s) is parallel to the view direction, from "
                   "eye (%s) to target (%s)", u[0], u[1], u[2], origin(vw->line_up, c, sizeof c),
                   origin(vw->line_eye, a, sizeof a), origin(vw->line_target, b, sizeof b));
    return 0;
}

int camera_init(camera *c, const view *vw)
{
    float th;
    vec3 fwd, side;
    if (!(vw->fov >= (float)VIEW_FOV_MIN && vw->fov < 180.0f))
        return say(vw, vw->line_fov, "fov %g: must be from %g (below it, neighbouring pixels' rays are one float direction) to "
                   "180 degrees (exclusive)", vw->fov, VIEW_FOV_MIN);
    if (vw->width < 1 || vw->height < 1 || vw->width > VIEW_SIZE_MAX || vw->height > VIEW_SIZE_MAX ||
        (double)vw->width * vw->height > VIEW_PIXELS_MAX)
        return say(vw, vw->line_size, "image size %dx%d is out of range (1 to %d pixels a side, at most %.0e pixels)",
                   vw->width, vw->height, VIEW_SIZE_MAX, VIEW_PIXELS_MAX);
    if (check_directions(vw)) return 1;
    th = tanf(0.5f * vw->fov * PI_F / 180.0f);
    fwd = v3_sub(vw->target, vw->eye);
    c->w = v3_normalize(fwd);
    side = v3_cross(c->w, vw->up);
    c->u = v3_scale(v3_normalize(side), th * (float)vw->width / (float)vw->height);
    c->v = v3_scale(v3_normalize(v3_cross(side, c->w)), th);
    c->eye = vw->eye;
    c->width = vw->width;
    c->height = vw->height;
    /* coordinates near the float range pass the checks in double but overflow here (|fwd|^2) */
    if (!v3_is_finite(c->w) || !v3_is_finite(c->u) || !v3_is_finite(c->v) || !(v3_length(side) > 1e-6f * v3_length(vw->up)))
        return say(vw, vw->line_eye > vw->line_target ? vw->line_eye : vw->line_target,
                   "eye, target or up too large for the camera's float arithmetic (keep coordinates below 1e18)");
    return 0;
}

ray camera_ray(const camera *c, float x, float y)
{
    ray r;
    float sx = 2.0f * x / (float)c->width - 1.0f, sy = 1.0f - 2.0f * y / (float)c->height;
    r.o = c->eye;
    r.d = v3_normalize(v3_add(c->w, v3_add(v3_scale(c->u, sx), v3_scale(c->v, sy))));
    r.tmax = INFINITY;
    return r;
}
