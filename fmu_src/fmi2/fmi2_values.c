/* FMI 2.0 getters and setters over runtime/values.c; no model has Boolean or String variables. */
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
    const char *self = fmi2_name(AK_FMI2_GET_INTEGER);
    if (!ak_values_call_valid(instance, &FMI2_RULES[AK_FMI2_GET_INTEGER], vr, nvr, value, nvr)) {
        return fmi2Error;
    }
    for (size_t i = 0; i < nvr; i++) {
        if (ak_variable_of_type(instance, self, vr[i], i, AK_TYPE_INTEGER) == NULL) {
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

/* Any value reference given to the Boolean and String functions is unknown. */
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
