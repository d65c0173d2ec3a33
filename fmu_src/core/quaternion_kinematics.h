/* Angular velocity and acceleration of a body whose attitude is given as a quaternion q(t) with
 * its first and second time derivatives (Euler parameters as absolute coordinates).
 *
 * Conventions (attitude.h, section 1): q = (q0, q1, q2, q3) = (s, v), scalar first, Hamilton
 * product a (x) b = (sa sb - va.vb, sa vb + sb va + va x vb), v_fixed = q (x) (0, v_body) (x) q*.
 * q need not have unit length (an integrator's q drifts): the attitude is u = q / |q|, and the
 * outputs are those of u(t) along the curve whose derivatives are q_dot and q_ddot. q and -q (with
 * their derivatives) give the same outputs; so do q and any positive multiple.
 *
 * Derivation. For a unit u, u* u = 1, so u* u' + u'* u = 0: u* u' is a pure quaternion, and
 * u' = u (x) (0, omega_body) / 2 = (0, omega_fixed) (x) u / 2 (attitude.h, section 2) gives
 *     omega_body = 2 vec(u* u'),  omega_fixed = 2 vec(u' u*).
 * Once more, d/dt (u* u') = u'* u' + u* u'', and u'* u' = |u'|^2 is real, so
 *     alpha_body = 2 vec(u* u''),  alpha_fixed = 2 vec(u'' u*)
 * (alpha, the derivative of omega, is the same vector in both frames since omega x omega = 0).
 * With n = |q|, u = q / n, p = q_dot / n, r = q_ddot / n and a = u . p (= n' / n):
 *     u'  = p - a u,
 *     u'' = r - 2 a p - (p . p + u . r - 3 a^2) u.
 * The terms along u drop out of vec(u* .) and vec(. u*) (u* u = u u* = 1 is real), so
 *     omega_body  = 2 vec(u* p),                   omega_fixed = 2 vec(p u*),
 *     alpha_body  = 2 vec(u* r) - 2 a omega_body,  alpha_fixed = 2 vec(r u*) - 2 a omega_fixed.
 * With b = u0 x_v - x0 u_v and c = u_v x x_v for x = p (or r),
 *     vec(u* x) = b - c,  vec(x u*) = b + c.
 * R is the direction cosine matrix of u in the form that holds for any length,
 *     R = [w^2+x^2-y^2-z^2  2(xy-wz)         2(xz+wy)
 *          2(xy+wz)         w^2-x^2+y^2-z^2  2(yz-wx)
 *          2(xz-wy)         2(yz+wx)         w^2-x^2-y^2+z^2] / (w^2+x^2+y^2+z^2),  u = (w, x, y, z),
 * so that the rounding of u's length (a few units of roundoff) does not enter R as it would
 * through 1 - 2 (y^2 + z^2); and q_norm = n.
 *
 * Norm. n = m sqrt(sum (q_k / m)^2) with m the largest |q_k|: no square of a component overflows
 * or underflows. q = 0 has no attitude, and below the smallest normal double (m < DBL_MIN) 1 / n
 * would overflow: both are refused (AK_QUATERNION_NOT_ATTITUDE).
 *
 * Accuracy. u, p and r are q, q_dot, q_ddot times one rounded 1 / n: each within about 2 units of
 * roundoff. Each component of vec(u* x) is a sum of four products of size at most |u||x|, so
 * omega is within a few units of roundoff of 2 |q_dot| / |q|, and alpha of 2 |q_ddot| / |q| +
 * 4 |q_dot|^2 / |q|^2 (a = u . p may cancel: its error is of the size of |p|, not of a); R within
 * a few units of roundoff of 1. */
#ifndef AK_QUATERNION_KINEMATICS_H
#define AK_QUATERNION_KINEMATICS_H

/* The outputs, in the order of the model's value references. */
typedef struct {
    double omega_fixed[3], omega_body[3];
    double alpha_fixed[3], alpha_body[3];
    double R[3][3]; /* row-major, v_fixed = R v_body */
    double q_norm;
} ak_quaternion_outputs;

typedef enum {
    AK_QUATERNION_OK = 0,
    AK_QUATERNION_NOT_ATTITUDE = 1, /* |q| is 0, or below the smallest normal double */
    AK_QUATERNION_OVERFLOW = 2      /* an output is not finite (|q|, or q_dot / |q| overflows) */
} ak_quaternion_status;

/* The outputs for q and its derivatives (finite). On AK_QUATERNION_NOT_ATTITUDE nothing is
 * written; on AK_QUATERNION_OVERFLOW everything is, an overflowed output not finite (or |q| above
 * the largest double, which leaves the other outputs meaningless). */
ak_quaternion_status ak_quaternion_kinematics(const double q[4], const double q_dot[4],
                                              const double q_ddot[4], ak_quaternion_outputs *out);

/* The change of the outputs along a change (dq, dq_dot, dq_ddot) of the inputs (forward mode):
 * with dn = u . dq, du = (dq - u dn) / n, dp = (dq_dot - p dn) / n, dr = (dq_ddot - r dn) / n,
 *     d omega_body = 2 vec(du* p + u* dp),   d omega_fixed = 2 vec(dp u* + p du*),
 *     d alpha_body = 2 vec(du* r + u* dr) - d(2a) omega_body - 2a d omega_body   (fixed alike),
 *     dR = the derivative of R(u) along du,  d|q| = dn.
 * For the inputs of an AK_QUATERNION_OK evaluation. */
void ak_quaternion_kinematics_tangent(const double q[4], const double q_dot[4],
                                      const double q_ddot[4], const double dq[4],
                                      const double dq_dot[4], const double dq_ddot[4],
                                      ak_quaternion_outputs *d_out);

#endif
