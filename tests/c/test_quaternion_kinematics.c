/* The quaternion kinematics core (fmu_src/core/quaternion_kinematics.h) against curves built from
 * chosen motions: a unit u with u' = u (0, omega) / 2 and u'' = u (0, alpha) / 2 - |omega|^2 u / 4
 * (the body-frame kinematic equation differentiated once), scaled by a length n(t) with chosen
 * n' and n'' (built in long double). The core must give omega and alpha back, in both frames, from
 * q = n u and its derivatives; and the same bits for -q and for q times a power of 2. Also the
 * sines of the principal angles that the model feeds its angle rates with
 * (ak_attitude_principal_sines) against sin and cos of the angles. */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>

#include "attitude_angles.h"
#include "kinematics_general.h"
#include "quaternion_kinematics.h"
#include "sequences.h"
#include "test_check.h"

static uint64_t state = 88172645463325252u;
static double uniform(void) { /* xorshift64, in [-1, 1) */
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return (double)(state >> 11) / 4503599627370496.0 - 1.0;
}

/* out := a b (Hamilton), long double. */
static void product(const long double a[4], const long double b[4], long double out[4]) {
    out[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
    out[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
    out[2] = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
    out[3] = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
}

/* v_fixed = u v_body u*, for the fixed-frame components of the chosen vectors. */
static void rotate(const long double u[4], const double v[3], long double out[3]) {
    const long double w[4] = {0.0L, v[0], v[1], v[2]}, conj[4] = {u[0], -u[1], -u[2], -u[3]};
    long double t[4], r[4];
    product(u, w, t);
    product(t, conj, r);
    for (int k = 0; k < 3; k++) {
        out[k] = r[k + 1];
    }
}

typedef struct {
    double q[4], q_dot[4], q_ddot[4];
    double omega[3], alpha[3];        /* chosen, body frame */
    long double omega_f[3], alpha_f[3]; /* the same in the fixed frame */
    long double n;
} curve;

static curve make_curve(double size) {
    curve c;
    long double u[4], norm = 0.0L;
    for (int k = 0; k < 4; k++) {
        u[k] = uniform();
        norm += u[k] * u[k];
    }
    norm = sqrtl(norm);
    for (int k = 0; k < 4; k++) {
        u[k] /= norm;
    }
    for (int k = 0; k < 3; k++) {
        c.omega[k] = 10.0 * uniform();
        c.alpha[k] = 100.0 * uniform();
    }
    const long double n = size * (1.5 + uniform()), n1 = size * uniform(),
                      n2 = size * 10.0 * uniform();
    const long double w[4] = {0.0L, c.omega[0] / 2.0L, c.omega[1] / 2.0L, c.omega[2] / 2.0L};
    const long double a[4] = {0.0L, c.alpha[0] / 2.0L, c.alpha[1] / 2.0L, c.alpha[2] / 2.0L};
    const long double w2 = (c.omega[0] * (long double)c.omega[0] +
                            c.omega[1] * (long double)c.omega[1] +
                            c.omega[2] * (long double)c.omega[2]) / 4.0L;
    long double u1[4], ua[4];
    product(u, w, u1);
    product(u, a, ua);
    for (int k = 0; k < 4; k++) {
        const long double u2 = ua[k] - w2 * u[k];
        c.q[k] = (double)(n * u[k]);
        c.q_dot[k] = (double)(n1 * u[k] + n * u1[k]);
        c.q_ddot[k] = (double)(n2 * u[k] + 2.0L * n1 * u1[k] + n * u2);
    }
    rotate(u, c.omega, c.omega_f);
    rotate(u, c.alpha, c.alpha_f);
    c.n = n;
    return c;
}

/* 2000 random curves of lengths 1e-3 to 1e3: the chosen omega and alpha back, within the
 * rounding of the inputs (a few units of roundoff of the sizes of the terms). */
static void chosen_motions(void) {
    double worst = 0.0;
    for (int trial = 0; trial < 2000; trial++) {
        const double size = pow(10.0, 3.0 * uniform());
        const curve c = make_curve(size);
        ak_quaternion_outputs out;
        ak_check(ak_quaternion_kinematics(c.q, c.q_dot, c.q_ddot, &out) == AK_QUATERNION_OK,
                 "trial %d: refused", trial);
        const double omega_scale = 10.0 * sqrt(3.0), alpha_scale = 100.0 * sqrt(3.0) + 300.0;
        for (int k = 0; k < 3; k++) {
            const double errors[4] = {
                fabs(out.omega_body[k] - c.omega[k]) / omega_scale,
                (double)fabsl(out.omega_fixed[k] - c.omega_f[k]) / omega_scale,
                fabs(out.alpha_body[k] - c.alpha[k]) / alpha_scale,
                (double)fabsl(out.alpha_fixed[k] - c.alpha_f[k]) / alpha_scale};
            for (int m = 0; m < 4; m++) {
                worst = fmax(worst, errors[m]);
                ak_check(errors[m] < 1e-14, "trial %d: output %d component %d off by %g of its "
                         "size", trial, m, k, errors[m]);
            }
        }
        ak_check(fabs(out.q_norm - (double)c.n) <= 4.0 * DBL_EPSILON * out.q_norm,
                 "trial %d: q_norm %.17g, expected %.17g", trial, out.q_norm, (double)c.n);
        /* R is a rotation: R omega_body = omega_fixed. */
        for (int i = 0; i < 3; i++) {
            const double Rw = out.R[i][0] * out.omega_body[0] + out.R[i][1] * out.omega_body[1] +
                              out.R[i][2] * out.omega_body[2];
            ak_check(fabs(Rw - out.omega_fixed[i]) < 1e-14 * omega_scale, "trial %d: R omega",
                     trial);
        }
    }
    printf("chosen motions: largest error %.3g of the size of the terms\n", worst);
}

/* A spin about the third axis at w from the identity: q' = (0, 0, 0, w/2), q'' = (-w^2/4, 0, 0, 0):
 * omega = (0, 0, w) and alpha = 0 exactly. */
static void spin(void) {
    const double w = 3.0;
    const double q[4] = {1.0, 0.0, 0.0, 0.0}, q_dot[4] = {0.0, 0.0, 0.0, w / 2.0},
                 q_ddot[4] = {-w * w / 4.0, 0.0, 0.0, 0.0};
    ak_quaternion_outputs out;
    ak_check(ak_quaternion_kinematics(q, q_dot, q_ddot, &out) == AK_QUATERNION_OK, "spin: ok");
    ak_check(out.omega_body[0] == 0.0 && out.omega_body[1] == 0.0 && out.omega_body[2] == w &&
                 out.omega_fixed[2] == w, "spin: omega = (%g, %g, %g)", out.omega_body[0],
             out.omega_body[1], out.omega_body[2]);
    ak_check(out.alpha_body[0] == 0.0 && out.alpha_body[1] == 0.0 && out.alpha_body[2] == 0.0,
             "spin: alpha = 0");
    ak_check(out.R[0][0] == 1.0 && out.R[1][1] == 1.0 && out.R[2][2] == 1.0 && out.q_norm == 1.0,
             "spin: R = I, |q| = 1");
}

/* Every output but q_norm (the last) bit for bit. */
static bool same_bits(const ak_quaternion_outputs *a, const ak_quaternion_outputs *b) {
    const double *x = (const double *)a, *y = (const double *)b;
    for (size_t k = 0; k + 1 < sizeof *a / sizeof(double); k++) {
        if (x[k] != y[k]) {
            return false;
        }
    }
    return true;
}

/* -q (with its derivatives) and q times 2^10 or 2^-10 are the same attitude and motion: the same
 * bits (|q| excepted for the scaled ones). */
static void sign_and_scale(void) {
    for (int trial = 0; trial < 200; trial++) {
        const curve c = make_curve(1.0);
        ak_quaternion_outputs out, other;
        ak_quaternion_kinematics(c.q, c.q_dot, c.q_ddot, &out);
        const double factors[3] = {-1.0, 1024.0, 1.0 / 1024.0};
        for (int f = 0; f < 3; f++) {
            double q[4], q_dot[4], q_ddot[4];
            for (int k = 0; k < 4; k++) {
                q[k] = factors[f] * c.q[k];
                q_dot[k] = factors[f] * c.q_dot[k];
                q_ddot[k] = factors[f] * c.q_ddot[k];
            }
            ak_quaternion_kinematics(q, q_dot, q_ddot, &other);
            ak_check(same_bits(&out, &other), "trial %d: factor %g changes the outputs", trial,
                     factors[f]);
            ak_check(other.q_norm == fabs(factors[f]) * out.q_norm, "trial %d: |q| scales",
                     trial);
        }
    }
}

/* q = 0 and q below the smallest normal double are no attitude; |q| or q_dot / |q| above the
 * largest double overflow. */
static void refusals(void) {
    const double zero[4] = {0.0, 0.0, 0.0, 0.0}, tiny[4] = {1e-310, 0.0, 0.0, 0.0},
                 huge[4] = {DBL_MAX, DBL_MAX, 0.0, 0.0}, small[4] = {1e-300, 0.0, 0.0, 0.0},
                 fast[4] = {0.0, 1e10, 0.0, 0.0}, one[4] = {1.0, 0.0, 0.0, 0.0};
    ak_quaternion_outputs out;
    ak_check(ak_quaternion_kinematics(zero, zero, zero, &out) == AK_QUATERNION_NOT_ATTITUDE,
             "q = 0 refused");
    ak_check(ak_quaternion_kinematics(tiny, zero, zero, &out) == AK_QUATERNION_NOT_ATTITUDE,
             "q below DBL_MIN refused");
    ak_check(ak_quaternion_kinematics(huge, zero, zero, &out) == AK_QUATERNION_OVERFLOW &&
                 isinf(out.q_norm), "|q| above DBL_MAX: overflow");
    ak_check(ak_quaternion_kinematics(small, fast, zero, &out) == AK_QUATERNION_OVERFLOW,
             "q_dot / |q| = 1e310: overflow");
    ak_check(ak_quaternion_kinematics(one, fast, zero, &out) == AK_QUATERNION_OK &&
                 out.omega_body[0] == 2e10, "q_dot / |q| = 1e10: omega = 2e10 (got %g)",
             out.omega_body[0]);
}

/* The tangent against central differences of the outputs along random directions (error of the
 * differences: about h^2 times the third derivative, and rounding / h). */
static void tangent(void) {
    double worst = 0.0;
    for (int trial = 0; trial < 200; trial++) {
        const curve c = make_curve(1.0);
        double d[12], plus[12], minus[12];
        for (int k = 0; k < 12; k++) {
            d[k] = uniform();
        }
        const double h = 1e-5;
        for (int k = 0; k < 12; k++) {
            const double x = k < 4 ? c.q[k] : k < 8 ? c.q_dot[k - 4] : c.q_ddot[k - 8];
            plus[k] = x + h * d[k];
            minus[k] = x - h * d[k];
        }
        ak_quaternion_outputs d_out, up, down;
        ak_quaternion_kinematics_tangent(c.q, c.q_dot, c.q_ddot, d, d + 4, d + 8, &d_out);
        ak_quaternion_kinematics(plus, plus + 4, plus + 8, &up);
        ak_quaternion_kinematics(minus, minus + 4, minus + 8, &down);
        const double *t = (const double *)&d_out, *u = (const double *)&up,
                     *w = (const double *)&down;
        for (size_t i = 0; i < sizeof d_out / sizeof(double); i++) {
            const double difference = (u[i] - w[i]) / (2.0 * h);
            const double error = fabs(t[i] - difference) / (1.0 + fabs(difference));
            worst = fmax(worst, error);
            ak_check(error < 1e-6, "trial %d: tangent of output %d: %.17g, differences %.17g",
                     trial, (int)i, t[i], difference);
        }
    }
    printf("tangent: largest difference to central differences %.3g\n", worst);
}

/* ak_attitude_principal_sines: sin and cos of the angles ak_attitude_angles gives (within 1e-15),
 * for all 24 sequences, random attitudes and attitudes next to and at the singularity; false
 * exactly below AK_ATTITUDE_SINGULAR_DISTANCE. */
static double worst_sine_error = 0.0;
static int sines_refused = 0;

static void check_principal_sines(const ak_sequence *seq, const double q[4]) {
    const double zero[4] = {0.0, 0.0, 0.0, 0.0};
    ak_quaternion_outputs out;
    ak_check(ak_quaternion_kinematics(q, zero, zero, &out) == AK_QUATERNION_OK, "%s: R of q",
             seq->name);
    double theta[3], distance, s[3], c[3];
    (void)ak_attitude_angles(seq, out.R, NULL, theta, &distance);
    const bool ok = ak_attitude_principal_sines(seq, out.R, s, c);
    ak_check(ok == (distance >= AK_ATTITUDE_SINGULAR_DISTANCE),
             "%s: sines given exactly above the singular distance", seq->name);
    if (!ok) {
        sines_refused++;
        return;
    }
    for (int k = 0; k < 3; k++) {
        const double error = fmax(fabs(s[k] - sin(theta[k])), fabs(c[k] - cos(theta[k])));
        worst_sine_error = fmax(worst_sine_error, error);
        ak_check(error <= 1e-15, "%s: sin, cos of theta[%d] = %.17g off by %g", seq->name, k,
                 theta[k], error);
    }
}

static void principal_sines(void) {
    for (int i = 0; i < AK_SEQUENCE_COUNT; i++) {
        const ak_sequence *seq = &AK_SEQUENCES[i];
        for (int trial = 0; trial < 2000; trial++) {
            const double q[4] = {uniform(), uniform(), uniform(), uniform()};
            check_principal_sines(seq, q);
            /* theta2 at 10^-1 .. 10^-16 from the singular angle, and at it. */
            const double singular = seq->proper_euler ? 0.0 : 1.5707963267948966;
            const double theta[3] = {3.0 * uniform(), singular + pow(10.0, -1.0 - trial % 16) *
                                                                     (uniform() < 0.0 ? -1.0 : 1.0),
                                     3.0 * uniform()};
            double near[4];
            ak_general_quaternion(seq, theta, near);
            check_principal_sines(seq, near);
        }
    }
    ak_check(sines_refused > 0, "%s: the singular case met", "principal sines");
    printf("principal sines: worst difference to sin, cos of the angles %.3g; %d attitudes "
           "below the singular distance\n", worst_sine_error, sines_refused);
}

int main(void) {
    principal_sines();
    tangent();
    spin();
    chosen_motions();
    sign_and_scale();
    refusals();
    printf("%d checks, %d failed\n", ak_check_count(), ak_check_failures());
    return ak_check_exit_status();
}
