/* The inverse map (kinematics_general.h, section 6): the angle rates from omega and omega_dot,
 * for EulerRates and AttitudePropagator. */
#include "kinematics_chain.h"

#include <float.h>
#include <math.h>

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

ak_rates_status ak_general_euler_rates(const ak_sequence *sequence, ak_frame frame,
                                       const double theta[3], const double omega[3],
                                       const double omega_dot[3], double tolerance,
                                       double theta_dot[3], double theta_ddot[3],
                                       double alpha_fixed[3], double alpha_body[3],
                                       double *distance) {
    chain ch;
    ak_chain_of_angles(sequence, theta, &ch);
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
