/*
 * General angular kinematics for the 24 rotation sequences of sequences.h, from one formulation.
 * Plain C, doubles in, doubles out, no FMI types. Units: rad, rad/s, rad/s^2.
 *
 * 1. Every sequence as a chain of three body-fixed rotations
 *   A body-fixed sequence I-J-K is the chain: axes (a1, a2, a3) = (I, J, K), chain angles
 *   (phi1, phi2, phi3) = (theta1, theta2, theta3). A space-fixed sequence I-J-K has
 *   R = R_K(theta3) R_J(theta2) R_I(theta1), which is the body-fixed product for the REVERSED axes
 *   and angles: chain axes (K, J, I), chain angles (theta3, theta2, theta1). So in both cases
 *       R = R_a1(phi1) R_a2(phi2) R_a3(phi3),
 *   and theta_k is the chain angle phi_k (body-fixed) or phi_(4-k) (space-fixed). The middle angle
 *   is theta2 in both cases.
 *
 * 2. Angular velocity: one sum over the chain
 *   Frames F0 = N, F1, F2, F3 = B; F_m is F_(m-1) turned by phi_m about its own axis a_m. The unit
 *   vector of that axis, u_m, is fixed in F_(m-1) and in F_m, and
 *       omega (of B in N) = phi1' u1 + phi2' u2 + phi3' u3.
 *   Fixed components:  u1 = e_a1,  u2 = R_a1 e_a2,  u3 = R_a1 R_a2 e_a3   (e_i: unit column i)
 *   Body components:   v3 = e_a3,  v2 = R_a3^T e_a2,  v1 = R_a3^T R_a2^T e_a1   (v_m = R^T u_m)
 *   The partial angular velocity matrices have as column k the axis of theta_k:
 *       omega_fixed = W_fixed theta_dot,  omega_body = W_body theta_dot,  W_body = R^T W_fixed.
 *
 * 3. Angular acceleration: the derivative of each axis is a cross product
 *   u_m is fixed in F_(m-1), whose angular velocity in N is Omega_(m-1) = sum_{l<m} phi_l' u_l, so
 *       d(u_m)/dt in N = Omega_(m-1) x u_m = sum_{l<m} phi_l' (u_l x u_m)    -> W_fixed_dot
 *   and, seen from B (whose angular velocity relative to F_(m-1) is sum_{l>=m} phi_l' u_l),
 *       d(v_m)/dt = v_m x (sum_{l>m} phi_l' v_l) = sum_{l>m} phi_l' (v_m x v_l) -> W_body_dot
 *   The fixed components of alpha are the derivatives of omega_fixed; because omega x omega = 0
 *   the body components of alpha are the derivatives of omega_body. Hence
 *       alpha_fixed = W_fixed theta_ddot + W_fixed_dot theta_dot
 *       alpha_body  = W_body  theta_ddot + W_body_dot  theta_dot.
 *   W_fixed_dot and W_body_dot are the time derivatives of the component matrices W_fixed, W_body.
 *   Each cross product is formed in the intermediate frame where one factor is a unit axis,
 *       u_l x u_m = P_l (e_al x (R_a(l+1) .. R_a(m-1) e_am)),      P_l = R_a1 .. R_al
 *       v_m x v_l = Q_l^T ((R_a(m+1) .. R_a(l-1))^T e_am x e_al),   Q_l = R_al .. R_a3
 *   and rotated out: no sin^2 + cos^2 has to cancel in rounding, so every output is computed from
 *   exactly the inputs its equation contains (what <ModelStructure> lists), and from no other.
 *
 * 4. Singular configuration
 *   det W_fixed = det W_body = eps(I,J,K) cos(theta2) for Tait-Bryan (eps = +1 for the cyclic
 *   orders 123, 231, 312, -1 otherwise; the same for body- and space-fixed), and -sin(theta2)
 *   (body-fixed) or +sin(theta2) (space-fixed) for proper Euler. The singularity distance is
 *       singularity_distance = |det W| = |cos theta2| (Tait-Bryan) or |sin theta2| (proper Euler),
 *   in [0, 1]: the sine of the angle between theta2 and the nearest singular value
 *   (+-pi/2 for Tait-Bryan, 0 or pi for proper Euler). The forward map is defined everywhere;
 *   only the inverse map (section 6) suffers from it.
 *
 * 5. Quaternion
 *   q = (q0, q1, q2, q3), SCALAR FIRST, Hamilton product, v_fixed = q v_body q* (the same rotation
 *   as R). Computed from half angles: q = q_a1(phi1) q_a2(phi2) q_a3(phi3), q_a(x) =
 *   (cos x/2, sin x/2 e_a). Sign: q and -q are the same rotation; the one returned has q0 >= 0,
 *   and when q0 == 0 the first non-zero of q1, q2, q3 is positive. So q is a function of the
 *   orientation alone (theta and theta + 2 pi give the same q); it jumps to -q where the rotation
 *   angle passes pi.
 *
 * 6. Inverse map (the kinematic differential equations, model EulerRates)
 *   Given theta and omega in the components of one frame (fixed or body) and omega_dot, the time
 *   derivative of those components (which is alpha in the same components, in either frame):
 *       theta_dot  = W^-1 omega
 *       theta_ddot = W^-1 (omega_dot - W_dot theta_dot)
 *   with W, W_dot of that frame. In chain order W^-1 has the rows (c2 x c3) / det, c2, and
 *   (c1 x c2) / det (c_m: the chain axes u_m or v_m; det of section 4 in closed form). The middle
 *   row is c2 itself because c2 is a unit vector orthogonal to c1 and c3, so the middle rate
 *   never divides by det: only theta1_dot and theta3_dot blow up at the singularity.
 *   Status: AK_RATES_OK; AK_RATES_NEAR_SINGULAR when singularity_distance < tolerance (results
 *   computed, the caller should warn); AK_RATES_SINGULAR when singularity_distance <=
 *   AK_SINGULAR_ROUNDING * max(1, |theta2|), i.e. theta2 is a singular angle to the rounding of
 *   the input (a double theta2 near pi/2 is only known to about DBL_EPSILON |theta2|); AK_RATES_
 *   OVERFLOW when a result is not finite. On AK_RATES_SINGULAR and AK_RATES_OVERFLOW nothing but
 *   the distance is written. (A NaN theta2 also gives AK_RATES_SINGULAR; validating inputs is
 *   the caller's job.)
 *   Where the rates come from: the checks and statuses are kinematics_euler_rates.c's; between
 *   them each sequence and frame runs its own straight-line kernel (kinematics_rates_sequences.c,
 *   generated by codegen/sequence_kernels.py from the general chain code, which the tests keep as
 *   ak_chain_euler_rates_of_sines in tests/c/kinematics_general_kernel.c): the same operations
 *   without the structurally zero terms, so the same bits but the sign of an exact zero. The
 *   kernels take the sines of theta: ak_general_euler_rates computes them (EulerRates,
 *   AttitudePropagator); QuaternionKinematics passes those of its angle extraction
 *   (ak_attitude_principal_sines, attitude_angles.h) to ak_general_euler_rates_of_sines.
 *
 * 7. Rotation angle
 *   The angle of the one rotation about a fixed axis that takes N to B (Euler's theorem), from
 *   q = (q0, v) of section 5 (q0 >= 0, |q| = 1):
 *       angle = 2 atan2(|v|, q0)   in [0, pi],
 *   continuous everywhere, where q jumps to -q too (q0 = 0: angle = pi either way). Along a change
 *   dq of q, with s = |v| and ds = (v . dv) / s,
 *       d angle = 2 (q0 ds - s dq0) / (q0^2 + s^2),
 *   which has no limit at s = 0 (angle = 0 is a kink, like |x| at 0): 0 is returned there.
 */
#ifndef ANGULAR_KINEMATICS_KINEMATICS_GENERAL_H
#define ANGULAR_KINEMATICS_KINEMATICS_GENERAL_H

#include "sequences.h"

typedef enum { AK_FRAME_FIXED = 0, AK_FRAME_BODY = 1 } ak_frame;

typedef enum {
    AK_RATES_OK = 0,
    AK_RATES_NEAR_SINGULAR = 1,
    AK_RATES_SINGULAR = 2,
    AK_RATES_OVERFLOW = 3
} ak_rates_status;

/* Multiple of DBL_EPSILON * max(1, |theta2|) below which the distance counts as zero. */
#define AK_SINGULAR_ROUNDING 4.0

/* sin and cos of three angles, indexed like theta. */
typedef struct {
    double sin[3];
    double cos[3];
} ak_sines;

/* The only transcendental functions of the forward map: sin and cos of theta_k (section 1).
 * Computed once, they serve every output below. */
void ak_angle_sines(const double theta[3], ak_sines *sines);
/* sin and cos of the half angles (section 5) from sines = ak_angle_sines(theta), by a square root
 * and a division each: of the half angle in [-pi/2, pi/2] (cos >= 0), which is theta_k / 2 or
 * theta_k / 2 + pi, so q changes at most its sign, which section 5 fixes anyway. */
void ak_half_angle_sines(const ak_sines *sines, ak_sines *half);

/* Omega and alpha (sections 2, 3): each sequence's generated kernel, kinematics_sequences.h; the
 * general chain kernel they are copies of is the tests' (tests/c/kinematics_general_kernel.h). */

/* Every orientation output at once, as the functions below give them one by one. */
typedef struct {
    double R[3][3];
    double q[4];
    double W_fixed[3][3], W_body[3][3], W_fixed_dot[3][3], W_body_dot[3][3];
} ak_rotation_outputs;

/* From sines = ak_angle_sines(theta) and half = ak_half_angle_sines(theta), with no further
 * sin or cos; bit for bit what the three functions below return for theta. */
void ak_general_rotation_outputs(const ak_sequence *sequence, const ak_sines *sines,
                                 const ak_sines *half, const double theta_dot[3],
                                 ak_rotation_outputs *out);

/* The rotation angle of q (section 7), and its change along dq (the tangent: what the
 * derivatives of an output computed from q need, models/model_derived.c). */
void ak_rotation_angle(const double q[4], double *angle);
void ak_rotation_angle_tangent(const double q[4], const double dq[4], double *d_angle);

/* Direction cosine matrix R (row-major, v_fixed = R v_body). */
void ak_general_rotation_matrix(const ak_sequence *sequence, const double theta[3], double R[3][3]);

/* Unit quaternion, scalar first, q0 >= 0 (section 5). */
void ak_general_quaternion(const ak_sequence *sequence, const double theta[3], double q[4]);

/* Partial angular velocity matrices (row-major, column k belongs to theta_k) and their time
 * derivatives (section 2, 3). */
void ak_general_partials(const ak_sequence *sequence, const double theta[3],
                         const double theta_dot[3], double W_fixed[3][3], double W_body[3][3],
                         double W_fixed_dot[3][3], double W_body_dot[3][3]);

/* Inverse map (section 6) from sines of theta: ak_angle_sines(theta) (ak_general_euler_rates
 * below), or other sines of the same angles (QuaternionKinematics: those of its angle
 * extraction); theta[1] sizes the singularity's rounding. omega and omega_dot are in the
 * components of `frame`. On AK_RATES_OK and AK_RATES_NEAR_SINGULAR writes theta_dot, theta_ddot,
 * and alpha in both sets of components (the input itself in its own frame, rotated by R in the
 * other). *distance is always written. The sequence's generated kernel
 * (kinematics_rates_sequences.c) between the checks of kinematics_euler_rates.c. */
ak_rates_status ak_general_euler_rates_of_sines(const ak_sequence *sequence, ak_frame frame,
                                                const double theta[3], const ak_sines *sines,
                                                const double omega[3],
                                                const double omega_dot[3], double tolerance,
                                                double theta_dot[3], double theta_ddot[3],
                                                double alpha_fixed[3], double alpha_body[3],
                                                double *distance);

/* The same from theta (EulerRates, AttitudePropagator). Inline: a model that passes its own
 * sines ships no copy of it. */
static inline ak_rates_status ak_general_euler_rates(const ak_sequence *sequence, ak_frame frame,
                                                     const double theta[3], const double omega[3],
                                                     const double omega_dot[3], double tolerance,
                                                     double theta_dot[3], double theta_ddot[3],
                                                     double alpha_fixed[3], double alpha_body[3],
                                                     double *distance) {
    ak_sines sines;
    ak_angle_sines(theta, &sines);
    return ak_general_euler_rates_of_sines(sequence, frame, theta, &sines, omega, omega_dot,
                                           tolerance, theta_dot, theta_ddot, alpha_fixed,
                                           alpha_body, distance);
}

#endif
