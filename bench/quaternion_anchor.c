/* The fixed anchor of QuaternionKinematics' benchmark (bench/bench_quaternion.c): the formula of
 * docs/quaternion_kinematics.md for the default sequence body123, written out once here in plain
 * C as a user would write it, with the C library's sqrt, atan2, sin and cos, and never changed with
 * the FMU's code (it calls nothing of fmu_src), so that the ratio's denominator does not move.
 *   in:  q, q_dot, q_ddot (4 each, scalar first, q of any nonzero length);
 *   out: omega_fixed, omega_body, alpha_fixed, alpha_body (3 each), R (9, row-major), |q|,
 *        theta, theta_dot, theta_ddot (3 each, body123), singularity_distance = |cos theta2|:
 *        the 32 outputs in the order of their value references (12 to 43).
 * With n2 = |q|^2:
 *   omega_body  = 2 vec(q* q_dot) / n2,  omega_fixed = 2 vec(q_dot q*) / n2,
 *   alpha_body  = 2 vec(q* q_ddot) / n2 - 2 (q . q_dot) / n2 omega_body, alpha_fixed likewise;
 *   R = R(q / |q|); body123 (R = R_x(theta1) R_y(theta2) R_z(theta3)):
 *   theta1 = atan2(-R23, R33), theta2 = atan2(R13, sqrt(R11^2 + R12^2)), theta3 = atan2(-R12, R11);
 *   omega_body = W(theta) theta_dot with W's inverse by hand (c2 = cos theta2, ...):
 *   theta_dot1 = (w1 c3 - w2 s3) / c2,  theta_dot2 = w1 s3 + w2 c3,
 *   theta_dot3 = w3 - s2 theta_dot1,
 *   and its time derivative:
 *   theta_ddot1 = (a1 c3 - a2 s3 - theta_dot2 theta_dot3 + s2 theta_dot1 theta_dot2) / c2,
 *   theta_ddot2 = a1 s3 + a2 c3 + c2 theta_dot1 theta_dot3,
 *   theta_ddot3 = a3 - s2 theta_ddot1 - c2 theta_dot1 theta_dot2. */
#include "quaternion_anchor.h"

#include <math.h>

/* 2 vec(a* b) and 2 vec(b a*) of two quaternions, scalar first. */
static void twice_vec_products(const double a[4], const double b[4], double body[3],
                               double fixed[3]) {
    const double s0 = a[0] * b[1] - b[0] * a[1], s1 = a[0] * b[2] - b[0] * a[2],
                 s2 = a[0] * b[3] - b[0] * a[3];
    const double c0 = a[2] * b[3] - a[3] * b[2], c1 = a[3] * b[1] - a[1] * b[3],
                 c2 = a[1] * b[2] - a[2] * b[1];
    body[0] = 2.0 * (s0 - c0), body[1] = 2.0 * (s1 - c1), body[2] = 2.0 * (s2 - c2);
    fixed[0] = 2.0 * (s0 + c0), fixed[1] = 2.0 * (s1 + c1), fixed[2] = 2.0 * (s2 + c2);
}

void ak_anchor_quaternion(const double in[12], double out[32]) {
    const double *q = &in[0], *qd = &in[4], *qdd = &in[8];
    double *omega_fixed = &out[0], *omega_body = &out[3], *alpha_fixed = &out[6],
           *alpha_body = &out[9], *R = &out[12], *theta = &out[22], *theta_dot = &out[25],
           *theta_ddot = &out[28];
    const double n2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
    const double inverse_n2 = 1.0 / n2;
    const double q_dot_q = q[0] * qd[0] + q[1] * qd[1] + q[2] * qd[2] + q[3] * qd[3];
    const double a2 = 2.0 * q_dot_q * inverse_n2;
    double wb[3], wf[3], ab[3], af[3];
    twice_vec_products(q, qd, wb, wf);
    twice_vec_products(q, qdd, ab, af);
    for (int k = 0; k < 3; k++) {
        omega_body[k] = wb[k] * inverse_n2;
        omega_fixed[k] = wf[k] * inverse_n2;
        alpha_body[k] = ab[k] * inverse_n2 - a2 * omega_body[k];
        alpha_fixed[k] = af[k] * inverse_n2 - a2 * omega_fixed[k];
    }

    const double n = sqrt(n2);
    const double w = q[0] / n, x = q[1] / n, y = q[2] / n, z = q[3] / n;
    R[0] = 1.0 - 2.0 * (y * y + z * z);
    R[1] = 2.0 * (x * y - w * z);
    R[2] = 2.0 * (x * z + w * y);
    R[3] = 2.0 * (x * y + w * z);
    R[4] = 1.0 - 2.0 * (x * x + z * z);
    R[5] = 2.0 * (y * z - w * x);
    R[6] = 2.0 * (x * z - w * y);
    R[7] = 2.0 * (y * z + w * x);
    R[8] = 1.0 - 2.0 * (x * x + y * y);
    out[21] = n;

    theta[0] = atan2(-R[5], R[8]);
    theta[1] = atan2(R[2], sqrt(R[0] * R[0] + R[1] * R[1]));
    theta[2] = atan2(-R[1], R[0]);
    const double s2 = sin(theta[1]), c2 = cos(theta[1]);
    const double s3 = sin(theta[2]), c3 = cos(theta[2]);
    const double *wv = omega_body, *av = alpha_body;
    theta_dot[0] = (wv[0] * c3 - wv[1] * s3) / c2;
    theta_dot[1] = wv[0] * s3 + wv[1] * c3;
    theta_dot[2] = wv[2] - s2 * theta_dot[0];
    theta_ddot[0] = (av[0] * c3 - av[1] * s3 - theta_dot[1] * theta_dot[2] +
                     s2 * theta_dot[0] * theta_dot[1]) / c2;
    theta_ddot[1] = av[0] * s3 + av[1] * c3 + c2 * theta_dot[0] * theta_dot[2];
    theta_ddot[2] = av[2] - s2 * theta_ddot[0] - c2 * theta_dot[0] * theta_dot[1];
    out[31] = fabs(c2);
}
