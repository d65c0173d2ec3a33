/* Instance initial condition and the lazy evaluation of the outputs. */
#include "fmi2_instance.h"

#include "fmi2_logging.h"
#include "kinematics.h"

void ak_instance_reset(ak_instance *instance) {
    for (int category = 0; category < AK_N_LOG_CATEGORIES; category++) {
        /* Errors and warnings are reported unless switched off; the call trace only on request. */
        instance->log_enabled[category] =
            category != AK_LOG_CALLS || instance->logging_on_at_instantiation;
    }
    instance->state = AK_STATE_INSTANTIATED;
    instance->time = 0.0;
    instance->stop_time_defined = false;
    instance->stop_time = 0.0;
    for (int vr = 0; vr < AK_N_VARIABLES; vr++) {
        instance->values[vr] = AK_VARIABLES[vr].start;
    }
    instance->outputs_stale = true;
    ak_instance_clear_input_derivatives(instance);
    instance->evaluations = 0;
}

void ak_instance_clear_input_derivatives(ak_instance *instance) {
    for (int k = 0; k < AK_N_INPUTS; k++) {
        for (int n = 0; n < AK_MAX_INPUT_DERIVATIVE_ORDER; n++) {
            instance->input_derivatives[k][n] = 0.0;
        }
    }
    instance->any_input_derivative = false;
}

void ak_instance_update_outputs(ak_instance *instance) {
    if (!instance->outputs_stale) {
        return;
    }
    double *v = instance->values;
    ak_angular_kinematics_123(&v[AK_VR_THETA], &v[AK_VR_THETA_DOT], &v[AK_VR_THETA_DDOT],
                              &v[AK_VR_OMEGA_FIXED], &v[AK_VR_OMEGA_BODY],
                              &v[AK_VR_ALPHA_FIXED], &v[AK_VR_ALPHA_BODY]);
    instance->outputs_stale = false;
    instance->evaluations++;
    if (ak_log_on(instance, AK_LOG_CALLS)) {
        ak_log(instance, AK_LOG_CALLS, fmi2OK, "kinematics evaluated (evaluation %lu)",
               instance->evaluations);
    }
}
