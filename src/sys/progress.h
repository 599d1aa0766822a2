/* progress.h — a render's progress on stderr, for a person: on a terminal a bar redrawn in place,
 * otherwise (a log, a batch job) one line every PROGRESS_LOG_SECONDS. Times read "4m15s". */
#ifndef PATHLAB_PROGRESS_H
#define PATHLAB_PROGRESS_H
#include <stddef.h>

#define PROGRESS_LOG_SECONDS 5.0

typedef struct {
    int on, tty;
    double t0, last;   /* start and last draw, clock_seconds() */
} progress;

/* Starts the clock; draws nothing if on is 0. */
void progress_start(progress *p, int on);
/* 1 if progress_update would draw now: callers build their `what` only then. */
int progress_due(const progress *p);
/* frac in [0, 1] done; `what` says where ("384 of 4096 spp"). Draws when due, with the elapsed time and the ETA. */
void progress_update(progress *p, double frac, const char *what);
/* The last draw (100% or where it stopped) and a newline on a terminal. */
void progress_end(progress *p, double frac, const char *what);
/* A duration as a person reads it: "0.4s", "12s", "4m15s", "2h05m", "3d04h". */
void progress_duration(char *buf, size_t cap, double seconds);
#endif
