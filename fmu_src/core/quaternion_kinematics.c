/* Quaternion kinematics: the equations are stated in quaternion_kinematics.h. */
#include "quaternion_kinematics.h"

#include <float.h>
#include <math.h>

#include "attitude_angles.h"

/* Inlined into its two calls (the compiler would rather call one copy): the products stay in
 * registers. */
#if defined(__GNUC__)
#define AK_QUATERNION_INLINE __attribute__((always_inline)) inline
#else
#define AK_QUATERNION_INLINE inline
#endif

/* vec(u* x) = b - c and vec(x u*) = b + c, with b = u0 x_v - x0 u_v and c = u_v x x_v; times 2. */
static AK_QUATERNION_INLINE void twice_products(const double u[4], const double x[4],
                                                double body[3], double fixed[3]) {
    const double b[3] = {u[0] * x[1] - x[0] * u[1], u[0] * x[2] - x[0] * u[2],
                         u[0] * x[3] - x[0] * u[3]};
    const double c[3] = {u[2] * x[3] - u[3] * x[2], u[3] * x[1] - u[1] * x[3],
                         u[1] * x[2] - u[2] * x[1]};
    for (int k = 0; k < 3; k++) {
        body[k] = 2.0 * (b[k] - c[k]);
        fixed[k] = 2.0 * (b[k] + c[k]);
    }
}

ak_quaternion_status ak_quaternion_kinematics(const double q[4], const double q_dot[4],
                                              const double q_ddot[4], ak_quaternion_outputs *out) {
    /* fmax's value without its call: largest is never NaN, and a NaN |q_k| is skipped by both. */
    double largest = 0.0;
    for (int k = 0; k < 4; k++) {
        const double size = fabs(q[k]);
        largest = size > largest ? size : largest;
    }
    if (!(largest >= DBL_MIN)) {
        return AK_QUATERNION_NOT_ATTITUDE;
    }
    const double scale = 1.0 / largest; /* finite from DBL_MIN on */
    double sum = 0.0;
    for (int k = 0; k < 4; k++) {
        const double x = q[k] * scale;
        sum += x * x;
    }
    const double n = largest * sqrt(sum);
    out->q_norm = n; /* above the largest double for some q near it: then u = 0, refused below */
    const double inverse = 1.0 / n;
    double u[4], p[4], r[4];
    for (int k = 0; k < 4; k++) {
        u[k] = q[k] * inverse;
        p[k] = q_dot[k] * inverse;
        r[k] = q_ddot[k] * inverse;
    }
    const double a2 = 2.0 * (u[0] * p[0] + u[1] * p[1] + u[2] * p[2] + u[3] * p[3]);
    double r_body[3], r_fixed[3];
    twice_products(u, p, out->omega_body, out->omega_fixed);
    twice_products(u, r, r_body, r_fixed);
    /* x - x is 0 for a finite x, NaN otherwise: summed, one test for all, without a branch. */
    double zero = 0.0;
    for (int k = 0; k < 3; k++) {
        const double body = r_body[k] - a2 * out->omega_body[k];
        const double fixed = r_fixed[k] - a2 * out->omega_fixed[k];
        out->alpha_body[k] = body;
        out->alpha_fixed[k] = fixed;
        zero += (body - body) + (fixed - fixed);
    }
    ak_quat_to_matrix(u, out->R);
    return n <= DBL_MAX && zero == 0.0 ? AK_QUATERNION_OK : AK_QUATERNION_OVERFLOW;
}
