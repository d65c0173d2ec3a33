/* The partial angular velocity matrices and their time derivatives (kinematics_general.h,
 * sections 2 and 3), alone: AngularKinematics' Jacobian and AttitudePropagator's angle rates. */
#include "kinematics_chain.h"

void ak_general_partials(const ak_sequence *sequence, const double theta[3],
                         const double theta_dot[3], double W_fixed[3][3], double W_body[3][3],
                         double W_fixed_dot[3][3], double W_body_dot[3][3]) {
    chain ch;
    ak_chain_of_angles(sequence, theta, &ch);
    chain_partials(&ch, theta_dot, W_fixed, W_body, W_fixed_dot, W_body_dot);
}
