/* The inputs every benchmark driver steps through (bench_fmu.c, bench_fmi3.c): one table, so that
 * their bare-core figures and ratios are comparable. Deterministic pseudo-random rows: angles in
 * [-pi, pi], rates in [-10, 10] rad/s, accelerations in [-100, 100] rad/s^2; consecutive rows
 * differ in every input, so every step evaluates. */
#ifndef ANGULAR_KINEMATICS_BENCH_INPUTS_H
#define ANGULAR_KINEMATICS_BENCH_INPUTS_H

enum { AK_BENCH_ROWS = 256, AK_BENCH_INPUTS = 9 };

/* Returns 0, or -1 if two consecutive rows share a value (then the table is unusable). */
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
    for (int row = 0; row < AK_BENCH_ROWS; row++) {
        for (int k = 0; k < AK_BENCH_INPUTS; k++) {
            if (table[row][k] == table[(row + 1) % AK_BENCH_ROWS][k]) {
                return -1;
            }
        }
    }
    return 0;
}

#endif
