/* R and the quaternion of the angles, one at a time (kinematics_general.h, sections 1 and 5), and
 * the half-angle sines: what AngularKinematics' outputs and the Jacobian of the general core
 * (kinematics_general_jacobian.c) both need. */
#include "kinematics_chain.h"

#include <math.h>

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

void ak_general_rotation_matrix(const ak_sequence *sequence, const double theta[3], double R[3][3]) {
    chain ch;
    ak_chain_of_angles(sequence, theta, &ch);
    chain_rotation_matrix(&ch, R);
}

void ak_general_quaternion(const ak_sequence *sequence, const double theta[3], double q[4]) {
    chain ch;
    ak_sines sines, half;
    ak_angle_sines(theta, &sines);
    chain_of_sines(sequence, &sines, &ch);
    ak_half_angle_sines(&sines, &half);
    chain_quaternion(&ch, &half, q);
}
