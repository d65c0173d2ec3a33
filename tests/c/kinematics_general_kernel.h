/* The general chain kernels of omega and alpha (kinematics_general.h, sections 2 and 3) and of
 * the inverse map (section 6): the reference of the generated kernels (kinematics_sequences.c,
 * kinematics_rates_sequences.c) for the tests and the benchmark. */
#ifndef ANGULAR_KINEMATICS_KINEMATICS_GENERAL_KERNEL_H
#define ANGULAR_KINEMATICS_KINEMATICS_GENERAL_KERNEL_H

#include "kinematics_general.h"

/* Angular velocity and acceleration of B in both sets of components (section 2, 3). */
void ak_general_angular_kinematics(const ak_sequence *sequence, const double theta[3],
                                   const double theta_dot[3], const double theta_ddot[3],
                                   double omega_fixed[3], double omega_body[3],
                                   double alpha_fixed[3], double alpha_body[3]);

/* The same, from sines = ak_angle_sines(theta): bit for bit the same results. */
void ak_general_angular_kinematics_of_sines(const ak_sequence *sequence, const ak_sines *sines,
                                            const double theta_dot[3], const double theta_ddot[3],
                                            double omega_fixed[3], double omega_body[3],
                                            double alpha_fixed[3], double alpha_body[3]);

/* The same by the general chain formulation for any sequence, which the function above runs
 * only for a sequence outside AK_SEQUENCES: the reference the generated kernels are checked
 * against (tests/c/test_sequence_kernels.c). */
void ak_chain_angular_kinematics_of_sines(const ak_sequence *sequence, const ak_sines *sines,
                                          const double theta_dot[3], const double theta_ddot[3],
                                          double omega_fixed[3], double omega_body[3],
                                          double alpha_fixed[3], double alpha_body[3]);

/* ak_general_euler_rates_of_sines by the general chain formulation: the reference its generated
 * kernels are checked against (tests/c/test_sequence_kernels.c). */
ak_rates_status ak_chain_euler_rates_of_sines(const ak_sequence *sequence, ak_frame frame,
                                              const double theta[3], const ak_sines *sines,
                                              const double omega[3], const double omega_dot[3],
                                              double tolerance, double theta_dot[3],
                                              double theta_ddot[3], double alpha_fixed[3],
                                              double alpha_body[3], double *distance);

#endif
