/* Unit tests of the general kinematics core (all 24 sequences), independent of the FMI layer.
 *
 * Each check derives the expected value another way than the core does:
 *   - R from the product of elementary rotation matrices in the order the sequence states;
 *   - omega_fixed from the skew matrix dR/dt R^T (dR/dt by the chain rule), omega_body = R^T omega;
 *   - alpha, W_dot from central differences along a smooth trajectory;
 *   - q through the rotation matrix it defines;
 *   - the inverse map by a round trip through the forward map;
 *   - body123 against the hand-written 1-2-3 core of kinematics.c.
 */
#include "elementary.h"
#include "kinematics_123.h"
#include "rotation_matrices.h"
#include "kinematics_general.h"
#include "kinematics_general_kernel.h"
#include "sequences.h"
#include "test_check.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Index of the sequence with that name, or -1. */
static int ak_sequence_index(const char *name) {
    if (name == NULL) {
        return -1;
    }
    for (int k = 0; k < AK_SEQUENCE_COUNT; k++) {
        if (strcmp(AK_SEQUENCES[k].name, name) == 0) {
            return k;
        }
    }
    return -1;
}

static double random_in(double low, double high) {
    return low + (high - low) * ((double)rand() / (double)RAND_MAX);
}

/* Magnitudes from 1e-3 to 1e3, either sign. */
static double random_rate(void) {
    return pow(10.0, random_in(-3.0, 3.0)) * (rand() % 2 ? 1.0 : -1.0);
}

/* R and dR/dt as the product in the order the sequence states: M[k] belongs to theta_k. */
static void reference_rotation(const ak_sequence *seq, const double theta[3], const double td[3],
                               double R[3][3], double Rdot[3][3]) {
    double M[3][3][3], dM[3][3][3];
    int order[3];
    for (int k = 0; k < 3; k++) {
        elementary_rotation(seq->axes[k] - 1, theta[k], M[k], dM[k]);
        order[k] = (seq->kind == AK_BODY_FIXED) ? k : 2 - k;
    }
    double P[3][3], Q[3][3];
    multiply(M[order[0]], M[order[1]], P);
    multiply(P, M[order[2]], R);
    memset(Rdot, 0, sizeof(double) * 9);
    for (int a = 0; a < 3; a++) {
        double *F[3];
        for (int n = 0; n < 3; n++) {
            F[n] = (order[n] == a) ? &dM[a][0][0] : &M[order[n]][0][0];
        }
        multiply((double (*)[3])F[0], (double (*)[3])F[1], P);
        multiply(P, (double (*)[3])F[2], Q);
        for (int r = 0; r < 3; r++) {
            for (int k = 0; k < 3; k++) {
                Rdot[r][k] += Q[r][k] * td[a];
            }
        }
    }
}

static void transpose_times(double R[3][3], const double v[3], double out[3]) {
    for (int k = 0; k < 3; k++) {
        out[k] = R[0][k] * v[0] + R[1][k] * v[1] + R[2][k] * v[2];
    }
}

static void times(double M[3][3], const double v[3], double out[3]) {
    for (int k = 0; k < 3; k++) {
        out[k] = M[k][0] * v[0] + M[k][1] * v[1] + M[k][2] * v[2];
    }
}

static double det3(double M[3][3]) {
    return M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) -
           M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
           M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
}

/* The singularity distance |det W| as the FMUs get it: from the inverse map, which always
 * writes it. */
static double singularity_distance(const ak_sequence *seq, const double theta[3]) {
    const double zero[3] = {0.0, 0.0, 0.0};
    double theta_dot[3], theta_ddot[3], alpha_fixed[3], alpha_body[3], distance;
    (void)ak_general_euler_rates(seq, AK_FRAME_FIXED, theta, zero, zero, 0.0, theta_dot,
                                 theta_ddot, alpha_fixed, alpha_body, &distance);
    return distance;
}

static void check_rotation(const ak_sequence *seq, const double theta[3], const double td[3]) {
    double R_ref[3][3], Rdot[3][3], R[3][3], q[4];
    reference_rotation(seq, theta, td, R_ref, Rdot);
    ak_general_rotation_matrix(seq, theta, R);
    for (int r = 0; r < 3; r++) {
        for (int k = 0; k < 3; k++) {
            ak_check_close(R[r][k], R_ref[r][k], 1e-15,
                           "%s: R = product of elementary rotations", seq->name);
            const double RRt = R[r][0] * R[k][0] + R[r][1] * R[k][1] + R[r][2] * R[k][2];
            ak_check_close(RRt, r == k ? 1.0 : 0.0, 1e-15, "%s: R R^T = I", seq->name);
        }
    }
    ak_check_close(det3(R), 1.0, 1e-15, "%s: det R = 1", seq->name);

    ak_general_quaternion(seq, theta, q);
    ak_check_close(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3], 1.0, 1e-15,
                   "%s: |q| = 1", seq->name);
    ak_check(q[0] >= 0.0, "%s: q0 >= 0", seq->name);
    const double Rq[3][3] = {
        {1 - 2 * (q[2] * q[2] + q[3] * q[3]), 2 * (q[1] * q[2] - q[0] * q[3]), 2 * (q[1] * q[3] + q[0] * q[2])},
        {2 * (q[1] * q[2] + q[0] * q[3]), 1 - 2 * (q[1] * q[1] + q[3] * q[3]), 2 * (q[2] * q[3] - q[0] * q[1])},
        {2 * (q[1] * q[3] - q[0] * q[2]), 2 * (q[2] * q[3] + q[0] * q[1]), 1 - 2 * (q[1] * q[1] + q[2] * q[2])}};
    for (int r = 0; r < 3; r++) {
        for (int k = 0; k < 3; k++) {
            ak_check_close(Rq[r][k], R_ref[r][k], 2e-15, "%s: R(q) = R", seq->name);
        }
    }
    /* theta + 2 pi on one angle is the same orientation, hence the same q. */
    double shifted[3] = {theta[0], theta[1], theta[2] + 6.283185307179586}, q2[4];
    ak_general_quaternion(seq, shifted, q2);
    for (int k = 0; k < 4; k++) {
        ak_check_close(q2[k], q[k], 1e-14, "%s: q(theta3 + 2 pi) = q(theta)", seq->name);
    }
}

static void check_velocity(const ak_sequence *seq, const double theta[3], const double td[3],
                           const double tdd[3]) {
    double R[3][3], Rdot[3][3], S[3][3];
    double wf[3], wb[3], af[3], ab[3], rotated[3], Wf[3][3], Wb[3][3], Wfd[3][3], Wbd[3][3], x[3];
    const double scale_w = fabs(td[0]) + fabs(td[1]) + fabs(td[2]);
    const double scale_a = fabs(tdd[0]) + fabs(tdd[1]) + fabs(tdd[2]) + scale_w * scale_w;
    reference_rotation(seq, theta, td, R, Rdot);
    for (int r = 0; r < 3; r++) {
        for (int k = 0; k < 3; k++) {
            S[r][k] = Rdot[r][0] * R[k][0] + Rdot[r][1] * R[k][1] + Rdot[r][2] * R[k][2];
        }
    }
    ak_general_angular_kinematics(seq, theta, td, tdd, wf, wb, af, ab);
    ak_check_close(wf[0], S[2][1], 1e-14 * scale_w,
                   "%s: omega_fixed[1] vs skew(dR/dt R^T)", seq->name);
    ak_check_close(wf[1], S[0][2], 1e-14 * scale_w,
                   "%s: omega_fixed[2] vs skew(dR/dt R^T)", seq->name);
    ak_check_close(wf[2], S[1][0], 1e-14 * scale_w,
                   "%s: omega_fixed[3] vs skew(dR/dt R^T)", seq->name);
    transpose_times(R, wf, rotated);
    for (int k = 0; k < 3; k++) {
        ak_check_close(wb[k], rotated[k], 1e-14 * scale_w,
                       "%s: omega_body = R^T omega_fixed", seq->name);
    }
    transpose_times(R, af, rotated);
    for (int k = 0; k < 3; k++) {
        ak_check_close(ab[k], rotated[k], 1e-14 * scale_a,
                       "%s: alpha_body = R^T alpha_fixed", seq->name);
    }

    ak_general_partials(seq, theta, td, Wf, Wb, Wfd, Wbd);
    times(Wf, td, x);
    for (int k = 0; k < 3; k++) {
        ak_check_close(x[k], wf[k], 1e-14 * scale_w,
                       "%s: omega_fixed = W_fixed theta_dot", seq->name);
    }
    times(Wb, td, x);
    for (int k = 0; k < 3; k++) {
        ak_check_close(x[k], wb[k], 1e-14 * scale_w,
                       "%s: omega_body = W_body theta_dot", seq->name);
    }
    for (int r = 0; r < 3; r++) {
        for (int k = 0; k < 3; k++) {
            const double rotated_column = R[0][r] * Wf[0][k] + R[1][r] * Wf[1][k] + R[2][r] * Wf[2][k];
            ak_check_close(Wb[r][k], rotated_column, 1e-15, "%s: W_body = R^T W_fixed", seq->name);
        }
    }
    const double d = singularity_distance(seq, theta);
    /* the core's own sines (fmu_src/elementary/) */
    const double expected_d = seq->proper_euler ? fabs(ak_sin(theta[1])) : fabs(ak_cos(theta[1]));
    ak_check_close(d, expected_d, 0.0, "%s: distance = |cos theta2| or |sin theta2|", seq->name);
    ak_check_close(fabs(det3(Wf)), d, 1e-15, "%s: |det W_fixed| = distance", seq->name);
    /* The signs stated in kinematics_general.h, section 4. */
    const int cyclic = (seq->axes[1] - seq->axes[0] + 3) % 3 == 1;
    const double signed_det = seq->proper_euler
                                  ? (seq->kind == AK_SPACE_FIXED ? 1.0 : -1.0) * sin(theta[1])
                                  : (cyclic ? 1.0 : -1.0) * cos(theta[1]);
    ak_check_close(det3(Wf), signed_det, 1e-15,
                   "%s: det W_fixed = eps cos theta2 or -+sin theta2", seq->name);
    ak_check_close(fabs(det3(Wb)), d, 1e-15, "%s: |det W_body| = distance", seq->name);

    /* Along theta(t) = theta + td t + tdd t^2 / 2: alpha = d(omega)/dt and W_dot = dW/dt,
     * a fourth-order central difference. */
    const double h = 1e-3 / (1.0 + scale_w + sqrt(fabs(tdd[0]) + fabs(tdd[1]) + fabs(tdd[2])));
    const double offsets[4] = {-2 * h, -h, h, 2 * h}, weights[4] = {1, -8, 8, -1};
    double dwf[3] = {0}, dwb[3] = {0}, dWf[3][3] = {{0}}, dWb[3][3] = {{0}};
    for (int n = 0; n < 4; n++) {
        double th[3], thd[3], w1[3], w2[3], a1[3], a2[3], Wf_n[3][3], Wb_n[3][3], unused[2][3][3];
        for (int k = 0; k < 3; k++) {
            th[k] = theta[k] + td[k] * offsets[n] + 0.5 * tdd[k] * offsets[n] * offsets[n];
            thd[k] = td[k] + tdd[k] * offsets[n];
        }
        ak_general_angular_kinematics(seq, th, thd, tdd, w1, w2, a1, a2);
        ak_general_partials(seq, th, thd, Wf_n, Wb_n, unused[0], unused[1]);
        for (int r = 0; r < 3; r++) {
            dwf[r] += weights[n] * w1[r] / (12 * h);
            dwb[r] += weights[n] * w2[r] / (12 * h);
            for (int k = 0; k < 3; k++) {
                dWf[r][k] += weights[n] * Wf_n[r][k] / (12 * h);
                dWb[r][k] += weights[n] * Wb_n[r][k] / (12 * h);
            }
        }
    }
    for (int r = 0; r < 3; r++) {
        ak_check_close(af[r], dwf[r], 1e-7 * scale_a,
                       "%s: alpha_fixed = d(omega_fixed)/dt", seq->name);
        ak_check_close(ab[r], dwb[r], 1e-7 * scale_a,
                       "%s: alpha_body = d(omega_body)/dt", seq->name);
        for (int k = 0; k < 3; k++) {
            ak_check_close(Wfd[r][k], dWf[r][k], 1e-7 * scale_w,
                           "%s: W_fixed_dot = d(W_fixed)/dt", seq->name);
            ak_check_close(Wbd[r][k], dWb[r][k], 1e-7 * scale_w,
                           "%s: W_body_dot = d(W_body)/dt", seq->name);
        }
    }
}

/* Forward then inverse gives back theta_dot and theta_ddot, to the conditioning 1/distance. */
static void check_round_trip(const ak_sequence *seq, const double theta[3], const double td[3],
                             const double tdd[3]) {
    double wf[3], wb[3], af[3], ab[3];
    ak_general_angular_kinematics(seq, theta, td, tdd, wf, wb, af, ab);
    const double d = singularity_distance(seq, theta);
    const double scale_w = fabs(td[0]) + fabs(td[1]) + fabs(td[2]);
    const double scale_a = fabs(tdd[0]) + fabs(tdd[1]) + fabs(tdd[2]) + scale_w * scale_w;
    for (int f = 0; f < 2; f++) {
        double td_back[3], tdd_back[3], af_back[3], ab_back[3], distance;
        const ak_rates_status status = ak_general_euler_rates(
            seq, f == 0 ? AK_FRAME_FIXED : AK_FRAME_BODY, theta, f == 0 ? wf : wb, f == 0 ? af : ab,
            1e-300, td_back, tdd_back, af_back, ab_back, &distance);
        ak_check(status == AK_RATES_OK, "%s: round trip: status OK", seq->name);
        ak_check_close(distance, d, 0.0, "%s: round trip: distance", seq->name);
        if (status != AK_RATES_OK) {
            continue;
        }
        for (int k = 0; k < 3; k++) {
            ak_check_close(td_back[k], td[k], 1e-14 * scale_w / d,
                           "%s: round trip: theta_dot", seq->name);
            ak_check_close(tdd_back[k], tdd[k], 1e-14 * scale_a / (d * d),
                           "%s: round trip: theta_ddot", seq->name);
            ak_check_close(af_back[k], af[k], 1e-14 * scale_a,
                           "%s: round trip: alpha_fixed", seq->name);
            ak_check_close(ab_back[k], ab[k], 1e-14 * scale_a,
                           "%s: round trip: alpha_body", seq->name);
        }
    }
}

static void check_singularity(const ak_sequence *seq) {
    const double pi = 3.141592653589793;
    const double singular[2] = {seq->proper_euler ? 0.0 : -pi / 2, seq->proper_euler ? pi : pi / 2};
    const double omega[3] = {0.3, -0.2, 0.1}, omega_dot[3] = {1.0, 2.0, 3.0};
    for (int n = 0; n < 2; n++) {
        for (int wrap = -2; wrap <= 2; wrap++) {
            const double theta[3] = {0.4, singular[n] + 2 * pi * wrap, -1.1};
            double td[3] = {7, 7, 7}, tdd[3] = {7, 7, 7}, af[3] = {7, 7, 7}, ab[3] = {7, 7, 7}, d;
            for (int f = 0; f < 2; f++) {
                const ak_rates_status status = ak_general_euler_rates(
                    seq, f ? AK_FRAME_BODY : AK_FRAME_FIXED, theta, omega, omega_dot, 1e-6, td, tdd, af, ab, &d);
                ak_check(status == AK_RATES_SINGULAR,
                         "%s: at the singular angle: AK_RATES_SINGULAR", seq->name);
                ak_check(d < 1e-14, "%s: at the singular angle: distance below 1e-14", seq->name);
                ak_check(td[0] == 7 && td[1] == 7 && td[2] == 7 && tdd[0] == 7 && tdd[2] == 7 &&
                         af[1] == 7 && ab[1] == 7,
                         "%s: at the singular angle: outputs untouched", seq->name);
            }
        }
        /* Inside the tolerance: computed, flagged. */
        const double theta[3] = {0.4, singular[n] + 1e-8, -1.1};
        double td[3], tdd[3], af[3], ab[3], d;
        ak_rates_status status = ak_general_euler_rates(seq, AK_FRAME_FIXED, theta, omega, omega_dot,
                                                        1e-6, td, tdd, af, ab, &d);
        ak_check(status == AK_RATES_NEAR_SINGULAR,
                 "%s: 1e-8 from singular: AK_RATES_NEAR_SINGULAR", seq->name);
        ak_check_close(d, 1e-8, 1e-15, "%s: 1e-8 from singular: distance", seq->name);
        status = ak_general_euler_rates(seq, AK_FRAME_FIXED, theta, omega, omega_dot, 1e-9, td, tdd,
                                        af, ab, &d);
        ak_check(status == AK_RATES_OK,
                 "%s: 1e-8 from singular, tolerance 1e-9: AK_RATES_OK", seq->name);
        /* Far from the singularity but the result overflows: refused, nothing written. */
        const double far[3] = {0.4, singular[n] + 1e-3, -1.1}, huge[3] = {1e300, -1e300, 1e300};
        td[0] = 7;
        status = ak_general_euler_rates(seq, AK_FRAME_BODY, far, huge, omega_dot, 1e-6, td, tdd,
                                        af, ab, &d);
        ak_check(status == AK_RATES_OVERFLOW, "%s: overflow: AK_RATES_OVERFLOW", seq->name);
        ak_check(td[0] == 7, "%s: overflow: outputs untouched", seq->name);
    }
}

static void check_table(void) {
    for (int i = 0; i < AK_SEQUENCE_COUNT; i++) {
        const ak_sequence *seq = &AK_SEQUENCES[i];
        char name[16];
        snprintf(name, sizeof name, "%s%d%d%d", seq->kind == AK_BODY_FIXED ? "body" : "space",
                 seq->axes[0], seq->axes[1], seq->axes[2]);
        ak_check(strcmp(name, seq->name) == 0, "%s: name says kind and axes", seq->name);
        ak_check(ak_sequence_index(seq->name) == i, "%s: index of name", seq->name);
        ak_check(seq->axes[0] != seq->axes[1] && seq->axes[1] != seq->axes[2],
                 "%s: consecutive axes differ", seq->name);
        ak_check(seq->proper_euler == (seq->axes[0] == seq->axes[2]),
                 "%s: proper_euler flag", seq->name);
        ak_check((i < 12) == (seq->kind == AK_BODY_FIXED),
                 "%s: body-fixed first, then space-fixed", seq->name);
        ak_check((i % 12 < 6) == !seq->proper_euler,
                 "%s: Tait-Bryan first in each half", seq->name);
    }
    ak_check(strcmp(AK_SEQUENCES[AK_SEQUENCE_DEFAULT].name, "body123") == 0,
             "%s: default is body123", "table");
    ak_check(ak_sequence_index("body111") == -1 && ak_sequence_index(NULL) == -1,
             "%s: unknown name", "table");
}

/* The general core for body123 against the hand-written 1-2-3 core; worst scaled difference. */
static double worst_body123_difference = 0.0;

static void check_body123_matches_core(const double theta[3], const double td[3], const double tdd[3]) {
    const ak_sequence *seq = &AK_SEQUENCES[ak_sequence_index("body123")];
    double g[4][3], h[4][3], Rg[3][3], Rh[3][3];
    const double scale_w = fabs(td[0]) + fabs(td[1]) + fabs(td[2]);
    const double scale_a = fabs(tdd[0]) + fabs(tdd[1]) + fabs(tdd[2]) + scale_w * scale_w;
    ak_general_angular_kinematics(seq, theta, td, tdd, g[0], g[1], g[2], g[3]);
    ak_angular_kinematics_123(theta, td, tdd, h[0], h[1], h[2], h[3]);
    for (int n = 0; n < 4; n++) {
        for (int k = 0; k < 3; k++) {
            const double scale = n < 2 ? scale_w : scale_a;
            ak_check_close(g[n][k], h[n][k], 1.5e-15 * scale,
                           "%s: general core = ak_angular_kinematics_123", "body123");
            if (fabs(g[n][k] - h[n][k]) / scale > worst_body123_difference) {
                worst_body123_difference = fabs(g[n][k] - h[n][k]) / scale;
            }
        }
    }
    ak_general_rotation_matrix(seq, theta, Rg);
    ak_rotation_matrix_123(theta, Rh);
    for (int r = 0; r < 3; r++) {
        for (int k = 0; k < 3; k++) {
            ak_check_close(Rg[r][k], Rh[r][k], 1e-15,
                           "%s: general R = ak_rotation_matrix_123", "body123");
        }
    }
}

/* The outputs from shared sines (ak_angle_sines, ak_half_angle_sines) are bit for bit those of
 * the one-output functions, and the default sequence's specialized copy (taken for the table's
 * own entry) gives bit for bit what the generic code gives for a copy of the entry. */
static void check_shared_sines(const ak_sequence *seq, const double theta[3], const double td[3],
                               const double tdd[3]) {
    const ak_sequence copy = *seq; /* another address: never the specialized path */
    ak_sines sines, half;
    ak_angle_sines(theta, &sines);
    ak_half_angle_sines(&sines, &half);

    double shared[12], own[12], generic[12];
    ak_general_angular_kinematics_of_sines(seq, &sines, td, tdd, shared, shared + 3, shared + 6,
                                           shared + 9);
    ak_general_angular_kinematics(seq, theta, td, tdd, own, own + 3, own + 6, own + 9);
    ak_general_angular_kinematics(&copy, theta, td, tdd, generic, generic + 3, generic + 6,
                                  generic + 9);
    ak_check(memcmp(shared, own, sizeof own) == 0,
             "%s: omega, alpha from shared sines bit-identical", seq->name);
    ak_check(memcmp(shared, generic, sizeof generic) == 0,
             "%s: omega, alpha of the table entry and of a copy bit-identical", seq->name);

    ak_rotation_outputs all, all_generic, one;
    ak_general_rotation_outputs(seq, &sines, &half, td, &all);
    ak_general_rotation_outputs(&copy, &sines, &half, td, &all_generic);
    ak_general_rotation_matrix(seq, theta, one.R);
    ak_general_quaternion(seq, theta, one.q);
    ak_general_partials(seq, theta, td, one.W_fixed, one.W_body, one.W_fixed_dot, one.W_body_dot);
    ak_check(memcmp(&all, &one, sizeof one) == 0,
             "%s: R, q, W, W_dot at once bit-identical to one by one", seq->name);
    ak_check(memcmp(&all, &all_generic, sizeof all) == 0,
             "%s: R, q, W, W_dot of the table entry and of a copy bit-identical", seq->name);
}

/* ak_half_angle_sines: sin and cos of the half angle in [-pi/2, pi/2] (theta / 2, or theta / 2 +
 * pi, which is the same q up to sign) from the angle's sines, within 2 ulp of 1 of libm's sin and
 * cos of that half angle; at and around 0, +-pi/2, +-pi and for large angles. */
static double worst_half_angle_difference = 0.0;

static void check_half_angles(double x) {
    const double theta[3] = {x, -x, 0.5 * x};
    ak_sines sines, half;
    ak_angle_sines(theta, &sines);
    ak_half_angle_sines(&sines, &half);
    for (int k = 0; k < 3; k++) {
        /* The half angle in [-pi/2, pi/2] of the angle libm's sin and cos describe. */
        const double h = 0.5 * atan2(sines.sin[k], sines.cos[k]);
        const double s = sin(h), c = cos(h);
        const double d = fmax(fabs(half.sin[k] - s), fabs(half.cos[k] - c));
        worst_half_angle_difference = fmax(worst_half_angle_difference, d);
        ak_check(d <= 4.5e-16,
                 "%s: ak_half_angle_sines = sin, cos of the half angle", "half angles");
        ak_check(half.cos[k] >= 0.0, "%s: cos of the half angle >= 0", "half angles");
        ak_check(fabs(half.sin[k] * half.sin[k] + half.cos[k] * half.cos[k] - 1.0) <= 4.5e-16,
                 "%s: sin^2 + cos^2 = 1", "half angles");
    }
}

int main(void) {
    srand(20261121);
    check_table();
    for (int i = 0; i < AK_SEQUENCE_COUNT; i++) {
        const ak_sequence *seq = &AK_SEQUENCES[i];
        const double singular = seq->proper_euler ? 0.0 : 1.5707963267948966;
        for (int n = 0; n < 300; n++) {
            double theta[3], td[3], tdd[3];
            for (int k = 0; k < 3; k++) {
                theta[k] = random_in(-4.0, 4.0);
                td[k] = random_rate();
                tdd[k] = random_rate();
            }
            if (n % 3 == 1) {
                theta[1] = singular + random_in(-1e-6, 1e-6); /* near the singular configuration */
            } else if (n % 3 == 2) {
                theta[1] = singular;                          /* at it */
            }
            check_rotation(seq, theta, td);
            check_velocity(seq, theta, td, tdd);
            check_shared_sines(seq, theta, td, tdd);
            if (n % 3 == 0 && singularity_distance(seq, theta) > 1e-2) {
                check_round_trip(seq, theta, td, tdd);
            }
        }
        check_singularity(seq);
    }
    for (int n = 0; n < 2000; n++) {
        double theta[3], td[3], tdd[3];
        for (int k = 0; k < 3; k++) {
            theta[k] = random_in(-10.0, 10.0);
            td[k] = random_rate();
            tdd[k] = random_rate();
        }
        check_body123_matches_core(theta, td, tdd);
    }
    printf("body123 general vs ak_angular_kinematics_123, 2000 states: worst scaled difference %.2e\n",
           worst_body123_difference);
    const double special[] = {0.0, 1e-300, 1e-8, 1.5707963267948966, 3.141592653589793,
                              3.1415926535897927, 3.141592653589794, 4.71238898038469,
                              6.283185307179586, 100.0, 12345.678};
    for (size_t i = 0; i < sizeof special / sizeof special[0]; i++) {
        for (int sign = -1; sign <= 1; sign += 2) {
            check_half_angles(sign * special[i]);
            check_half_angles(sign * nextafter(special[i], 10.0));
            check_half_angles(sign * nextafter(special[i], -10.0));
        }
    }
    for (int n = 0; n < 20000; n++) {
        check_half_angles(random_in(-20.0, 20.0));
    }
    printf("half angles from the angles' sines, 20066 x 3 angles: worst difference %.2e\n",
           worst_half_angle_difference);
    printf("%d checks, %d failures\n", ak_check_count(), ak_check_failures());
    return ak_check_exit_status();
}
