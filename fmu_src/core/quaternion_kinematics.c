/* Quaternion kinematics: the equations are stated in quaternion_kinematics.h. */
#include "quaternion_kinematics.h"

#include <float.h>
#include <math.h>

/* Inlined into its calls (the compiler would rather call one copy): the products stay in
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

/* R of u (the header's form for any length: the rounding of |u| does not enter). */
static void rotation_matrix(const double u[4], double R[3][3]) {
    const double w = u[0], x = u[1], y = u[2], z = u[3];
    const double ww = w * w, xx = x * x, yy = y * y, zz = z * z;
    const double inverse = 1.0 / ((ww + xx) + (yy + zz)), twice = 2.0 * inverse;
    R[0][0] = ((ww + xx) - (yy + zz)) * inverse;
    R[0][1] = twice * (x * y - w * z);
    R[0][2] = twice * (x * z + w * y);
    R[1][0] = twice * (x * y + w * z);
    R[1][1] = ((ww + yy) - (xx + zz)) * inverse;
    R[1][2] = twice * (y * z - w * x);
    R[2][0] = twice * (x * z - w * y);
    R[2][1] = twice * (y * z + w * x);
    R[2][2] = ((ww + zz) - (xx + yy)) * inverse;
}

/* The largest |q_k|: |q| is computed scaled by it, so that no square overflows or underflows. */
static double largest_component(const double q[4]) {
    /* fmax's value without its call: largest is never NaN, and a NaN |q_k| is skipped by both. */
    double largest = 0.0;
    for (int k = 0; k < 4; k++) {
        const double size = fabs(q[k]);
        largest = size > largest ? size : largest;
    }
    return largest;
}

/* |q|, and u, p and r of the header's notation (q, q_dot, q_ddot times 1 / |q|); largest from
 * largest_component, at least DBL_MIN. */
static double normalized(const double q[4], const double q_dot[4], const double q_ddot[4],
                         double largest, double u[4], double p[4], double r[4]) {
    const double scale = 1.0 / largest; /* finite from DBL_MIN on */
    double sum = 0.0;
    for (int k = 0; k < 4; k++) {
        const double x = q[k] * scale;
        sum += x * x;
    }
    const double n = largest * sqrt(sum);
    const double inverse = 1.0 / n; /* 0 when n overflowed: the caller refuses that */
    for (int k = 0; k < 4; k++) {
        u[k] = q[k] * inverse;
        p[k] = q_dot[k] * inverse;
        r[k] = q_ddot[k] * inverse;
    }
    return n;
}

ak_quaternion_status ak_quaternion_kinematics(const double q[4], const double q_dot[4],
                                              const double q_ddot[4], ak_quaternion_outputs *out) {
    const double largest = largest_component(q);
    if (!(largest >= DBL_MIN)) {
        return AK_QUATERNION_NOT_ATTITUDE;
    }
    double u[4], p[4], r[4];
    const double n = normalized(q, q_dot, q_ddot, largest, u, p, r);
    out->q_norm = n;
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
    rotation_matrix(u, out->R);
    return n <= DBL_MAX && zero == 0.0 ? AK_QUATERNION_OK : AK_QUATERNION_OVERFLOW;
}

/* body := 2 vec(a* x + b* y), fixed := 2 vec(x a* + y b*): the change of twice_products(u, x)
 * with a = du, x = p (or r) and b = u, y = dp. */
static void twice_products_tangent(const double a[4], const double x[4], const double b[4],
                                   const double y[4], double body[3], double fixed[3]) {
    double body_1[3], fixed_1[3], body_2[3], fixed_2[3];
    twice_products(a, x, body_1, fixed_1);
    twice_products(b, y, body_2, fixed_2);
    for (int k = 0; k < 3; k++) {
        body[k] = body_1[k] + body_2[k];
        fixed[k] = fixed_1[k] + fixed_2[k];
    }
}

void ak_quaternion_kinematics_tangent(const double q[4], const double q_dot[4],
                                      const double q_ddot[4], const double dq[4],
                                      const double dq_dot[4], const double dq_ddot[4],
                                      ak_quaternion_outputs *d_out) {
    double u[4], p[4], r[4];
    const double n = normalized(q, q_dot, q_ddot, largest_component(q), u, p, r);
    const double inverse = 1.0 / n;
    const double dn = u[0] * dq[0] + u[1] * dq[1] + u[2] * dq[2] + u[3] * dq[3];
    const double dn_over_n = dn * inverse;
    double du[4], dp[4], dr[4];
    for (int k = 0; k < 4; k++) {
        du[k] = dq[k] * inverse - u[k] * dn_over_n;
        dp[k] = dq_dot[k] * inverse - p[k] * dn_over_n;
        dr[k] = dq_ddot[k] * inverse - r[k] * dn_over_n;
    }
    double omega_body[3], omega_fixed[3], d_r_body[3], d_r_fixed[3];
    twice_products(u, p, omega_body, omega_fixed);
    twice_products_tangent(du, p, u, dp, d_out->omega_body, d_out->omega_fixed);
    twice_products_tangent(du, r, u, dr, d_r_body, d_r_fixed);
    double a2 = 0.0, d_a2 = 0.0;
    for (int k = 0; k < 4; k++) {
        a2 += 2.0 * u[k] * p[k];
        d_a2 += 2.0 * (du[k] * p[k] + u[k] * dp[k]);
    }
    for (int k = 0; k < 3; k++) {
        d_out->alpha_body[k] = d_r_body[k] - d_a2 * omega_body[k] - a2 * d_out->omega_body[k];
        d_out->alpha_fixed[k] = d_r_fixed[k] - d_a2 * omega_fixed[k] - a2 * d_out->omega_fixed[k];
    }
    /* R(u) differentiated term by term in its unit form 1 - 2 (y^2 + z^2), ...: for the exact u
     * and du (u . du = 0) the same as the header's form. */
    const double w = u[0], x = u[1], y = u[2], z = u[3];
    const double dw = du[0], dx = du[1], dy = du[2], dz = du[3];
    d_out->R[0][0] = -4.0 * (y * dy + z * dz);
    d_out->R[0][1] = 2.0 * (dx * y + x * dy - dw * z - w * dz);
    d_out->R[0][2] = 2.0 * (dx * z + x * dz + dw * y + w * dy);
    d_out->R[1][0] = 2.0 * (dx * y + x * dy + dw * z + w * dz);
    d_out->R[1][1] = -4.0 * (x * dx + z * dz);
    d_out->R[1][2] = 2.0 * (dy * z + y * dz - dw * x - w * dx);
    d_out->R[2][0] = 2.0 * (dx * z + x * dz - dw * y - w * dy);
    d_out->R[2][1] = 2.0 * (dy * z + y * dz + dw * x + w * dx);
    d_out->R[2][2] = -4.0 * (x * dx + y * dy);
    d_out->q_norm = dn;
}
