/* The equations and their derivation: point_kinematics.h. */
#include "point_kinematics.h"

static void cross(const double a[3], const double b[3], double out[3]) {
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

void ak_point_kinematics(const ak_point_inputs *in, ak_point_outputs *out) {
    double omega_x_r[3], omega_x_r_dot[3];
    cross(in->omega, in->r, omega_x_r);
    cross(in->omega, in->r_dot, omega_x_r_dot);
    cross(in->alpha, in->r, out->a_tangential);
    cross(in->omega, omega_x_r, out->a_centripetal);
    for (int k = 0; k < 3; k++) {
        out->a_coriolis[k] = 2.0 * omega_x_r_dot[k];
        out->v_P[k] = in->v_O[k] + omega_x_r[k] + in->r_dot[k];
        out->a_P[k] = in->a_O[k] + out->a_tangential[k] + out->a_centripetal[k] +
                      out->a_coriolis[k] + in->r_ddot[k];
        out->specific_force[k] = out->a_P[k] - in->g[k];
    }
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
