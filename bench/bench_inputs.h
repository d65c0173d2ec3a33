/* The inputs every benchmark driver steps through (bench_fmu.c, bench_fmi3.c,
 * bench_sequences_fmu.c, bench_attitude.c): one table of 256 rows, cycled, so that their figures
 * and ratios are comparable. Two kinds, chosen with --inputs:
 *   random (the default): deterministic pseudo-random rows: angles anywhere in [-pi, pi], rates
 *     in [-10, 10] rad/s, accelerations in [-100, 100] rad/s^2, at every step (the rows the
 *     guard's counts were recorded with);
 *   smooth: the rows a co-simulation feeds, a tumbling body sampled every 0.01 s:
 *     theta_i(t) = rate_i t + amplitude_i sin(frequency_i t + phase_i) with its exact first and
 *     second derivatives, as in demo/trajectories.py, the rates and frequencies rounded to
 *     multiples of 2 pi / 2.56 s so that the 256 rows close on themselves (the angles move by at
 *     most 0.04 rad a step; theta[3] comes back 2 pi further at the wrap, the same attitude).
 * Consecutive rows differ in every input (checked), so every step evaluates. */
#ifndef ANGULAR_KINEMATICS_BENCH_INPUTS_H
#define ANGULAR_KINEMATICS_BENCH_INPUTS_H

#include <math.h>
#include <string.h>

enum { AK_BENCH_ROWS = 256, AK_BENCH_INPUTS = 9 };

/* The sampling step of the smooth rows, s. */
#define AK_BENCH_SMOOTH_STEP 0.01

typedef enum { AK_BENCH_RANDOM, AK_BENCH_SMOOTH } ak_bench_kind;

/* "random" or "smooth" into *kind; -1 for any other name. */
static inline int ak_bench_parse_kind(const char *name, ak_bench_kind *kind) {
    if (strcmp(name, "random") == 0) {
        *kind = AK_BENCH_RANDOM;
    } else if (strcmp(name, "smooth") == 0) {
        *kind = AK_BENCH_SMOOTH;
    } else {
        return -1;
    }
    return 0;
}

static inline const char *ak_bench_kind_name(ak_bench_kind kind) {
    return kind == AK_BENCH_SMOOTH ? "smooth" : "random";
}

/* Returns 0, or -1 if two consecutive rows share a value (then the table is unusable). */
static inline int ak_bench_check_inputs(double table[AK_BENCH_ROWS][AK_BENCH_INPUTS]) {
    for (int row = 0; row < AK_BENCH_ROWS; row++) {
        for (int k = 0; k < AK_BENCH_INPUTS; k++) {
            if (table[row][k] == table[(row + 1) % AK_BENCH_ROWS][k]) {
                return -1;
            }
        }
    }
    return 0;
}

/* The random rows. Returns 0, or -1 (see ak_bench_check_inputs). */
static inline int ak_bench_fill_inputs(double table[AK_BENCH_ROWS][AK_BENCH_INPUTS]) {
    unsigned long long state = 0x9E3779B97F4A7C15ull;
    static const double ranges[3] = {3.141592653589793, 10.0, 100.0};
    for (int row = 0; row < AK_BENCH_ROWS; row++) {
        for (int k = 0; k < AK_BENCH_INPUTS; k++) {
            state = state * 6364136223846793005ull + 1442695040888963407ull;
            const double unit = (double)(state >> 11) / 9007199254740992.0; /* [0, 1) */
            table[row][k] = (2.0 * unit - 1.0) * ranges[k / 3];
        }
    }
    return ak_bench_check_inputs(table);
}

/* The smooth rows: row k is the tumbling body at t = 0.01 k. demo/trajectories.py has rates
 * (0.6, 0, 2.5) rad/s, amplitudes (0.8, pi/2 - 0.05, 0.5) rad (theta[2] swings to within 0.05
 * rad of the 1-2-3 singularity), frequencies (1.3, 0.9, 2.1) rad/s, phases (0, 0.4, 1.0); here
 * rates (0, 0, w) and frequencies (w, w, w), w = 2 pi / 2.56 s = 2.454 rad/s. Returns 0 or -1. */
static inline int ak_bench_fill_smooth_inputs(double table[AK_BENCH_ROWS][AK_BENCH_INPUTS]) {
    const double w = 2.0 * 3.14159265358979323846 / (AK_BENCH_ROWS * AK_BENCH_SMOOTH_STEP);
    const double rate[3] = {0.0, 0.0, w}, frequency[3] = {w, w, w};
    const double amplitude[3] = {0.8, 0.5 * 3.14159265358979323846 - 0.05, 0.5};
    const double phase[3] = {0.0, 0.4, 1.0};
    for (int row = 0; row < AK_BENCH_ROWS; row++) {
        const double t = AK_BENCH_SMOOTH_STEP * row;
        for (int i = 0; i < 3; i++) {
            const double argument = frequency[i] * t + phase[i];
            table[row][i] = rate[i] * t + amplitude[i] * sin(argument);
            table[row][3 + i] = rate[i] + amplitude[i] * frequency[i] * cos(argument);
            table[row][6 + i] = -amplitude[i] * frequency[i] * frequency[i] * sin(argument);
        }
    }
    return ak_bench_check_inputs(table);
}

/* The rows of `kind`. Returns 0 or -1. */
static inline int ak_bench_fill_inputs_of_kind(ak_bench_kind kind,
                                               double table[AK_BENCH_ROWS][AK_BENCH_INPUTS]) {
    return kind == AK_BENCH_SMOOTH ? ak_bench_fill_smooth_inputs(table)
                                   : ak_bench_fill_inputs(table);
}

#endif
