/* FMI 2.0 values and their derivatives. No model has Boolean or String variables. */
#include <math.h>

#include "fmi2_layer.h"

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       fmi2Real value[]) {
    return fmi2_status(ak_get_values(c, &FMI2_RULES[AK_FMI2_GET_REAL], vr, nvr, value, nvr));
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       const fmi2Real value[]) {
    return fmi2_status(ak_set_values(c, &FMI2_RULES[AK_FMI2_SET_REAL], vr, nvr, value, nvr));
}

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          fmi2Integer value[]) {
    ak_instance *instance = c;
    if (!ak_values_call_valid(instance, &FMI2_RULES[AK_FMI2_GET_INTEGER], vr, nvr, value, nvr)) {
        return fmi2Error;
    }
    for (size_t i = 0; i < nvr; i++) {
        if (ak_variable_of_type(instance, fmi2_name(AK_FMI2_GET_INTEGER), vr[i], i,
                                AK_TYPE_INTEGER) == NULL) {
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
    const char *self = fmi2_name(AK_FMI2_SET_INTEGER);
    if (!ak_values_call_valid(instance, &FMI2_RULES[AK_FMI2_SET_INTEGER], vr, nvr, value, nvr)) {
        return fmi2Error;
    }
    for (size_t i = 0; i < nvr; i++) {
        const ak_variable *variable =
            ak_variable_of_type(instance, self, vr[i], i, AK_TYPE_INTEGER);
        if (variable == NULL || !ak_parameter_settable(instance, self, i, variable, value[i])) {
            return fmi2Error;
        }
    }
    for (size_t i = 0; i < nvr; i++) {
        ak_store(instance, self, vr[i], (double)value[i]);
    }
    return fmi2OK;
}

static fmi2Status reject_absent_type(const ak_instance *instance, ak_fmi2_function function,
                                     const char *type, size_t nvr, const void *vr,
                                     const void *values) {
    if (!ak_values_call_valid(instance, &FMI2_RULES[function], vr, nvr, values, nvr)) {
        return fmi2Error;
    }
    if (nvr > 0) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: vr[0] = %u is not a value reference of this FMU, which has no %s variables",
               fmi2_name(function), ((const fmi2ValueReference *)vr)[0], type);
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

enum { MAX_OUTPUT_DERIVATIVE_ORDER = 1 };

static bool offered(ak_instance *instance, ak_fmi2_function function, bool provided,
                    const char *flag) {
    const bool allowed = fmi2_allowed(instance, function);
    if (allowed && !provided) {
        (void)ak_not_provided(instance, fmi2_name(function), flag);
    }
    return allowed && provided;
}

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                       const fmi2Integer order[], const fmi2Real value[]) {
    const char *self = fmi2_name(AK_FMI2_SET_REAL_INPUT_DERIVATIVES);
    if (!offered(c, AK_FMI2_SET_REAL_INPUT_DERIVATIVES, AK_MODEL.can_interpolate_inputs,
                 "canInterpolateInputs=\"false\"") ||
        !ak_given(c, self, nvr, "nvr", vr, "vr") ||
        !ak_given(c, self, nvr, "nvr", order, "order") ||
        !ak_given(c, self, nvr, "nvr", value, "value")) {
        return fmi2Error;
    }
    return fmi2_status(ak_set_input_derivatives(c, self, vr, nvr, order, value));
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                        const fmi2Integer order[], fmi2Real value[]) {
    ak_instance *instance = c;
    const char *self = fmi2_name(AK_FMI2_GET_REAL_OUTPUT_DERIVATIVES);
    if (!offered(instance, AK_FMI2_GET_REAL_OUTPUT_DERIVATIVES,
                 AK_MODEL.output_derivatives != NULL, "maxOutputDerivativeOrder=\"0\"") ||
        !ak_given(instance, self, nvr, "nvr", vr, "vr") ||
        !ak_given(instance, self, nvr, "nvr", order, "order") ||
        !ak_given(instance, self, nvr, "nvr", value, "value")) {
        return fmi2Error;
    }
    for (size_t i = 0; i < nvr; i++) {
        if (!ak_derivative_variable(instance, self, "vr", i, vr[i], AK_CAUSALITY_OUTPUT, NULL)) {
            return fmi2Error;
        }
        if (order[i] < 1 || order[i] > MAX_OUTPUT_DERIVATIVE_ORDER) {
            ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
                   "%s: order[%zu] = %d for %s: this FMU gives order %d only "
                   "(maxOutputDerivativeOrder)",
                   self, i, (int)order[i], AK_MODEL.variables[vr[i]].name,
                   MAX_OUTPUT_DERIVATIVE_ORDER);
            return fmi2Error;
        }
    }
    return fmi2_status(ak_output_derivatives(instance, self, vr, nvr, value));
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference vUnknown_ref[],
                                        size_t nUnknown, const fmi2ValueReference vKnown_ref[],
                                        size_t nKnown, const fmi2Real dvKnown[],
                                        fmi2Real dvUnknown[]) {
    ak_instance *instance = c;
    const char *self = fmi2_name(AK_FMI2_GET_DIRECTIONAL_DERIVATIVE);
    if (!offered(instance, AK_FMI2_GET_DIRECTIONAL_DERIVATIVE, AK_MODEL.jacobian != NULL,
                 "providesDirectionalDerivative=\"false\"") ||
        !ak_given(instance, self, nUnknown, "nUnknown", vUnknown_ref, "vUnknown_ref") ||
        !ak_given(instance, self, nUnknown, "nUnknown", dvUnknown, "dvUnknown") ||
        !ak_given(instance, self, nKnown, "nKnown", vKnown_ref, "vKnown_ref") ||
        !ak_given(instance, self, nKnown, "nKnown", dvKnown, "dvKnown")) {
        return fmi2Error;
    }
    for (size_t i = 0; i < nUnknown; i++) {
        if (!ak_derivative_variable(instance, self, "vUnknown_ref", i, vUnknown_ref[i],
                                    AK_CAUSALITY_OUTPUT, AK_MODEL.derivative_vrs)) {
            return fmi2Error;
        }
    }
    for (size_t j = 0; j < nKnown; j++) {
        if (!ak_derivative_variable(instance, self, "vKnown_ref", j, vKnown_ref[j],
                                    AK_CAUSALITY_INPUT, AK_MODEL.state_vrs)) {
            return fmi2Error;
        }
        if (!isfinite(dvKnown[j])) {
            ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
                   "%s: dvKnown[%zu] = %g (seed of %s) is not finite", self, j, dvKnown[j],
                   AK_MODEL.variables[vKnown_ref[j]].name);
            return fmi2Error;
        }
    }
    return fmi2_status(ak_derivative(instance, vUnknown_ref, nUnknown, vKnown_ref, nKnown, dvKnown,
                                     dvUnknown, false));
}
