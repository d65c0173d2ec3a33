/* Instance initial condition and the lazy evaluation of the outputs. */
#include "fmi2_instance.h"

#include "fmi2_logging.h"

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
    for (int vr = 0; vr < AK_MAX_VARIABLES; vr++) {
        instance->values[vr] = vr < AK_MODEL.n_variables ? AK_MODEL.variables[vr].start : 0.0;
    }
    ak_instance_inputs_changed(instance);
    instance->lazy_stale = true;
    instance->evaluation_status = AK_EVAL_OK;
    ak_instance_clear_input_derivatives(instance);
    instance->evaluations = 0;
}

void ak_instance_clear_input_derivatives(ak_instance *instance) {
    for (int k = 0; k < AK_MAX_INPUTS; k++) {
        for (int n = 0; n < AK_MAX_INPUT_DERIVATIVE_ORDER; n++) {
            instance->input_derivatives[k][n] = 0.0;
        }
    }
    instance->any_input_derivative = false;
}

ak_eval_status ak_instance_update_outputs(ak_instance *instance) {
    if (!instance->outputs_stale) {
        return instance->evaluation_status;
    }
    instance->evaluation_status = AK_MODEL.evaluate(instance);
    instance->outputs_stale = false;
    instance->lazy_stale = true;
    instance->evaluations++;
    if (ak_log_on(instance, AK_LOG_CALLS)) {
        ak_log(instance, AK_LOG_CALLS, fmi2OK, "kinematics evaluated (evaluation %lu)",
               instance->evaluations);
    }
    return instance->evaluation_status;
}

ak_eval_status ak_instance_update_all_outputs(ak_instance *instance) {
    const ak_eval_status status = ak_instance_update_outputs(instance);
    if (instance->lazy_stale && status != AK_EVAL_FAILED && AK_MODEL.evaluate_lazy) {
        AK_MODEL.evaluate_lazy(instance);
        instance->lazy_stale = false;
        if (ak_log_on(instance, AK_LOG_CALLS)) {
            ak_log(instance, AK_LOG_CALLS, fmi2OK, "lazy outputs evaluated");
        }
    }
    return status;
}

fmi2Status ak_instance_read_status(const ak_instance *instance, ak_eval_status status) {
    switch (status) {
    case AK_EVAL_OK:
        return fmi2OK;
    case AK_EVAL_WARNING:
        return fmi2Warning;
    case AK_EVAL_FAILED:
    default:
        /* FMI 2.0.4, 2.1.3: fmi2Discard is the model-exchange answer to "a function is outside
         * of its domain", and for co-simulation the master "has to decide if the simulation run
         * can be continued"; fmi2Error would make the instance unusable, which it is not. */
        (void)instance;
        return fmi2Discard;
    }
}
