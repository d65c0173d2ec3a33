/* The EulerRates model: the inverse map. Angles of any of the 24 rotation sequences, the angular
 * velocity and its time derivative in the components of one frame (parameter frame) in; the
 * first and second time derivatives of the angles, alpha in both sets of components and the
 * distance to the sequence's singular configuration out.
 *
 * Near the singularity (kinematics_general.h, section 6): below `tolerance` the outputs are
 * computed and a warning is logged (fmi2Warning); at the singularity itself, or when a result
 * overflows, the evaluation fails with a message naming theta[2], its value and the distance,
 * the outputs keep their last valid values (singularity_distance excepted: it is always the
 * current one), reads return fmi2Discard and so does fmi2DoStep (fmi2_stepping.c). */
#include "EulerRates_variables.h"

#include "kinematics_general.h"

_Static_assert(ER_N_VALUE_REFERENCES <= AK_MAX_VARIABLES, "the value array holds them");

static ak_eval_status evaluate(ak_model_data *data) {
    double *v = data->values;
    const ak_sequence *sequence = &AK_SEQUENCES[(int)v[ER_VR_SEQUENCE] - 1];
    const ak_frame frame = (int)v[ER_VR_FRAME] == 2 ? AK_FRAME_BODY : AK_FRAME_FIXED;
    const double tolerance = v[ER_VR_TOLERANCE];
    double theta_dot[3], theta_ddot[3], alpha_fixed[3], alpha_body[3], distance;
    const ak_rates_status status = ak_general_euler_rates(
        sequence, frame, &v[ER_VR_THETA], &v[ER_VR_OMEGA], &v[ER_VR_OMEGA_DOT], tolerance,
        theta_dot, theta_ddot, alpha_fixed, alpha_body, &distance);
    v[ER_VR_SINGULARITY_DISTANCE] = distance;
    const char *singular_at = sequence->proper_euler ? "0 or pi" : "+-pi/2";
    if (status == AK_RATES_SINGULAR || status == AK_RATES_OVERFLOW) {
        ak_model_log(data, AK_LOG_WARNING, AK_STATUS_DISCARD,
               "%s: theta[2] = %.17g is %s the singular configuration of %s (theta[2] = %s): "
               "singularity_distance = %g; theta_dot and theta_ddot are not defined there; the "
               "outputs keep their last valid values",
               AK_MODEL.model_identifier, v[ER_VR_THETA + 1],
               status == AK_RATES_SINGULAR ? "at" : "so close to that the rates overflow at",
               sequence->name, singular_at, distance);
        return AK_EVAL_FAILED;
    }
    for (int k = 0; k < 3; k++) {
        v[ER_VR_THETA_DOT + k] = theta_dot[k];
        v[ER_VR_THETA_DDOT + k] = theta_ddot[k];
        v[ER_VR_ALPHA_FIXED + k] = alpha_fixed[k];
        v[ER_VR_ALPHA_BODY + k] = alpha_body[k];
    }
    if (status == AK_RATES_NEAR_SINGULAR) {
        ak_model_log(data, AK_LOG_WARNING, AK_STATUS_WARNING,
               "%s: theta[2] = %.17g is near the singular configuration of %s (theta[2] = %s): "
               "singularity_distance = %g < tolerance = %g; theta_dot[1] and theta_dot[3] grow "
               "as 1/singularity_distance",
               AK_MODEL.model_identifier, v[ER_VR_THETA + 1], sequence->name, singular_at,
               distance, tolerance);
        return AK_EVAL_WARNING;
    }
    return AK_EVAL_OK;
}

const ak_model AK_MODEL = {
    .model_identifier = "EulerRates",
    .guid = ER_GUID,
    .variables = ER_VARIABLES,
    .n_value_references = ER_N_VALUE_REFERENCES,
    .n_inputs = ER_N_INPUTS,
    .evaluate = evaluate,
    .evaluate_lazy = NULL,
    .jacobian = NULL,
    .output_derivatives = NULL,
    .can_interpolate_inputs = true,
    .derived = &ER_DERIVED_OUTPUTS,
    .evaluate_in_step = true,
};
