/* The general chain kernels of omega and alpha (kinematics_general.h, sections 2 and 3) and of
 * the inverse map (section 6), which the generated kernels of kinematics_sequences.c and
 * kinematics_rates_sequences.c are copies of without their structurally zero terms
 * (codegen/sequence_kernels.py): the tests' and the benchmark's reference; no model calls them
 * (the models call their sequence's generated kernel). */
#include "kinematics_general_kernel.h"

#include <float.h>
#include <math.h>
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

/* det of the chain's W = [u1 u2 u3] (header, section 4), in closed form so that it keeps its
 * relative accuracy near zero. det W of the user's theta order is the same for body-fixed
 * sequences and its negative for space-fixed ones (columns 1 and 3 swapped). */
static double chain_determinant(const chain *ch) {
    if (ch->axis[0] == ch->axis[2]) {
        return -ch->s[1];
    }
    return (ch->axis[1] == NEXT[ch->axis[0]]) ? ch->c[1] : -ch->c[1];
}

static double dot(const double a[3], const double b[3]) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* The inverse map (header, section 6) by the general chain code: what the core ran before its
 * kernels were generated from it (kinematics_rates_sequences.c), kept as their reference. */
ak_rates_status ak_chain_euler_rates_of_sines(const ak_sequence *sequence, ak_frame frame,
                                              const double theta[3], const ak_sines *sines,
                                              const double omega[3], const double omega_dot[3],
                                              double tolerance, double theta_dot[3],
                                              double theta_ddot[3], double alpha_fixed[3],
                                              double alpha_body[3], double *distance) {
    chain ch;
    chain_of_sines(sequence, sines, &ch);
    const double det = chain_determinant(&ch);
    *distance = fabs(det);
    const double theta2_size = fabs(theta[1]) > 1.0 ? fabs(theta[1]) : 1.0;
    if (!(*distance > AK_SINGULAR_ROUNDING * DBL_EPSILON * theta2_size)) {
        return AK_RATES_SINGULAR;
    }

    /* Rows of W^-1 in chain order: (c2 x c3) / det, c3 x c1 / det, (c1 x c2) / det. The middle
     * row is c2 itself: c2 is a unit vector orthogonal to c1 and c3 (R_a2 keeps the a2 component
     * of e_a3, which is zero), so it needs no division. The cross products are the exact-structure
     * ones of chain_cross_products. */
    const int body = (frame == AK_FRAME_BODY);
    double u[3][3], v[3][3], du[3][3], dv[3][3], rows[3][3], R[3][3];
    cross_products x;
    chain_axes(&ch, u, v);
    chain_cross_products(&ch, &x);
    for (int r = 0; r < 3; r++) {
        rows[0][r] = (body ? x.v23[r] : x.u23[r]) / det;
        rows[1][r] = body ? v[1][r] : u[1][r];
        rows[2][r] = (body ? x.v12[r] : x.u12[r]) / det;
    }

    double pd[3], pdd[3], rhs[3];
    for (int m = 0; m < 3; m++) {
        pd[m] = dot(rows[m], omega);
    }
    axis_rates_of(&x, pd, du, dv); /* the cross products above: not computed twice */
    for (int r = 0; r < 3; r++) {
        double (*rate)[3] = body ? dv : du;
        rhs[r] = omega_dot[r] - (pd[0] * rate[0][r] + pd[1] * rate[1][r] + pd[2] * rate[2][r]);
    }
    for (int m = 0; m < 3; m++) {
        pdd[m] = dot(rows[m], rhs);
    }

    chain_rotation_matrix(&ch, R); /* the chain's sines: no second sin and cos of theta */
    double other[3];
    for (int r = 0; r < 3; r++) {
        other[r] = body ? R[r][0] * omega_dot[0] + R[r][1] * omega_dot[1] + R[r][2] * omega_dot[2]
                        : R[0][r] * omega_dot[0] + R[1][r] * omega_dot[1] + R[2][r] * omega_dot[2];
    }
    for (int m = 0; m < 3; m++) {
        if (!isfinite(pd[m]) || !isfinite(pdd[m]) || !isfinite(other[m])) {
            return AK_RATES_OVERFLOW;
        }
    }
    for (int m = 0; m < 3; m++) {
        theta_dot[ch.angle[m]] = pd[m];
        theta_ddot[ch.angle[m]] = pdd[m];
        alpha_fixed[m] = body ? other[m] : omega_dot[m];
        alpha_body[m] = body ? omega_dot[m] : other[m];
    }
    return (*distance < tolerance) ? AK_RATES_NEAR_SINGULAR : AK_RATES_OK;
}
