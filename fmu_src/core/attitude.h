/*
 * Attitude on unit quaternions: product, exponential map, the geometric propagation step, and
 * the angles of any of the 24 rotation sequences (sequences.h) with continuity across +-pi and
 * through the singular configuration. Plain C, doubles in, doubles out, no FMI types.
 *
 * 1. Quaternions
 *   q = (q0, q1, q2, q3) = (s, v), SCALAR FIRST, Hamilton product
 *       a (x) b = (sa sb - va.vb,  sa vb + sb va + va x vb),
 *   v_fixed = q (x) (0, v_body) (x) q*: the rotation of R (kinematics_general.h, section 5), but
 *   here the sign of q is NOT normalized: q and -q are the same attitude, and a propagated q stays
 *   continuous in time.
 *   R(q) for a unit q (row-major, v_fixed = R v_body):
 *       R = [1-2(q2^2+q3^2)  2(q1q2-q0q3)    2(q1q3+q0q2)
 *            2(q1q2+q0q3)    1-2(q1^2+q3^2)  2(q2q3-q0q1)
 *            2(q1q3-q0q2)    2(q2q3+q0q1)    1-2(q1^2+q2^2)]
 *
 * 2. Kinematics: with omega in body components (B) or fixed components (N)
 *       dq/dt = q (x) (0, omega_body) / 2  =  (0, omega_fixed) (x) q / 2.
 *   Both are linear in q, so |q| is a constant of the exact motion.
 *
 * 3. Exponential map: exp((0, v)) = (cos|v|, sin|v| v/|v|), with the Taylor series of sin|v|/|v|
 *   below |v| = 1e-4 (error < 1e-20 there), unit to rounding.
 *
 * 4. The step (co-simulation): over [t, t + h] omega is a cubic polynomial
 *       omega(t + s) = c0 + c1 s + c2 s^2 + c3 s^3,
 *   built by ak_attitude_input_polynomial from what the master gives at t: omega (w0), its first
 *   derivative (w1, omega_dot) and, if given, its second (w2); and, when the previous step also
 *   had derivatives, from omega and omega_dot at the previous communication point t - hp:
 *     with history:  c0 = w0, c1 = w1, and c2, c3 such that the cubic also takes the value wp and
 *                    the slope wdp at s = -hp (Hermite; with w2 given, c2 = w2 / 2 and only the
 *                    slope is matched): D = wp - w0 + w1 hp, E = wdp - w1,
 *                    c3 = (E + 2 D / hp) / hp^2,  c2 = D / hp^2 + c3 hp;
 *     without:       c0 = w0, c1 = w1, c2 = w2 / 2, c3 = 0 (Taylor).
 *   Why the history: omega and omega_dot at t alone leave an O(h^3) error in the integral of
 *   omega over the step, which makes any method second order in h; the cubic errs by O(h^4), so
 *   the integral by O(h^5) and the method is fourth order. Constant omega gives c1 = c2 = c3 = 0
 *   exactly. Held inputs (no derivatives given) are held: c0 = w0 and nothing else.
 *   The first step with derivatives has no history: taken with the Taylor polynomial, its
 *   O(h^3) error would stay in every later result (third order). So at the next step, when
 *   omega and omega_dot at its end are known, it is retaken: the Hermite cubic over it (the same
 *   formulas with hp = -h) gives Omega_new, and q := q (x) exp(-Omega_old) (x) exp(Omega_new)
 *   (ak_attitude_retake_step). The attitude reported at the end of that first step keeps its
 *   O(h^3) error; every later one is fourth order.
 *   The 4th-order Magnus method with the two Gauss points s_1,2 = h (1/2 -+ sqrt(3)/6),
 *   A_i = (0, omega(s_i)) / 2, is, for the body form dq/dt = q (x) A(t):
 *       q(t + h) = q(t) (x) exp(Omega),  Omega = h (A1 + A2) / 2 + (sqrt(3)/12) h^2 [A1, A2],
 *   and for the fixed form dq/dt = A(t) (x) q:
 *       q(t + h) = exp(Omega) (x) q(t),  Omega = h (A1 + A2) / 2 - (sqrt(3)/12) h^2 [A1, A2].
 *   (The standard Magnus formula is for Y' = A Y; Y' = Y A is its transpose, which flips the sign
 *   of the commutator.) For pure quaternions [a, b] = a b - b a = (0, 2 va x vb), so with
 *   a_i = omega(s_i): Omega = (0, h (a1 + a2)/4 +- (sqrt(3)/24) h^2 a1 x a2).
 *   Constant omega: a1 = a2, the cross product is exactly 0, Omega = h omega / 2 and the step is
 *   the exact solution, to rounding. Smooth omega: local error O(h^5), global order 4
 *   (tests/python/test_attitude_accuracy.py measures it).
 *   Norm: exp(Omega) is unit to rounding and the product of unit quaternions is unit, so the
 *   method itself keeps |q| = 1; only the rounding of each product moves it, by a random walk
 *   of about 1e-16 per step (about 3e-13 after 1e7 steps). ak_attitude_step removes that rounding
 *   part with one first-order correction q := q (3 - |q|^2) / 2, which changes q by at most a few
 *   units of rounding per step (tests/c/test_attitude.c checks this bound), so it cannot hide a
 *   drift of the method.
 *
 * 5., 6. The angles of a sequence from R (sections 1 and 2 of attitude_angles.h).
 *
 * 7. Rates: theta_dot = W^-1 omega through ak_general_euler_rates (kinematics_general.h, section
 *   6), with theta from attitude_angles.h, section 2. At the singular configuration, consistent with
 *   the
 *   choice above, theta1_dot = 0, theta2_dot = c2 . omega and theta3_dot = c3 . (omega -
 *   theta2_dot c2) (c_m the chain axes, in the frame of omega; c1 is +-c3 there).
 */
#ifndef ANGULAR_KINEMATICS_ATTITUDE_H
#define ANGULAR_KINEMATICS_ATTITUDE_H

#include <stdbool.h>

#include "attitude_angles.h"
#include "kinematics_general.h"
#include "sequences.h"

/* out := a (x) b (out may alias neither). */
void ak_quat_multiply(const double a[4], const double b[4], double out[4]);

/* out := exp((0, v)) (section 3). */
void ak_quat_exp(const double v[3], double out[4]);

/* R of a unit q (section 1), row-major. */
void ak_quat_to_matrix(const double q[4], double R[3][3]);

/* The cubic c[m][k] (coefficient of s^m, component k) of omega over a step (section 4): w0, w1,
 * w2 at the step start; wp, wdp (omega and omega_dot at the previous communication point, hp
 * before) or wp == NULL when there is no history. */
void ak_attitude_input_polynomial(const double w0[3], const double w1[3], const double w2[3],
                                  const double *wp, const double *wdp, double hp,
                                  double c[4][3]);

/* The rotation vector Omega of one step (section 4) for omega(s) = sum c[m] s^m, step h. */
void ak_attitude_step_vector(ak_frame frame, double c[4][3], double h, double omega_vector[3]);

/* ak_attitude_step_vector for a constant omega (c = {omega, 0, 0, 0}), bit for bit, cheaper. */
void ak_attitude_step_vector_constant(ak_frame frame, const double omega[3], double h,
                                      double omega_vector[3]);

/* q := q (x) exp(-old) (x) exp(new) (body) or exp(new) (x) exp(-old) (x) q (fixed): a step that
 * was taken with the rotation vector `old` retaken with `new` (section 4, the first step). */
void ak_attitude_retake_step(ak_frame frame, const double old_vector[3],
                             const double new_vector[3], double q[4]);

/* q := q advanced over h (section 4) from the step's rotation vector Omega
 * (ak_attitude_step_vector): q := q (x) exp(Omega) (body) or exp(Omega) (x) q (fixed), and the
 * norm correction. Returns false, q untouched, when the result is not finite (a huge omega h).
 * *correction (may be NULL) receives |q_new - q_uncorrected|, the size of the rounding
 * correction. */
bool ak_attitude_advance(ak_frame frame, const double v[3], double q[4], double *correction);

/* theta_dot for the angles theta of the attitude R and omega in `frame` components (section 7).
 * theta comes from ak_attitude_angles; singular is its result. */
void ak_attitude_angle_rates(const ak_sequence *sequence, ak_frame frame, const double theta[3],
                             bool singular, const double omega[3], double theta_dot[3]);

#endif
