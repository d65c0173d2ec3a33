/* Attitude on unit quaternions: the equations are stated in attitude.h. */
#include "attitude.h"

#include "elementary.h"

#include <math.h>
#include <stddef.h>

void ak_quat_multiply(const double a[4], const double b[4], double out[4]) {
    out[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
    out[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
    out[2] = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
    out[3] = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
}

void ak_quat_exp(const double v[3], double out[4]) {
    const double angle = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    double sinc; /* sin(angle) / angle */
    double s, c;
    ak_sincos(angle, &s, &c);
    if (angle < 1e-4) {
        const double a2 = angle * angle;
        sinc = 1.0 - a2 / 6.0 * (1.0 - a2 / 20.0);
    } else {
        sinc = s / angle;
    }
    out[0] = c;
    out[1] = sinc * v[0];
    out[2] = sinc * v[1];
    out[3] = sinc * v[2];
}

void ak_quat_to_matrix(const double q[4], double R[3][3]) {
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    R[0][0] = 1.0 - 2.0 * (y * y + z * z);
    R[0][1] = 2.0 * (x * y - w * z);
    R[0][2] = 2.0 * (x * z + w * y);
    R[1][0] = 2.0 * (x * y + w * z);
    R[1][1] = 1.0 - 2.0 * (x * x + z * z);
    R[1][2] = 2.0 * (y * z - w * x);
    R[2][0] = 2.0 * (x * z - w * y);
    R[2][1] = 2.0 * (y * z + w * x);
    R[2][2] = 1.0 - 2.0 * (x * x + y * y);
}

void ak_attitude_input_polynomial(const double w0[3], const double w1[3], const double w2[3],
                                  const double *wp, const double *wdp, double hp,
                                  double c[4][3]) {
    for (int k = 0; k < 3; k++) {
        c[0][k] = w0[k];
        c[1][k] = w1[k];
        c[2][k] = 0.5 * w2[k];
        c[3][k] = 0.0;
        if (wp == NULL) {
            continue;
        }
        const double slope_gap = wdp[k] - w1[k];
        if (w2[k] != 0.0) { /* c2 given: the cubic term matches the slope at -hp */
            c[3][k] = (slope_gap + 2.0 * c[2][k] * hp) / (3.0 * hp * hp);
        } else {
            const double value_gap = wp[k] - w0[k] + w1[k] * hp;
            c[3][k] = (slope_gap + 2.0 * value_gap / hp) / (hp * hp);
            c[2][k] = value_gap / (hp * hp) + c[3][k] * hp;
        }
    }
}

/* Omega from omega at the two Gauss points (section 4). */
static inline void gauss_combination(ak_frame frame, double a[2][3], double h,
                                     double omega_vector[3]) {
    const double cross[3] = {a[0][1] * a[1][2] - a[0][2] * a[1][1],
                             a[0][2] * a[1][0] - a[0][0] * a[1][2],
                             a[0][0] * a[1][1] - a[0][1] * a[1][0]};
    /* +sqrt(3)/24 for q (x) A (body), - for A (x) q (fixed). */
    const double commutator = (frame == AK_FRAME_BODY ? 1.0 : -1.0) * 0.07216878364870322056 * h * h;
    for (int k = 0; k < 3; k++) {
        omega_vector[k] = 0.25 * h * (a[0][k] + a[1][k]) + commutator * cross[k];
    }
}

void ak_attitude_step_vector(ak_frame frame, double c[4][3], double h, double omega_vector[3]) {
    /* Gauss points s = h (1/2 -+ sqrt(3)/6) of the polynomial omega(s) (attitude.h, section 4). */
    const double r = 0.28867513459481288225; /* sqrt(3) / 6 */
    const double s[2] = {h * (0.5 - r), h * (0.5 + r)};
    double a[2][3];
    for (int g = 0; g < 2; g++) {
        for (int k = 0; k < 3; k++) {
            a[g][k] = c[0][k] + s[g] * (c[1][k] + s[g] * (c[2][k] + s[g] * c[3][k]));
        }
    }
    gauss_combination(frame, a, h, omega_vector);
}

void ak_attitude_step_vector_constant(ak_frame frame, const double omega[3], double h,
                                      double omega_vector[3]) {
    /* ak_attitude_step_vector's polynomial at either Gauss point s >= 0 with c1 = c2 = c3 = +0
     * is c0 + s (0 + s (0 + s 0)) = c0 + (+0), bit for bit (x + 0.0 is not x for x = -0). */
    double a[2][3];
    for (int k = 0; k < 3; k++) {
        a[0][k] = a[1][k] = omega[k] + 0.0;
    }
    gauss_combination(frame, a, h, omega_vector);
}

void ak_attitude_retake_step(ak_frame frame, const double old_vector[3],
                             const double new_vector[3], double q[4]) {
    const double back[3] = {-old_vector[0], -old_vector[1], -old_vector[2]};
    double undo[4], redo[4], change[4], next[4];
    ak_quat_exp(back, undo);
    ak_quat_exp(new_vector, redo);
    if (frame == AK_FRAME_BODY) {
        ak_quat_multiply(undo, redo, change);
        ak_quat_multiply(q, change, next);
    } else {
        ak_quat_multiply(redo, undo, change);
        ak_quat_multiply(change, q, next);
    }
    for (int k = 0; k < 4; k++) {
        q[k] = next[k];
    }
}

bool ak_attitude_advance(ak_frame frame, const double v[3], double q[4], double *correction) {
    double e[4], next[4];
    ak_quat_exp(v, e);
    if (frame == AK_FRAME_BODY) {
        ak_quat_multiply(q, e, next);
    } else {
        ak_quat_multiply(e, q, next);
    }
    /* Remove the rounding of the product from the norm (attitude.h, section 4). */
    const double n2 = next[0] * next[0] + next[1] * next[1] + next[2] * next[2] + next[3] * next[3];
    const double factor = 0.5 * (3.0 - n2);
    double moved = 0.0;
    for (int k = 0; k < 4; k++) {
        const double corrected = next[k] * factor;
        if (correction != NULL) { /* its size only when asked: the step itself does not need it */
            moved += (corrected - next[k]) * (corrected - next[k]);
        }
        next[k] = corrected;
    }
    for (int k = 0; k < 4; k++) {
        if (!isfinite(next[k])) {
            return false;
        }
    }
    for (int k = 0; k < 4; k++) {
        q[k] = next[k];
    }
    if (correction != NULL) {
        *correction = sqrt(moved);
    }
    return true;
}

void ak_attitude_angle_rates(const ak_sequence *sequence, ak_frame frame, const double theta[3],
                             bool singular, const double omega[3], double theta_dot[3]) {
    if (!singular) {
        const double zero[3] = {0.0, 0.0, 0.0};
        double theta_ddot[3], alpha_fixed[3], alpha_body[3], distance;
        const ak_rates_status status =
            ak_general_euler_rates(sequence, frame, theta, omega, zero, 0.0, theta_dot,
                                   theta_ddot, alpha_fixed, alpha_body, &distance);
        if (status == AK_RATES_OK || status == AK_RATES_NEAR_SINGULAR) {
            return;
        }
        /* Singular to rounding or overflowing: the singular choice keeps the rates finite. */
    }
    const double rates[3] = {0.0, 0.0, 0.0};
    double W_fixed[3][3], W_body[3][3], Wd_fixed[3][3], Wd_body[3][3];
    ak_general_partials(sequence, theta, rates, W_fixed, W_body, Wd_fixed, Wd_body);
    double (*W)[3] = frame == AK_FRAME_BODY ? W_body : W_fixed;
    double rest[3];
    theta_dot[0] = 0.0;
    theta_dot[1] = W[0][1] * omega[0] + W[1][1] * omega[1] + W[2][1] * omega[2];
    for (int r = 0; r < 3; r++) {
        rest[r] = omega[r] - theta_dot[1] * W[r][1];
    }
    theta_dot[2] = W[0][2] * rest[0] + W[1][2] * rest[1] + W[2][2] * rest[2];
}
