/* The life cycle of both FMI versions: debug logging, the experiment, initialization, reset. */
#include <math.h>
#include <string.h>

#include "runtime.h"

ak_status ak_enter_state(ak_instance *instance, const ak_function_rule *call, ak_state state) {
    if (!ak_call_allowed(instance, call)) {
        return AK_STATUS_ERROR;
    }
    instance->state = state;
    return AK_STATUS_OK;
}

ak_status ak_reset(ak_instance *instance, const ak_function_rule *call) {
    if (!ak_call_allowed(instance, call)) {
        return AK_STATUS_ERROR;
    }
    ak_instance_reset(instance);
    return AK_STATUS_OK;
}

ak_status ak_set_debug_logging(ak_instance *instance, const ak_function_rule *call, bool on,
                               size_t n, const char *const categories[]) {
    if (!ak_call_allowed(instance, call) ||
        !ak_given(instance, call->name, n, "nCategories", categories, "categories")) {
        return AK_STATUS_ERROR;
    }
    bool named[AK_N_LOG_CATEGORIES] = {false};
    for (size_t i = 0; i < n; i++) { /* every name checked before anything changes */
        int c = 0;
        while (c < AK_N_LOG_CATEGORIES &&
               (categories[i] == NULL || strcmp(categories[i], AK_LOG_CATEGORY_NAMES[c]) != 0)) {
            c++;
        }
        if (c == AK_N_LOG_CATEGORIES) {
            ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
                   "%s: categories[%zu] = \"%s\" is not a log category of this FMU "
                   "(" AK_LOG_CATEGORY_LIST ")",
                   call->name, i, categories[i] ? categories[i] : "(null)");
            return AK_STATUS_ERROR;
        }
        named[c] = true;
    }
    on = on && instance->has_logger; /* nothing reaches an importer that gave no logger */
    for (int c = 0; c < AK_N_LOG_CATEGORIES; c++) {
        if (n == 0 || named[c]) {
            instance->log_enabled[c] = on;
        }
    }
    return AK_STATUS_OK;
}

ak_status ak_setup_experiment(ak_instance *instance, const ak_function_rule *call,
                              bool tolerance_defined, double tolerance, double start_time,
                              bool stop_time_defined, double stop_time, ak_state then) {
    if (!ak_call_allowed(instance, call)) {
        return AK_STATUS_ERROR;
    }
    if (tolerance_defined && !(isfinite(tolerance) && tolerance >= 0.0)) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: tolerance = %g must be finite and >= 0", call->name, tolerance);
        return AK_STATUS_ERROR;
    }
    if (!isfinite(start_time)) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR, "%s: startTime = %g is not finite",
               call->name, start_time);
        return AK_STATUS_ERROR;
    }
    if (stop_time_defined && !(isfinite(stop_time) && stop_time >= start_time)) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: stopTime = %.17g must be finite and >= startTime = %.17g", call->name,
               stop_time, start_time);
        return AK_STATUS_ERROR;
    }
    /* No model integrates with an error control: the tolerance has nothing to control. */
    instance->time = start_time;
    instance->stop_time_defined = stop_time_defined;
    instance->stop_time = stop_time;
    instance->state = then;
    return AK_STATUS_OK;
}

ak_status ak_exit_initialization_mode(ak_instance *instance, const ak_function_rule *call) {
    if (!ak_call_allowed(instance, call)) {
        return AK_STATUS_ERROR;
    }
    if (AK_MODEL.initialize != NULL) {
        if (AK_MODEL.initialize(&instance->data) == AK_EVAL_FAILED) {
            ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
                   "%s: the parameters give no initial state (see the message before); the "
                   "instance stays in %s",
                   call->name, ak_state_name(instance, AK_INITIALIZATION_MODE));
            return AK_STATUS_ERROR;
        }
        ak_instance_inputs_changed(instance);
    }
    /* The outputs at the initial inputs; a failed evaluation is reported by the reads. */
    (void)ak_instance_update(instance, AK_GROUP_MAIN);
    instance->state = instance->interface == AK_MODEL_EXCHANGE ? AK_EVENT_MODE : AK_STEP_MODE;
    return AK_STATUS_OK;
}

void ak_instance_release(ak_instance *instance) {
    ak_free_all_fmu_states(instance);
    instance->layer->release(instance, instance->instance_name);
}
