/* Omega and alpha of each of the 24 rotation sequences as its own straight-line kernel
 * (kinematics_sequences.c), and the inverse map of each (kinematics_rates_sequences.c), generated
 * from the sequence's axes by codegen/sequence_kernels.py: the general chain formulation of
 * kinematics_general.h without its structurally zero terms. */
#ifndef ANGULAR_KINEMATICS_KINEMATICS_SEQUENCES_H
#define ANGULAR_KINEMATICS_KINEMATICS_SEQUENCES_H

#include "kinematics_general.h"

/* ak_general_angular_kinematics_of_sines for one sequence. */
typedef void ak_sequence_kinematics(const ak_sines *sines, const double theta_dot[3],
                                    const double theta_ddot[3], double omega_fixed[3],
                                    double omega_body[3], double alpha_fixed[3],
                                    double alpha_body[3]);

/* Indexed like AK_SEQUENCES. */
extern ak_sequence_kinematics *const AK_SEQUENCE_KINEMATICS[AK_SEQUENCE_COUNT];

/* The inverse map of one sequence and frame between its checks (kinematics_rates_sequences.c):
 * theta_dot, theta_ddot from sines of theta, det of W (section 4, never 0), omega and
 * omega_dot in the frame's components; other = omega_dot rotated into the other frame. */
typedef void ak_sequence_rates(const ak_sines *sines, double det, const double omega[3],
                               const double omega_dot[3], double theta_dot[3],
                               double theta_ddot[3], double other[3]);

/* [kind][proper Euler][first axis - 1][second axis - 1][frame]: a sequence's facts, no order;
 * NULL where there is no sequence. */
extern ak_sequence_rates *const AK_SEQUENCE_RATES[2][2][3][3][2];

#endif
