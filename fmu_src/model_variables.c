/* The variable table; see model_variables.h. */
#include "model_variables.h"

const ak_variable AK_VARIABLES[AK_N_VARIABLES] = {
    {0, "theta[1]", AK_CAUSALITY_INPUT, "Angle", "rad", 0.0, "angle 1 of the body-fixed 1-2-3 sequence", 0, {0}},
    {1, "theta[2]", AK_CAUSALITY_INPUT, "Angle", "rad", 0.0, "angle 2 of the body-fixed 1-2-3 sequence", 0, {0}},
    {2, "theta[3]", AK_CAUSALITY_INPUT, "Angle", "rad", 0.0, "angle 3 of the body-fixed 1-2-3 sequence", 0, {0}},
    {3, "theta_dot[1]", AK_CAUSALITY_INPUT, "AngularVelocity", "rad/s", 0.0, "first time derivative of theta[1]", 0, {0}},
    {4, "theta_dot[2]", AK_CAUSALITY_INPUT, "AngularVelocity", "rad/s", 0.0, "first time derivative of theta[2]", 0, {0}},
    {5, "theta_dot[3]", AK_CAUSALITY_INPUT, "AngularVelocity", "rad/s", 0.0, "first time derivative of theta[3]", 0, {0}},
    {6, "theta_ddot[1]", AK_CAUSALITY_INPUT, "AngularAcceleration", "rad/s2", 0.0, "second time derivative of theta[1]", 0, {0}},
    {7, "theta_ddot[2]", AK_CAUSALITY_INPUT, "AngularAcceleration", "rad/s2", 0.0, "second time derivative of theta[2]", 0, {0}},
    {8, "theta_ddot[3]", AK_CAUSALITY_INPUT, "AngularAcceleration", "rad/s2", 0.0, "second time derivative of theta[3]", 0, {0}},
    {9, "omega_fixed[1]", AK_CAUSALITY_OUTPUT, "AngularVelocity", "rad/s", 0.0, "fixed-frame component 1 of the angular velocity of the body", 3, {1, 3, 5}},
    {10, "omega_fixed[2]", AK_CAUSALITY_OUTPUT, "AngularVelocity", "rad/s", 0.0, "fixed-frame component 2 of the angular velocity of the body", 4, {0, 1, 4, 5}},
    {11, "omega_fixed[3]", AK_CAUSALITY_OUTPUT, "AngularVelocity", "rad/s", 0.0, "fixed-frame component 3 of the angular velocity of the body", 4, {0, 1, 4, 5}},
    {12, "omega_body[1]", AK_CAUSALITY_OUTPUT, "AngularVelocity", "rad/s", 0.0, "body-frame component 1 of the angular velocity of the body", 4, {1, 2, 3, 4}},
    {13, "omega_body[2]", AK_CAUSALITY_OUTPUT, "AngularVelocity", "rad/s", 0.0, "body-frame component 2 of the angular velocity of the body", 4, {1, 2, 3, 4}},
    {14, "omega_body[3]", AK_CAUSALITY_OUTPUT, "AngularVelocity", "rad/s", 0.0, "body-frame component 3 of the angular velocity of the body", 3, {1, 3, 5}},
    {15, "alpha_fixed[1]", AK_CAUSALITY_OUTPUT, "AngularAcceleration", "rad/s2", 0.0, "fixed-frame component 1 of the angular acceleration of the body", 5, {1, 4, 5, 6, 8}},
    {16, "alpha_fixed[2]", AK_CAUSALITY_OUTPUT, "AngularAcceleration", "rad/s2", 0.0, "fixed-frame component 2 of the angular acceleration of the body", 7, {0, 1, 3, 4, 5, 7, 8}},
    {17, "alpha_fixed[3]", AK_CAUSALITY_OUTPUT, "AngularAcceleration", "rad/s2", 0.0, "fixed-frame component 3 of the angular acceleration of the body", 7, {0, 1, 3, 4, 5, 7, 8}},
    {18, "alpha_body[1]", AK_CAUSALITY_OUTPUT, "AngularAcceleration", "rad/s2", 0.0, "body-frame component 1 of the angular acceleration of the body", 7, {1, 2, 3, 4, 5, 6, 7}},
    {19, "alpha_body[2]", AK_CAUSALITY_OUTPUT, "AngularAcceleration", "rad/s2", 0.0, "body-frame component 2 of the angular acceleration of the body", 7, {1, 2, 3, 4, 5, 6, 7}},
    {20, "alpha_body[3]", AK_CAUSALITY_OUTPUT, "AngularAcceleration", "rad/s2", 0.0, "body-frame component 3 of the angular acceleration of the body", 5, {1, 3, 4, 6, 8}},
};

const char *ak_causality_name(ak_causality causality) {
    return causality == AK_CAUSALITY_INPUT ? "input" : "output";
}
