/* Angular kinematics core: the equations are stated in kinematics.h. */
#include "kinematics_123.h"

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
