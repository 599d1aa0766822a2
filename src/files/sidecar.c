/* sidecar.c — reading, writing and comparing the FILE.meta that says what made FILE. */
#include "files/sidecar.h"
#include "sys/input_file.h"
#include "sys/shown.h"
#include "sys/output_path.h"
#include "tracer/integrator.h"
#include "util/textfile.h"
#include <errno.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void sidecar_path(char *dst, size_t cap, const char *image_path) { snprintf(dst, cap, "%s.meta", image_path); }

int sidecar_is_sobol(const sidecar *m) { return !strncmp(m->sampler, "sobol", 5); }   /* sobol, sobol1 */

int64_t sidecar_spp(const sidecar *m)
{
    int64_t n = 0;
    int i;
    for (i = 0; i < m->nranges; i++) n += m->range[i][1] - m->range[i][0];
    return n;
}

void sidecar_ranges_text(const sidecar *m, char *dst, size_t cap)
{
    size_t len = 0;
    int i;
    dst[0] = '\0';
    for (i = 0; i < m->nranges && len < cap; i++)
        len += (size_t)snprintf(dst + len, cap - len, "%s%" PRId64 ":%" PRId64, i ? "," : "", m->range[i][0], m->range[i][1]);
}

void sidecar_escape(char *dst, size_t cap, const char *src, int spaces)
{
    size_t n = 0;
    for (; *src; src++) {
        unsigned char c = (unsigned char)*src;
        /* a space first or last too: the reader trims the blanks around a value */
        int plain = c >= 0x20 && c != 0x7f && c != '\\' && !(c == ' ' && (spaces || n == 0 || !src[1]));
        if (n + (plain ? 1 : 4) >= cap) break;
        if (plain) dst[n++] = (char)c;
        else n += (size_t)sprintf(dst + n, "\\x%02x", c);
    }
    if (cap) dst[n] = '\0';
}

static int hex_digit(char c) { return c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1; }

int sidecar_unescape(char *s)
{
    char *w = s;
    for (; *s; s++) {
        if (*s != '\\') { *w++ = *s; continue; }
        if (s[1] != 'x' || hex_digit(s[2]) < 0 || hex_digit(s[3]) < 0) return 1;
        *w++ = (char)(hex_digit(s[2]) * 16 + hex_digit(s[3]));
        s += 3;
    }
    *w = '\0';
    return 0;
}

int sidecar_write_to(const sidecar *m, const char *image_path, const char *path)
{
    char tmp[PATH_CAP], ranges[SIDECAR_RANGES_TEXT], name[4 * PATH_CAP], scene[4 * SIDECAR_TEXT], variance[4 * SIDECAR_TEXT], count[4 * SIDECAR_TEXT];
    FILE *f;
    if (!(f = textfile_open(path, tmp, sizeof tmp))) return 1;
    sidecar_ranges_text(m, ranges, sizeof ranges);
    sidecar_escape(name, sizeof name, image_path, 0);
    sidecar_escape(scene, sizeof scene, m->scene, 0);
    sidecar_escape(variance, sizeof variance, m->variance, 0);
    sidecar_escape(count, sizeof count, m->sample_count, 0);
    fprintf(f, "# pathlab: what made %s (read by pathlab merge, render --resume and grade)\n", name);
    fprintf(f, "kind %s\nlayer %s\nsamples %s\n", m->kind, m->layer, ranges);
    if (m->adaptive[0])   /* the range is of the pixel with the most samples: its width is no spp */
        fprintf(f, "spp adaptive: per pixel, mean %.6g, at most %" PRId64 "\nspp-mean %.9g\nspp-cap %" PRId64 "\nadaptive %s\n"
                   "pilot-seed %" PRIu64 "\n", m->spp_mean, m->spp_cap, m->spp_mean, m->spp_cap, m->adaptive, m->pilot_seed);
    else fprintf(f, "spp %" PRId64 "\n", sidecar_spp(m));
    if (m->sample_count[0]) fprintf(f, "sample-count %s\n", count);
    fprintf(f, "seed %" PRIu64 "\n", m->seed);
    fprintf(f, "scene %s\nscene-id %s\nflags %s\ncamera %s\n", scene, m->scene_id, m->flags, m->camera);
    if (m->sky_id[0]) fprintf(f, "sky-id %s\n", m->sky_id);
    if (m->variance[0]) fprintf(f, "variance %s\n", variance);
    if (m->layers_n > 0) fprintf(f, "layers %d:%d\n", m->layers_first, m->layers_first + m->layers_n - 1);
    if (m->stopped[0]) fprintf(f, "stopped %s\n", m->stopped);
    if (m->sampler[0]) fprintf(f, "sampler %s\n", m->sampler);
    if (m->variance_dof > 0) fprintf(f, "variance-dof %d\n", m->variance_dof);
    fprintf(f, "revision %s\n", m->revision);
    return textfile_close(f, tmp, path);
}

/* "A:B[,C:D...]" into m's ranges; 0, or 1 if malformed (empty, A >= B, unsorted or overlapping). */
static int parse_ranges(sidecar *m, const char *s)
{
    char *end;
    m->nranges = 0;
    for (;;) {
        long long a = strtoll(s, &end, 10), b;
        if (end == s || *end != ':' || a < 0) return 1;
        s = end + 1;
        b = strtoll(s, &end, 10);
        if (end == s || b <= a || m->nranges == SIDECAR_MAX_RANGES) return 1;
        if (b > SIDECAR_INDEX_MAX) return 3;
        if (m->nranges > 0 && a < m->range[m->nranges - 1][1]) return 1;
        m->range[m->nranges][0] = a;
        m->range[m->nranges][1] = b;
        m->nranges++;
        if (*end == '\0') return 0;
        if (*end != ',') return 1;
        s = end + 1;
    }
}

/* "A:B", 0 <= A <= B <= BOUNCES_CAP, into m's layers; 0, or 1 if malformed. */
static int parse_layers(sidecar *m, const char *s)
{
    char *end;
    long a = strtol(s, &end, 10), b;
    if (end == s || *end != ':') return 1;
    s = end + 1;
    b = strtol(s, &end, 10);
    if (end == s || *end || a < 0 || b < a || b > BOUNCES_CAP) return 1;
    m->layers_first = (int)a;
    m->layers_n = (int)(b - a + 1);
    return 0;
}

/* A seed: digits only (strtoull would take "-1" as 2^64 - 1); 1 if malformed or beyond 2^64 - 1. */
static int parse_u64(uint64_t *x, const char *v)
{
    char *end;
    unsigned long long n;
    if (*v < '0' || *v > '9') return 1;
    errno = 0;
    n = strtoull(v, &end, 10);
    *x = n;
    return *end != '\0' || errno == ERANGE;
}

/* Copies the value into a text field; 1 if it does not fit. */
static int set_text(char *dst, size_t cap, const char *v)
{
    if (strlen(v) >= cap) return 1;
    strcpy(dst, v);
    return 0;
}

/* The same for a name, written escaped (sidecar_escape); 1 if it does not fit or is badly escaped. */
static int set_name(char *dst, size_t cap, const char *v)
{
    char name[4 * SIDECAR_TEXT];
    return set_text(name, sizeof name, v) || sidecar_unescape(name) || set_text(dst, cap, name);
}

/* One "key value" line; 0, or 1 if the value is malformed (unknown keys are skipped). */
static int parse_line(sidecar *m, const char *key, const char *v)
{
    char *end;
    if (!strcmp(key, "kind")) return set_text(m->kind, sizeof m->kind, v);
    if (!strcmp(key, "layer")) return set_text(m->layer, sizeof m->layer, v);
    if (!strcmp(key, "samples")) return parse_ranges(m, v);
    if (!strcmp(key, "seed")) return parse_u64(&m->seed, v);
    if (!strcmp(key, "scene")) return set_name(m->scene, sizeof m->scene, v);
    if (!strcmp(key, "scene-id")) return set_text(m->scene_id, sizeof m->scene_id, v);
    if (!strcmp(key, "sky-id")) return set_text(m->sky_id, sizeof m->sky_id, v);
    if (!strcmp(key, "flags")) return set_text(m->flags, sizeof m->flags, v);
    if (!strcmp(key, "camera")) return set_text(m->camera, sizeof m->camera, v);
    if (!strcmp(key, "variance")) return set_name(m->variance, sizeof m->variance, v);
    if (!strcmp(key, "layers")) return parse_layers(m, v);
    if (!strcmp(key, "revision")) return set_text(m->revision, sizeof m->revision, v);
    if (!strcmp(key, "stopped")) return set_text(m->stopped, sizeof m->stopped, v);
    if (!strcmp(key, "adaptive")) return set_text(m->adaptive, sizeof m->adaptive, v);
    if (!strcmp(key, "sample-count")) return set_name(m->sample_count, sizeof m->sample_count, v);
    if (!strcmp(key, "spp-mean")) {
        m->spp_mean = strtod(v, &end);
        return end == v || *end != '\0' ? 1 : !(m->spp_mean >= 0.0 && m->spp_mean <= (double)SIDECAR_SPP_MAX) ? 4 : 0;
    }
    if (!strcmp(key, "pilot-seed")) return parse_u64(&m->pilot_seed, v);
    if (!strcmp(key, "spp-cap")) {
        m->spp_cap = strtoll(v, &end, 10);
        return end == v || *end != '\0' ? 1 : m->spp_cap < 1 || m->spp_cap > SIDECAR_SPP_MAX ? 4 : 0;
    }
    if (!strcmp(key, "sampler")) return set_text(m->sampler, sizeof m->sampler, v);
    if (!strcmp(key, "variance-dof")) {
        long d = strtol(v, &end, 10);
        m->variance_dof = (int)d;
        return end == v || *end != '\0' || d < 1 || d > 1000000;
    }
    return 0;
}

/* Cuts a line into its key and its value (blanks around the value and the line end dropped). */
static int split_line(char *line, char **key, char **value)
{
    char *e = line + strlen(line);
    while (e > line && (e[-1] == '\n' || e[-1] == '\r' || e[-1] == ' ' || e[-1] == '\t')) *--e = '\0';
    while (*line == ' ' || *line == '\t') line++;
    if (*line == '\0' || *line == '#') return 0;
    *key = line;
    while (*line && *line != ' ' && *line != '\t') line++;
    if (*line) *line++ = '\0';
    while (*line == ' ' || *line == '\t') line++;
    *value = line;
    return 1;
}

int sidecar_read(sidecar *m, const char *image_path)
{
    char path[PATH_CAP], line[4 * SIDECAR_TEXT + SIDECAR_RANGES_TEXT], *key, *value;
    int lineno = 0, err = 0;
    FILE *f;
    memset(m, 0, sizeof *m);
    sidecar_path(path, sizeof path, image_path);
    if (!(f = input_file_open(path, 1))) {   /* a FIFO named FILE.meta must not hang grade or view */
        if (errno == ENOENT) return -1;
        fprintf(stderr, "%s: cannot read: %s\n", shown(path), input_file_why(errno));
        return 1;
    }
    while (!err && fgets(line, sizeof line, f)) {
        lineno++;
        if (!strchr(line, '\n') && !feof(f)) err = 2;
        else if (split_line(line, &key, &value)) err = parse_line(m, key, value);
    }
    fclose(f);
    if (err) fprintf(stderr, "%s:%d: %s\n", shown(path), lineno, err == 2 ? "line too long"
                     : err == 3 ? "a sample index beyond 2^62, the limit of --samples"
                     : err == 4 ? "a count of samples out of 1 .. 2^30, the limits of --spp" : "bad value");
    else if (!m->kind[0] || !m->nranges) fprintf(stderr, "%s: no %s line: not a pathlab sidecar\n", shown(path), m->kind[0] ? "samples" : "kind");
    else if (m->adaptive[0] && m->spp_cap < 1) fprintf(stderr, "%s: an adaptive render without its spp-cap line\n", shown(path));
    return err || !m->kind[0] || !m->nranges || (m->adaptive[0] && m->spp_cap < 1);
}

/* The ranges of a and b together, sorted; adjacent ranges joined. */
int sidecar_add_ranges(sidecar *a, const sidecar *b, const char *a_name, const char *b_name)
{
    int64_t r[2 * SIDECAR_MAX_RANGES][2];
    int n = 0, i = 0, k = 0;
    while (i < a->nranges || k < b->nranges) {
        const int64_t *next = (k >= b->nranges || (i < a->nranges && a->range[i][0] <= b->range[k][0])) ? a->range[i++] : b->range[k++];
        if (n > 0 && next[0] < r[n - 1][1]) {
            fprintf(stderr, "pathlab: %s and %s both have samples %" PRId64 ":%" PRId64 " (the same samples twice)\n",
                    a_name, b_name, next[0], next[1] < r[n - 1][1] ? next[1] : r[n - 1][1]);
            return 1;
        }
        if (n > 0 && next[0] == r[n - 1][1]) r[n - 1][1] = next[1];
        else { r[n][0] = next[0]; r[n][1] = next[1]; n++; }
    }
    if (n > SIDECAR_MAX_RANGES) {
        fprintf(stderr, "pathlab: %s and %s together have %d separate sample ranges (at most %d)\n", shown(a_name), shown(b_name), n, SIDECAR_MAX_RANGES);
        return 1;
    }
    memcpy(a->range, r, sizeof(r[0]) * (size_t)n);
    a->nranges = n;
    return 0;
}

static int differ(const char *cmd, const char *a_name, const char *b_name, const char *key, const char *x, const char *y)
{
    fprintf(stderr, "pathlab %s: %s and %s differ in %s:\n  '%s'\n  '%s'\n", cmd, shown(a_name), shown(b_name), shown(key), shown(x), shown(y));
    return 1;
}

int sidecar_check_same(const sidecar *a, const sidecar *b, const char *cmd, const char *a_name, const char *b_name)
{
    char sa[32], sb[32];
    if (a->adaptive[0] || b->adaptive[0]) {
        fprintf(stderr, "pathlab %s: %s is an adaptive render (%s): its pixels hold different numbers of samples, "
                        "which %s cannot combine; render it again with a larger --spp cap or a smaller --target-error\n",
                cmd, a->adaptive[0] ? a_name : b_name, a->adaptive[0] ? a->adaptive : b->adaptive, cmd);
        return 1;
    }
    if (strcmp(a->kind, b->kind)) return differ(cmd, a_name, b_name, "kind", a->kind, b->kind);
    if (strcmp(a->layer, b->layer)) return differ(cmd, a_name, b_name, "layer", a->layer, b->layer);
    if (strcmp(a->scene_id, b->scene_id)) return differ(cmd, a_name, b_name, "scene (its triangles, materials or textures)", a->scene, b->scene);
    /* a sidecar written before sky-id existed has none: its sky cannot be compared */
    if (a->sky_id[0] && b->sky_id[0] && strcmp(a->sky_id, b->sky_id))
        return differ(cmd, a_name, b_name, "--sky image (its pixels; the same name, another file)", a->sky_id, b->sky_id);
    if (strcmp(a->flags, b->flags)) return differ(cmd, a_name, b_name, "flags", a->flags, b->flags);
    if (strcmp(a->sampler, b->sampler))
        return differ(cmd, a_name, b_name, "sampler", a->sampler[0] ? a->sampler : "independent", b->sampler[0] ? b->sampler : "independent");
    if (strcmp(a->camera, b->camera)) return differ(cmd, a_name, b_name, "camera", a->camera, b->camera);
    snprintf(sa, sizeof sa, "%" PRIu64, a->seed);
    snprintf(sb, sizeof sb, "%" PRIu64, b->seed);
    if (a->seed != b->seed) return differ(cmd, a_name, b_name, "seed (pieces of one render share it; their sample ranges differ)", sa, sb);
    return 0;
}

int sidecar_render_command(const sidecar *m, int w, int h, const char *stem, char *out, size_t cap)
{
    char eye[128], target[128], up[128], fov[64];
    int sw, sh;
    if (sscanf(m->camera, "eye %127s target %127s up %127s fov %63s size %dx%d", eye, target, up, fov, &sw, &sh) != 6) return 1;
    if (w <= 0 || h <= 0) w = sw, h = sh;
    /* the sampler said explicitly: the command means the same if the default of --sampler changes */
    snprintf(out, cap, "pathlab render %s --eye %s --target %s --up %s --fov %s --size %dx%d %s%s --seed %llu --spp %lld%s%s "
             "-o %s.pfm --variance %s_var.pfm", m->scene, eye, target, up, fov, w, h, m->flags,
             strstr(m->flags, "--sampler") ? "" : " --sampler independent", (unsigned long long)m->seed,
             (long long)(m->adaptive[0] ? m->spp_cap : sidecar_spp(m)), m->adaptive[0] ? " " : "", m->adaptive, stem, stem);
    return 0;
}
