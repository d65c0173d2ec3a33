/*
 * Angular kinematics core of AngularKinematics: plain C, doubles in, doubles out, no FMI types.
 *
 * Sequence
 *   Body B is oriented in the fixed frame N by a body-fixed (intrinsic) 1-2-3 sequence:
 *   theta1 about n1, then theta2 about the once-rotated axis a2, then theta3 about the
 *   twice-rotated axis b3. With Ri(x) the right-handed rotation about axis i by x,
 *       R = R1(theta1) R2(theta2) R3(theta3)
 *   maps body components to fixed components: v_fixed = R v_body.
 *
 * Frames
 *   "fixed" components are along n1, n2, n3; "body" components are along b1, b2, b3.
 *   The vectors are the same, only their components differ: omega_body = R^T omega_fixed,
 *   alpha_body = R^T alpha_fixed.
 *
 * Equations (Si = sin(theta_i), Ci = cos(theta_i), td = theta_dot, tdd = theta_ddot)
 *   omega = td1 n1 + td2 a2 + td3 b3, so omega_fixed = W td and omega_body = W' td with
 *       W  = [ 1   0    S2    ]        W' = [  C2 C3  S3  0 ]
 *            [ 0   C1  -S1 C2 ]             [ -C2 S3  C3  0 ]
 *            [ 0   S1   C1 C2 ]             [  S2     0   1 ]
 *   The angular acceleration is the time derivative of omega in N; its fixed components are
 *   the derivatives of omega_fixed and, because omega x omega = 0, its body components are
 *   the derivatives of omega_body:
 *       alpha_fixed = W tdd + dW/dt td,   alpha_body = W' tdd + dW'/dt td
 *   with
 *       dW/dt  = [ 0   0         C2 td2                 ]
 *                [ 0  -S1 td1    S1 S2 td2 - C1 C2 td1  ]
 *                [ 0   C1 td1  -(S1 C2 td1 + C1 S2 td2) ]
 *       dW'/dt = [ -(S2 C3 td2 + C2 S3 td3)   C3 td3  0 ]
 *                [   S2 S3 td2 - C2 C3 td3   -S3 td3  0 ]
 *                [   C2 td2                   0       0 ]
 *   (The course note's body-frame equation (4) multiplies W' by td instead of tdd: a typo.)
 *
 * Derivatives
 *   The exact Jacobian of these outputs and the angular jerk d(alpha)/dt, for this and every other
 *   sequence, are those of the general core (kinematics_general_jacobian.h); for body123 its
 *   Jacobian is checked against finite differences of this function (test_kinematics_jacobian.c).
 *
 * Units
 *   theta in rad, theta_dot and omega in rad/s, theta_ddot and alpha in rad/s^2.
 *
 * The map is purely algebraic, defined for every finite input (W is singular at
 * theta2 = +-pi/2, but only the inverse map, not this one, suffers from that).
 */
#ifndef ANGULAR_KINEMATICS_KINEMATICS_H
#define ANGULAR_KINEMATICS_KINEMATICS_H

/* Angular velocity and acceleration of B in both sets of components. */
void ak_angular_kinematics_123(const double theta[3], const double theta_dot[3],
                               const double theta_ddot[3], double omega_fixed[3],
                               double omega_body[3], double alpha_fixed[3], double alpha_body[3]);

/* Direction cosine matrix R (row-major), mapping body components to fixed components. */
void ak_rotation_matrix_123(const double theta[3], double R[3][3]);

#endif
