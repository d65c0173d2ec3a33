/* Unit tests of the analytic Jacobian of the general core (kinematics_general_jacobian.h), for
 * the default sequence body123, against the hand-written 1-2-3 core:
 *
 *   - every column of the omega and alpha rows against a fourth-order central difference of
 *     ak_angular_kinematics_123 with respect to that input;
 *   - every entry that the 1-2-3 equations make structurally zero is exactly zero;
 *   - the angular jerk the FMU's output derivatives return, the alpha rows applied to
 *     (td, tdd, tddd), against a fourth-order central difference of alpha along the cubic motion
 *     theta(t) = theta + td t + tdd t^2/2 + tddd t^3/6.
 * (tests/test_sequences_fmu.py checks all 61 rows for all 24 sequences against sympy.)
 */
#include "kinematics_123.h"
#include "kinematics_general_jacobian.h"
#include "sequences.h"
#include "test_check.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* The omega and alpha rows: the first 12 outputs of the general core. */
enum { N_IN = AK_GENERAL_N_INPUTS, N_OUT = 12 };

static double random_in(double low, double high) {
    return low + (high - low) * ((double)rand() / (double)RAND_MAX);
}

static void outputs(const double u[N_IN], double y[N_OUT]) {
    ak_angular_kinematics_123(&u[0], &u[3], &u[6], &y[0], &y[3], &y[6], &y[9]);
}

/* Which inputs each output contains, read off the 1-2-3 equations of kinematics.h (reference.py
 * derives the same sets with sympy). */
static const int DEPENDS[N_OUT][N_IN] = {
    {0, 1, 0, 1, 0, 1, 0, 0, 0}, {1, 1, 0, 0, 1, 1, 0, 0, 0}, {1, 1, 0, 0, 1, 1, 0, 0, 0},
    {0, 1, 1, 1, 1, 0, 0, 0, 0}, {0, 1, 1, 1, 1, 0, 0, 0, 0}, {0, 1, 0, 1, 0, 1, 0, 0, 0},
    {0, 1, 0, 0, 1, 1, 1, 0, 1}, {1, 1, 0, 1, 1, 1, 0, 1, 1}, {1, 1, 0, 1, 1, 1, 0, 1, 1},
    {0, 1, 1, 1, 1, 1, 1, 1, 0}, {0, 1, 1, 1, 1, 1, 1, 1, 0}, {0, 1, 0, 1, 1, 0, 1, 0, 1},
};

static void body123_jacobian(const double u[N_IN], double J[AK_GENERAL_N_OUTPUTS][N_IN]) {
    ak_general_jacobian(&AK_SEQUENCES[0], &u[0], &u[3], &u[6], J);
}

static void check_jacobian(const double u[N_IN], double scale) {
    double J[AK_GENERAL_N_OUTPUTS][N_IN];
    body123_jacobian(u, J);
    for (int j = 0; j < N_IN; j++) {
        /* A step relative to the input's own size: angles are O(1), rates O(scale). */
        const double h = 1e-3 * (j < 3 ? 1.0 : (j < 6 ? scale : scale * scale));
        double y[4][N_OUT];
        const double offsets[4] = {-2 * h, -h, h, 2 * h};
        for (int n = 0; n < 4; n++) {
            double v[N_IN];
            for (int k = 0; k < N_IN; k++) {
                v[k] = u[k];
            }
            v[j] += offsets[n];
            outputs(v, y[n]);
        }
        for (int i = 0; i < N_OUT; i++) {
            const double fd = (y[0][i] - 8 * y[1][i] + 8 * y[2][i] - y[3][i]) / (12 * h);
            /* d y / d u scales as (scale of y) / (scale of u). */
            const double y_scale = i < 6 ? scale : scale * scale;
            const double u_scale = j < 3 ? 1.0 : (j < 6 ? scale : scale * scale);
            ak_check_close(J[i][j], fd, 1e-8 * y_scale / u_scale,
                           "J vs finite difference [%d][%d]", i, j);
            if (!DEPENDS[i][j]) {
                ak_check_close(J[i][j], 0.0, 0.0, "structural zero [%d][%d]", i, j);
            }
        }
    }
}

static void check_jerk(const double u[N_IN], const double tddd[3], double scale) {
    /* d alpha / dt = (d alpha / d theta) td + (d alpha / d td) tdd + (d alpha / d tdd) tddd */
    double J[AK_GENERAL_N_OUTPUTS][N_IN], jf[3], jb[3];
    body123_jacobian(u, J);
    for (int k = 0; k < 3; k++) {
        jf[k] = jb[k] = 0.0;
        for (int m = 0; m < 3; m++) {
            jf[k] += J[6 + k][m] * u[3 + m] + J[6 + k][3 + m] * u[6 + m] + J[6 + k][6 + m] * tddd[m];
            jb[k] += J[9 + k][m] * u[3 + m] + J[9 + k][3 + m] * u[6 + m] + J[9 + k][6 + m] * tddd[m];
        }
    }
    const double h = 1e-3 / scale;
    const double offsets[4] = {-2 * h, -h, h, 2 * h};
    double y[4][N_OUT];
    for (int n = 0; n < 4; n++) {
        const double t = offsets[n];
        double v[N_IN];
        for (int k = 0; k < 3; k++) {
            v[k] = u[k] + u[3 + k] * t + u[6 + k] * t * t / 2 + tddd[k] * t * t * t / 6;
            v[3 + k] = u[3 + k] + u[6 + k] * t + tddd[k] * t * t / 2;
            v[6 + k] = u[6 + k] + tddd[k] * t;
        }
        outputs(v, y[n]);
    }
    for (int k = 0; k < 3; k++) {
        const double dfixed = (y[0][6 + k] - 8 * y[1][6 + k] + 8 * y[2][6 + k] - y[3][6 + k]) / (12 * h);
        const double dbody = (y[0][9 + k] - 8 * y[1][9 + k] + 8 * y[2][9 + k] - y[3][9 + k]) / (12 * h);
        ak_check_close(jf[k], dfixed, 1e-7 * pow(scale, 3),
                       "jerk_fixed vs d(alpha_fixed)/dt [%d]", k);
        ak_check_close(jb[k], dbody, 1e-7 * pow(scale, 3), "jerk_body vs d(alpha_body)/dt [%d]", k);
    }
}

int main(void) {
    srand(2468);
    for (int n = 0; n < 5000; n++) {
        /* Rates of size s, accelerations s^2, jerks s^3: every term of an output has one size. */
        const double scale = pow(10.0, random_in(-2.0, 2.0));
        double u[N_IN], tddd[3];
        for (int k = 0; k < 3; k++) {
            u[k] = random_in(-7.0, 7.0);
            u[3 + k] = scale * random_in(-1.0, 1.0);
            u[6 + k] = scale * scale * random_in(-1.0, 1.0);
            tddd[k] = scale * scale * scale * random_in(-1.0, 1.0);
        }
        if (n % 5 == 0) {
            u[1] = 1.5707963267948966; /* gimbal lock changes nothing for this map */
        }
        check_jacobian(u, scale);
        check_jerk(u, tddd, scale);
    }
    printf("%d checks, %d failures\n", ak_check_count(), ak_check_failures());
    return ak_check_exit_status();
}
