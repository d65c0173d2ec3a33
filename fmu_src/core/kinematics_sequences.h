/* Omega and alpha of each of the 24 rotation sequences as its own straight-line kernel,
 * generated from the sequence's axes (kinematics_sequences.c, by codegen/sequence_kernels.py):
 * the general chain formulation of kinematics_general.h without its structurally zero terms. */
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

#endif
