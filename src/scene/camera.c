/* camera.c — view files and the pinhole camera. */
#include "scene/camera.h"
#include <errno.h>
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

/* Reads n floats from the rest of a line; 0 on success, and nothing may follow them. */
static int read_floats(const char *s, float *out, int n)
{
    int i;
    char *end;
    for (i = 0; i < n; i++) {
        double d = strtod(s, &end);
        if (end == s || !isfinite(d)) return 1;
        out[i] = (float)d;
        s = end;
    }
    while (*s == ' ' || *s == '\t' || *s == '\r' || *s == '\n') s++;
    return *s != '\0';
}

static int parse_view_line(view *vw, char *line)
{
    char key[16];
    float f[3];
    int n = 0;
    char *hash = strchr(line, '#');
    if (hash) *hash = '\0';
    if (sscanf(line, " %15s%n", key, &n) != 1) return 0;   /* blank line */
    line += n;
    if (!strcmp(key, "eye") || !strcmp(key, "target") || !strcmp(key, "up")) {
        if (read_floats(line, f, 3)) return 1;
        if (key[0] == 'e') { vw->eye = v3(f[0], f[1], f[2]); vw->has_eye = 1; }
        else if (key[0] == 't') { vw->target = v3(f[0], f[1], f[2]); vw->has_target = 1; }
        else vw->up = v3(f[0], f[1], f[2]);
    } else if (!strcmp(key, "fov")) {
        if (read_floats(line, f, 1)) return 1;
        vw->fov = f[0];
    } else if (!strcmp(key, "size")) {
        if (read_floats(line, f, 2) || f[0] != (int)f[0] || f[1] != (int)f[1]) return 1;
        vw->width = (int)f[0];
        vw->height = (int)f[1];
    } else {
        return 2;
    }
    return 0;
}

int view_read(view *vw, const char *path)
{
    char line[1024];
    int lineno = 0, rc;
    FILE *fp = fopen(path, "r");
    if (!fp) return errno == ENOENT ? -1 : (fprintf(stderr, "%s: cannot open: %s\n", path, strerror(errno)), 1);
    while (fgets(line, sizeof line, fp)) {
        lineno++;
        rc = parse_view_line(vw, line);
        if (rc) {
            fprintf(stderr, rc == 2 ? "%s:%d: unknown key (expected eye, target, up, fov or size)\n"
                                    : "%s:%d: bad values (eye/target/up take 3 numbers, fov 1, size 2 whole numbers)\n",
                    path, lineno);
            fclose(fp);
            return 1;
        }
    }
    fclose(fp);
    return 0;
}

void view_print(FILE *f, const view *vw)
{
    fprintf(f, "eye %.9g %.9g %.9g\n", vw->eye.x, vw->eye.y, vw->eye.z);
    fprintf(f, "target %.9g %.9g %.9g\n", vw->target.x, vw->target.y, vw->target.z);
    fprintf(f, "up %.9g %.9g %.9g\n", vw->up.x, vw->up.y, vw->up.z);
    fprintf(f, "fov %.9g\n", vw->fov);
    fprintf(f, "size %d %d\n", vw->width, vw->height);
}

void view_frame_bounds(view *vw, vec3 lo, vec3 hi)
{
    vec3 c = v3_scale(v3_add(lo, hi), 0.5f);
    float radius = 0.5f * v3_length(v3_sub(hi, lo));
    /* far enough along +z that the bounding sphere fits in the narrower field of view */
    float half = 0.5f * vw->fov * PI_F / 180.0f;
    float aspect = (float)vw->width / (float)vw->height;
    float half_min = aspect < 1.0f ? atanf(tanf(half) * aspect) : half;
    if (!vw->has_target) vw->target = c;
    if (!vw->has_eye) vw->eye = v3_add(vw->target, v3(0, 0, 1.05f * radius / sinf(half_min)));
    vw->has_eye = vw->has_target = 1;
}

int camera_init(camera *c, const view *vw)
{
    float th = tanf(0.5f * vw->fov * PI_F / 180.0f);
    vec3 fwd = v3_sub(vw->target, vw->eye), side;
    if (!(vw->fov > 0.0f && vw->fov < 180.0f)) { fprintf(stderr, "camera: fov must be between 0 and 180 degrees\n"); return 1; }
    if (vw->width < 1 || vw->height < 1 || vw->width > 65536 || vw->height > 65536 ||
        (double)vw->width * vw->height > 1e9) {
        fprintf(stderr, "camera: image size %dx%d is out of range\n", vw->width, vw->height);
        return 1;
    }
    if (!(v3_length(fwd) > 0.0f)) { fprintf(stderr, "camera: eye and target are the same point\n"); return 1; }
    c->w = v3_normalize(fwd);
    side = v3_cross(c->w, vw->up);
    if (!(v3_length(side) > 1e-6f * v3_length(vw->up))) { fprintf(stderr, "camera: up is parallel to the view direction\n"); return 1; }
    c->u = v3_scale(v3_normalize(side), th * (float)vw->width / (float)vw->height);
    c->v = v3_scale(v3_normalize(v3_cross(side, c->w)), th);
    c->eye = vw->eye;
    c->width = vw->width;
    c->height = vw->height;
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
