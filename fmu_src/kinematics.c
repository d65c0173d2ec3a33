/* Angular kinematics core: the equations are stated in kinematics.h. */
#include "kinematics.h"

#include <math.h>

void ak_angular_kinematics_123(const double theta[3], const double theta_dot[3],
                               const double theta_ddot[3], double omega_fixed[3],
                               double omega_body[3], double alpha_fixed[3], double alpha_body[3]) {
    const double s1 = sin(theta[0]), c1 = cos(theta[0]);
    const double s2 = sin(theta[1]), c2 = cos(theta[1]);
    const double s3 = sin(theta[2]), c3 = cos(theta[2]);
    const double td1 = theta_dot[0], td2 = theta_dot[1], td3 = theta_dot[2];
    const double tdd1 = theta_ddot[0], tdd2 = theta_ddot[1], tdd3 = theta_ddot[2];
    const double s1c2 = s1 * c2, c1c2 = c1 * c2;
    const double c2c3 = c2 * c3, c2s3 = c2 * s3;

    omega_fixed[0] = td1 + s2 * td3;
    omega_fixed[1] = c1 * td2 - s1c2 * td3;
    omega_fixed[2] = s1 * td2 + c1c2 * td3;

    omega_body[0] = c2c3 * td1 + s3 * td2;
    omega_body[1] = -c2s3 * td1 + c3 * td2;
    omega_body[2] = s2 * td1 + td3;

    alpha_fixed[0] = tdd1 + s2 * tdd3 + c2 * td2 * td3;
    alpha_fixed[1] = c1 * tdd2 - s1c2 * tdd3 - s1 * td1 * td2 + (s1 * s2 * td2 - c1c2 * td1) * td3;
    alpha_fixed[2] = s1 * tdd2 + c1c2 * tdd3 + c1 * td1 * td2 - (s1c2 * td1 + c1 * s2 * td2) * td3;

    alpha_body[0] = c2c3 * tdd1 + s3 * tdd2 - (s2 * c3 * td2 + c2s3 * td3) * td1 + c3 * td3 * td2;
    alpha_body[1] = -c2s3 * tdd1 + c3 * tdd2 + (s2 * s3 * td2 - c2c3 * td3) * td1 - s3 * td3 * td2;
    alpha_body[2] = s2 * tdd1 + tdd3 + c2 * td2 * td1;
}

void ak_rotation_matrix_123(const double theta[3], double R[3][3]) {
    const double s1 = sin(theta[0]), c1 = cos(theta[0]);
    const double s2 = sin(theta[1]), c2 = cos(theta[1]);
    const double s3 = sin(theta[2]), c3 = cos(theta[2]);

    R[0][0] = c2 * c3;
    R[0][1] = -c2 * s3;
    R[0][2] = s2;
    R[1][0] = c1 * s3 + s1 * s2 * c3;
    R[1][1] = c1 * c3 - s1 * s2 * s3;
    R[1][2] = -s1 * c2;
    R[2][0] = s1 * s3 - c1 * s2 * c3;
    R[2][1] = s1 * c3 + c1 * s2 * s3;
    R[2][2] = c1 * c2;
}

/* Row indices of J: outputs in value-reference order minus the 9 inputs. */
enum { OMEGA_FIXED = 0, OMEGA_BODY = 3, ALPHA_FIXED = 6, ALPHA_BODY = 9 };
/* Column indices of J. */
enum { THETA = 0, TD = 3, TDD = 6 };

void ak_angular_kinematics_123_jacobian(const double theta[3], const double theta_dot[3],
                                        const double theta_ddot[3],
                                        double J[AK_KINEMATICS_N_OUTPUTS][AK_KINEMATICS_N_INPUTS]) {
    const double s1 = sin(theta[0]), c1 = cos(theta[0]);
    const double s2 = sin(theta[1]), c2 = cos(theta[1]);
    const double s3 = sin(theta[2]), c3 = cos(theta[2]);
    const double td1 = theta_dot[0], td2 = theta_dot[1], td3 = theta_dot[2];
    const double tdd1 = theta_ddot[0], tdd2 = theta_ddot[1], tdd3 = theta_ddot[2];

    for (int i = 0; i < AK_KINEMATICS_N_OUTPUTS; i++) {
        for (int j = 0; j < AK_KINEMATICS_N_INPUTS; j++) {
            J[i][j] = 0.0;
        }
    }
    /* W and W': d omega / d td and d alpha / d tdd. */
    const double W[3][3] = {{1.0, 0.0, s2}, {0.0, c1, -s1 * c2}, {0.0, s1, c1 * c2}};
    const double Wb[3][3] = {{c2 * c3, s3, 0.0}, {-c2 * s3, c3, 0.0}, {s2, 0.0, 1.0}};
    for (int i = 0; i < 3; i++) {
        for (int k = 0; k < 3; k++) {
            J[OMEGA_FIXED + i][TD + k] = W[i][k];
            J[ALPHA_FIXED + i][TDD + k] = W[i][k];
            J[OMEGA_BODY + i][TD + k] = Wb[i][k];
            J[ALPHA_BODY + i][TDD + k] = Wb[i][k];
        }
    }

    /* omega_fixed */
    J[OMEGA_FIXED + 0][THETA + 1] = c2 * td3;
    J[OMEGA_FIXED + 1][THETA + 0] = -s1 * td2 - c1 * c2 * td3;
    J[OMEGA_FIXED + 1][THETA + 1] = s1 * s2 * td3;
    J[OMEGA_FIXED + 2][THETA + 0] = c1 * td2 - s1 * c2 * td3;
    J[OMEGA_FIXED + 2][THETA + 1] = -c1 * s2 * td3;

    /* omega_body */
    J[OMEGA_BODY + 0][THETA + 1] = -s2 * c3 * td1;
    J[OMEGA_BODY + 0][THETA + 2] = -c2 * s3 * td1 + c3 * td2;
    J[OMEGA_BODY + 1][THETA + 1] = s2 * s3 * td1;
    J[OMEGA_BODY + 1][THETA + 2] = -c2 * c3 * td1 - s3 * td2;
    J[OMEGA_BODY + 2][THETA + 1] = c2 * td1;

    /* alpha_fixed */
    J[ALPHA_FIXED + 0][THETA + 1] = c2 * tdd3 - s2 * td2 * td3;
    J[ALPHA_FIXED + 0][TD + 1] = c2 * td3;
    J[ALPHA_FIXED + 0][TD + 2] = c2 * td2;

    J[ALPHA_FIXED + 1][THETA + 0] =
        -s1 * tdd2 - c1 * c2 * tdd3 - c1 * td1 * td2 + (c1 * s2 * td2 + s1 * c2 * td1) * td3;
    J[ALPHA_FIXED + 1][THETA + 1] = s1 * s2 * tdd3 + (s1 * c2 * td2 + c1 * s2 * td1) * td3;
    J[ALPHA_FIXED + 1][TD + 0] = -s1 * td2 - c1 * c2 * td3;
    J[ALPHA_FIXED + 1][TD + 1] = -s1 * td1 + s1 * s2 * td3;
    J[ALPHA_FIXED + 1][TD + 2] = s1 * s2 * td2 - c1 * c2 * td1;

    J[ALPHA_FIXED + 2][THETA + 0] =
        c1 * tdd2 - s1 * c2 * tdd3 - s1 * td1 * td2 + (s1 * s2 * td2 - c1 * c2 * td1) * td3;
    J[ALPHA_FIXED + 2][THETA + 1] = -c1 * s2 * tdd3 + (s1 * s2 * td1 - c1 * c2 * td2) * td3;
    J[ALPHA_FIXED + 2][TD + 0] = c1 * td2 - s1 * c2 * td3;
    J[ALPHA_FIXED + 2][TD + 1] = c1 * td1 - c1 * s2 * td3;
    J[ALPHA_FIXED + 2][TD + 2] = -(s1 * c2 * td1 + c1 * s2 * td2);

    /* alpha_body */
    J[ALPHA_BODY + 0][THETA + 1] = -s2 * c3 * tdd1 - (c2 * c3 * td2 - s2 * s3 * td3) * td1;
    J[ALPHA_BODY + 0][THETA + 2] =
        -c2 * s3 * tdd1 + c3 * tdd2 + (s2 * s3 * td2 - c2 * c3 * td3) * td1 - s3 * td2 * td3;
    J[ALPHA_BODY + 0][TD + 0] = -(s2 * c3 * td2 + c2 * s3 * td3);
    J[ALPHA_BODY + 0][TD + 1] = -s2 * c3 * td1 + c3 * td3;
    J[ALPHA_BODY + 0][TD + 2] = -c2 * s3 * td1 + c3 * td2;

    J[ALPHA_BODY + 1][THETA + 1] = s2 * s3 * tdd1 + (c2 * s3 * td2 + s2 * c3 * td3) * td1;
    J[ALPHA_BODY + 1][THETA + 2] =
        -c2 * c3 * tdd1 - s3 * tdd2 + (s2 * c3 * td2 + c2 * s3 * td3) * td1 - c3 * td2 * td3;
    J[ALPHA_BODY + 1][TD + 0] = s2 * s3 * td2 - c2 * c3 * td3;
    J[ALPHA_BODY + 1][TD + 1] = s2 * s3 * td1 - s3 * td3;
    J[ALPHA_BODY + 1][TD + 2] = -c2 * c3 * td1 - s3 * td2;

    J[ALPHA_BODY + 2][THETA + 1] = c2 * tdd1 - s2 * td1 * td2;
    J[ALPHA_BODY + 2][TD + 0] = c2 * td2;
    J[ALPHA_BODY + 2][TD + 1] = c2 * td1;
}

void ak_angular_jerk_123(const double theta[3], const double theta_dot[3],
                         const double theta_ddot[3], const double theta_dddot[3],
                         double jerk_fixed[3], double jerk_body[3]) {
    double J[AK_KINEMATICS_N_OUTPUTS][AK_KINEMATICS_N_INPUTS];
    ak_angular_kinematics_123_jacobian(theta, theta_dot, theta_ddot, J);
    /* The time derivatives of the inputs along the motion: (td, tdd, tddd). */
    double rate[AK_KINEMATICS_N_INPUTS];
    for (int k = 0; k < 3; k++) {
        rate[THETA + k] = theta_dot[k];
        rate[TD + k] = theta_ddot[k];
        rate[TDD + k] = theta_dddot[k];
    }
    for (int i = 0; i < 3; i++) {
        double fixed = 0.0, body = 0.0;
        for (int j = 0; j < AK_KINEMATICS_N_INPUTS; j++) {
            fixed += J[ALPHA_FIXED + i][j] * rate[j];
            body += J[ALPHA_BODY + i][j] * rate[j];
        }
        jerk_fixed[i] = fixed;
        jerk_body[i] = body;
    }
}
