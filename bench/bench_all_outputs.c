/* Every output of AngularKinematics from one chain, the benchmark's all-outputs anchor
 * (bench_sequences_fmu.c): what the FMU's kernels and lazy outputs give apart, at once. */
#include "bench_all_outputs.h"

#include "kinematics_chain.h"

/* Every output from one chain: the general kernel (tests/c/kinematics_general_kernel.c) and
 * chain_rotation_outputs (kinematics_rotation.c) together, the axes and their rates computed once. */
static inline void chain_all_outputs(const ak_sequence *sequence, const ak_sines *sines,
                                     const ak_sines *half, const double theta_dot[3],
                                     const double theta_ddot[3], double omega_fixed[3],
                                     double omega_body[3], double alpha_fixed[3],
                                     double alpha_body[3], double R[3][3], double q[4],
                                     double W_fixed[3][3], double W_body[3][3],
                                     double W_fixed_dot[3][3], double W_body_dot[3][3]) {
    chain ch;
    chain_rates x;
    chain_of_sines(sequence, sines, &ch);
    chain_rates_of(&ch, theta_dot, theta_ddot, &x);
    combine_kinematics(&x, omega_fixed, omega_body, alpha_fixed, alpha_body);
    store_partials(&ch, &x, W_fixed, W_body, W_fixed_dot, W_body_dot);
    chain_rotation_matrix(&ch, R);
    chain_quaternion(&ch, half, q);
}

#if defined(__GNUC__)
__attribute__((flatten))
#endif
static void body123_all_outputs(const ak_sines *sines, const ak_sines *half,
                                const double theta_dot[3], const double theta_ddot[3],
                                double omega_fixed[3], double omega_body[3],
                                double alpha_fixed[3], double alpha_body[3], double R[3][3],
                                double q[4], double W_fixed[3][3], double W_body[3][3],
                                double W_fixed_dot[3][3], double W_body_dot[3][3]) {
    chain_all_outputs(&AK_SEQUENCES[AK_SEQUENCE_DEFAULT], sines, half, theta_dot, theta_ddot,
                      omega_fixed, omega_body, alpha_fixed, alpha_body, R, q, W_fixed, W_body,
                      W_fixed_dot, W_body_dot);
}

void ak_general_all_outputs(const ak_sequence *sequence, const ak_sines *sines,
                            const ak_sines *half, const double theta_dot[3],
                            const double theta_ddot[3], double omega_fixed[3],
                            double omega_body[3], double alpha_fixed[3], double alpha_body[3],
                            double R[3][3], double q[4], double W_fixed[3][3],
                            double W_body[3][3], double W_fixed_dot[3][3],
                            double W_body_dot[3][3]) {
    if (sequence == &AK_SEQUENCES[AK_SEQUENCE_DEFAULT]) {
        body123_all_outputs(sines, half, theta_dot, theta_ddot, omega_fixed, omega_body,
                            alpha_fixed, alpha_body, R, q, W_fixed, W_body, W_fixed_dot,
                            W_body_dot);
    } else {
        chain_all_outputs(sequence, sines, half, theta_dot, theta_ddot, omega_fixed, omega_body,
                          alpha_fixed, alpha_body, R, q, W_fixed, W_body, W_fixed_dot,
                          W_body_dot);
    }
}
