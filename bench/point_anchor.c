/* The fixed anchor of PointKinematics' benchmark (bench/bench_point.c): the hand-written formula
 * of core/point_kinematics.h, written out once here in plain C and never changed with the core,
 * so that the ratio's denominator does not move with the code. in: omega, alpha, v_O, a_O, r,
 * r_dot, r_ddot, g (3 each); out: v_P, a_P, specific_force, a_tangential, a_centripetal,
 * a_coriolis (3 each). */
#include "point_anchor.h"

void ak_anchor_point(const double in[24], double out[18]) {
    const double *w = &in[0], *al = &in[3], *vo = &in[6], *ao = &in[9], *r = &in[12],
                 *rd = &in[15], *rdd = &in[18], *g = &in[21];
    const double wr0 = w[1] * r[2] - w[2] * r[1], wr1 = w[2] * r[0] - w[0] * r[2],
                 wr2 = w[0] * r[1] - w[1] * r[0];
    const double t0 = al[1] * r[2] - al[2] * r[1], t1 = al[2] * r[0] - al[0] * r[2],
                 t2 = al[0] * r[1] - al[1] * r[0];
    const double c0 = w[1] * wr2 - w[2] * wr1, c1 = w[2] * wr0 - w[0] * wr2,
                 c2 = w[0] * wr1 - w[1] * wr0;
    const double k0 = 2.0 * (w[1] * rd[2] - w[2] * rd[1]), k1 = 2.0 * (w[2] * rd[0] - w[0] * rd[2]),
                 k2 = 2.0 * (w[0] * rd[1] - w[1] * rd[0]);
    out[0] = vo[0] + wr0 + rd[0];
    out[1] = vo[1] + wr1 + rd[1];
    out[2] = vo[2] + wr2 + rd[2];
    out[3] = ao[0] + t0 + c0 + k0 + rdd[0];
    out[4] = ao[1] + t1 + c1 + k1 + rdd[1];
    out[5] = ao[2] + t2 + c2 + k2 + rdd[2];
    out[6] = out[3] - g[0];
    out[7] = out[4] - g[1];
    out[8] = out[5] - g[2];
    out[9] = t0, out[10] = t1, out[11] = t2;
    out[12] = c0, out[13] = c1, out[14] = c2;
    out[15] = k0, out[16] = k1, out[17] = k2;
}
