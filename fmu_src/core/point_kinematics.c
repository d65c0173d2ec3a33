/* The equations and their derivation: point_kinematics.h. */
#include "point_kinematics.h"

static void cross(const double a[3], const double b[3], double out[3]) {
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* A copy of the three components of a vector. */
static void load(const double *from, double to[3]) {
    to[0] = from[0], to[1] = from[1], to[2] = from[2];
}

bool ak_point_kinematics(const ak_point_inputs *in, ak_point_outputs *out) {
    /* The inputs copied first: out may alias them (a model's value array holds both), and the
     * compiler would otherwise read them again after every store. */
    double omega[3], alpha[3], v_O[3], a_O[3], r[3], r_dot[3], r_ddot[3], g[3];
    load(in->omega, omega), load(in->alpha, alpha), load(in->v_O, v_O), load(in->a_O, a_O);
    load(in->r, r), load(in->r_dot, r_dot), load(in->r_ddot, r_ddot), load(in->g, g);
    double omega_x_r[3], omega_x_r_dot[3], tangential[3], centripetal[3];
    cross(omega, r, omega_x_r);
    cross(omega, r_dot, omega_x_r_dot);
    cross(alpha, r, tangential);
    cross(omega, omega_x_r, centripetal);
    /* x - x is 0 for a finite x and NaN otherwise: one sum tells whether all 18 are finite, from
     * the values as they are computed (reading them back from out would cost more). */
    double zero = 0.0;
    for (int k = 0; k < 3; k++) {
        const double coriolis = 2.0 * omega_x_r_dot[k];
        const double v_P = v_O[k] + omega_x_r[k] + r_dot[k];
        const double a_P = a_O[k] + tangential[k] + centripetal[k] + coriolis + r_ddot[k];
        const double specific_force = a_P - g[k];
        zero += (v_P - v_P) + (a_P - a_P) + (specific_force - specific_force) +
                (tangential[k] - tangential[k]) + (centripetal[k] - centripetal[k]) +
                (coriolis - coriolis);
        out->v_P[k] = v_P;
        out->a_P[k] = a_P;
        out->specific_force[k] = specific_force;
        out->a_tangential[k] = tangential[k];
        out->a_centripetal[k] = centripetal[k];
        out->a_coriolis[k] = coriolis;
    }
    return zero == 0.0;
}

/* d(a x b) = da x b + a x db */
static void cross_tangent(const double a[3], const double b[3], const double da[3],
                          const double db[3], double out[3]) {
    double first[3], second[3];
    cross(da, b, first);
    cross(a, db, second);
    for (int k = 0; k < 3; k++) {
        out[k] = first[k] + second[k];
    }
}

void ak_point_kinematics_tangent(const ak_point_inputs *in, const ak_point_inputs *d_in,
                                 ak_point_outputs *d_out) {
    double omega_x_r[3], d_omega_x_r[3], d_omega_x_r_dot[3];
    cross(in->omega, in->r, omega_x_r);
    cross_tangent(in->omega, in->r, d_in->omega, d_in->r, d_omega_x_r);
    cross_tangent(in->omega, in->r_dot, d_in->omega, d_in->r_dot, d_omega_x_r_dot);
    cross_tangent(in->alpha, in->r, d_in->alpha, d_in->r, d_out->a_tangential);
    cross_tangent(in->omega, omega_x_r, d_in->omega, d_omega_x_r, d_out->a_centripetal);
    for (int k = 0; k < 3; k++) {
        d_out->a_coriolis[k] = 2.0 * d_omega_x_r_dot[k];
        d_out->v_P[k] = d_in->v_O[k] + d_omega_x_r[k] + d_in->r_dot[k];
        d_out->a_P[k] = d_in->a_O[k] + d_out->a_tangential[k] + d_out->a_centripetal[k] +
                        d_out->a_coriolis[k] + d_in->r_ddot[k];
        d_out->specific_force[k] = d_out->a_P[k] - d_in->g[k];
    }
}
