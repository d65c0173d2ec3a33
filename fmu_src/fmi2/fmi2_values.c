/* FMI 2.0 getters and setters. Every call checks all of its arguments before it touches a
 * value, so a rejected call changes nothing. The variables are the model's (fmi2_model.h):
 * Real inputs, Real outputs, and parameters of variability fixed (Real or Integer), which can be
 * set only in Instantiated and InitializationMode. */
#include <math.h>

#include "fmi2Functions.h"
#include "fmi2_derivatives.h"
#include "fmi2_instance.h"
#include "fmi2_logging.h"
#include "fmi2_state_machine.h"

/* NULL arrays are fine only when there is nothing to read or write. */
static bool arrays_given(const ak_instance *instance, ak_function function, size_t nvr,
                         const void *vr, const void *values) {
    if (nvr > 0 && (vr == NULL || values == NULL)) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error, "%s: %s is NULL with nvr = %zu",
               ak_function_name(function), vr == NULL ? "vr" : "value", nvr);
        return false;
    }
    return true;
}

static const char *type_name(ak_type type) {
    return type == AK_TYPE_INTEGER ? "Integer" : "Real";
}

/* The variable of a value reference of this model whose variable has the function's type, or
 * NULL after logging why not. */
static const ak_variable *variable_of_type(const ak_instance *instance, ak_function function,
                                           fmi2ValueReference vr, size_t index, ak_type type) {
    const ak_variable *variable = ak_variable_of(vr);
    if (variable == NULL) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error,
               "%s: vr[%zu] = %u is not a value reference of this FMU (0 to %d)",
               ak_function_name(function), index, vr, AK_MODEL.n_value_references - 1);
        return NULL;
    }
    if (variable->type != type) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error,
               "%s: vr[%zu] = %u is %s, of type %s, not %s",
               ak_function_name(function), index, vr, variable->name,
               type_name(variable->type), type_name(type));
        return NULL;
    }
    return variable;
}

/* A parameter may be set only before fmi2ExitInitializationMode (variability fixed); the value
 * must be one the model accepts. */
static bool parameter_settable(const ak_instance *instance, ak_function function, size_t index,
                               const ak_variable *variable, double value) {
    if ((instance->state & (AK_STATE_INSTANTIATED | AK_STATE_INITIALIZATION_MODE)) == 0) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error,
               "%s: %s (vr[%zu] = %u) is a parameter of variability fixed: it can be set only "
               "in Instantiated and InitializationMode, not in %s; no value set",
               ak_function_name(function), variable->name, index, variable->value_reference,
               ak_state_name(instance->state));
        return false;
    }
    const char *why = AK_MODEL.check_parameter(variable, value);
    if (why != NULL) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error, "%s: %s = %.17g (vr[%zu] = %u) %s; no value set",
               ak_function_name(function), variable->name, value, index,
               variable->value_reference, why);
        return false;
    }
    return true;
}

static void store(ak_instance *instance, ak_function function, bool trace, fmi2ValueReference vr,
                  double value) {
    if (trace) {
        const ak_variable *variable = ak_variable_of(vr); /* checked by the caller: never NULL */
        ak_log(instance, AK_LOG_CALLS, fmi2OK, "%s: %s = %.17g", ak_function_name(function),
               variable != NULL ? variable->name : "?", value);
    }
    /* Only a real change makes the outputs stale: masters often set unchanged inputs. */
    if (instance->data.values[vr] != value) {
        instance->data.values[vr] = value;
        ak_instance_inputs_changed(instance);
    }
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       fmi2Real value[]) {
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_GET_REAL) ||
        !arrays_given(instance, AK_FMI2_GET_REAL, nvr, vr, value)) {
        return fmi2Error;
    }
    /* The highest role read decides what must be brought up to date: nothing for inputs and
     * parameters, the main group for its outputs, both groups for a lazy output. */
    ak_real_role lowest = AK_REAL_LAZY_OUTPUT, highest = AK_REAL_INPUT;
    for (size_t i = 0; i < nvr; i++) {
        const ak_real_role role = ak_real_role_of(instance, vr[i]);
        lowest = role < lowest ? role : lowest;
        highest = role > highest ? role : highest;
    }
    if (lowest == AK_REAL_ABSENT) { /* the first such value reference, and why */
        size_t i = 0;
        while (ak_real_role_of(instance, vr[i]) != AK_REAL_ABSENT) {
            i++;
        }
        (void)variable_of_type(instance, AK_FMI2_GET_REAL, vr[i], i, AK_TYPE_REAL);
        return fmi2Error;
    }
    fmi2Status status = fmi2OK;
    if (highest == AK_REAL_LAZY_OUTPUT) {
        status = ak_instance_read_status(instance, ak_instance_update_all_outputs(instance));
    } else if (highest == AK_REAL_MAIN_OUTPUT) {
        status = ak_instance_read_status(instance, ak_instance_update_outputs(instance));
    }
    for (size_t i = 0; i < nvr; i++) {
        value[i] = instance->data.values[vr[i]];
    }
    return status;
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       const fmi2Real value[]) {
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_SET_REAL) ||
        !arrays_given(instance, AK_FMI2_SET_REAL, nvr, vr, value)) {
        return fmi2Error;
    }
    for (size_t i = 0; i < nvr; i++) {
        /* The usual call first: a finite value for an input needs no other check. */
        if (ak_real_role_of(instance, vr[i]) == AK_REAL_INPUT && isfinite(value[i])) {
            continue;
        }
        const ak_variable *variable =
            variable_of_type(instance, AK_FMI2_SET_REAL, vr[i], i, AK_TYPE_REAL);
        if (variable == NULL) {
            return fmi2Error;
        }
        if (variable->causality == AK_CAUSALITY_OUTPUT ||
            variable->causality == AK_CAUSALITY_LOCAL) {
            ak_log(instance, AK_LOG_ERROR, fmi2Error,
                   "fmi2SetReal: vr[%zu] = %u is %s, %s %s%s: only inputs and parameters can be "
                   "set; no value set",
                   i, vr[i], variable->name,
                   variable->causality == AK_CAUSALITY_OUTPUT ? "an" : "a",
                   ak_causality_name(variable->causality),
                   ak_is_state(vr[i]) ? " and a continuous state (fmi2SetContinuousStates sets "
                                        "states in model exchange)"
                                      : "");
            return fmi2Error;
        }
        if (!isfinite(value[i])) {
            ak_log(instance, AK_LOG_ERROR, fmi2Error,
                   "fmi2SetReal: %s = %g (vr[%zu] = %u) is not finite; no value set",
                   variable->name, value[i], i, vr[i]);
            return fmi2Error;
        }
        if (variable->causality == AK_CAUSALITY_PARAMETER &&
            !parameter_settable(instance, AK_FMI2_SET_REAL, i, variable, value[i])) {
            return fmi2Error;
        }
    }
    const bool trace = ak_log_on(instance, AK_LOG_CALLS);
    for (size_t i = 0; i < nvr; i++) {
        store(instance, AK_FMI2_SET_REAL, trace, vr[i], value[i]);
        if (instance->data.any_input_derivative && vr[i] < (fmi2ValueReference)AK_MODEL.n_inputs) {
            ak_forget_input_derivatives(instance, vr[i]);
        }
    }
    return fmi2OK;
}

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          fmi2Integer value[]) {
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_GET_INTEGER) ||
        !arrays_given(instance, AK_FMI2_GET_INTEGER, nvr, vr, value)) {
        return fmi2Error;
    }
    for (size_t i = 0; i < nvr; i++) {
        if (variable_of_type(instance, AK_FMI2_GET_INTEGER, vr[i], i, AK_TYPE_INTEGER) == NULL) {
            return fmi2Error;
        }
    }
    for (size_t i = 0; i < nvr; i++) {
        value[i] = (fmi2Integer)instance->data.values[vr[i]];
    }
    return fmi2OK;
}

fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          const fmi2Integer value[]) {
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_SET_INTEGER) ||
        !arrays_given(instance, AK_FMI2_SET_INTEGER, nvr, vr, value)) {
        return fmi2Error;
    }
    for (size_t i = 0; i < nvr; i++) {
        const ak_variable *variable =
            variable_of_type(instance, AK_FMI2_SET_INTEGER, vr[i], i, AK_TYPE_INTEGER);
        if (variable == NULL ||
            !parameter_settable(instance, AK_FMI2_SET_INTEGER, i, variable, (double)value[i])) {
            return fmi2Error;
        }
    }
    const bool trace = ak_log_on(instance, AK_LOG_CALLS);
    for (size_t i = 0; i < nvr; i++) {
        store(instance, AK_FMI2_SET_INTEGER, trace, vr[i], (double)value[i]);
    }
    return fmi2OK;
}

/* The models have no Boolean and no String variables: any value reference given to those
 * functions is unknown. */
static fmi2Status reject_absent_type(const ak_instance *instance, ak_function function,
                                     const char *type, size_t nvr, const void *vr,
                                     const void *values) {
    if (!ak_call_allowed(instance, function)) {
        return fmi2Error;
    }
    if (!arrays_given(instance, function, nvr, vr, values)) {
        return fmi2Error;
    }
    if (nvr > 0) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error,
               "%s: vr[0] = %u is not a value reference of this FMU, which has no %s variables",
               ak_function_name(function), ((const fmi2ValueReference *)vr)[0], type);
        return fmi2Error;
    }
    return fmi2OK;
}

fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          fmi2Boolean value[]) {
    return reject_absent_type(c, AK_FMI2_GET_BOOLEAN, "Boolean", nvr, vr, value);
}

fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                         fmi2String value[]) {
    return reject_absent_type(c, AK_FMI2_GET_STRING, "String", nvr, vr, value);
}

fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          const fmi2Boolean value[]) {
    return reject_absent_type(c, AK_FMI2_SET_BOOLEAN, "Boolean", nvr, vr, value);
}

fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                         const fmi2String value[]) {
    return reject_absent_type(c, AK_FMI2_SET_STRING, "String", nvr, vr, value);
}
