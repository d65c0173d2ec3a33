/* The clock, the median and the options of every benchmark driver (bench_fmu.c, bench_fmi3.c,
 * bench_attitude.c). Needs _POSIX_C_SOURCE 200809L before the first include (clock_gettime). */
#ifndef ANGULAR_KINEMATICS_BENCH_TIMING_H
#define ANGULAR_KINEMATICS_BENCH_TIMING_H

#include <stdlib.h>
#include <string.h>
#include <time.h>

/* CPU time of this thread: on a machine shared with other jobs, the time the thread was not
 * running does not count against the FMU (wall time would charge it). */
static inline double ak_bench_now_ns(void) {
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec * 1e9 + (double)t.tv_nsec;
}

static inline int ak_bench_compare_doubles(const void *a, const void *b) {
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The median of n values (sorts them in place). */
static inline double ak_bench_median(double *values, int n) {
    qsort(values, (size_t)n, sizeof *values, ak_bench_compare_doubles);
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

/* The options --calls N and --repeats R of the drivers of one function (bench_sincos.c,
 * bench_atan2.c) into *calls and *repeats, which keep their defaults when not given. */
static inline void ak_bench_calls_and_repeats(int argc, char **argv, double *calls, int *repeats) {
    for (int i = 1; i + 1 < argc; i += 2) {
        if (strcmp(argv[i], "--calls") == 0) {
            *calls = atof(argv[i + 1]);
        } else if (strcmp(argv[i], "--repeats") == 0) {
            *repeats = atoi(argv[i + 1]);
        }
    }
}

#endif
