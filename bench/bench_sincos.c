/* The project's ak_sincos (fmu_src/elementary/elementary.h, inlined) beside the C library's sin
 * and cos, alternately in one process: the cost a model pays per angle. The arguments are the
 * models' usual ones, 4096 angles in [-pi, pi) from a fixed generator. Each repeat times both
 * loops; the figures are medians of the repeats (thread CPU time per call).
 *   build/bench/bench_sincos [--calls N] [--repeats R]
 * It fails (exit 1) unless ak_sincos is within 2 ulp of the C library's on every argument (each
 * is within 1 ulp of sin and cos). */
#define _POSIX_C_SOURCE 200809L
#include "bench_timing.h"
#include "elementary.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

enum { N_ARGS = 4096, MAX_REPEATS = 99 };

static double seconds(void) {
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int by_value(const void *a, const void *b) {
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v, int n) {
    qsort(v, (size_t)n, sizeof v[0], by_value);
    return v[n / 2];
}

/* A volatile sink: the loops' results are used, so the compiler keeps them. */
static volatile double sink;

static double time_libm(const double *x, long rounds) {
    double acc = 0.0;
    const double start = seconds();
    for (long k = 0; k < rounds; k++) {
        for (int i = 0; i < N_ARGS; i++) {
            acc += sin(x[i]) + cos(x[i]);
        }
    }
    const double elapsed = seconds() - start;
    sink = acc;
    return elapsed;
}

static double time_own(const double *x, long rounds) {
    double acc = 0.0;
    const double start = seconds();
    for (long k = 0; k < rounds; k++) {
        for (int i = 0; i < N_ARGS; i++) {
            double s, c;
            ak_sincos(x[i], &s, &c);
            acc += s + c;
        }
    }
    const double elapsed = seconds() - start;
    sink = acc;
    return elapsed;
}

static double ulps(double a, double b) {
    return fabs(a - b) / (nextafter(fabs(b), INFINITY) - fabs(b));
}

int main(int argc, char **argv) {
    double calls = 4e7;
    int repeats = 5;
    ak_bench_calls_and_repeats(argc, argv, &calls, &repeats);
    if (repeats < 1 || repeats > MAX_REPEATS || !(calls >= N_ARGS)) {
        fprintf(stderr, "usage: bench_sincos [--calls N >= %d] [--repeats 1..%d]\n", N_ARGS,
                MAX_REPEATS);
        return 2;
    }
    static double x[N_ARGS];
    unsigned state = 1u;
    for (int i = 0; i < N_ARGS; i++) {
        state = state * 1664525u + 1013904223u;
        x[i] = ((double)state / 4294967296.0 - 0.5) * 2.0 * 3.14159265358979323846;
    }
    double worst = 0.0;
    for (int i = 0; i < N_ARGS; i++) {
        double s, c;
        ak_sincos(x[i], &s, &c);
        const double e = fmax(ulps(s, sin(x[i])), ulps(c, cos(x[i])));
        worst = e > worst ? e : worst;
    }
    if (worst > 2.0) {
        fprintf(stderr, "bench_sincos: ak_sincos is %.2f ulp from the C library's\n", worst);
        return 1;
    }
    const long rounds = (long)(calls / N_ARGS);
    double libm[MAX_REPEATS], own[MAX_REPEATS], ratio[MAX_REPEATS];
    for (int r = 0; r < repeats; r++) {
        libm[r] = time_libm(x, rounds) / ((double)rounds * N_ARGS) * 1e9;
        own[r] = time_own(x, rounds) / ((double)rounds * N_ARGS) * 1e9;
        ratio[r] = own[r] / libm[r];
    }
    printf("| loop (one angle, [-pi, pi)) | ns/call |\n|---|---:|\n");
    printf("| C library's sin + cos | %.2f |\n", median(libm, repeats));
    printf("| ak_sincos | %.2f |\n", median(own, repeats));
    printf("\nak_sincos / C library: %.3f (median of %d alternating repeats; largest difference "
           "%.2f ulp)\n", median(ratio, repeats), repeats, worst);
    return 0;
}
