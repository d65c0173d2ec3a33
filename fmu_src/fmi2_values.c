/* FMI 2.0 getters and setters. Every call checks all of its arguments before it touches a
 * value, so a rejected call changes nothing. The variables are the model's (fmi2_model.h):
 * Real inputs, Real outputs, and parameters of variability fixed (Real or Integer), which can be
 * set only in Instantiated and InitializationMode. */
#include <math.h>
#include <stdint.h>
#include <string.h>

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

/* A value reference of this model whose variable has the function's type. */
static bool known_value_reference(const ak_instance *instance, ak_function function,
                                  fmi2ValueReference vr, size_t index, ak_type type) {
    if (type == AK_TYPE_REAL && vr < (fmi2ValueReference)AK_MODEL.first_parameter) {
        return true; /* inputs and outputs, all Real (fmi2_model.h): no table lookup */
    }
    if (vr >= (fmi2ValueReference)AK_MODEL.n_variables) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error,
               "%s: vr[%zu] = %u is not a value reference of this FMU (0 to %d)",
               ak_function_name(function), index, vr, AK_MODEL.n_variables - 1);
        return false;
    }
    const ak_variable *variable = &AK_MODEL.variables[vr];
    if (variable->type != type) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error,
               "%s: vr[%zu] = %u is %s, of type %s, not %s",
               ak_function_name(function), index, vr, variable->name,
               type_name(variable->type), type_name(type));
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
    /* No early exit: one pass of or-ed differences, which the compiler vectorizes. */
    fmi2ValueReference differ = 0;
    for (size_t i = 0; i < nvr; i++) {
        differ |= vr[i] ^ (vr[0] + (fmi2ValueReference)i);
    }
    return differ == 0;
}

/* The usual fmi2SetReal: every value reference is an input and every value finite. One pass
 * with no branch per value; any failure is diagnosed by the detailed loop of fmi2SetReal. */
static bool all_inputs_finite(const fmi2ValueReference vr[], size_t nvr, const double value[]) {
    /* In 64-bit integers, so that the compiler vectorizes the pass: bit 63 of `bad` ends up set
     * when some vr is not below n_inputs (n_inputs - 1 - vr is then negative), or when some
     * value is not finite (its exponent field is all ones, and adding one to the field carries
     * into bit 63). */
    const uint64_t exponent = 0x7ff0000000000000u, exponent_one = 0x0010000000000000u;
    const uint64_t last_input = (uint64_t)AK_MODEL.n_inputs - 1;
    uint64_t bad = 0;
    for (size_t i = 0; i < nvr; i++) {
        uint64_t bits;
        memcpy(&bits, &value[i], sizeof bits);
        bad |= ((bits & exponent) + exponent_one) | (last_input - (uint64_t)vr[i]);
    }
    return (bad >> 63) == 0;
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
        ak_log(instance, AK_LOG_CALLS, fmi2OK, "%s: %s = %.17g", ak_function_name(function),
               AK_MODEL.variables[vr].name, value);
    }
    /* Only a real change makes the outputs stale: masters often set unchanged inputs. */
    if (instance->values[vr] != value) {
        instance->values[vr] = value;
        ak_instance_inputs_changed(instance);
    }
}

/* Brings the outputs read up to date (main: some output of the main group or the lazy group is
 * read; lazy: some of the lazy group); the status the read returns. */
static fmi2Status update_for_read(ak_instance *instance, bool main, bool lazy) {
    if (!main) {
        return fmi2OK;
    }
    return ak_instance_read_status(instance, lazy ? ak_instance_update_all_outputs(instance)
                                                  : ak_instance_update_outputs(instance));
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       fmi2Real value[]) {
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_GET_REAL) ||
        !arrays_given(instance, AK_FMI2_GET_REAL, nvr, vr, value)) {
        return fmi2Error;
    }
    if (run_below(vr, nvr, (size_t)AK_MODEL.first_lazy_output)) {
        /* The usual read: inputs and outputs of the main group, Real all of them. */
        fmi2Status status = fmi2OK;
        if (vr[0] + nvr > (size_t)AK_MODEL.n_inputs) {
            status = ak_instance_read_status(instance, ak_instance_update_outputs(instance));
        }
        const double *first = &instance->values[vr[0]];
        for (size_t i = 0; i < nvr; i++) {
            value[i] = first[i];
        }
        return status;
    }
    /* Inputs and outputs of the main group in another order: one pass finds the highest value
     * reference (no branch, vectorized), which tells whether outputs are read. */
    fmi2ValueReference highest = 0;
    for (size_t i = 0; i < nvr; i++) {
        highest = vr[i] > highest ? vr[i] : highest;
    }
    if (highest < (fmi2ValueReference)AK_MODEL.first_lazy_output) {
        const fmi2Status status = update_for_read(
            instance, highest >= (fmi2ValueReference)AK_MODEL.n_inputs, false);
        for (size_t i = 0; i < nvr; i++) {
            value[i] = instance->values[vr[i]];
        }
        return status;
    }
    /* Which output groups are read: past the inputs, and past the main group (lazy outputs or,
     * rarely, Real parameters: then sorted out below). No branch per value reference. */
    bool past_inputs = false, past_main = false;
    for (size_t i = 0; i < nvr; i++) {
        if (!known_value_reference(instance, AK_FMI2_GET_REAL, vr[i], i, AK_TYPE_REAL)) {
            return fmi2Error;
        }
        past_inputs |= vr[i] >= (fmi2ValueReference)AK_MODEL.n_inputs;
        past_main |= vr[i] >= (fmi2ValueReference)AK_MODEL.first_lazy_output;
    }
    bool main = past_inputs, lazy = false;
    if (past_main) {
        main = false;
        for (size_t i = 0; i < nvr; i++) {
            if (vr[i] >= (fmi2ValueReference)AK_MODEL.n_inputs &&
                vr[i] < (fmi2ValueReference)AK_MODEL.first_parameter) {
                main = true;
                lazy = lazy || vr[i] >= (fmi2ValueReference)AK_MODEL.first_lazy_output;
            }
        }
    }
    const fmi2Status status = update_for_read(instance, main, lazy);
    for (size_t i = 0; i < nvr; i++) {
        value[i] = instance->values[vr[i]];
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
    const bool usual = all_inputs_finite(vr, nvr, value);
    if (usual && !instance->any_input_derivative && !ak_log_on(instance, AK_LOG_CALLS)) {
        /* Only a real change makes the outputs stale: masters often set unchanged inputs. */
        bool changed = false;
        for (size_t i = 0; i < nvr; i++) {
            double *slot = &instance->values[vr[i]];
            if (*slot != value[i]) {
                *slot = value[i];
                changed = true;
            }
        }
        if (changed) {
            ak_instance_inputs_changed(instance);
        }
        return fmi2OK;
    }
    for (size_t i = 0; i < nvr && !usual; i++) {
        /* Inputs have the value references below n_inputs (fmi2_model.h): a finite value for one
         * of them, the usual case, needs no further check. */
        if (vr[i] < (fmi2ValueReference)AK_MODEL.n_inputs && isfinite(value[i])) {
            continue;
        }
        if (!known_value_reference(instance, AK_FMI2_SET_REAL, vr[i], i, AK_TYPE_REAL)) {
            return fmi2Error;
        }
        const ak_variable *variable = &AK_MODEL.variables[vr[i]];
        if (variable->causality == AK_CAUSALITY_OUTPUT) {
            ak_log(instance, AK_LOG_ERROR, fmi2Error,
                   "fmi2SetReal: vr[%zu] = %u is %s, an %s: only inputs and parameters can be "
                   "set; no value set",
                   i, vr[i], variable->name, ak_causality_name(variable->causality));
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
        if (instance->any_input_derivative && vr[i] < (fmi2ValueReference)AK_MODEL.n_inputs) {
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
        if (!known_value_reference(instance, AK_FMI2_GET_INTEGER, vr[i], i, AK_TYPE_INTEGER)) {
            return fmi2Error;
        }
    }
    for (size_t i = 0; i < nvr; i++) {
        value[i] = (fmi2Integer)instance->values[vr[i]];
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
        if (!known_value_reference(instance, AK_FMI2_SET_INTEGER, vr[i], i, AK_TYPE_INTEGER) ||
            !parameter_settable(instance, AK_FMI2_SET_INTEGER, i, &AK_MODEL.variables[vr[i]],
                                (double)value[i])) {
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
