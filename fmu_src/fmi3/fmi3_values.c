/* FMI 3.0 getters and setters, and FMI3_LAYER. A value reference names a whole array, nValues
 * counts all elements. Float64 holds the Reals and time (read only), Int64 the Enumerations. */
#include <stdlib.h>

#include "fmi3_layer.h"

static const ak3_array *array_of_type(const ak_instance *instance, const char *function,
                                      size_t index, unsigned int vr, ak_type type) {
    const ak3_array *array = ak3_array_of(vr);
    if (array == NULL) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: valueReferences[%zu] = %u is not a value reference of this FMU's FMI 3 "
               "variables (docs/fmi3_variables.md)",
               function, index, vr);
        return NULL;
    }
    if (AK_MODEL.variables[vr].type != type) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: valueReferences[%zu] = %u is %s, of type %s", function, index, vr, array->name,
               AK_MODEL.variables[vr].type == AK_TYPE_INTEGER
                   ? "Enumeration (fmi3GetInt64/fmi3SetInt64)"
                   : "Float64 (fmi3GetFloat64/fmi3SetFloat64)");
        return NULL;
    }
    return array;
}

static const char *name_of_vr(unsigned int vr) {
    if (vr == AK3_TIME_VALUE_REFERENCE) {
        return "time";
    }
    const ak3_array *array = ak3_array_of(vr);
    return array != NULL ? array->name : "?";
}

bool ak3_count_matches(const ak_instance *instance, const char *function, const char *count_name,
                       size_t n, size_t total, const unsigned int vr[], size_t n_vr) {
    if (n == total) {
        return true;
    }
    ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
           "%s: %s = %zu, but the %zu value references (%s%s%s) have %zu elements (too %s); "
           "nothing read or written",
           function, count_name, n, n_vr, n_vr > 0 ? name_of_vr(vr[0]) : "",
           n_vr > 1 ? " .. " : "", n_vr > 1 ? name_of_vr(vr[n_vr - 1]) : "", total,
           n < total ? "few" : "many");
    return false;
}

static unsigned int elements_at(unsigned int vr) {
    const ak3_array *array = ak3_array_of(vr);
    return array != NULL ? array->n_elements : 0u;
}

static void refuse_real(const ak_instance *instance, const char *function, size_t index,
                        unsigned int vr, bool set) {
    if (set && vr == AK3_TIME_VALUE_REFERENCE) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: valueReferences[%zu] = %u is time, the independent variable, which cannot be "
               "set; no value set",
               function, index, vr);
        return;
    }
    (void)array_of_type(instance, function, index, vr, AK_TYPE_REAL);
}

/* Unlike FMI 2's, FMI 3's logMessage takes the message, not a printf format. */
static void send(const ak_instance *instance, ak_log_category category, ak_status status,
                 const char *message) {
    const fmi3_logger *logger = &((const fmi3_instance *)instance)->logger;
    logger->log_message(logger->environment, fmi3_status(status), AK_LOG_CATEGORY_NAMES[category],
                        message);
}

static void *allocate(const ak_instance *instance, size_t size) {
    (void)instance;
    return calloc(1, size);
}

static void release(const ak_instance *instance, void *memory) {
    (void)instance;
    free(memory);
}

const ak_layer FMI3_LAYER = {
    .state_names = {"Instantiated", "Configuration Mode", "Initialization Mode", "Event Mode",
                    "Step Mode", "Continuous-Time Mode", "Reconfiguration Mode", "Terminated",
                    "Step In Progress", "Step Failed", "Step Canceled"},
    .other_interface = {"not available to this instance, made by fmi3InstantiateModelExchange",
                        "not available to this instance, made by fmi3InstantiateCoSimulation "
                        "without Event Mode"},
    .vr_name = "valueReferences",
    .vr_count_name = "nValueReferences",
    .values_name = "values",
    .values_count_name = "nValues",
    .state_setter_note = " and a continuous state (fmi3SetContinuousStates sets states in model "
                         "exchange)",
    .step_discarded_state = AK_STEP_MODE, /* FMI 3 has no StepFailed state */
    .state_format = {"AKinFMU3", 1u, "FMI 3 FMU state", "instantiationToken", "interface",
                     "FMUState", "fmi3GetFMUState", "fmi3DeserializeFMUState",
                     "fmi3SerializedFMUStateSize", false},
    .image_states = {AK_INSTANTIATED, AK_CONFIGURATION_MODE, AK_INITIALIZATION_MODE, AK_EVENT_MODE,
                     AK_STEP_MODE, AK_CONTINUOUS_TIME_MODE, AK_RECONFIGURATION_MODE,
                     AK_TERMINATED},
    .possible_states = {AK_INSTANTIATED | AK_INITIALIZATION_MODE | AK_TERMINATED | AK_EVENT_MODE |
                            AK_CONTINUOUS_TIME_MODE,
                        AK_INSTANTIATED | AK_INITIALIZATION_MODE | AK_TERMINATED | AK_STEP_MODE},
    .elements_at = elements_at,
    .time_vr = &AK3_TIME_VALUE_REFERENCE,
    .refuse_real = refuse_real,
    .name_of = name_of_vr,
    .count_matches = ak3_count_matches,
    .errors_always_logged = true,
    .send = send,
    .allocate = allocate,
    .release = release,
};

fmi3Status fmi3GetFloat64(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                          fmi3Float64 values[], size_t nValues) {
    return fmi3_status(ak_get_values(c, &FMI3_RULES[AK3_GET_FLOAT64], vr, nvr, values, nValues));
}

fmi3Status fmi3SetFloat64(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                          const fmi3Float64 values[], size_t nValues) {
    return fmi3_status(ak_set_values(c, &FMI3_RULES[AK3_SET_FLOAT64], vr, nvr, values, nValues));
}

/* An Enumeration is a scalar: nValues is one per value reference. */
static bool int64_call_valid(ak_instance *instance, ak3_function function,
                             const fmi3ValueReference vr[], size_t nvr, const void *values,
                             size_t nValues) {
    if (!ak_values_call_valid(instance, &FMI3_RULES[function], vr, nvr, values, nValues)) {
        return false;
    }
    for (size_t i = 0; i < nvr; i++) {
        if (array_of_type(instance, fmi3_name(function), i, vr[i], AK_TYPE_INTEGER) == NULL) {
            return false;
        }
    }
    return ak3_count_matches(instance, fmi3_name(function), "nValues", nValues, nvr, vr, nvr);
}

fmi3Status fmi3GetInt64(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                        fmi3Int64 values[], size_t nValues) {
    ak_instance *instance = c;
    if (!int64_call_valid(instance, AK3_GET_INT64, vr, nvr, values, nValues)) {
        return fmi3Error;
    }
    for (size_t i = 0; i < nvr; i++) {
        values[i] = (fmi3Int64)instance->data.values[vr[i]];
    }
    return fmi3OK;
}

fmi3Status fmi3SetInt64(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                        const fmi3Int64 values[], size_t nValues) {
    const char *self = fmi3_name(AK3_SET_INT64);
    if (!int64_call_valid(c, AK3_SET_INT64, vr, nvr, values, nValues)) {
        return fmi3Error;
    }
    for (size_t i = 0; i < nvr; i++) {
        /* An Int64 far out of range becomes a large double, which the parameter range refuses. */
        if (!ak_parameter_settable(c, self, i, &AK_MODEL.variables[vr[i]], (double)values[i])) {
            return fmi3Error;
        }
    }
    for (size_t i = 0; i < nvr; i++) {
        ak_store(c, self, vr[i], (double)values[i]);
    }
    return fmi3OK;
}
