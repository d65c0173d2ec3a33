/* Unit tests of the attitude core (fmu_src/core/attitude.h) against independent forms: matrix
 * products, the angle-based rotation matrix of kinematics_general, closed-form constant rotation,
 * and the round trip angles -> R -> angles for all 24 sequences.
 *
 *     test_attitude              the tests, with a 1e5-step norm run (ctest)
 *     test_attitude STEPS        only the norm run, over STEPS steps (1e7: the figure of
 *                                docs/attitude_propagator.md, about a minute) */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "attitude.h"
#include "attitude_step.h"
#include "kinematics_general.h"
#include "test_check.h"

/* Deterministic pseudo-random numbers in [-1, 1) (no global state: the caller keeps the seed). */
static double uniform(uint64_t *seed) {
    *seed = *seed * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*seed >> 11) / 4503599627370496.0 - 1.0;
}

static double matrix_difference(double A[3][3], double B[3][3]) {
    double worst = 0.0;
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
            worst = fmax(worst, fabs(A[i][j] - B[i][j]));
        }
    }
    return worst;
}

static void random_unit_quaternion(uint64_t *seed, double q[4]) {
    double n = 0.0;
    for (int k = 0; k < 4; k++) {
        q[k] = uniform(seed);
        n += q[k] * q[k];
    }
    for (int k = 0; k < 4; k++) {
        q[k] /= sqrt(n);
    }
}

/* R(a (x) b) = R(a) R(b): the product composes rotations. */
static void test_product_composes(void) {
    uint64_t seed = 1;
    double worst = 0.0;
    for (int n = 0; n < 1000; n++) {
        double a[4], b[4], ab[4], Ra[3][3], Rb[3][3], Rab[3][3], product[3][3];
        random_unit_quaternion(&seed, a);
        random_unit_quaternion(&seed, b);
        ak_quat_multiply(a, b, ab);
        ak_quat_to_matrix(a, Ra);
        ak_quat_to_matrix(b, Rb);
        ak_quat_to_matrix(ab, Rab);
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                product[i][j] = Ra[i][0] * Rb[0][j] + Ra[i][1] * Rb[1][j] + Ra[i][2] * Rb[2][j];
            }
        }
        worst = fmax(worst, matrix_difference(Rab, product));
    }
    ak_check(worst < 4e-15, "%s: %.3e (bound %.3e)", "R(a b) = R(a) R(b)", worst, 4e-15);
}

/* R(q) agrees with the angle-based R and quaternion of kinematics_general for every sequence. */
static void test_matrix_matches_kinematics_general(void) {
    uint64_t seed = 2;
    double worst = 0.0;
    for (int s = 0; s < AK_SEQUENCE_COUNT; s++) {
        for (int n = 0; n < 50; n++) {
            const double theta[3] = {3.0 * uniform(&seed), 3.0 * uniform(&seed), 3.0 * uniform(&seed)};
            double q[4], R[3][3], Rq[3][3];
            ak_general_quaternion(&AK_SEQUENCES[s], theta, q);
            ak_general_rotation_matrix(&AK_SEQUENCES[s], theta, R);
            ak_quat_to_matrix(q, Rq);
            worst = fmax(worst, matrix_difference(R, Rq));
        }
    }
    ak_check(worst < 1e-15, "%s: %.3e (bound %.3e)", "R(q) = R(theta)", worst, 1e-15);
}

/* exp is unit and continuous across its series threshold (|v| = 1e-4). */
static void test_exp(void) {
    double worst_norm = 0.0;
    for (double a = 1e-9; a < 10.0; a *= 1.37) {
        const double v[3] = {0.48 * a, -0.6 * a, 0.64 * a}; /* |v| = a */
        double e[4];
        ak_quat_exp(v, e);
        worst_norm = fmax(worst_norm, fabs(sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2] + e[3] * e[3]) - 1.0));
    }
    ak_check(worst_norm < 3e-16, "%s: %.3e (bound %.3e)", "|exp(v)| - 1", worst_norm, 3e-16);
    const double below[3] = {0.99999999e-4, 0.0, 0.0}, above[3] = {1.00000001e-4, 0.0, 0.0};
    double eb[4], ea[4];
    ak_quat_exp(below, eb);
    ak_quat_exp(above, ea);
    const double expected = cos(1e-4) * (above[0] - below[0]); /* d sin(a) = cos(a) da */
    ak_check(fabs((ea[1] - eb[1]) - expected) < 1e-19,
             "%s: %.3e (bound %.3e)",
             "exp continuous at 1e-4", fabs((ea[1] - eb[1]) - expected), 1e-19);
}

/* Constant omega: q(t) = q0 (x) exp(t omega / 2) (body) and exp(t omega / 2) (x) q0 (fixed). */
static void test_constant_rotation_is_exact(void) {
    const double w[3] = {0.3, -1.1, 2.0};
    double c[4][3] = {{w[0], w[1], w[2]}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
    const double q0[4] = {0.5, 0.5, -0.5, 0.5};
    for (int f = 0; f < 2; f++) {
        const ak_frame frame = f ? AK_FRAME_BODY : AK_FRAME_FIXED;
        double q[4] = {q0[0], q0[1], q0[2], q0[3]};
        const double h = 1e-2;
        const int steps = 1000;
        for (int n = 0; n < steps; n++) {
            ak_attitude_step(frame, c, h, q, NULL);
        }
        const double t = h * steps, v[3] = {w[0] * t / 2, w[1] * t / 2, w[2] * t / 2};
        double e[4], exact[4];
        ak_quat_exp(v, e);
        if (frame == AK_FRAME_BODY) {
            ak_quat_multiply(q0, e, exact);
        } else {
            ak_quat_multiply(e, q0, exact);
        }
        double error = 0.0;
        for (int k = 0; k < 4; k++) {
            error = fmax(error, fabs(q[k] - exact[k]));
        }
        /* 1000 products, each rounding to ~1e-16: a bound of 1e-13 is rounding, not truncation
         * (the truncation error of any non-exact method at h = 1e-2 over 10 s is far larger). */
        ak_check(error < 1e-13,
                 "%s: %.3e (bound %.3e)", frame == AK_FRAME_BODY ? "constant rotation, body" : "constant rotation, fixed", error, 1e-13);
    }
}

/* The input cubic from the history reproduces a cubic omega exactly (attitude.h, section 4). */
static void test_input_polynomial(void) {
    const double C[4][3] = {{0.3, -1.0, 2.0}, {0.7, 0.2, -0.5}, {-0.4, 1.1, 0.25}, {0.9, -0.6, 0.3}};
    const double hp = 0.37;
    double w0[3], w1[3], w2[3], wp[3], wdp[3], none[3] = {0.0, 0.0, 0.0};
    for (int k = 0; k < 3; k++) {
        const double s = -hp;
        w0[k] = C[0][k];
        w1[k] = C[1][k];
        w2[k] = 2.0 * C[2][k];
        wp[k] = C[0][k] + s * (C[1][k] + s * (C[2][k] + s * C[3][k]));
        wdp[k] = C[1][k] + s * (2.0 * C[2][k] + s * 3.0 * C[3][k]);
    }
    double c[4][3], worst = 0.0, worst_given = 0.0;
    ak_attitude_input_polynomial(w0, w1, none, wp, wdp, hp, c);
    for (int m = 0; m < 4; m++) {
        for (int k = 0; k < 3; k++) {
            worst = fmax(worst, fabs(c[m][k] - C[m][k]));
        }
    }
    ak_attitude_input_polynomial(w0, w1, w2, wp, wdp, hp, c);
    for (int m = 0; m < 4; m++) {
        for (int k = 0; k < 3; k++) {
            worst_given = fmax(worst_given, fabs(c[m][k] - C[m][k]));
        }
    }
    ak_check(worst < 1e-13,
             "%s: %.3e (bound %.3e)", "Hermite cubic from the history", worst, 1e-13);
    ak_check(worst_given < 1e-13,
             "%s: %.3e (bound %.3e)", "cubic from w2 and the history slope", worst_given, 1e-13);
    ak_attitude_input_polynomial(w0, w1, w2, NULL, NULL, 0.0, c);
    ak_check(c[2][1] == C[2][1] && c[3][1] == 0.0,
             "%s: %.3e (bound %.3e)", "Taylor without history", c[3][1], 0.0);
}

/* Angles -> R -> angles returns the principal angles for all 24 sequences, and the angles of a
 * singular attitude rebuild the same R with theta1 held. */
static void test_angles_round_trip(void) {
    uint64_t seed = 3;
    double worst = 0.0, worst_matrix = 0.0;
    for (int s = 0; s < AK_SEQUENCE_COUNT; s++) {
        const ak_sequence *sequence = &AK_SEQUENCES[s];
        for (int n = 0; n < 200; n++) {
            double theta[3] = {3.1 * uniform(&seed), 1.5 * uniform(&seed), 3.1 * uniform(&seed)};
            if (sequence->proper_euler) {
                theta[1] = 1.5 + 1.5 * uniform(&seed); /* (0, pi) */
            }
            double R[3][3], back[3], distance, Rb[3][3];
            ak_general_rotation_matrix(sequence, theta, R);
            ak_attitude_angles(sequence, R, NULL, back, &distance);
            for (int k = 0; k < 3; k++) {
                worst = fmax(worst, fabs(back[k] - theta[k]) * distance);
            }
            /* Continuity from a nearby previous set that lies on the other branch. */
            const double previous[3] = {back[0] + 0.01 + 6.283185307179586, back[1], back[2] - 0.01};
            ak_attitude_angles(sequence, R, previous, back, &distance);
            ak_general_rotation_matrix(sequence, back, Rb);
            worst_matrix = fmax(worst_matrix, matrix_difference(R, Rb));
            ak_check(fabs(back[0] - previous[0]) < 0.1,
                     "%s: %.3e (bound %.3e)",
                     "unwrapped theta1 near previous", fabs(back[0] - previous[0]), 0.1);
        }
        /* The singular attitude: theta2 = pi/2 (Tait-Bryan) or 0 (proper Euler). */
        const double singular[3] = {0.7, sequence->proper_euler ? 0.0 : 1.5707963267948966, -0.4};
        const double previous[3] = {0.65, singular[1], -0.3};
        double R[3][3], back[3], distance, Rb[3][3];
        ak_general_rotation_matrix(sequence, singular, R);
        const bool held = ak_attitude_angles(sequence, R, previous, back, &distance);
        ak_general_rotation_matrix(sequence, back, Rb);
        ak_check(held && back[0] == previous[0],
                 "%s: %.3e (bound %.3e)",
                 "theta1 held at the singular angle", back[0], previous[0]);
        ak_check(matrix_difference(R, Rb) < 1e-15,
                 "%s: %.3e (bound %.3e)",
                 "singular angles rebuild R", matrix_difference(R, Rb), 1e-15);
    }
    ak_check(worst < 1e-14,
             "%s: %.3e (bound %.3e)", "angles -> R -> angles (times distance)", worst, 1e-14);
    ak_check(worst_matrix < 2e-15,
             "%s: %.3e (bound %.3e)", "continuous angles rebuild R", worst_matrix, 2e-15);
}

/* A smooth trajectory through gimbal lock: theta(t) recovered from R(theta(t)) sampled densely,
 * theta2 crossing +pi/2 (Tait-Bryan) or 0 (proper Euler) and theta1 crossing pi. */
static void test_trajectory_through_singularity(void) {
    double worst = 0.0;
    for (int s = 0; s < AK_SEQUENCE_COUNT; s++) {
        const ak_sequence *sequence = &AK_SEQUENCES[s];
        const double middle = sequence->proper_euler ? 0.0 : 1.5707963267948966;
        double previous[3];
        for (int n = 0; n <= 2000; n++) {
            const double t = -1.0 + 1e-3 * n + 1.234567e-5; /* no sample exactly singular */
            const double theta[3] = {3.0 + 0.8 * t, middle + 0.5 * t, -2.0 + 1.3 * t * t};
            double R[3][3], back[3], distance;
            ak_general_rotation_matrix(sequence, theta, R);
            ak_attitude_angles(sequence, R, n == 0 ? NULL : previous, back, &distance);
            if (n == 0) { /* the principal set: put it on the trajectory's branch */
                ak_attitude_angles(sequence, R, theta, back, &distance);
            }
            for (int k = 0; k < 3; k++) {
                /* theta1 and theta3 are known to rounding / distance near the singularity. */
                const double bound = 1e-15 / distance + 1e-14;
                worst = fmax(worst, fabs(back[k] - theta[k]) / bound);
                previous[k] = back[k];
            }
        }
    }
    ak_check(worst < 1.0,
             "%s: %.3e (bound %.3e)", "trajectory through gimbal lock (error / bound)", worst, 1.0);
}

/* A tumbling body: omega(t) = (sin t, 0.5 cos 2t, 0.3 + 0.2 sin 3t) rad/s, body frame, h = 1e-3,
 * with its exact Taylor cubic. Reports | |q| - 1 | after `steps` steps, the largest rounding
 * correction of one step, and | |p| - 1 | of the same steps without the correction (p, for the
 * record: the rounding random walk the correction removes). */
static void norm_run(long steps, double *drift, double *largest_correction, double *uncorrected) {
    double q[4] = {1.0, 0.0, 0.0, 0.0}, p[4] = {1.0, 0.0, 0.0, 0.0};
    const double h = 1e-3;
    *largest_correction = 0.0;
    for (long n = 0; n < steps; n++) {
        const double t = h * (double)n;
        /* The Taylor cubic of omega at t. */
        double c[4][3] = {{sin(t), 0.5 * cos(2 * t), 0.3 + 0.2 * sin(3 * t)},
                          {cos(t), -sin(2 * t), 0.6 * cos(3 * t)},
                          {-sin(t) / 2, -cos(2 * t), -0.9 * sin(3 * t)},
                          {-cos(t) / 6, 4.0 * sin(2 * t) / 6, -5.4 * cos(3 * t) / 6}};
        double correction, v[3], e[4], next[4];
        ak_attitude_step(AK_FRAME_BODY, c, h, q, &correction);
        *largest_correction = fmax(*largest_correction, correction);
        ak_attitude_step_vector(AK_FRAME_BODY, c, h, v);
        ak_quat_exp(v, e);
        ak_quat_multiply(p, e, next);
        for (int k = 0; k < 4; k++) {
            p[k] = next[k];
        }
    }
    *drift = fabs(sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]) - 1.0);
    *uncorrected = fabs(sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2] + p[3] * p[3]) - 1.0);
}

int main(int argc, char **argv) {
    if (argc > 1) {
        const long steps = strtol(argv[1], NULL, 10);
        double drift, correction, uncorrected;
        norm_run(steps, &drift, &correction, &uncorrected);
        printf("tumbling body, h = 1e-3, %ld steps: | |q| - 1 | = %.3e, largest correction of "
               "one step = %.3e (without the correction: %.3e)\n", steps, drift, correction,
               uncorrected);
        return drift < 1e-15 && correction < 1e-15 ? 0 : 1;
    }
    test_product_composes();
    test_matrix_matches_kinematics_general();
    test_exp();
    test_constant_rotation_is_exact();
    test_input_polynomial();
    test_angles_round_trip();
    test_trajectory_through_singularity();
    double drift, correction, uncorrected;
    norm_run(100000, &drift, &correction, &uncorrected);
    ak_check(drift < 1e-15, "%s: %.3e (bound %.3e)", "norm drift after 1e5 steps", drift, 1e-15);
    /* The correction only ever removes rounding: a few units of 1e-16 at most. */
    ak_check(correction < 1e-15,
             "%s: %.3e (bound %.3e)", "largest norm correction of one step", correction, 1e-15);
    printf("norm after 1e5 steps: | |q| - 1 | = %.3e, largest correction %.3e\n", drift, correction);
    if (ak_check_failures()) {
        printf("%d failure(s)\n", ak_check_failures());
        return 1;
    }
    printf("attitude core: all tests passed\n");
    return 0;
}
