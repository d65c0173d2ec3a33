/* The inverse map (kinematics_general.h, section 6): the angle rates from omega and omega_dot,
 * for EulerRates, AttitudePropagator and QuaternionKinematics. The checks and statuses are here;
 * the arithmetic between them is the sequence's generated kernel (kinematics_rates_sequences.c),
 * the general chain code (ak_chain_euler_rates, tests/c/kinematics_general_kernel.c) without its
 * structurally zero terms. */
#include "kinematics_general.h"
#include "kinematics_sequences.h"

#include <float.h>
#include <math.h>

/* det of the chain's W = [u1 u2 u3] (header, section 4), in closed form so that it keeps its
 * relative accuracy near zero: -sin(theta2) for proper Euler sequences, +-cos(theta2) for
 * Tait-Bryan ones, + when the chain's second axis follows its first cyclically. det W of the
 * user's theta order is the same for body-fixed sequences and its negative for space-fixed ones
 * (columns 1 and 3 swapped). */
static double determinant(const ak_sequence *sequence, const ak_sines *sines) {
    const int *a = sequence->axes;
    if (a[0] == a[2]) {
        return -sines->sin[1];
    }
    const int first = (sequence->kind == AK_SPACE_FIXED) ? a[2] : a[0];
    return (a[1] == first % 3 + 1) ? sines->cos[1] : -sines->cos[1];
}

ak_rates_status ak_general_euler_rates_of_sines(const ak_sequence *sequence, ak_frame frame,
                                                const double theta[3], const ak_sines *sines,
                                                const double omega[3],
                                                const double omega_dot[3], double tolerance,
                                                double theta_dot[3], double theta_ddot[3],
                                                double alpha_fixed[3], double alpha_body[3],
                                                double *distance) {
    const double det = determinant(sequence, sines);
    *distance = fabs(det);
    const double theta2_size = fabs(theta[1]) > 1.0 ? fabs(theta[1]) : 1.0;
    if (!(*distance > AK_SINGULAR_ROUNDING * DBL_EPSILON * theta2_size)) {
        return AK_RATES_SINGULAR;
    }
    const int body = (frame == AK_FRAME_BODY);
    double td[3], tdd[3], other[3];
    const int *a = sequence->axes;
    AK_SEQUENCE_RATES[sequence->kind][a[0] == a[2]][a[0] - 1][a[1] - 1][body](
        sines, det, omega, omega_dot, td, tdd, other);
    for (int k = 0; k < 3; k++) {
        if (!isfinite(td[k]) || !isfinite(tdd[k]) || !isfinite(other[k])) {
            return AK_RATES_OVERFLOW;
        }
    }
    for (int k = 0; k < 3; k++) {
        theta_dot[k] = td[k];
        theta_ddot[k] = tdd[k];
        alpha_fixed[k] = body ? other[k] : omega_dot[k];
        alpha_body[k] = body ? omega_dot[k] : other[k];
    }
    return (*distance < tolerance) ? AK_RATES_NEAR_SINGULAR : AK_RATES_OK;
}
