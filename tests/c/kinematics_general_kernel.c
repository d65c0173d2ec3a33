/* The general chain kernel of omega and alpha (kinematics_general.h, sections 2 and 3), which
 * the generated kernels of kinematics_sequences.c are copies of without their structurally zero
 * terms (codegen/sequence_kernels.py): the tests' and the benchmark's reference; no model calls it
 * (AngularKinematics calls its sequence's generated kernel directly). */
#include "kinematics_general_kernel.h"

#include <stdint.h>

#include "kinematics_chain.h"
#include "kinematics_sequences.h"

/* Omega and alpha (header, sections 2, 3): the general kernel. Each sequence of the table runs
 * its own copy of it without the structurally zero terms, generated from this code
 * (kinematics_sequences.c, codegen/sequence_kernels.py). */
static inline void chain_kinematics(const ak_sequence *sequence, const ak_sines *sines,
                                    const double theta_dot[3], const double theta_ddot[3],
                                    double omega_fixed[3], double omega_body[3],
                                    double alpha_fixed[3], double alpha_body[3]) {
    chain ch;
    chain_rates x;
    chain_of_sines(sequence, sines, &ch);
    chain_rates_of(&ch, theta_dot, theta_ddot, &x);
    combine_kinematics(&x, omega_fixed, omega_body, alpha_fixed, alpha_body);
}

void ak_chain_angular_kinematics_of_sines(const ak_sequence *sequence, const ak_sines *sines,
                                          const double theta_dot[3], const double theta_ddot[3],
                                          double omega_fixed[3], double omega_body[3],
                                          double alpha_fixed[3], double alpha_body[3]) {
    chain_kinematics(sequence, sines, theta_dot, theta_ddot, omega_fixed, omega_body, alpha_fixed,
                     alpha_body);
}

void ak_general_angular_kinematics_of_sines(const ak_sequence *sequence, const ak_sines *sines,
                                            const double theta_dot[3], const double theta_ddot[3],
                                            double omega_fixed[3], double omega_body[3],
                                            double alpha_fixed[3], double alpha_body[3]) {
    /* A sequence of the table through its generated kernel (docs/performance.md); any other
     * (a copy, in the tests) through the general one. */
    const uintptr_t at = (uintptr_t)sequence, first = (uintptr_t)AK_SEQUENCES;
    if (at >= first && at < first + sizeof AK_SEQUENCES) {
        AK_SEQUENCE_KINEMATICS[(at - first) / sizeof AK_SEQUENCES[0]](sines, theta_dot, theta_ddot, omega_fixed, omega_body,
                                      alpha_fixed, alpha_body);
    } else {
        ak_chain_angular_kinematics_of_sines(sequence, sines, theta_dot, theta_ddot, omega_fixed,
                                             omega_body, alpha_fixed, alpha_body);
    }
}

/* The core's one-call form. The FMU calls the _of_sines form (it keeps the sines for the lazy
 * group); the C tests and the benchmark's bare kernel call this one. */
void ak_general_angular_kinematics(const ak_sequence *sequence, const double theta[3],
                                   const double theta_dot[3], const double theta_ddot[3],
                                   double omega_fixed[3], double omega_body[3],
                                   double alpha_fixed[3], double alpha_body[3]) {
    ak_sines sines;
    ak_angle_sines(theta, &sines);
    ak_general_angular_kinematics_of_sines(sequence, &sines, theta_dot, theta_ddot, omega_fixed,
                                           omega_body, alpha_fixed, alpha_body);
}
