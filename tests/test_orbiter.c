/* test_orbiter.c — gKit orbiter files: the camera of issue 11's check values (position and two rays,
 * 2e-4 per component, gKit's pixel (x, y) counted from the bottom row), what gKit itself writes
 * (%f numbers, no f line in older files, "s size" alone), every error with its "file:line", and
 * view files written with view_print read back bit for bit. */
#include "check.h"
#include "scratch.h"
#include "scene/orbiter.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const char *errbuf = "";   /* what the last read printed on stderr */
static char path[64];       /* the temporary file of write_file */

/* Writes n bytes of text (NUL bytes included) into a new temporary file, its name in path. */
static void write_bytes(const char *text, size_t n)
{
    int fd;
    FILE *f;
    strcpy(path, "/tmp/test_orbiter_XXXXXX");
    fd = mkstemp(path);
    f = fd >= 0 ? fdopen(fd, "w") : NULL;
    if (!f) { perror("test_orbiter: temporary file"); exit(1); }
    fwrite(text, 1, n, f);
    fclose(f);
}

static void write_file(const char *text) { write_bytes(text, strlen(text)); }

/* orbiter_read of file, stderr captured into errbuf (on one line). */
static int read_path(const char *file, orbiter *o)
{
    int r;
    capture_begin();
    r = orbiter_read(o, file);
    errbuf = chop_newlines(capture_end());
    return r;
}

/* orbiter_read of a file holding text. */
static int read_text(const char *text, orbiter *o)
{
    int r;
    write_file(text);
    r = read_path(path, o);
    remove(path);
    return r;
}

static int close_to(vec3 a, double x, double y, double z, double tol)
{
    return fabs(a.x - x) <= tol && fabs(a.y - y) <= tol && fabs(a.z - z) <= tol;
}

/* The ray through gKit's pixel position (gx, gy), gy counted from the bottom row. */
static ray gkit_ray(const camera *cam, float gx, float gy) { return camera_ray(cam, gx, (float)cam->height - gy); }

#define ISSUE_FILE "c -0.01 0.995 -0.025\np 0.149664 -0.266665\nr 18 16\ns 2.450631 3.48732\nf 45 1024 640\n"

static void test_check_values(void)
{
    orbiter o;
    view vw;
    camera cam;
    ray r0, r1;
    int rc = read_text(ISSUE_FILE, &o);
    check(rc == 0 && o.has_f && o.width == 1024 && o.height == 640 && o.fov == 45.0 && o.radius == 3.48732,
          "orbiter_read: the issue's file, with its f line", "rc %d: %s", rc, errbuf);
    view_defaults(&vw);
    orbiter_view(&o, &vw);
    rc = camera_init(&cam, &vw);
    check(rc == 0 && vw.width == 1024 && vw.height == 640 && vw.fov == 45.0f, "orbiter_view: the size and fov of the f line",
          "%dx%d, fov %g", vw.width, vw.height, vw.fov);
    check(close_to(cam.eye, -0.5313, 1.4987, 2.3359, 2e-4), "orbiter: camera position (-0.5313, 1.4987, 2.3359)",
          "(%.5f, %.5f, %.5f)", cam.eye.x, cam.eye.y, cam.eye.z);
    r0 = gkit_ray(&cam, 0.5f, 0.5f);
    r1 = gkit_ray(&cam, 512.5f, 320.5f);
    check(close_to(r0.d, -0.3228, -0.5536, -0.7677, 2e-4), "orbiter: the ray through gKit pixel (0, 0), the bottom left",
          "(%.5f, %.5f, %.5f)", r0.d.x, r0.d.y, r0.d.z);
    check(close_to(r1.d, 0.2628, -0.3084, -0.9142, 2e-4), "orbiter: the ray through gKit pixel (512, 320)",
          "(%.5f, %.5f, %.5f)", r1.d.x, r1.d.y, r1.d.z);
    check(close_to(r0.o, cam.eye.x, cam.eye.y, cam.eye.z, 0.0), "orbiter: rays start at the eye (not on gKit's near plane)", NULL);
    check(fabs(orbiter_znear(&o) - 0.1) < 1e-12, "orbiter_znear: max(0.1, |c - (px, py, size)| - radius)", "%g", orbiter_znear(&o));
}

/* What gKit's write_orbiter prints (%f, width and height as floats), and older files. */
static void test_gkit_forms(void)
{
    orbiter o;
    view vw;
    int rc = read_text("c -0.010000 0.995000 -0.025000\np 0.149664 -0.266665\nr 18.000000 16.000000\n"
                       "s 2.450631 3.487320\nf 45.000000 1024.000000 640.000000\n", &o);
    check(rc == 0 && o.width == 1024 && o.height == 640, "orbiter_read: gKit's %f output (1024.000000)", "rc %d: %s", rc, errbuf);
    rc = read_text("c 0 0 0\np 0 0\nr 0 0\ns 5\n", &o);
    check(rc == 0 && !o.has_f && o.size == 5.0 && o.radius == 5.0, "orbiter_read: an older file, 's size' alone and no f line",
          "rc %d: %s", rc, errbuf);
    view_defaults(&vw);
    orbiter_view(&o, &vw);
    check(vw.width == 512 && vw.height == 512 && vw.fov == 40.0f && close_to(vw.eye, 0, 0, 5, 1e-6)
              && close_to(vw.target, 0, 0, 0, 1e-6) && close_to(vw.up, 0, 1, 0, 1e-6),
          "orbiter_view: no f line keeps the view's size and fov; r 0 0 looks down -z from (0, 0, size)", NULL);
    rc = read_text("# a comment\n\nf 60 32 16\ns 2 3\n  r 90 0\np 0 0\nc 1 2 3\n", &o);
    view_defaults(&vw);
    orbiter_view(&o, &vw);
    check(rc == 0 && close_to(vw.eye, 1, 4, 3, 1e-6) && close_to(vw.up, 0, 0, -1, 1e-6),
          "orbiter_read: any order, blank lines, comments; r 90 0 looks straight down", "rc %d: %s", rc, errbuf);
}

/* A refused file: status 1 and a message with "file:line" and what. */
static void expect_refused(const char *text, int line, const char *what, const char *name)
{
    orbiter o;
    char where[96];
    int rc = read_text(text, &o);
    snprintf(where, sizeof where, "%s:%d: ", path, line);
    check(rc == 1 && strstr(errbuf, where) && strstr(errbuf, what), name, "'%s%s', got rc %d: %s", where, what, rc, errbuf);
}

static void test_errors(void)
{
    orbiter o;
    expect_refused("c 0 0 0\nr 0 0\ns 5 5\n", 3, "'p px py (the pan)'", "orbiter_read: a missing p line is named");
    expect_refused("p 0 0\nr 0 0\ns 5 5\n", 3, "'c cx cy cz", "orbiter_read: a missing c line is named");
    expect_refused("c 0 0 0\np 0 0\nr 0 0\n", 3, "'s size radius", "orbiter_read: a missing s line is named");
    expect_refused("", 1, "'c cx cy cz", "orbiter_read: an empty file");
    expect_refused("c 0 0 0\np 0 x\nr 0 0\ns 5 5\n", 2, "got 'p 0 x'", "orbiter_read: a bad number");
    expect_refused("c 0 0\np 0 0\nr 0 0\ns 5 5\n", 1, "expected 'c cx cy cz", "orbiter_read: too few numbers");
    expect_refused("c 0 0 0 1\np 0 0\nr 0 0\ns 5 5\n", 1, "expected 'c cx cy cz", "orbiter_read: too many numbers");
    expect_refused("c 0 0 0\np 0 0\nr 0 0\ns 0 5\n", 4, "expected 's size radius", "orbiter_read: size 0 (gKit keeps it >= 0.001)");
    expect_refused("c 0 0 0\np 0 0\nr 0 0\ns 5 5\nf 45 1024.5 640\n", 5, "expected 'f fov width height",
                   "orbiter_read: a width that is not whole");
    expect_refused("c 0 0 0\np 0 0\nr 0 0\ns 5 5\nf 180 10 10\n", 5, "expected 'f fov", "orbiter_read: fov 180");
    expect_refused("c 0 0 0\nc 0 0 0\n", 2, "a second 'c' line (the first is line 1)", "orbiter_read: a repeated line");
    expect_refused("c 0 0 0\nzoom 2\n", 2, "'zoom 2' is not a line of a gKit orbiter file", "orbiter_read: an unknown line");
    expect_refused("c 0 0 0\ncc 2\n", 2, "is not a line", "orbiter_read: a key is one letter");
    check(read_path("/nonexistent/orbiter.txt", &o) == 1 && strstr(errbuf, "/nonexistent/orbiter.txt: cannot open"),
          "orbiter_read: a missing file is an error", "%s", errbuf);
}

/* Found by fuzzing and by hand (issue 13): lines of any length are read whole (a long comment's tail
 * was read as a new line), a NUL byte is an error (the rest of its line was ignored), and numbers
 * too large for the float camera are refused with their line (they made an infinite eye). */
static void test_hostile(void)
{
    static const char nul[] = "c 0 0 0\np 0 0\0p 1 1\nr 0 0\ns 5 5\n";
    orbiter o;
    char text[2200];
    int rc;
    snprintf(text, sizeof text, "c 0 0 0\np 0 0\nr 0 0\ns 5 5\n#%01022dc 9 9 9\n", 0);
    rc = read_text(text, &o);
    check(rc == 0 && o.c[0] == 0.0, "orbiter_read: a 1030-character comment is one line (its tail 'c 9 9 9' is no c line)",
          "rc %d: %s", rc, errbuf);
    snprintf(text, sizeof text, "c 0 0 0\np 0 0\nr 0 0\ns 5 5%1100s\nf x\n", "");
    expect_refused(text, 5, "expected", "orbiter_read: a 1100-character line is read whole (the next line keeps its number)");
    write_bytes(nul, sizeof nul - 1);
    rc = read_path(path, &o);
    remove(path);
    check(rc == 1 && strstr(errbuf, ":2: a NUL byte"), "orbiter_read: a NUL byte is an error naming its line", "rc %d: %s", rc, errbuf);
    expect_refused("c 1e300 0 0\np 0 0\nr 0 0\ns 5 5\n", 1, "a number beyond 1e+30", "orbiter_read: a centre beyond float range");
    expect_refused("c 0 0 0\np 0 0\nr 0 0\ns 2e38 5\n", 4, "a number beyond 1e+30", "orbiter_read: a distance beyond 1e30");
}

/* view_print then view_read: the same floats, bit for bit (%.9g), whatever the values. */
static void test_view_round_trip(void)
{
    orbiter o;
    view a, b;
    FILE *f;
    int rc;
    read_text(ISSUE_FILE, &o);
    view_defaults(&a);
    orbiter_view(&o, &a);
    a.up = v3(1.0f / 3.0f, 0.7f, 1e-7f);
    write_file("");
    f = fopen(path, "w");
    if (f) { view_print(f, &a); fclose(f); }
    view_defaults(&b);
    b.fov = 1.0f;
    rc = view_read(&b, path);
    remove(path);
    check(rc == 0 && !memcmp(&a.eye, &b.eye, sizeof a.eye) && !memcmp(&a.target, &b.target, sizeof a.target)
              && !memcmp(&a.up, &b.up, sizeof a.up) && a.fov == b.fov && a.width == b.width && a.height == b.height
              && b.has_eye && b.has_target,
          "view_print then view_read: the same view, bit for bit", "rc %d", rc);
}

int main(void)
{
    test_check_values();
    test_gkit_forms();
    test_errors();
    test_hostile();
    test_view_round_trip();
    return check_summary();
}
