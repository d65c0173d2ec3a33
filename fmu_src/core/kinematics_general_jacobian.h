/*
 * Exact partial derivatives of every output of the general core (kinematics_general.h) with
 * respect to theta, theta_dot and theta_ddot, for all 24 sequences. Plain C, no FMI types.
 *
 * In chain order (kinematics_general.h, section 1; u_m, v_m the chain axes in fixed and body
 * components, p = phi_dot, a = phi_ddot), each chain axis moves only with the chain angles that
 * precede it (fixed components) or follow it (body components):
 *     d u_m / d phi_j = u_j x u_m   (j < m),      d v_m / d phi_j = v_m x v_j   (j > m),
 * and a cross product of two such axes moves as a rigid pair when both move:
 *     d (u_l x u_m) / d phi_j = u_j x (u_l x u_m)  (j < l),   u_l x (u_j x u_m)  (l <= j < m)
 *     d (v_m x v_l) / d phi_j = (v_m x v_l) x v_j  (j > l),   (v_m x v_j) x v_l  (m < j <= l)
 * With omega_fixed = sum p_m u_m, alpha_fixed = sum a_m u_m + sum_{l<m} p_l p_m (u_l x u_m) and
 * the body counterparts (alpha_body = sum a_m v_m + sum_{m<l} p_m p_l (v_m x v_l)), every entry
 * is a sum of such terms:
 *     d omega_fixed / d phi_j = sum_{m>j} p_m (u_j x u_m)       d omega / d p_k = u_k (v_k)
 *     d alpha_fixed / d p_k = sum_{l<k} p_l (u_l x u_k) + sum_{m>k} p_m (u_k x u_m)
 *     d alpha / d a_k = u_k (v_k)
 *     d R / d phi_j = [u_j]x R,      d q / d phi_j = (1/2) (0, u_j) q   (Hamilton product)
 *     W_fixed column m is u_m; W_fixed_dot column m is sum_{l<m} p_l (u_l x u_m); the same for the
 *     body matrices with v and sum_{l>m} p_l (v_m x v_l).
 * The theta columns are the chain columns permuted (theta_k is chain angle k, or 4 - k for
 * space-fixed sequences). Checked against the 40-digit sympy reference in
 * tests/test_sequences_fmu.py (through the FMU's directional derivatives).
 */
#ifndef ANGULAR_KINEMATICS_KINEMATICS_GENERAL_JACOBIAN_H
#define ANGULAR_KINEMATICS_KINEMATICS_GENERAL_JACOBIAN_H

#include "sequences.h"

/* Outputs in the order omega_fixed[3], omega_body[3], alpha_fixed[3], alpha_body[3],
 * R[3][3] (row-major), q[4], W_fixed, W_body, W_fixed_dot, W_body_dot (each 3x3 row-major);
 * inputs in the order theta[3], theta_dot[3], theta_ddot[3]. */
enum { AK_GENERAL_N_OUTPUTS = 12 + 9 + 4 + 36, AK_GENERAL_N_INPUTS = 9 };

void ak_general_jacobian(const ak_sequence *sequence, const double theta[3],
                         const double theta_dot[3], const double theta_ddot[3],
                         double J[AK_GENERAL_N_OUTPUTS][AK_GENERAL_N_INPUTS]);

#endif
