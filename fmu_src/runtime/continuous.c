/* Model exchange for both FMI versions; no model has event indicators, so no event happens. */
#include <math.h>

#include "runtime.h"

static bool refuse_count(const ak_instance *instance, const char *function, const char *count_name,
                         size_t n) {
    ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
           "%s: %s = %zu, but this FMU has %s (%s must be 0)", function, count_name, n,
           AK_MODEL.n_states == 0 ? "no continuous states and no event indicators"
                                  : "no event indicators",
           count_name);
    return false;
}

/* The call check, then an array of states, derivatives or nominals: one per state, given if any. */
static bool state_array(ak_instance *instance, const ak_function_rule *call,
                        const char *count_name, const char *array_name, const void *array,
                        size_t nx) {
    if (!ak_call_allowed(instance, call)) {
        return false;
    }
    if (AK_MODEL.n_states == 0 && nx != 0) {
        return refuse_count(instance, call->name, count_name, nx);
    }
    if (nx != (size_t)AK_MODEL.n_states) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: %s = %zu, but this FMU has %d continuous states (numberOfContinuousStates)",
               call->name, count_name, nx, AK_MODEL.n_states);
        return false;
    }
    return ak_given(instance, call->name, nx, count_name, array, array_name);
}

typedef enum { STATES, DERIVATIVES, NOMINALS } state_array_kind;

/* In Initialization Mode the states follow the parameters (DISCARD when they give none). */
static ak_status get_states(ak_instance *instance, const ak_function_rule *call,
                            const char *count_name, const char *array_name, double out[],
                            size_t nx, state_array_kind kind) {
    if (!state_array(instance, call, count_name, array_name, out, nx)) {
        return AK_STATUS_ERROR;
    }
    if (nx == 0) {
        return AK_STATUS_OK;
    }
    if (kind != NOMINALS && (instance->state & AK_INITIALIZATION_MODE) != 0 &&
        ak_instance_update(instance, AK_GROUP_MAIN) == AK_STATUS_DISCARD) {
        return AK_STATUS_DISCARD;
    }
    if (kind == DERIVATIVES) {
        AK_MODEL.derivatives(&instance->data); /* cheap, and exact for the current states */
    }
    const unsigned int *vrs = kind == DERIVATIVES ? AK_MODEL.derivative_vrs : AK_MODEL.state_vrs;
    for (size_t k = 0; k < nx; k++) {
        out[k] = kind == NOMINALS ? AK_MODEL.state_nominals[k] : instance->data.values[vrs[k]];
    }
    return AK_STATUS_OK;
}

ak_status ak_get_continuous_states(ak_instance *instance, const ak_function_rule *call,
                                   const char *count_name, const char *array_name, double x[],
                                   size_t nx) {
    return get_states(instance, call, count_name, array_name, x, nx, STATES);
}

ak_status ak_get_state_derivatives(ak_instance *instance, const ak_function_rule *call,
                                   const char *count_name, const char *array_name,
                                   double derivatives[], size_t nx) {
    return get_states(instance, call, count_name, array_name, derivatives, nx, DERIVATIVES);
}

ak_status ak_get_nominals(ak_instance *instance, const ak_function_rule *call,
                          const char *count_name, const char *array_name, double nominals[],
                          size_t nx) {
    return get_states(instance, call, count_name, array_name, nominals, nx, NOMINALS);
}

ak_status ak_set_continuous_states(ak_instance *instance, const ak_function_rule *call,
                                   const char *count_name, const char *array_name,
                                   const double x[], size_t nx) {
    if (!state_array(instance, call, count_name, array_name, x, nx)) {
        return AK_STATUS_ERROR;
    }
    for (size_t k = 0; k < nx; k++) {
        if (!isfinite(x[k])) {
            ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
                   "%s: %s[%zu] = %g (%s) is not finite; no state set", call->name, array_name,
                   k, x[k], AK_MODEL.variables[AK_MODEL.state_vrs[k]].name);
            return AK_STATUS_ERROR;
        }
    }
    for (size_t k = 0; k < nx; k++) {
        double *value = &instance->data.values[AK_MODEL.state_vrs[k]];
        if (*value != x[k]) {
            *value = x[k];
            ak_instance_inputs_changed(instance);
        }
    }
    return AK_STATUS_OK;
}

ak_status ak_set_time(ak_instance *instance, const ak_function_rule *call, double time) {
    if (!ak_call_allowed(instance, call)) {
        return AK_STATUS_ERROR;
    }
    if (!isfinite(time)) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR, "%s: time = %g is not finite", call->name,
               time);
        return AK_STATUS_ERROR;
    }
    /* No output depends on the time, which may go back when an integrator rejects a step. */
    ak_log(instance, AK_LOG_CALLS, AK_STATUS_OK, "%s: time = %.17g", call->name, time);
    instance->time = time;
    return AK_STATUS_OK;
}

ak_status ak_no_event_indicators(ak_instance *instance, const ak_function_rule *call,
                                 const char *count_name, size_t n) {
    if (!ak_call_allowed(instance, call)) {
        return AK_STATUS_ERROR;
    }
    return n == 0 || refuse_count(instance, call->name, count_name, n) ? AK_STATUS_OK
                                                                       : AK_STATUS_ERROR;
}
