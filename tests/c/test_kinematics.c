/* Unit tests of the kinematics core, independent of the FMI layer.
 *
 * Each check derives the expected value another way than the core does:
 *   - R from the product of elementary rotation matrices;
 *   - omega from the skew matrix dR/dt R^T, with dR/dt from the chain rule;
 *   - omega_body = R^T omega_fixed, alpha_body = R^T alpha_fixed;
 *   - alpha from a central difference of omega along a smooth trajectory.
 */
#include "kinematics_123.h"
#include "rotation_matrices.h"
#include "test_check.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static void transpose_times(double R[3][3], const double v[3], double out[3]) {
    for (int k = 0; k < 3; k++) {
        out[k] = R[0][k] * v[0] + R[1][k] * v[1] + R[2][k] * v[2];
    }
}

static double random_in(double low, double high) {
    return low + (high - low) * ((double)rand() / (double)RAND_MAX);
}

static void check_state(const double theta[3], const double td[3], const double tdd[3]) {
    double M[3][3][3], dM[3][3][3], tmp[3][3], R[3][3], R_core[3][3];
    double wf[3], wb[3], af[3], ab[3];
    const double scale_w = fabs(td[0]) + fabs(td[1]) + fabs(td[2]);
    const double scale_a = fabs(tdd[0]) + fabs(tdd[1]) + fabs(tdd[2]) + scale_w * scale_w;

    for (int a = 0; a < 3; a++) {
        elementary_rotation(a, theta[a], M[a], dM[a]);
    }
    multiply(M[0], M[1], tmp);
    multiply(tmp, M[2], R);
    ak_rotation_matrix_123(theta, R_core);
    for (int r = 0; r < 3; r++) {
        for (int k = 0; k < 3; k++) {
            ak_check_close(R_core[r][k], R[r][k], 4e-16, "R");
        }
    }

    /* dR/dt = sum_a (R1 .. dRa .. R3) td_a, and skew(omega_fixed) = dR/dt R^T. */
    double Rdot[3][3] = {{0}};
    for (int a = 0; a < 3; a++) {
        double P[3][3], Q[3][3];
        multiply(a == 0 ? dM[0] : M[0], a == 1 ? dM[1] : M[1], P);
        multiply(P, a == 2 ? dM[2] : M[2], Q);
        for (int r = 0; r < 3; r++) {
            for (int k = 0; k < 3; k++) {
                Rdot[r][k] += Q[r][k] * td[a];
            }
        }
    }
    double S[3][3];
    for (int r = 0; r < 3; r++) {
        for (int k = 0; k < 3; k++) {
            S[r][k] = Rdot[r][0] * R[k][0] + Rdot[r][1] * R[k][1] + Rdot[r][2] * R[k][2];
        }
    }

    ak_angular_kinematics_123(theta, td, tdd, wf, wb, af, ab);
    ak_check_close(wf[0], S[2][1], 1e-14 * scale_w, "omega_fixed[1] vs skew");
    ak_check_close(wf[1], S[0][2], 1e-14 * scale_w, "omega_fixed[2] vs skew");
    ak_check_close(wf[2], S[1][0], 1e-14 * scale_w, "omega_fixed[3] vs skew");

    double rotated[3];
    transpose_times(R, wf, rotated);
    for (int k = 0; k < 3; k++) {
        ak_check_close(wb[k], rotated[k], 1e-14 * scale_w, "omega_body = R^T omega_fixed");
    }
    transpose_times(R, af, rotated);
    for (int k = 0; k < 3; k++) {
        ak_check_close(ab[k], rotated[k], 1e-14 * scale_a, "alpha_body = R^T alpha_fixed");
    }

    /* alpha = d(omega)/dt along theta(t) = theta + td t + tdd t^2 / 2, a fourth-order difference. */
    const double h = 1e-3 / (1.0 + scale_w + sqrt(fabs(tdd[0]) + fabs(tdd[1]) + fabs(tdd[2])));
    double wf_steps[4][3], wb_steps[4][3], unused[3][3];
    const double offsets[4] = {-2 * h, -h, h, 2 * h};
    for (int n = 0; n < 4; n++) {
        double th[3], thd[3];
        for (int k = 0; k < 3; k++) {
            th[k] = theta[k] + td[k] * offsets[n] + 0.5 * tdd[k] * offsets[n] * offsets[n];
            thd[k] = td[k] + tdd[k] * offsets[n];
        }
        ak_angular_kinematics_123(th, thd, tdd, wf_steps[n], wb_steps[n], unused[0], unused[1]);
    }
    for (int k = 0; k < 3; k++) {
        const double dwf = (wf_steps[0][k] - 8 * wf_steps[1][k] + 8 * wf_steps[2][k] - wf_steps[3][k]) / (12 * h);
        const double dwb = (wb_steps[0][k] - 8 * wb_steps[1][k] + 8 * wb_steps[2][k] - wb_steps[3][k]) / (12 * h);
        ak_check_close(af[k], dwf, 1e-7 * scale_a, "alpha_fixed = d(omega_fixed)/dt");
        ak_check_close(ab[k], dwb, 1e-7 * scale_a, "alpha_body = d(omega_body)/dt");
    }
}

static void check_identity_orientation(void) {
    const double zero[3] = {0, 0, 0}, td[3] = {0.3, -1.2, 2.5}, tdd[3] = {-4.0, 0.7, 1.1};
    double wf[3], wb[3], af[3], ab[3];
    ak_angular_kinematics_123(zero, td, tdd, wf, wb, af, ab);
    for (int k = 0; k < 3; k++) {
        ak_check_close(wf[k], td[k], 0.0, "omega_fixed at theta = 0");
        ak_check_close(wb[k], td[k], 0.0, "omega_body at theta = 0");
    }
    /* At theta = 0 only the products of rates remain beside tdd: alpha1 = tdd1 + td2 td3. */
    ak_check_close(af[0], tdd[0] + td[1] * td[2], 1e-15, "alpha_fixed[1] at theta = 0");
    ak_check_close(ab[2], tdd[2] + td[0] * td[1], 1e-15, "alpha_body[3] at theta = 0");
}

int main(void) {
    const double half_pi = 1.5707963267948966;
    srand(12345);
    check_identity_orientation();
    for (int n = 0; n < 20000; n++) {
        double theta[3], td[3], tdd[3];
        const double magnitude = pow(10.0, random_in(-3.0, 3.0));
        for (int k = 0; k < 3; k++) {
            theta[k] = random_in(-7.0, 7.0);
            td[k] = magnitude * random_in(-1.0, 1.0);
            tdd[k] = magnitude * magnitude * random_in(-1.0, 1.0);
        }
        if (n % 4 == 0) {
            theta[1] = (n % 8 == 0 ? 1 : -1) * half_pi + random_in(-1e-9, 1e-9);
        }
        check_state(theta, td, tdd);
    }
    printf("%d checks, %d failures\n", ak_check_count(), ak_check_failures());
    return ak_check_exit_status();
}
