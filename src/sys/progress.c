/* progress.c — the progress bar or log line and the ETA (from the fraction done so far). */
#include "sys/progress.h"
#include "sys/clock.h"
#include <math.h>
#include <stdio.h>
#include <unistd.h>

void progress_duration(char *buf, size_t cap, double s)
{
    long t;
    if (!(s >= 0.0)) s = 0.0;
    if (s < 10.0) { snprintf(buf, cap, "%.1fs", s); return; }
    t = s > 1e9 ? 1000000000L : (long)floor(s + 0.5);
    if (t < 60) snprintf(buf, cap, "%lds", t);
    else if (t < 3600) snprintf(buf, cap, "%ldm%02lds", t / 60, t % 60);
    else if (t < 86400) snprintf(buf, cap, "%ldh%02ldm", t / 3600, (t % 3600) / 60);
    else snprintf(buf, cap, "%ldd%02ldh", t / 86400, (t % 86400) / 3600);
}

void progress_start(progress *p, int on)
{
    p->on = on;
    p->tty = isatty(2);
    p->t0 = p->last = clock_seconds();
}

static void draw(progress *p, double frac, const char *what, int final)
{
    char el[32], eta[32];
    double t = clock_seconds() - p->t0;
    int i, bar = (int)(30 * frac);
    progress_duration(el, sizeof el, t);
    progress_duration(eta, sizeof eta, frac > 0 ? t / frac - t : 0.0);
    if (p->tty) {
        fprintf(stderr, "\r[");
        for (i = 0; i < 30; i++) fputc(i < bar ? '#' : ' ', stderr);
        fprintf(stderr, "] %3d%%  %s  %s", (int)(100 * frac), what, el);
        if (!final && frac > 0) fprintf(stderr, "  ETA %s   ", eta);
        else fprintf(stderr, "              \n");
    } else if (!final) {
        fprintf(stderr, "progress: %3d%%  %s  %s elapsed, ETA %s\n", (int)(100 * frac), what, el, eta);
    }
    fflush(stderr);
    p->last = clock_seconds();
}

int progress_due(const progress *p)
{
    return p->on && clock_seconds() - p->last >= (p->tty ? 0.1 : PROGRESS_LOG_SECONDS);
}

void progress_update(progress *p, double frac, const char *what)
{
    if (progress_due(p)) draw(p, frac, what, 0);
}

void progress_end(progress *p, double frac, const char *what)
{
    if (p->on && p->tty) draw(p, frac, what, 1);
}
