/* The frozen anchors of bench_attitude: see attitude_anchor.h. The arithmetic is the core's of
 * 0.3.0 (fmu_src/core/attitude.c then), operation for operation, so that the results were equal
 * bit for bit when they were written. */
#include "attitude_anchor.h"

#include <math.h>

static const double PI = 3.14159265358979323846;
static const double TWO_PI = 6.28318530717958647692;
static const double SINGULAR_DISTANCE = 1.4901161193847656e-08; /* sqrt(DBL_EPSILON) */

bool ak_anchor_attitude_step(const double omega[3], double h, double q[4]) {
    /* The cubic c0 + c1 s + c2 s^2 + c3 s^3 of omega (here c1 = c2 = c3 = 0) at the two Gauss
     * points, the fourth-order Magnus vector, exp, the product, the norm correction. */
    const double c[4][3] = {{omega[0], omega[1], omega[2]}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0},
                            {0.0, 0.0, 0.0}};
    const double r = 0.28867513459481288225; /* sqrt(3) / 6 */
    const double s[2] = {h * (0.5 - r), h * (0.5 + r)};
    double a[2][3];
    for (int g = 0; g < 2; g++) {
        for (int k = 0; k < 3; k++) {
            a[g][k] = c[0][k] + s[g] * (c[1][k] + s[g] * (c[2][k] + s[g] * c[3][k]));
        }
    }
    const double cross[3] = {a[0][1] * a[1][2] - a[0][2] * a[1][1],
                             a[0][2] * a[1][0] - a[0][0] * a[1][2],
                             a[0][0] * a[1][1] - a[0][1] * a[1][0]};
    const double commutator = 1.0 * 0.07216878364870322056 * h * h;
    double v[3];
    for (int k = 0; k < 3; k++) {
        v[k] = 0.25 * h * (a[0][k] + a[1][k]) + commutator * cross[k];
    }
    const double angle = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    double sinc;
    if (angle < 1e-4) {
        const double a2 = angle * angle;
        sinc = 1.0 - a2 / 6.0 * (1.0 - a2 / 20.0);
    } else {
        sinc = sin(angle) / angle;
    }
    const double e[4] = {cos(angle), sinc * v[0], sinc * v[1], sinc * v[2]};
    double next[4] = {q[0] * e[0] - q[1] * e[1] - q[2] * e[2] - q[3] * e[3],
                      q[0] * e[1] + q[1] * e[0] + q[2] * e[3] - q[3] * e[2],
                      q[0] * e[2] - q[1] * e[3] + q[2] * e[0] + q[3] * e[1],
                      q[0] * e[3] + q[1] * e[2] - q[2] * e[1] + q[3] * e[0]};
    const double n2 = next[0] * next[0] + next[1] * next[1] + next[2] * next[2] + next[3] * next[3];
    const double factor = 0.5 * (3.0 - n2);
    for (int k = 0; k < 4; k++) {
        next[k] = next[k] * factor;
    }
    for (int k = 0; k < 4; k++) {
        if (!isfinite(next[k])) {
            return false;
        }
    }
    for (int k = 0; k < 4; k++) {
        q[k] = next[k];
    }
    return true;
}

void ak_anchor_quat_to_matrix(const double q[4], double R[3][3]) {
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    R[0][0] = 1.0 - 2.0 * (y * y + z * z);
    R[0][1] = 2.0 * (x * y - w * z);
    R[0][2] = 2.0 * (x * z + w * y);
    R[1][0] = 2.0 * (x * y + w * z);
    R[1][1] = 1.0 - 2.0 * (x * x + z * z);
    R[1][2] = 2.0 * (y * z - w * x);
    R[2][0] = 2.0 * (x * z - w * y);
    R[2][1] = 2.0 * (y * z + w * x);
    R[2][2] = 1.0 - 2.0 * (x * x + y * y);
}

static double unwrap(double x, double reference) {
    return x + TWO_PI * nearbyint((reference - x) / TWO_PI);
}

bool ak_anchor_angles_123(double R[3][3], const double previous[3], double theta[3],
                          double *distance) {
    /* Chain axes 1, 2, 3 (0-based i = 0, j = 1, k = 2), parity e = +1, Tait-Bryan. */
    *distance = sqrt(R[0][0] * R[0][0] + R[0][1] * R[0][1]);
    const double phi[3] = {atan2(-1.0 * R[1][2], R[2][2]), atan2(1.0 * R[0][2], *distance),
                           atan2(-1.0 * R[0][1], R[0][0])};
    if (*distance < SINGULAR_DISTANCE) { /* theta1 held; theta3 from R_1(theta1)^T R */
        const double held = previous[0], sn = sin(held), cs = cos(held);
        const double m10 = 0.0 * R[0][0] + cs * R[1][0] + sn * R[2][0];
        const double m11 = 0.0 * R[0][1] + cs * R[1][1] + sn * R[2][1];
        theta[0] = held;
        theta[1] = unwrap(phi[1], previous[1]);
        theta[2] = unwrap(atan2(m10, m11), previous[2]);
        return true;
    }
    double sets[2][3] = {{phi[0], phi[1], phi[2]}, {phi[0] + PI, PI - phi[1], phi[2] + PI}};
    double squared[2] = {0.0, 0.0};
    for (int s = 0; s < 2; s++) {
        for (int k = 0; k < 3; k++) {
            sets[s][k] = unwrap(sets[s][k], previous[k]);
            squared[s] += (sets[s][k] - previous[k]) * (sets[s][k] - previous[k]);
        }
    }
    const int best = squared[1] < squared[0];
    for (int k = 0; k < 3; k++) {
        theta[k] = sets[best][k];
    }
    return false;
}
