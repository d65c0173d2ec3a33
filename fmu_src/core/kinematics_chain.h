/* The chain of three rotations that every sequence is (kinematics_general.h, section 1) and the
 * inline pieces its outputs are built from, shared by the core's files: each of those holds what
 * one group of models calls, so that an FMU compiles only what its model calls. */
#ifndef ANGULAR_KINEMATICS_KINEMATICS_CHAIN_H
#define ANGULAR_KINEMATICS_KINEMATICS_CHAIN_H

#include "kinematics_general.h"

/* The sequence as a chain of three body-fixed rotations (header, section 1). */
typedef struct {
    int axis[3];    /* 0-based chain axes a1, a2, a3 */
    double s[3];    /* sin(phi_m) */
    double c[3];    /* cos(phi_m) */
    int angle[3];   /* index k of the theta_k that is chain angle m */
} chain;

static inline void chain_of_sines(const ak_sequence *sequence, const ak_sines *sines, chain *ch) {
    for (int m = 0; m < 3; m++) {
        const int k = (sequence->kind == AK_SPACE_FIXED) ? 2 - m : m;
        ch->axis[m] = sequence->axes[k] - 1;
        ch->angle[m] = k;
        ch->s[m] = sines->sin[k];
        ch->c[m] = sines->cos[k];
    }
}

/* The chain of theta, with its sines. Inline: not every model that computes the sines of theta
 * uses the chain (EulerRates runs its sequence's generated inverse map on them). */
static inline void ak_chain_of_angles(const ak_sequence *sequence, const double theta[3],
                                      chain *ch) {
    ak_sines sines;
    ak_angle_sines(theta, &sines);
    chain_of_sines(sequence, &sines, ch);
}

/* The two axes after each axis, cyclically: rotation about a turns the (a+1, a+2) plane. */
static const int NEXT[3] = {1, 2, 0};
static const int AFTER_NEXT[3] = {2, 0, 1};

/* v := R_axis(x) v, with s = sin x, c = cos x. */
static inline void rotate(int axis, double s, double c, double v[3]) {
    const int i = NEXT[axis], j = AFTER_NEXT[axis];
    const double vi = v[i], vj = v[j];
    v[i] = c * vi - s * vj;
    v[j] = s * vi + c * vj;
}

/* v := R_axis(x)^T v. */
static inline void rotate_back(int axis, double s, double c, double v[3]) {
    rotate(axis, -s, c, v);
}

static inline void unit(int axis, double v[3]) {
    v[0] = v[1] = v[2] = 0.0;
    v[axis] = 1.0;
}

/* out := e_axis x x: only moves and negates components. All three are zeroed first (out[axis]
 * stays 0) so that gcc -fanalyzer (scripts/check_static.sh) sees every component written; it cannot
 * tell that axis, i and j are 0, 1, 2 in some order. */
static inline void axis_cross(int axis, const double x[3], double out[3]) {
    const int i = NEXT[axis], j = AFTER_NEXT[axis];
    out[0] = out[1] = out[2] = 0.0;
    out[i] = -x[j];
    out[j] = x[i];
}

/* Chain axes in fixed (u) and body (v) components, u[m], v[m] for chain rotation m. */
static inline void chain_axes(const chain *ch, double u[3][3], double v[3][3]) {
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

/* v := R_a(phi_m) v for the chain rotations first..last, applied innermost (last) first. */
static inline void rotate_chain(const chain *ch, int first, int last, double v[3]) {
    for (int m = last; m >= first; m--) {
        rotate(ch->axis[m], ch->s[m], ch->c[m], v);
    }
}

/* v := (R_a(phi_first) .. R_a(phi_last))^T v. */
static inline void rotate_chain_back(const chain *ch, int first, int last, double v[3]) {
    for (int m = first; m <= last; m++) {
        rotate_back(ch->axis[m], ch->s[m], ch->c[m], v);
    }
}

/* Derivatives of the chain axes (header, section 3), phi_dot in chain order: du[m], dv[m].
 * The cross products u_l x u_m and v_m x v_l are formed in the frame where one factor is a unit
 * axis e_a (then the product only moves and negates components) and rotated out afterwards:
 *     u_l x u_m = P_l (e_al x (R_a(l+1) .. R_a(m-1) e_am)),  P_l = R_a1 .. R_al,
 *     v_m x v_l = Q_l^T (((R_a(m+1) .. R_a(l-1))^T e_am) x e_al),  Q_l = R_al .. R_a3.
 * So no rounding brings in an angle that the exact value does not contain (sin^2 + cos^2 never
 * has to cancel), and the outputs depend on exactly the inputs their equations contain. */
typedef struct {
    double u12[3], u13[3], u23[3];   /* u_l x u_m, fixed components */
    double v12[3], v13[3], v23[3];   /* v_l x v_m, body components */
} cross_products;

static inline void chain_cross_products(const chain *ch, cross_products *x) {
    const int a1 = ch->axis[0], a2 = ch->axis[1], a3 = ch->axis[2];
    double w[3];
    unit(a2, w);
    axis_cross(a1, w, x->u12);                  /* u1 x u2 = P_1 (e_a1 x e_a2) */
    rotate_chain(ch, 0, 0, x->u12);
    unit(a3, w);
    rotate_chain(ch, 1, 1, w);
    axis_cross(a1, w, x->u13);                  /* u1 x u3 = P_1 (e_a1 x R_a2 e_a3) */
    rotate_chain(ch, 0, 0, x->u13);
    unit(a3, w);
    axis_cross(a2, w, x->u23);                  /* u2 x u3 = P_2 (e_a2 x e_a3) */
    rotate_chain(ch, 0, 1, x->u23);

    unit(a2, w);
    axis_cross(a1, w, x->v12);                  /* v1 x v2 = Q_2^T (e_a1 x e_a2) */
    rotate_chain_back(ch, 1, 2, x->v12);
    unit(a1, w);
    rotate_chain_back(ch, 1, 1, w);
    axis_cross(a3, w, x->v13);                  /* v1 x v3 = Q_3^T ((R_a2^T e_a1) x e_a3) */
    for (int r = 0; r < 3; r++) {
        x->v13[r] = -x->v13[r];
    }
    rotate_chain_back(ch, 2, 2, x->v13);
    unit(a3, w);
    axis_cross(a2, w, x->v23);                  /* v2 x v3 = Q_3^T (e_a2 x e_a3) */
    rotate_chain_back(ch, 2, 2, x->v23);
}

/* The axis rates from the cross products x of the chain. */
static inline void axis_rates_of(const cross_products *x, const double phi_dot[3],
                                 double du[3][3], double dv[3][3]) {
    for (int r = 0; r < 3; r++) {
        du[0][r] = 0.0;
        du[1][r] = phi_dot[0] * x->u12[r];
        du[2][r] = phi_dot[0] * x->u13[r] + phi_dot[1] * x->u23[r];
        dv[0][r] = phi_dot[1] * x->v12[r] + phi_dot[2] * x->v13[r];
        dv[1][r] = phi_dot[2] * x->v23[r];
        dv[2][r] = 0.0;
    }
}

static inline void chain_axis_rates(const chain *ch, const double phi_dot[3], double du[3][3],
                             double dv[3][3]) {
    cross_products x;
    chain_cross_products(ch, &x);
    axis_rates_of(&x, phi_dot, du, dv);
}

static inline void to_chain_order(const chain *ch, const double x[3], double out[3]) {
    for (int m = 0; m < 3; m++) {
        out[m] = x[ch->angle[m]];
    }
}

/* The axes of a chain, their rates and the rates in chain order: what every output of
 * sections 2 and 3 is made of. */
typedef struct {
    double u[3][3], v[3][3], du[3][3], dv[3][3];
    double pd[3], pdd[3];
} chain_rates;

static inline void chain_rates_of(const chain *ch, const double theta_dot[3],
                                  const double theta_ddot[3], chain_rates *r) {
    chain_axes(ch, r->u, r->v);
    to_chain_order(ch, theta_dot, r->pd);
    to_chain_order(ch, theta_ddot, r->pdd);
    chain_axis_rates(ch, r->pd, r->du, r->dv);
}

static inline void combine_kinematics(const chain_rates *x, double omega_fixed[3],
                                      double omega_body[3], double alpha_fixed[3],
                                      double alpha_body[3]) {
    const double *pd = x->pd, *pdd = x->pdd;
    for (int r = 0; r < 3; r++) {
        omega_fixed[r] = pd[0] * x->u[0][r] + pd[1] * x->u[1][r] + pd[2] * x->u[2][r];
        omega_body[r] = pd[0] * x->v[0][r] + pd[1] * x->v[1][r] + pd[2] * x->v[2][r];
        alpha_fixed[r] = pdd[0] * x->u[0][r] + pdd[1] * x->u[1][r] + pdd[2] * x->u[2][r] +
                         pd[1] * x->du[1][r] + pd[2] * x->du[2][r];
        alpha_body[r] = pdd[0] * x->v[0][r] + pdd[1] * x->v[1][r] + pdd[2] * x->v[2][r] +
                        pd[0] * x->dv[0][r] + pd[1] * x->dv[1][r];
    }
}

/* The partial angular velocity matrices: column theta_k is the axis of the chain angle k. */
static inline void store_partials(const chain *ch, const chain_rates *x, double W_fixed[3][3],
                                  double W_body[3][3], double W_fixed_dot[3][3],
                                  double W_body_dot[3][3]) {
    for (int m = 0; m < 3; m++) {
        const int col = ch->angle[m];
        for (int r = 0; r < 3; r++) {
            W_fixed[r][col] = x->u[m][r];
            W_body[r][col] = x->v[m][r];
            W_fixed_dot[r][col] = x->du[m][r];
            W_body_dot[r][col] = x->dv[m][r];
        }
    }
}

static inline void chain_rotation_matrix(const chain *ch, double R[3][3]) {
    for (int col = 0; col < 3; col++) {
        double e[3];
        unit(col, e);
        for (int m = 2; m >= 0; m--) {
            rotate(ch->axis[m], ch->s[m], ch->c[m], e);
        }
        for (int r = 0; r < 3; r++) {
            R[r][col] = e[r];
        }
    }
}

/* q from the chain's axes and the sines of the half angles (header, section 5). */
static inline void chain_quaternion(const chain *ch, const ak_sines *half, double q[4]) {
    double p[4] = {1.0, 0.0, 0.0, 0.0};
    for (int m = 0; m < 3; m++) {
        const int k = ch->angle[m];
        double e[4] = {half->cos[k], 0.0, 0.0, 0.0};
        e[1 + ch->axis[m]] = half->sin[k];
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

static inline void chain_partials(const chain *ch, const double theta_dot[3], double W_fixed[3][3],
                           double W_body[3][3], double W_fixed_dot[3][3],
                           double W_body_dot[3][3]) {
    const double no_acceleration[3] = {0.0, 0.0, 0.0};
    chain_rates x;
    chain_rates_of(ch, theta_dot, no_acceleration, &x);
    store_partials(ch, &x, W_fixed, W_body, W_fixed_dot, W_body_dot);
}

#endif
