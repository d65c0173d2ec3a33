/* General angular kinematics for every rotation sequence: the formulation is stated in
 * kinematics_general.h. Everything is built from the chain of section 1 and the axes u_m, v_m. */
#include "kinematics_general.h"

#include "elementary.h"
#include "elementary_sincos_three.h"

#include <float.h>
#include <math.h>
#include <stdint.h>

#include "kinematics_sequences.h"

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

static void make_chain(const ak_sequence *sequence, const double theta[3], chain *ch) {
    ak_sines sines;
    ak_angle_sines(theta, &sines);
    chain_of_sines(sequence, &sines, ch);
}

/* Angle by angle: an angle off the usual paths (tiny, huge, not finite, near a multiple of
 * pi/2). Out of line: rare, and ak_sincos is large. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static void angle_sines_each(const double theta[3], ak_sines *sines) {
    for (int k = 0; k < 3; k++) {
        ak_sincos(theta[k], &sines->sin[k], &sines->cos[k]);
    }
}

void ak_angle_sines(const double theta[3], ak_sines *sines) {
    /* The project's sincos (elementary.h), inlined: the same bits on every platform, and one
     * argument reduction for both; the three angles side by side when all take its usual path. */
    if (!ak_sincos_three_usual(theta, sines->sin, sines->cos)) {
        angle_sines_each(theta, sines);
    }
}

void ak_half_angle_sines(const ak_sines *sines, ak_sines *half) {
    for (int k = 0; k < 3; k++) {
        const double s = sines->sin[k], c = sines->cos[k];
        /* The larger of |cos x/2| and |sin x/2|, then the other from sin x = 2 sin x/2 cos x/2:
         * neither cancels, near x = 0 or near x = pi. */
        const double large = sqrt(0.5 * (1.0 + fabs(c)));
        const double small = s / (2.0 * large);
        half->cos[k] = c >= 0.0 ? large : fabs(small);
        half->sin[k] = c >= 0.0 ? small : copysign(large, s);
    }
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

void ak_general_rotation_matrix(const ak_sequence *sequence, const double theta[3], double R[3][3]) {
    chain ch;
    make_chain(sequence, theta, &ch);
    chain_rotation_matrix(&ch, R);
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

void ak_general_quaternion(const ak_sequence *sequence, const double theta[3], double q[4]) {
    chain ch;
    ak_sines sines, half;
    ak_angle_sines(theta, &sines);
    chain_of_sines(sequence, &sines, &ch);
    ak_half_angle_sines(&sines, &half);
    chain_quaternion(&ch, &half, q);
}

static inline void chain_partials(const chain *ch, const double theta_dot[3], double W_fixed[3][3],
                           double W_body[3][3], double W_fixed_dot[3][3],
                           double W_body_dot[3][3]) {
    const double no_acceleration[3] = {0.0, 0.0, 0.0};
    chain_rates x;
    chain_rates_of(ch, theta_dot, no_acceleration, &x);
    store_partials(ch, &x, W_fixed, W_body, W_fixed_dot, W_body_dot);
}

void ak_general_partials(const ak_sequence *sequence, const double theta[3],
                         const double theta_dot[3], double W_fixed[3][3], double W_body[3][3],
                         double W_fixed_dot[3][3], double W_body_dot[3][3]) {
    chain ch;
    make_chain(sequence, theta, &ch);
    chain_partials(&ch, theta_dot, W_fixed, W_body, W_fixed_dot, W_body_dot);
}

/* Every orientation output from one chain; body123_rotation_outputs makes a copy of it. */
static inline void chain_rotation_outputs(const ak_sequence *sequence, const ak_sines *sines,
                                          const ak_sines *half, const double theta_dot[3],
                                          ak_rotation_outputs *out) {
    chain ch;
    chain_of_sines(sequence, sines, &ch);
    chain_rotation_matrix(&ch, out->R);
    chain_quaternion(&ch, half, out->q);
    chain_partials(&ch, theta_dot, out->W_fixed, out->W_body, out->W_fixed_dot, out->W_body_dot);
}

/* chain_rotation_outputs for body123 with every helper inlined, so that the compiler folds the
 * constant axes: the same arithmetic in the same order, hence the same bits. */
#if defined(__GNUC__)
__attribute__((flatten))
#endif
static void body123_rotation_outputs(const ak_sines *sines, const ak_sines *half,
                                     const double theta_dot[3], ak_rotation_outputs *out) {
    chain_rotation_outputs(&AK_SEQUENCES[AK_SEQUENCE_DEFAULT], sines, half, theta_dot, out);
}

void ak_general_rotation_outputs(const ak_sequence *sequence, const ak_sines *sines,
                                 const ak_sines *half, const double theta_dot[3],
                                 ak_rotation_outputs *out) {
    if (sequence == &AK_SEQUENCES[AK_SEQUENCE_DEFAULT]) {
        body123_rotation_outputs(sines, half, theta_dot, out);
    } else {
        chain_rotation_outputs(sequence, sines, half, theta_dot, out);
    }
}

/* Every output from one chain: the sum of chain_kinematics and chain_rotation_outputs, with the
 * axes and their rates computed once. */
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
    make_chain(sequence, theta, &ch);
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

static double vector_part_norm(const double q[4]) {
    return sqrt(q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
}

void ak_rotation_angle(const double q[4], double *angle) {
    /* 2 atan2(s, q0) with s, q0 >= 0, as the atan of whichever ratio is at most 1: the project's
     * atan (elementary.h) of a ratio at most 1 costs about 60 instructions less than its atan2,
     * which would also correct the quotient's rounding (measured with callgrind, bench/run.sh's
     * "all outputs" row). */
    static const double PI = 3.14159265358979323846;
    const double s = vector_part_norm(q);
    *angle = s < q[0] ? 2.0 * ak_atan(s / q[0]) : s > 0.0 ? PI - 2.0 * ak_atan(q[0] / s) : 0.0;
}

void ak_rotation_angle_tangent(const double q[4], const double dq[4], double *d_angle) {
    const double s = vector_part_norm(q);
    if (s == 0.0) {
        *d_angle = 0.0;
        return;
    }
    const double ds = (q[1] * dq[1] + q[2] * dq[2] + q[3] * dq[3]) / s;
    *d_angle = 2.0 * (q[0] * ds - s * dq[0]) / (q[0] * q[0] + s * s);
}
