/* The anchor of the AngularKinematics drivers (bench_fmu.c, bench_fmi3.c): the
 * hand-written body-fixed 1-2-3 formula of tests/c/kinematics_123.c, the project's test reference
 * and the physical limit of the main use. It does not move with the FMU or its general core, so a
 * ratio to it shows a regression as one. Needs bench_inputs.h, bench_timing.h, kinematics_123.h. */
#ifndef ANGULAR_KINEMATICS_BENCH_ANCHOR_H
#define ANGULAR_KINEMATICS_BENCH_ANCHOR_H

/* The formula on the inputs of steps 0..n-1, one output per step summed into *sum: ns per step. */
static inline double ak_bench_time_anchor(double table[AK_BENCH_ROWS][AK_BENCH_INPUTS],
                                          long n, double *sum) { /* table only read */
    double y[12], total = 0.0;
    int k = 0;
    const double start = ak_bench_now_ns();
    for (long step = 0; step < n; step++) {
        const double *u = table[step & (AK_BENCH_ROWS - 1)];
        ak_angular_kinematics_123(u, u + 3, u + 6, y, y + 3, y + 6, y + 9);
        total += y[k];
        k = k == 11 ? 0 : k + 1;
    }
    const double elapsed = ak_bench_now_ns() - start;
    *sum = total;
    return elapsed / (double)n;
}

#endif
