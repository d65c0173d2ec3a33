/* Every output of AngularKinematics from one chain: the benchmark's all-outputs anchor. */
#ifndef ANGULAR_KINEMATICS_BENCH_ALL_OUTPUTS_H
#define ANGULAR_KINEMATICS_BENCH_ALL_OUTPUTS_H

#include "kinematics_general.h"

/* Omega, alpha and every orientation output at once, from one chain: bit for bit what
 * ak_general_angular_kinematics_of_sines and ak_general_rotation_outputs give, for little more
 * than the cost of the first. */
void ak_general_all_outputs(const ak_sequence *sequence, const ak_sines *sines,
                            const ak_sines *half, const double theta_dot[3],
                            const double theta_ddot[3], double omega_fixed[3],
                            double omega_body[3], double alpha_fixed[3], double alpha_body[3],
                            double R[3][3], double q[4], double W_fixed[3][3],
                            double W_body[3][3], double W_fixed_dot[3][3],
                            double W_body_dot[3][3]);

#endif
