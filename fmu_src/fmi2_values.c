/* FMI 2.0 getters and setters. Every call checks all of its arguments before it touches a
 * value, so a rejected call changes nothing. */
#include <math.h>
#include <stdint.h>

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

static bool known_value_reference(const ak_instance *instance, ak_function function,
                                  fmi2ValueReference vr, size_t index) {
    if (vr >= AK_N_VARIABLES) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error,
               "%s: vr[%zu] = %u is not a value reference of this FMU (0 to %d)",
               ak_function_name(function), index, vr, AK_N_VARIABLES - 1);
        return false;
    }
    return true;
}

/* True when vr is the run vr[0], vr[0] + 1, ..., all below `end`. Masters usually pass the
 * variables in the order of modelDescription.xml, which gives such a run: its values can be
 * copied as a block, with no check per value reference. */
static bool run_below(const fmi2ValueReference vr[], size_t nvr, size_t end) {
    if (nvr == 0 || vr[0] >= end || nvr > end - vr[0]) {
        return false;
    }
    for (size_t i = 1; i < nvr; i++) {
        if (vr[i] != vr[0] + i) {
            return false;
        }
    }
    return true;
}

/* The model has only Real variables: any value reference given to the Integer, Boolean and
 * String functions is unknown. */
static fmi2Status reject_non_real(const ak_instance *instance, ak_function function,
                                  const char *type_name, size_t nvr, const void *vr,
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
               ak_function_name(function), ((const fmi2ValueReference *)vr)[0], type_name);
        return fmi2Error;
    }
    return fmi2OK;
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       fmi2Real value[]) {
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_GET_REAL) ||
        !arrays_given(instance, AK_FMI2_GET_REAL, nvr, vr, value)) {
        return fmi2Error;
    }
    if (run_below(vr, nvr, AK_N_VARIABLES)) {
        ak_instance_update_outputs(instance);
        const double *first = &instance->values[vr[0]];
        for (size_t i = 0; i < nvr; i++) {
            value[i] = first[i];
        }
        return fmi2OK;
    }
    for (size_t i = 0; i < nvr; i++) {
        if (!known_value_reference(instance, AK_FMI2_GET_REAL, vr[i], i)) {
            return fmi2Error;
        }
    }
    ak_instance_update_outputs(instance);
    for (size_t i = 0; i < nvr; i++) {
        value[i] = instance->values[vr[i]];
    }
    return fmi2OK;
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       const fmi2Real value[]) {
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_SET_REAL) ||
        !arrays_given(instance, AK_FMI2_SET_REAL, nvr, vr, value)) {
        return fmi2Error;
    }
    for (size_t i = 0; i < nvr; i++) {
        /* Inputs have the value references below AK_N_INPUTS (model_variables.h): a finite value
         * for one of them, the usual case, needs no further check. */
        if (vr[i] < AK_N_INPUTS && isfinite(value[i])) {
            continue;
        }
        if (!known_value_reference(instance, AK_FMI2_SET_REAL, vr[i], i)) {
            return fmi2Error;
        }
        const ak_variable *variable = &AK_VARIABLES[vr[i]];
        if (variable->causality != AK_CAUSALITY_INPUT) {
            ak_log(instance, AK_LOG_ERROR, fmi2Error,
                   "fmi2SetReal: vr[%zu] = %u is %s, an %s: only inputs can be set; no value set",
                   i, vr[i], variable->name, ak_causality_name(variable->causality));
            return fmi2Error;
        }
        if (!isfinite(value[i])) {
            ak_log(instance, AK_LOG_ERROR, fmi2Error,
                   "fmi2SetReal: %s = %g (vr[%zu] = %u) is not finite; no value set",
                   variable->name, value[i], i, vr[i]);
            return fmi2Error;
        }
    }
    const bool trace = ak_log_on(instance, AK_LOG_CALLS);
    for (size_t i = 0; i < nvr; i++) {
        if (trace) {
            ak_log(instance, AK_LOG_CALLS, fmi2OK, "fmi2SetReal: %s = %.17g",
                   AK_VARIABLES[vr[i]].name, value[i]);
        }
        /* Only a real change makes the outputs stale: masters often set unchanged inputs. */
        if (instance->values[vr[i]] != value[i]) {
            instance->values[vr[i]] = value[i];
            instance->outputs_stale = true;
        }
        if (instance->any_input_derivative) {
            ak_forget_input_derivatives(instance, vr[i]);
        }
    }
    return fmi2OK;
}

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          fmi2Integer value[]) {
    return reject_non_real(c, AK_FMI2_GET_INTEGER, "Integer", nvr, vr, value);
}

fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          fmi2Boolean value[]) {
    return reject_non_real(c, AK_FMI2_GET_BOOLEAN, "Boolean", nvr, vr, value);
}

fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                         fmi2String value[]) {
    return reject_non_real(c, AK_FMI2_GET_STRING, "String", nvr, vr, value);
}

fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          const fmi2Integer value[]) {
    return reject_non_real(c, AK_FMI2_SET_INTEGER, "Integer", nvr, vr, value);
}

fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          const fmi2Boolean value[]) {
    return reject_non_real(c, AK_FMI2_SET_BOOLEAN, "Boolean", nvr, vr, value);
}

fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                         const fmi2String value[]) {
    return reject_non_real(c, AK_FMI2_SET_STRING, "String", nvr, vr, value);
}
