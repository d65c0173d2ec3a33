/* General angular kinematics for every rotation sequence: the formulation is stated in
 * kinematics_general.h. Everything is built from the chain of section 1 and the axes u_m, v_m. */
#include "kinematics_general.h"

#include <float.h>
#include <math.h>

/* The sequence as a chain of three body-fixed rotations (header, section 1). */
typedef struct {
    int axis[3];    /* 0-based chain axes a1, a2, a3 */
    double s[3];    /* sin(phi_m) */
    double c[3];    /* cos(phi_m) */
    int angle[3];   /* index k of the theta_k that is chain angle m */
} chain;

static void make_chain(const ak_sequence *sequence, const double theta[3], chain *ch) {
    for (int m = 0; m < 3; m++) {
        const int k = (sequence->kind == AK_SPACE_FIXED) ? 2 - m : m;
        ch->axis[m] = sequence->axes[k] - 1;
        ch->angle[m] = k;
        ch->s[m] = sin(theta[k]);
        ch->c[m] = cos(theta[k]);
    }
}

/* The two axes after each axis, cyclically: rotation about a turns the (a+1, a+2) plane. */
static const int NEXT[3] = {1, 2, 0};
static const int AFTER_NEXT[3] = {2, 0, 1};

/* v := R_axis(x) v, with s = sin x, c = cos x. */
static void rotate(int axis, double s, double c, double v[3]) {
    const int i = NEXT[axis], j = AFTER_NEXT[axis];
    const double vi = v[i], vj = v[j];
    v[i] = c * vi - s * vj;
    v[j] = s * vi + c * vj;
}

/* v := R_axis(x)^T v. */
static void rotate_back(int axis, double s, double c, double v[3]) {
    rotate(axis, -s, c, v);
}

static void unit(int axis, double v[3]) {
    v[0] = v[1] = v[2] = 0.0;
    v[axis] = 1.0;
}

static void cross(const double a[3], const double b[3], double out[3]) {
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* Chain axes in fixed (u) and body (v) components, u[m], v[m] for chain rotation m. */
static void chain_axes(const chain *ch, double u[3][3], double v[3][3]) {
    for (int m = 0; m < 3; m++) {
        unit(ch->axis[m], u[m]);
        for (int l = m - 1; l >= 0; l--) {
            rotate(ch->axis[l], ch->s[l], ch->c[l], u[m]);
        }
        unit(ch->axis[m], v[m]);
        for (int l = m + 1; l < 3; l++) {
            rotate_back(ch->axis[l], ch->s[l], ch->c[l], v[m]);
        }
    }
}

/* Derivatives of the chain axes (header, section 3), phi_dot in chain order. */
static void chain_axis_rates(double u[3][3], double v[3][3], const double phi_dot[3],
                             double du[3][3], double dv[3][3]) {
    double Omega[3] = {0.0, 0.0, 0.0};
    for (int m = 0; m < 3; m++) {
        cross(Omega, u[m], du[m]);
        for (int r = 0; r < 3; r++) {
            Omega[r] += phi_dot[m] * u[m][r];
        }
    }
    double rest[3] = {0.0, 0.0, 0.0};
    for (int m = 2; m >= 0; m--) {
        cross(v[m], rest, dv[m]);
        for (int r = 0; r < 3; r++) {
            rest[r] += phi_dot[m] * v[m][r];
        }
    }
}

static void to_chain_order(const chain *ch, const double x[3], double out[3]) {
    for (int m = 0; m < 3; m++) {
        out[m] = x[ch->angle[m]];
    }
}

void ak_general_angular_kinematics(const ak_sequence *sequence, const double theta[3],
                                   const double theta_dot[3], const double theta_ddot[3],
                                   double omega_fixed[3], double omega_body[3],
                                   double alpha_fixed[3], double alpha_body[3]) {
    chain ch;
    double u[3][3], v[3][3], du[3][3], dv[3][3], pd[3], pdd[3];
    make_chain(sequence, theta, &ch);
    chain_axes(&ch, u, v);
    to_chain_order(&ch, theta_dot, pd);
    to_chain_order(&ch, theta_ddot, pdd);
    chain_axis_rates(u, v, pd, du, dv);
    for (int r = 0; r < 3; r++) {
        omega_fixed[r] = pd[0] * u[0][r] + pd[1] * u[1][r] + pd[2] * u[2][r];
        omega_body[r] = pd[0] * v[0][r] + pd[1] * v[1][r] + pd[2] * v[2][r];
        alpha_fixed[r] = pdd[0] * u[0][r] + pdd[1] * u[1][r] + pdd[2] * u[2][r] +
                         pd[1] * du[1][r] + pd[2] * du[2][r];
        alpha_body[r] = pdd[0] * v[0][r] + pdd[1] * v[1][r] + pdd[2] * v[2][r] +
                        pd[0] * dv[0][r] + pd[1] * dv[1][r];
    }
}

void ak_general_rotation_matrix(const ak_sequence *sequence, const double theta[3], double R[3][3]) {
    chain ch;
    make_chain(sequence, theta, &ch);
    for (int col = 0; col < 3; col++) {
        double e[3];
        unit(col, e);
        for (int m = 2; m >= 0; m--) {
            rotate(ch.axis[m], ch.s[m], ch.c[m], e);
        }
        for (int r = 0; r < 3; r++) {
            R[r][col] = e[r];
        }
    }
}

void ak_general_quaternion(const ak_sequence *sequence, const double theta[3], double q[4]) {
    chain ch;
    make_chain(sequence, theta, &ch);
    double p[4] = {1.0, 0.0, 0.0, 0.0};
    for (int m = 0; m < 3; m++) {
        const double half = 0.5 * theta[ch.angle[m]];
        double e[4] = {cos(half), 0.0, 0.0, 0.0};
        e[1 + ch.axis[m]] = sin(half);
        /* p := p e, Hamilton product, scalar first. */
        const double r0 = p[0] * e[0] - p[1] * e[1] - p[2] * e[2] - p[3] * e[3];
        const double r1 = p[0] * e[1] + p[1] * e[0] + p[2] * e[3] - p[3] * e[2];
        const double r2 = p[0] * e[2] - p[1] * e[3] + p[2] * e[0] + p[3] * e[1];
        const double r3 = p[0] * e[3] + p[1] * e[2] - p[2] * e[1] + p[3] * e[0];
        p[0] = r0;
        p[1] = r1;
        p[2] = r2;
        p[3] = r3;
    }
    /* One sign per orientation: q0 > 0, or the first non-zero component positive. */
    int first = 0;
    while (first < 3 && p[first] == 0.0) {
        first++;
    }
    const double sign = (p[first] < 0.0) ? -1.0 : 1.0;
    for (int k = 0; k < 4; k++) {
        q[k] = sign * p[k];
    }
}

void ak_general_partials(const ak_sequence *sequence, const double theta[3],
                         const double theta_dot[3], double W_fixed[3][3], double W_body[3][3],
                         double W_fixed_dot[3][3], double W_body_dot[3][3]) {
    chain ch;
    double u[3][3], v[3][3], du[3][3], dv[3][3], pd[3];
    make_chain(sequence, theta, &ch);
    chain_axes(&ch, u, v);
    to_chain_order(&ch, theta_dot, pd);
    chain_axis_rates(u, v, pd, du, dv);
    for (int m = 0; m < 3; m++) {
        const int col = ch.angle[m];
        for (int r = 0; r < 3; r++) {
            W_fixed[r][col] = u[m][r];
            W_body[r][col] = v[m][r];
            W_fixed_dot[r][col] = du[m][r];
            W_body_dot[r][col] = dv[m][r];
        }
    }
}

/* det W (header, section 4), in closed form so that it keeps its relative accuracy near zero. */
static double determinant(const ak_sequence *sequence, const double theta[3]) {
    if (sequence->proper_euler) {
        const double s2 = sin(theta[1]);
        return (sequence->kind == AK_SPACE_FIXED) ? s2 : -s2;
    }
    const int cyclic = ((sequence->axes[1] - sequence->axes[0] + 3) % 3) == 1;
    const double c2 = cos(theta[1]);
    return cyclic ? c2 : -c2;
}

double ak_singularity_distance(const ak_sequence *sequence, const double theta[3]) {
    return fabs(determinant(sequence, theta));
}

/* out := W^-1 x, W^-1 = adjugate / det; c[k] is column k of W. */
static void solve(double c[3][3], double det, const double x[3], double out[3]) {
    double row[3];
    for (int k = 0; k < 3; k++) {
        cross(c[(k + 1) % 3], c[(k + 2) % 3], row);
        out[k] = (row[0] * x[0] + row[1] * x[1] + row[2] * x[2]) / det;
    }
}

ak_rates_status ak_general_euler_rates(const ak_sequence *sequence, ak_frame frame,
                                       const double theta[3], const double omega[3],
                                       const double omega_dot[3], double tolerance,
                                       double theta_dot[3], double theta_ddot[3],
                                       double alpha_fixed[3], double alpha_body[3],
                                       double *distance) {
    const double det = determinant(sequence, theta);
    *distance = fabs(det);
    const double theta2_size = fabs(theta[1]) > 1.0 ? fabs(theta[1]) : 1.0;
    if (!(*distance > AK_SINGULAR_ROUNDING * DBL_EPSILON * theta2_size)) {
        return AK_RATES_SINGULAR;
    }

    const int f = (frame == AK_FRAME_BODY) ? 1 : 0;
    double W[2][3][3], W_dot[2][3][3], R[3][3];
    double columns[3][3], column_rates[3][3];
    const double zero[3] = {0.0, 0.0, 0.0};
    double td[3], tdd[3], rhs[3];

    ak_general_partials(sequence, theta, zero, W[0], W[1], W_dot[0], W_dot[1]);
    for (int k = 0; k < 3; k++) {
        for (int r = 0; r < 3; r++) {
            columns[k][r] = W[f][r][k];
        }
    }
    solve(columns, det, omega, td);

    ak_general_partials(sequence, theta, td, W[0], W[1], W_dot[0], W_dot[1]);
    for (int k = 0; k < 3; k++) {
        for (int r = 0; r < 3; r++) {
            column_rates[k][r] = W_dot[f][r][k];
        }
    }
    for (int r = 0; r < 3; r++) {
        rhs[r] = omega_dot[r] - (column_rates[0][r] * td[0] + column_rates[1][r] * td[1] +
                                 column_rates[2][r] * td[2]);
    }
    solve(columns, det, rhs, tdd);

    ak_general_rotation_matrix(sequence, theta, R);
    double other[3];
    for (int r = 0; r < 3; r++) {
        other[r] = (f == 0)
                       ? R[0][r] * omega_dot[0] + R[1][r] * omega_dot[1] + R[2][r] * omega_dot[2]
                       : R[r][0] * omega_dot[0] + R[r][1] * omega_dot[1] + R[r][2] * omega_dot[2];
    }
    for (int k = 0; k < 3; k++) {
        if (!isfinite(td[k]) || !isfinite(tdd[k]) || !isfinite(other[k])) {
            return AK_RATES_OVERFLOW;
        }
    }
    for (int k = 0; k < 3; k++) {
        theta_dot[k] = td[k];
        theta_ddot[k] = tdd[k];
        alpha_fixed[k] = (f == 0) ? omega_dot[k] : other[k];
        alpha_body[k] = (f == 0) ? other[k] : omega_dot[k];
    }
    return (*distance < tolerance) ? AK_RATES_NEAR_SINGULAR : AK_RATES_OK;
}
