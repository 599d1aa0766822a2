/* test_obj.c — the OBJ/MTL reader: index forms, polygons, text quirks, materials, every error
 * with its "file:line: message", and every OBJ under ../shared/data (skipped if that is absent).
 * Run from the repository root: inputs are tests/obj/... and ../shared/data/... */
#include "check.h"
#include "scratch.h"
#include "sys/clock.h"
#include "scene/obj.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#define DATA "../shared/data"
#define MAXCORNERS 4096

static const char *errbuf = ""; /* what the last load() printed on stderr */

/* obj_load() with stderr captured into errbuf. */
static int load(const char *path, mesh *m, int quiet)
{
    int r;
    capture_begin();
    r = obj_load(path, m, quiet);
    errbuf = capture_end();
    return r;
}

/* errbuf on one line and cut short, for the detail of a check. */
static const char *shown(void)
{
    static char line[400];
    size_t i;
    for (i = 0; errbuf[i] && i < sizeof line - 1; i++) line[i] = errbuf[i] == '\n' ? '|' : errbuf[i];
    line[i] = '\0';
    return line;
}

static int said(const char *text) { return strstr(errbuf, text) != NULL; }

static int times_said(const char *text)
{
    int n = 0;
    const char *p;
    for (p = errbuf; (p = strstr(p, text)); p++) n++;
    return n;
}

static int near(float a, float b) { return fabsf(a - b) <= 1e-6f * (1.0f + fabsf(b)); }
static int vec_is(vec3 a, float x, float y, float z) { return near(a.x, x) && near(a.y, y) && near(a.z, z); }
static int tri_is(const mesh *m, int t, int a, int b, int c)
{
    return m->tri[3 * t] == a && m->tri[3 * t + 1] == b && m->tri[3 * t + 2] == c;
}

/* The last part of a path, to name checks after their input file. */
static const char *base(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

static int have_data(void)
{
    struct stat st;
    return stat(DATA, &st) == 0;
}

/* Loads path and checks it gives ntris triangles (and ndegen dropped ones). */
static void expect_load(const char *path, int ntris, int ndegen)
{
    mesh m;
    char name[256];
    int r = load(path, &m, 1);
    snprintf(name, sizeof name, "obj_loads_%s", base(path));
    check(r == 0 && m.ntris == ntris && m.ndegenerate == ndegen, name,
          "%s: %d triangles (%d zero-area dropped), got rc %d, %d (%d) %s", path, ntris, ndegen, r, m.ntris, m.ndegenerate, shown());
    mesh_free(&m);
}

/* Loads path and checks that it is refused with message (which names the file and line). */
static void expect_error(const char *path, const char *message)
{
    mesh m;
    char name[256];
    int r = load(path, &m, 0);
    snprintf(name, sizeof name, "obj_refuses_%s", base(path));
    check(r != 0 && said(message) && m.ntris == 0 && m.P == NULL && m.mats == NULL, name,
          "\"%s\"; got rc %d, stderr: %s", message, r, shown());
}

/* ---- polygons ---- */

/* The 0-based vertex indices of the first face of file path, as written. */
static int first_face(const char *path, int *idx)
{
    FILE *f = fopen(path, "r");
    static char line[1 << 16];
    char *p, *end;
    int n = 0;
    if (!f) return 0;
    while (fgets(line, sizeof line, f))
        if (line[0] == 'f' && line[1] == ' ') break;
    fclose(f);
    for (p = line + 1; n < MAXCORNERS; p = end) {
        long i = strtol(p, &end, 10);
        if (end == p) break;
        idx[n++] = (int)i - 1;
        while (*end && *end != ' ' && *end != '\t') end++;
    }
    return n;
}

static double comp(vec3 v, int axis) { return axis == 0 ? v.x : axis == 1 ? v.y : v.z; }

/* Crossing-number test of point (x, y) against the projected polygon. */
static int inside(const mesh *m, const int *idx, int n, int u, int v, double x, double y)
{
    int i, in = 0;
    for (i = 0; i < n; i++) {
        vec3 a = m->P[idx[i]], b = m->P[idx[(i + 1) % n]];
        double ay = comp(a, v), by = comp(b, v);
        if ((ay > y) != (by > y) && x < comp(a, u) + (y - ay) / (by - ay) * (comp(b, u) - comp(a, u))) in = !in;
    }
    return in;
}

/* The triangles of m must tile polygon idx[0..n): projected on the polygon's dominant plane their
 * signed areas add up to its area and all have its sign (same winding), and each centroid lies
 * inside it. For a planar polygon the 3D areas add up too. */
static void check_tiling(const char *name, const mesh *m, const int *idx, int n, int planar)
{
    double N[3] = {0, 0, 0}, area, sum = 0, sum3 = 0, an;
    int i, t, axis, u, v, flipped = 0, outside = 0;
    char full[300];
    for (i = 0; i < n; i++) {
        vec3 a = m->P[idx[i]], b = m->P[idx[(i + 1) % n]];
        N[0] += ((double)a.y - b.y) * ((double)a.z + b.z);
        N[1] += ((double)a.z - b.z) * ((double)a.x + b.x);
        N[2] += ((double)a.x - b.x) * ((double)a.y + b.y);
    }
    axis = fabs(N[0]) > fabs(N[1]) ? (fabs(N[0]) > fabs(N[2]) ? 0 : 2) : (fabs(N[1]) > fabs(N[2]) ? 1 : 2);
    u = (axis + 1) % 3;
    v = (axis + 2) % 3;
    area = N[axis] / 2;
    an = sqrt(N[0] * N[0] + N[1] * N[1] + N[2] * N[2]) / 2;
    for (t = 0; t < m->ntris; t++) {
        vec3 a = m->P[m->tri[3 * t]], b = m->P[m->tri[3 * t + 1]], c = m->P[m->tri[3 * t + 2]];
        vec3 cr = v3_cross(v3_sub(b, a), v3_sub(c, a));
        double s = ((comp(b, u) - comp(a, u)) * (comp(c, v) - comp(a, v))
                    - (comp(b, v) - comp(a, v)) * (comp(c, u) - comp(a, u))) / 2;
        flipped += s * area <= 0 || (planar && cr.x * N[0] + cr.y * N[1] + cr.z * N[2] <= 0);
        sum += s;
        sum3 += v3_length(cr) / 2;
        outside += !inside(m, idx, n, u, v, (comp(a, u) + comp(b, u) + comp(c, u)) / 3,
                           (comp(a, v) + comp(b, v) + comp(c, v)) / 3);
    }
    snprintf(full, sizeof full, "%s_area_sum", name);
    check(fabs(sum - area) <= 1e-5 * fabs(area), full, "projected signed areas: triangles %.9g, polygon %.9g", sum, area);
    snprintf(full, sizeof full, "%s_winding", name);
    check(flipped == 0, full, "%d triangles wound against the polygon", flipped);
    snprintf(full, sizeof full, "%s_inside", name);
    check(outside == 0, full, "%d triangles with their centroid outside the polygon", outside);
    snprintf(full, sizeof full, "%s_area_3d", name);
    if (planar) check(fabs(sum3 - an) <= 1e-5 * an, full, "3D areas: triangles %.9g, polygon %.9g", sum3, an);
}

/* label names the checks; area > 0 is the polygon's known area. */
static void test_polygon(const char *path, const char *label, int ntris, int planar, double area)
{
    static int idx[MAXCORNERS];
    char name[256];
    mesh m;
    int n = first_face(path, idx);
    double t0 = clock_seconds(), secs;
    int r = load(path, &m, 1);
    secs = clock_seconds() - t0;
    snprintf(name, sizeof name, "obj_polygon_%s_count", label);
    check(r == 0 && m.ntris == ntris && m.ndegenerate == 0, name,
          "%d corners into %d triangles: rc %d, %d triangles, %d dropped, %.3f s %s", n, ntris, r, m.ntris, m.ndegenerate, secs, shown());
    snprintf(name, sizeof name, "obj_polygon_%s", label);
    if (r == 0) check_tiling(name, &m, idx, n, planar);
    if (r == 0 && area > 0) {
        double sum = 0;
        int t;
        for (t = 0; t < m.ntris; t++) {
            vec3 a = m.P[m.tri[3 * t]], b = m.P[m.tri[3 * t + 1]], c = m.P[m.tri[3 * t + 2]];
            sum += v3_length(v3_cross(v3_sub(b, a), v3_sub(c, a))) / 2;
        }
        snprintf(name, sizeof name, "obj_polygon_%s_area", label);
        check(fabs(sum - area) < 1e-5 * area, name, "%g, got %.9g", area, sum);
    }
    mesh_free(&m);
}

/* Writes a star of k points (2k corners; k = 1 with equal radii is not meant) to a temp file. */
static void write_star(const char *path, int corners, double r_in)
{
    FILE *f = fopen(path, "w");
    int i;
    if (!f) return;
    for (i = 0; i < corners; i++) {
        double a = 2 * PI_F * i / corners, r = i % 2 ? r_in : 1.0;
        fprintf(f, "v %.9g %.9g 0\n", r * cos(a), r * sin(a));
    }
    fprintf(f, "f");
    for (i = 1; i <= corners; i++) fprintf(f, " %d", i);
    fprintf(f, "\n");
    fclose(f);
}

static void test_polygons(void)
{
    char path[] = "/tmp/pathlab_test_obj_XXXXXX";
    int fd = mkstemp(path);
    test_polygon("tests/obj/poly_l.obj", "l_ccw", 4, 1, 4.0);
    test_polygon("tests/obj/poly_l_cw.obj", "l_cw", 4, 1, 4.0);
    test_polygon("tests/obj/poly_comb.obj", "comb", 18, 1, 19.0);
    test_polygon("tests/obj/poly_star.obj", "star_tilted", 22, 1, 0);
    test_polygon("tests/obj/poly_spiral.obj", "spiral_warped", 118, 0, 0);
    if (fd < 0) { check(0, "obj_polygon_temp_file", "mkstemp failed"); return; }
    close(fd);
    write_star(path, 2000, 1.0); /* a convex 2000-gon */
    test_polygon(path, "convex_2000", 1998, 1, 0);
    write_star(path, 3000, 0.5); /* a star of 1500 spikes: half its corners reflex */
    test_polygon(path, "star_3000", 2998, 1, 0);
    remove(path);
}

/* Convex polygons, warped or not, give gKit's fan (read_mesh: 0 1 2, 0 2 3, ...): a student's render
 * of a warped quad and pathlab's must be of the same surface. */
static void test_fan_order(void)
{
    mesh m;
    int r = load("tests/obj/fan.obj", &m, 1);
    check(r == 0 && m.ntris == 5, "obj_fan_load", "rc %d, %d triangles %s", r, m.ntris, shown());
    if (r == 0 && m.ntris == 5)
        check(tri_is(&m, 0, 0, 1, 2) && tri_is(&m, 1, 0, 2, 3) && tri_is(&m, 2, 4, 5, 6) && tri_is(&m, 3, 4, 6, 7) &&
                  tri_is(&m, 4, 4, 7, 8),
              "obj_fan_order", "warped quad and convex pentagon as gKit's fan; got (%d %d %d) (%d %d %d) (%d %d %d)",
              m.tri[0], m.tri[1], m.tri[2], m.tri[3], m.tri[4], m.tri[5], m.tri[6], m.tri[7], m.tri[8]);
    mesh_free(&m);
}

/* ---- features ---- */

static void test_index_forms(void)
{
    mesh m;
    int r = load("tests/obj/forms.obj", &m, 1);
    check(r == 0 && m.ntris == 4 && m.nverts == 4 && m.nnormals == 2 && m.ntexcoords == 2, "obj_index_forms",
          "v, v/t, v/t/n, v//n: rc %d, %d triangles %s", r, m.ntris, shown());
    if (r == 0)
        check(tri_is(&m, 0, 0, 1, 2) && tri_is(&m, 1, 0, 1, 2) && tri_is(&m, 2, 0, 1, 3) && tri_is(&m, 3, 0, 2, 3),
              "obj_index_forms_values", "vertex indices and corner order kept");
    if (r == 0) {
        static const int want_t[12] = {-1, -1, -1, 0, 1, 0, 0, 1, 0, -1, -1, -1};
        static const int want_n[12] = {-1, -1, -1, -1, -1, -1, 0, 1, 1, 0, 1, 0};
        check(m.tri_t && m.tri_n && !memcmp(m.tri_t, want_t, sizeof want_t) && !memcmp(m.tri_n, want_n, sizeof want_n),
              "obj_corner_vt_vn", "each corner keeps its vt and vn (-1: none), made on first use");
        check(m.N && vec_is(m.N[1], 0, 0, -1) && m.T && m.T[2] == 1.0f && m.T[3] == 0.0f, "obj_vn_vt_values",
              "vn and vt kept as written");
    }
    mesh_free(&m);
    r = load("tests/obj/vnvt.obj", &m, 1);
    check(r == 0 && m.ntris == 2 && m.tri_t && m.tri_n && m.tri_t[0] == 0 && m.tri_t[1] == 1 && m.tri_t[2] == 2
              && m.tri_t[5] == 3 && m.tri_n[3] == 0 && m.tri_n[4] == 2 && m.tri_n[5] == 3 && m.T[6] == 0.0f && m.T[7] == 0.0f,
          "obj_polygon_vt_vn", "a quad's triangles carry their corners' vt and vn (negative indices, vt without v)");
    mesh_free(&m);
    r = load("tests/obj/negative.obj", &m, 1);
    check(r == 0 && m.ntris == 3, "obj_negative_indices_load", "rc %d %s", r, shown());
    if (r == 0)
        check(tri_is(&m, 0, 0, 1, 2) && tri_is(&m, 1, 0, 3, 4) && tri_is(&m, 2, 4, 1, 2), "obj_negative_indices",
              "count back from the latest vertex; got (%d %d %d) (%d %d %d) (%d %d %d)", m.tri[0], m.tri[1],
              m.tri[2], m.tri[3], m.tri[4], m.tri[5], m.tri[6], m.tri[7], m.tri[8]);
    mesh_free(&m);
}

static void test_text(void)
{
    mesh m;
    int r = load("tests/obj/crlf.obj", &m, 1);
    check(r == 0 && m.ntris == 2 && m.nverts == 4 && vec_is(m.P[1], 1, 0, 0) && vec_is(m.P[3], 0, 1, 0),
          "obj_crlf_tabs_comments", "CRLF, tabs, runs of blanks, end-of-line comments: rc %d %s", r, shown());
    mesh_free(&m);
    r = load("tests/obj/continued.obj", &m, 1);
    check(r == 0 && m.nverts == 4 && m.ntris == 1 && vec_is(m.P[1], 1, 0, 0) && vec_is(m.P[3], 5, 5, 5)
              && tri_is(&m, 0, 0, 1, 2), "obj_line_continuation",
          "a final backslash continues a line, not in a comment: rc %d, %d vertices %s", r, m.nverts, shown());
    mesh_free(&m);
    r = load("tests/obj/nofinal.obj", &m, 1);
    check(r == 0 && m.ntris == 1, "obj_no_final_newline", "rc %d %s", r, shown());
    mesh_free(&m);
    r = load("tests/obj/numbers.obj", &m, 1);
    check(r == 0 && m.nverts == 3 && m.P[0].x == (float)strtod("+1", NULL) && m.P[0].y == (float)strtod("-2.", NULL)
              && m.P[0].z == (float)strtod(".5", NULL) && m.P[1].x == (float)strtod("1e2", NULL)
              && m.P[1].y == (float)strtod("2.E-1", NULL) && m.P[1].z == (float)strtod("-3.1e+2", NULL)
              && m.P[2].x == 16.0f && m.P[2].y == (float)strtod("1e-3", NULL),
          "obj_number_forms", "+1 -2. .5 1e2 2.E-1 -3.1e+2 0x10 read as strtod reads them: rc %d %s", r, shown());
    mesh_free(&m);
}

/* A 1 MB comment, 100k blanks inside a vertex line and tabs inside a face line. */
static void test_long_lines(void)
{
    char path[] = "/tmp/pathlab_test_obj_XXXXXX";
    int fd = mkstemp(path), i, r;
    FILE *f = fd >= 0 ? fdopen(fd, "w") : NULL;
    mesh m;
    if (!f) { check(0, "obj_long_lines", "cannot write a temp file"); return; }
    fputc('#', f);
    for (i = 0; i < 1000000; i++) fputc('x', f);
    fprintf(f, "\nv 0");
    for (i = 0; i < 100000; i++) fputc(' ', f);
    fprintf(f, "0 0\nv 1 0 0\nv 0 1 0\nf 1");
    for (i = 0; i < 50000; i++) fputc('\t', f);
    fprintf(f, "2 3");
    fclose(f);
    r = load(path, &m, 1);
    check(r == 0 && m.ntris == 1 && m.nverts == 3, "obj_long_lines", "1 MB comment, 100k blanks in a line: rc %d %s", r,
          shown());
    mesh_free(&m);
    remove(path);
}

static void test_degenerate(void)
{
    mesh m;
    int r = load("tests/obj/degenerate.obj", &m, 0);
    check(r == 0 && m.ntris == 2 && m.ndegenerate == 3, "obj_degenerate_dropped",
          "repeated corner, collinear, cross product overflowing: dropped and counted; needle kept: "
          "rc %d, %d kept, %d dropped", r, m.ntris, m.ndegenerate);
    check(said("tests/obj/degenerate.obj: dropped 3 triangles of zero area"), "obj_degenerate_reported", "%s", shown());
    if (r == 0)
        check(tri_is(&m, 0, 0, 1, 3) && tri_is(&m, 1, 0, 1, 4), "obj_degenerate_needle_kept", "the needle and the plain triangle");
    mesh_free(&m);
}

static void test_ignored(void)
{
    mesh m;
    int r = load("tests/obj/ignored.obj", &m, 0);
    check(r == 0 && m.ntris == 1, "obj_ignored_keywords_accepted", "o, g, s, l, p, vp, cstype: rc %d %s", r, shown());
    check(times_said("ignoring unknown keyword 'vp'") == 1 && said("tests/obj/ignored.obj:5: ignoring unknown keyword 'vp'")
              && times_said("ignoring unknown keyword 'cstype'") == 1,
          "obj_unknown_keyword_warned_once", "%s", shown());
    check(times_said("ignoring points and lines") == 1 && said("ignored.obj:8:"), "obj_points_lines_warned_once", "%s",
          shown());
    check(!said("'o'") && !said("'g'") && !said("'s'"), "obj_o_g_s_silent", "%s", shown());
    mesh_free(&m);
    r = load("tests/obj/ignored.obj", &m, 1);
    check(r == 0 && errbuf[0] == '\0', "obj_quiet", "no warnings when quiet: %s", shown());
    mesh_free(&m);
}

static void test_materials(void)
{
    mesh m;
    material *mt;
    int r = load("tests/obj/mats.obj", &m, 0);
    check(r == 0 && m.nmats == 6 && m.ntris == 5, "obj_mtl_loads", "rc %d, %d materials %s", r, m.nmats, shown());
    if (r != 0) return;
    mt = m.mats;
    check(strcmp(mt[0].name, "(default)") == 0 && vec_is(mt[0].Kd, 0.5f, 0.5f, 0.5f) && v3_is_zero(mt[0].Ks)
              && v3_is_zero(mt[0].Ke) && m.tri_mat[0] == 0,
          "obj_mtl_default", "mats[0] (default) Kd 0.5 for faces before usemtl");
    check(strcmp(mt[1].name, "red") == 0 && vec_is(mt[1].Kd, 0.5f, 0.1f, 0.1f) && vec_is(mt[1].Ks, 0.25f, 0.25f, 0.25f)
              && mt[1].Ns == 40.0f && v3_is_zero(mt[1].Ke), "obj_mtl_values", "Kd, Ks, Ns, Ke with CRLF, comments, tabs");
    check(strcmp(mt[2].name, "grey only") == 0 && vec_is(mt[2].Kd, 0.3f, 0.3f, 0.3f), "obj_mtl_grey_and_blank_name",
          "Kd 0.3 is grey; the name keeps its blank");
    check(strcmp(mt[3].name, "bare") == 0 && v3_is_zero(mt[3].Kd) && v3_is_zero(mt[3].Ks) && mt[3].Ns == 0 && v3_is_zero(mt[3].Ke),
          "obj_mtl_absent_is_zero", "Kd Ks Ke Ns of a bare newmtl");
    check(vec_is(mt[4].Ke, 17, 12, 4), "obj_mtl_emission", "Ke 17 12 4");
    check(m.tri_mat[1] == 1 && m.tri_mat[2] == 2 && m.tri_mat[3] == 4 && m.tri_mat[4] == 5, "obj_usemtl",
          "materials of faces: %d %d %d %d", m.tri_mat[1], m.tri_mat[2], m.tri_mat[3], m.tri_mat[4]);
    check(strstr(m.energy_note, "tests/obj/mats.mtl:22: material 'hot' has Kd + Ks = 1.1 > 1") && m.n_energy == 1
              && times_said("Kd + Ks") == 0, "obj_mtl_energy_note", "noted for the scene's one warning: %s", m.energy_note);
    check(said("tests/obj/mats.mtl:9: map_Kd 'tex.png': no such file; the material renders without it") && m.ntextures == 0,
          "obj_mtl_missing_texture_warned", "%s", shown());
    check(times_said("tests/obj/mats.mtl: ignored keys: Ka (2), illum (1); not supported: transmission "
                     "(d (1)): every surface is opaque") == 1 && times_said("ignored keys") == 1 && !said(" Kd ("),
          "obj_mtl_ignored_keys_once", "one line per file, transmission apart: %s", shown());
    mesh_free(&m);
}

static void test_libraries(void)
{
    mesh m;
    int r = load("tests/obj/libs.obj", &m, 0);
    check(r == 0 && m.ntris == 5 && m.nmats == 5, "obj_mtllib_several",
          "two files on a line, a subfolder, a second mtllib after faces: rc %d, %d materials %s", r, m.nmats, shown());
    if (r == 0) {
        check(strcmp(m.mats[m.tri_mat[0]].name, "from_b") == 0 && vec_is(m.mats[m.tri_mat[1]].Kd, 0.1f, 0.2f, 0.3f)
                  && strcmp(m.mats[m.tri_mat[2]].name, "from_c") == 0 && vec_is(m.mats[m.tri_mat[3]].Kd, 0.9f, 0.9f, 0.9f)
                  && m.tri_mat[4] == m.tri_mat[3],
              "obj_mtllib_latest_definition", "each usemtl resolves to the latest newmtl");
        check(said("tests/obj/sub/c.mtl:3: material 'from_a' defined again") && times_said("defined again") == 1,
              "obj_mtl_redefinition_warned", "a repeated mtllib is not read again: %s", shown());
    }
    mesh_free(&m);
    r = load("tests/obj/nolib.obj", &m, 0);
    check(r == 0 && m.ntris == 1 && m.tri_mat[0] == 0
              && said("tests/obj/nolib.obj:4: usemtl 'Whatever' but no mtllib before it: using the default material"),
          "obj_usemtl_without_mtllib", "default material and a warning: rc %d %s", r, shown());
    mesh_free(&m);
}

static void test_errors(void)
{
    static const char *cases[][2] = {
        {"tests/obj/err_bad_number.obj", "tests/obj/err_bad_number.obj:2: bad number 'abc'"},
        {"tests/obj/err_few_numbers.obj", "tests/obj/err_few_numbers.obj:3: 'v' needs 3 to 6 numbers, found 2"},
        {"tests/obj/err_trailing.obj", "tests/obj/err_trailing.obj:1: bad number '1.5x'"},
        {"tests/obj/err_nan.obj", "tests/obj/err_nan.obj:2: 'nan' is not a finite float"},
        {"tests/obj/err_inf.obj", "tests/obj/err_inf.obj:1: '-inf' is not a finite float"},
        {"tests/obj/err_float_range.obj", "tests/obj/err_float_range.obj:1: '1e39' is not a finite float"},
        {"tests/obj/err_too_many.obj", "tests/obj/err_too_many.obj:4: too many numbers after 'vn' (at most 3)"},
        {"tests/obj/err_index_range.obj", "tests/obj/err_index_range.obj:4: vertex index 4 out of range (3 defined so far)"},
        {"tests/obj/err_index_zero.obj", "tests/obj/err_index_zero.obj:4: vertex index 0 (OBJ indices start at 1)"},
        {"tests/obj/err_negative_range.obj", "tests/obj/err_negative_range.obj:4: vertex index -4 out of range (3 defined so far)"},
        {"tests/obj/err_vt_range.obj", "tests/obj/err_vt_range.obj:5: texture coordinate index 2 out of range (1 defined so far)"},
        {"tests/obj/err_vn_range.obj", "tests/obj/err_vn_range.obj:5: normal index 2 out of range (1 defined so far)"},
        {"tests/obj/err_corner.obj", "tests/obj/err_corner.obj:4: bad face corner '1/1/1/1'"},
        {"tests/obj/err_face2.obj", "tests/obj/err_face2.obj:4: face with 2 vertices (needs at least 3)"},
        {"tests/obj/err_missing_mtl.obj", "tests/obj/err_missing_mtl.obj:3: cannot open 'nothere.mtl': No such file or directory"},
        {"tests/obj/err_unknown_mtl.obj", "tests/obj/err_unknown_mtl.obj:7: unknown material 'blue'"},
        {"tests/obj/err_utf16.obj", "tests/obj/err_utf16.obj:1: not a text file (UTF-16?)"},
        {"tests/obj/err_nul.obj", "tests/obj/err_nul.obj:3: not a text file (UTF-16?)"},
        {"tests/obj/err_empty.obj", "tests/obj/err_empty.obj: no triangles"},
        {"tests/obj/err_lines_only.obj", "tests/obj/err_lines_only.obj: no triangles"},
        {"tests/obj/err_all_degenerate.obj", "tests/obj/err_all_degenerate.obj: no triangles: all 1 had zero area"},
        {"tests/obj/err_kd_negative.obj", "tests/obj/err_kd_negative.mtl:3: negative value in 'Kd'"},
        {"tests/obj/err_ns_negative.obj", "tests/obj/err_ns_negative.mtl:2: negative value in 'Ns'"},
        {"tests/obj/err_kd_two.obj", "tests/obj/err_kd_two.mtl:2: 'Kd' needs 1 (grey) or 3 numbers (r g b), found 2"},
        {"tests/obj/err_before_newmtl.obj", "tests/obj/err_before_newmtl.mtl:2: 'Kd' before the first newmtl"},
        {"tests/obj/err_mtl_number.obj", "tests/obj/err_mtl_number.mtl:3: bad number 'x0.1'"},
        {"tests/obj/does_not_exist.obj", "tests/obj/does_not_exist.obj: cannot open: No such file or directory"},
        {"tests/obj", "tests/obj: cannot open: a folder, not a file"},
    };
    size_t i;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) expect_error(cases[i][0], cases[i][1]);
}

static void test_bounds(void)
{
    mesh m;
    vec3 lo, hi;
    int r = load("tests/obj/continued.obj", &m, 1); /* vertex 4 (5, 5, 5) is used by no triangle */
    if (r == 0) mesh_bounds(&m, &lo, &hi);
    check(r == 0 && vec_is(lo, 0, 0, 0) && vec_is(hi, 1, 1, 0), "mesh_bounds_used_vertices",
          "an unused vertex at (5, 5, 5) is left out");
    mesh_free(&m);
    mesh_free(&m); /* twice is harmless */
    check(m.P == NULL && m.ntris == 0, "mesh_free_twice", "clears the mesh");
}

/* ---- files from the wild ---- */

static void test_edge_cases(void)
{
    static int idx[MAXCORNERS];
    mesh m;
    int r, n;
    const char *d = DATA "/obj-edge-cases/";
    char p[512];
#define EDGE(file) (snprintf(p, sizeof p, "%s%s", d, file), p)
    expect_load(EDGE("WusonOBJ.obj"), 3732, 0);
    expect_load(EDGE("box.obj"), 12, 0);
    expect_load(EDGE("box_without_lineending.obj"), 12, 0);
    expect_load(EDGE("cube_with_vertexcolors.obj"), 12, 0);
    expect_load(EDGE("cube_with_vertexcolors_uni.obj"), 12, 0);
    expect_load(EDGE("multiple_spaces.obj"), 1, 0);
    expect_load(EDGE("regr01.obj"), 2706, 4);
    expect_load(EDGE("regr_3429812.obj"), 4, 0);
    expect_load(EDGE("spider.obj"), 1312, 56);
    expect_load(EDGE("testmixed.obj"), 12, 0);
    expect_load(EDGE("empty_mat.obj"), 256, 0);
    expect_error(EDGE("box_UTF16BE.obj"), "box_UTF16BE.obj:1: not a text file (UTF-16?)");
    expect_error(EDGE("cube_mtllib_after_g.obj"),
                 "cube_mtllib_after_g.obj:2: cannot open 'cube_mtllib_after_g.mat': No such file");
    expect_error(EDGE("cube_usemtl.obj"), "cube_usemtl.obj:21: unknown material 'mtl3'");
    expect_error(EDGE("number_formats.obj"), "number_formats.obj:11: bad number '3.1+e2'");
    expect_error(EDGE("point_cloud.obj"), "point_cloud.obj: no triangles");
    expect_error(EDGE("testline.obj"), "testline.obj: no triangles");
    expect_error(EDGE("testpoints.obj"), "testpoints.obj: no triangles");

    /* 936 corners going round the same square 234 times: 2 triangles per round, the rest zero-area */
    {
        double t0 = clock_seconds();
        r = load(EDGE("box_longline.obj"), &m, 1);
        check(r == 0 && m.ntris == 478 && m.ndegenerate == 466 && clock_seconds() - t0 < 0.5, "obj_936_sided_face",
              "box_longline.obj: rc %d, %d triangles, %d dropped, %.3f s", r, m.ntris, m.ndegenerate, clock_seconds() - t0);
        mesh_free(&m);
    }
    r = load(EDGE("box_mat_with_spaces.obj"), &m, 1);
    check(r == 0 && m.ntris == 12 && strcmp(m.mats[m.tri_mat[0]].name, "Material name with many, many spaces") == 0
              && vec_is(m.mats[m.tri_mat[0]].Kd, 0.2f, 0.2f, 0.2f), "obj_loads_box_mat_with_spaces.obj",
          "material name with blanks: rc %d %s", r, shown());
    mesh_free(&m);
    r = load(EDGE("space_in_material_name.obj"), &m, 1);
    check(r == 0 && m.ntris == 64 && strcmp(m.mats[m.tri_mat[0]].name, "Hard Shiny Plastic White") == 0,
          "obj_loads_space_in_material_name.obj", "rc %d %s", r, shown());
    mesh_free(&m);
    /* 66 corners over 64 vertices: a polygon with a hole joined by a bridge */
    n = first_face(EDGE("concave_polygon.obj"), idx);
    r = load(p, &m, 1);
    check(r == 0 && m.ntris == 64 && n == 66, "obj_polygon_concave_polygon.obj_count", "rc %d, %d triangles, %d corners",
          r, m.ntris, n);
    if (r == 0) check_tiling("obj_polygon_concave_polygon.obj", &m, idx, n, 1);
    if (r == 0)
        check(strcmp(m.mats[m.tri_mat[0]].name, "test") == 0 && m.mats[1].Ns == 400.0f,
              "obj_loads_concave_polygon.obj_material", "usemtl test, Ns 400");
    mesh_free(&m);
#undef EDGE
}

static void test_mcguire(void)
{
    static const struct { const char *file; int ntris; } boxes[] = {
        {"CornellBox-Empty-CO.obj", 12}, {"CornellBox-Empty-RG.obj", 12}, {"CornellBox-Empty-Squashed.obj", 12},
        {"CornellBox-Empty-White.obj", 12}, {"CornellBox-Glossy.obj", 1112}, {"CornellBox-Mirror.obj", 36},
        {"CornellBox-Original.obj", 36}, {"CornellBox-Sphere.obj", 2188}, {"CornellBox-Water.obj", 7088},
    };
    char p[512];
    size_t i;
    mesh m;
    int r, light;
    for (i = 0; i < sizeof boxes / sizeof boxes[0]; i++) {
        snprintf(p, sizeof p, DATA "/cornell-mcguire/%s", boxes[i].file);
        expect_load(p, boxes[i].ntris, 0);
    }
    expect_error(DATA "/cornell-mcguire/water.obj", "water.obj:1: cannot open 'water.mtl': No such file or directory");
    r = load(DATA "/cornell-mcguire/CornellBox-Original.obj", &m, 1);
    for (light = m.nmats - 1; r == 0 && light > 0 && strcmp(m.mats[light].name, "light") != 0; light--) {}
    check(r == 0 && m.nmats == 9 && light > 0 && vec_is(m.mats[light].Kd, 0.78f, 0.78f, 0.78f) && vec_is(m.mats[light].Ke, 17, 12, 4)
              && m.mats[light].Ns == 10.0f && v3_is_zero(m.mats[light].Ks) && vec_is(m.mats[1].Kd, 0.63f, 0.065f, 0.05f),
          "obj_mcguire_original_materials", "Kd, Ks, Ns, Ke: rc %d, %d materials", r, m.nmats);
    if (r == 0) {
        vec3 lo, hi;
        mesh_bounds(&m, &lo, &hi);
        check(vec_is(lo, -1.02f, 0, -1.04f) && vec_is(hi, 1, 1.99f, 0.99f), "obj_mcguire_original_bounds", "(%g %g %g) (%g %g %g)",
              lo.x, lo.y, lo.z, hi.x, hi.y, hi.z);
    }
    mesh_free(&m);
    r = load(DATA "/cornell-mcguire/CornellBox-Glossy.obj", &m, 0);
    check(r == 0 && strstr(m.energy_note, "CornellBox-Glossy.mtl:12: material 'sphere' has Kd + Ks = 1.363 > 1") && m.n_energy == 2,
          "obj_mcguire_glossy_energy_notes", "%d: %s", m.n_energy, m.energy_note);
    mesh_free(&m);
}

static void test_meshes(void)
{
    mesh m;
    double t0 = clock_seconds();
    int r = load(DATA "/meshes/bunny.obj", &m, 1);
    check(r == 0 && m.ntris == 69451 && m.ndegenerate == 0 && m.nverts == 35947, "obj_bunny",
          "69451 triangles: rc %d, %d triangles, %.3f s", r, m.ntris, clock_seconds() - t0);
    mesh_free(&m);
    t0 = clock_seconds();
    r = load(DATA "/meshes/dragon.obj", &m, 1);
    check(r == 0 && m.ntris + m.ndegenerate == 871414 && m.ndegenerate == 108 && m.nverts == 437645,
          "obj_dragon", "871414 faces, of which 108 zero-area: rc %d, %d triangles + %d dropped, loaded in %.3f s",
          r, m.ntris, m.ndegenerate, clock_seconds() - t0);
    mesh_free(&m);
}

/* 200,000 materials, each used once, in a folder of their own: every face gets its own material (by
 * hash, not by a linear search: 50,000 took 9 s), a name defined twice takes the later values, and the
 * load stays far under a second per 100,000 materials (bound 4 s: a shared machine; the linear search
 * took minutes). */
static void test_many_materials(void)
{
    char dir[] = "/tmp/pathlab_test_mats_XXXXXX", obj[64], mtl[64];
    enum { N = 200000 };
    FILE *f;
    mesh m;
    int i, r, right = 0;
    double t0;
    if (!mkdtemp(dir)) { check(0, "obj_many_materials", "mkdtemp failed"); return; }
    snprintf(obj, sizeof obj, "%s/m.obj", dir), snprintf(mtl, sizeof mtl, "%s/m.mtl", dir);
    if (!(f = fopen(mtl, "w"))) { check(0, "obj_many_materials", "cannot write %s", mtl); return; }
    for (i = 0; i < N; i++) fprintf(f, "newmtl mat_%d\nKd %g 0 0\n", i, (i % 1000) / 1000.0);
    fprintf(f, "newmtl mat_7\nKd 0 1 0\n");    /* defined again: the later one wins */
    fclose(f);
    if (!(f = fopen(obj, "w"))) { check(0, "obj_many_materials", "cannot write %s", obj); return; }
    fprintf(f, "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");
    for (i = 0; i < N; i++) fprintf(f, "usemtl mat_%d\nf 1 2 3\n", i);
    fclose(f);
    t0 = clock_seconds();
    r = load(obj, &m, 1);
    t0 = clock_seconds() - t0;
    for (i = 0; r == 0 && i < m.ntris; i++) {
        const material *mt = &m.mats[m.tri_mat[i]];
        char want[32];
        snprintf(want, sizeof want, "mat_%d", i);
        right += !strcmp(mt->name, want) && (i == 7 ? vec_is(mt->Kd, 0, 1, 0) : near(mt->Kd.x, (i % 1000) / 1000.0f));
    }
    check(r == 0 && m.ntris == N && right == N, "obj_many_materials", "rc %d, %d of %d faces with their own material",
          r, right, N);
    check(r == 0 && t0 < 4.0, "obj_many_materials_fast", "%d materials and usemtl lines loaded in %.2f s", N, t0);
    if (r == 0) mesh_free(&m);
    remove(obj), remove(mtl), rmdir(dir);
}

int main(void)
{
    test_index_forms();
    test_polygons();
    test_fan_order();
    test_text();
    test_long_lines();
    test_degenerate();
    test_ignored();
    test_materials();
    test_many_materials();
    test_libraries();
    test_errors();
    test_bounds();
    if (!have_data()) {
        check(1, "obj_shared_data", "skipped: " DATA " not found");
        return check_summary();
    }
    test_edge_cases();
    test_mcguire();
    test_meshes();
    return check_summary();
}
