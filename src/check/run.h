/* run.h — running cases (case.h) on threads, with sys/parallel.h's parallel_for. Case i draws from
 * its own seed, splitmix64 of (seed, i), so that the results do not depend on the thread count nor
 * on which thread ran the case. */
#ifndef PATHLAB_CHECK_RUN_H
#define PATHLAB_CHECK_RUN_H
#include "check/case.h"

/* Runs the ncases cases c on `threads` threads, n samples each (times the case's share); result i
 * in r[i]. */
void check_sampling_run_all(const sampling_case *c, int ncases, long n, uint64_t seed, int threads, sampling_result *r);
#endif
