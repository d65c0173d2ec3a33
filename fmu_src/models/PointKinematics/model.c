/* The PointKinematics model: the body's angular velocity and acceleration, the motion of a
 * reference point O and the position of a point P relative to it in; the velocity and
 * acceleration of P, their parts and the specific force at P out, all in body components.
 * Equations: core/point_kinematics.h.
 *
 * Every output is a sum of products of inputs: finite inputs give finite outputs unless a product
 * overflows (|omega|^2 |r| above about 1.8e308). Then the evaluation fails with a message naming
 * the output, the outputs keep their last valid values, reads return fmi2Discard and so does
 * fmi2DoStep. */
#include "PointKinematics_variables.h"

#include <math.h>
#include <string.h>

#include "point_kinematics.h"

_Static_assert(PK_N_VALUE_REFERENCES <= AK_MAX_VARIABLES, "the value array holds them");
_Static_assert(PK_N_INPUTS <= AK_MAX_INPUTS, "the input arrays hold them");
/* The outputs are stored in one copy of ak_point_outputs: their value references follow it. */
_Static_assert(PK_VR_A_P == PK_VR_V_P + 3 && PK_VR_SPECIFIC_FORCE == PK_VR_A_P + 3 &&
                   PK_VR_A_TANGENTIAL == PK_VR_SPECIFIC_FORCE + 3 &&
                   PK_VR_A_CENTRIPETAL == PK_VR_A_TANGENTIAL + 3 &&
                   PK_VR_A_CORIOLIS == PK_VR_A_CENTRIPETAL + 3,
               "the outputs follow ak_point_outputs");
_Static_assert(sizeof(ak_point_outputs) == 18 * sizeof(double), "no padding");

/* The core's inputs: the input vectors of `values` (the instance's, or a tangent's). */
static ak_point_inputs inputs_of(const double *values) {
    return (ak_point_inputs){.omega = &values[PK_VR_OMEGA], .alpha = &values[PK_VR_ALPHA],
                             .v_O = &values[PK_VR_V_O], .a_O = &values[PK_VR_A_O],
                             .r = &values[PK_VR_R], .r_dot = &values[PK_VR_R_DOT],
                             .r_ddot = &values[PK_VR_R_DDOT], .g = &values[PK_VR_G]};
}

/* |v|, scaled so that it overflows only when it is above the largest double. */
static double size_of(const double v[3]) {
    const double largest = fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2])));
    if (largest == 0.0) {
        return 0.0;
    }
    const double x = v[0] / largest, y = v[1] / largest, z = v[2] / largest;
    return largest * sqrt(x * x + y * y + z * z);
}

static ak_eval_status evaluate(ak_model_data *data) {
    double *v = data->values;
    double kept[PK_N_OUTPUTS]; /* the last valid outputs, put back if the new ones overflow */
    memcpy(kept, &v[PK_VR_V_P], sizeof kept);
    const ak_point_inputs in = inputs_of(v);
    if (ak_point_kinematics(&in, (ak_point_outputs *)&v[PK_VR_V_P])) {
        return AK_EVAL_OK;
    }
    int k = 0;
    while (isfinite(v[PK_VR_V_P + k])) {
        k++;
    }
    ak_model_log(data, AK_LOG_WARNING, AK_STATUS_DISCARD,
                 "%s: %s = %g: a product of the inputs overflows (|omega| = %g, |alpha| = %g, "
                 "|r| = %g, |r_dot| = %g); the outputs keep their last valid values",
                 AK_MODEL.model_identifier, PK_VARIABLES[PK_VR_V_P + k].name, v[PK_VR_V_P + k],
                 size_of(in.omega), size_of(in.alpha), size_of(in.r), size_of(in.r_dot));
    memcpy(&v[PK_VR_V_P], kept, sizeof kept);
    return AK_EVAL_FAILED;
}

/* Column k of the Jacobian is the change of the outputs along input k (core's tangent). */
static void jacobian(const ak_model_data *data, const unsigned int out[], size_t n_out,
                     double J[][AK_MAX_KNOWNS]) {
    const ak_point_inputs in = inputs_of(data->values);
    for (int k = 0; k < PK_N_INPUTS; k++) {
        double direction[PK_N_INPUTS] = {0.0};
        direction[k] = 1.0;
        const ak_point_inputs d_in = inputs_of(direction);
        ak_point_outputs d_out;
        ak_point_kinematics_tangent(&in, &d_in, &d_out);
        const double *d = (const double *)&d_out;
        for (size_t i = 0; i < n_out; i++) {
            J[i][k] = d[out[i] - PK_VR_V_P];
        }
    }
}

const ak_model AK_MODEL = {
    .model_identifier = "PointKinematics",
    .guid = PK_GUID,
    .variables = PK_VARIABLES,
    .n_value_references = PK_N_VALUE_REFERENCES,
    .n_inputs = PK_N_INPUTS,
    .evaluate = evaluate,
    .evaluate_lazy = NULL,
    .jacobian = jacobian,
    .output_derivatives = NULL,
    .can_interpolate_inputs = true,
    .derived = &PK_DERIVED_OUTPUTS,
    .evaluate_in_step = true, /* an overflow fails the step, as a read */
};
