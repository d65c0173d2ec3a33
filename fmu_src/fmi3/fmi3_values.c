/* FMI 3.0 getters and setters. A value reference names a whole array (theta: 3 values, R: 9,
 * row-major) and nValues must be exactly the number of elements of all the value references
 * given. Every call checks all of its arguments before it touches a value, so a rejected call
 * changes nothing. Float64 holds the Real variables (and the independent variable time, which
 * can be read only); Int64 the Enumerations (FMI 3, section 2.4.7.1); no variable has another
 * type (fmi3_unsupported.c). The usual calls of a communication point take the paths below;
 * every other call is the runtime's (ak_get_values, ak_set_values), in this layer's words. */
#include <string.h>

#include "ak_bytes.h"
#include "fmi3_layer.h"

static const char *type_name(ak_type type) {
    return type == AK_TYPE_INTEGER ? "Enumeration (fmi3GetInt64/fmi3SetInt64)"
                                   : "Float64 (fmi3GetFloat64/fmi3SetFloat64)";
}

/* The array of a value reference whose variable has the function's type; NULL after logging. */
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
    const ak_variable *variable = &AK_MODEL.variables[vr]; /* known: an array */
    if (variable->type != type) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
                "%s: valueReferences[%zu] = %u is %s, of type %s", function,
                index, vr, array->name, type_name(variable->type));
        return NULL;
    }
    return array;
}

const ak3_array *ak3_array_of_causality(const ak_instance *instance, const char *function,
                                        const char *list_name, size_t index, unsigned int vr,
                                        ak_causality causality) {
    const ak3_array *array = ak3_array_of(vr);
    if (array == NULL) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
                "%s: %s[%zu] = %u is not a value reference of this FMU's FMI 3 variables",
                function, list_name, index, vr);
        return NULL;
    }
    const ak_causality found = AK_MODEL.variables[vr].causality;
    if (found != causality) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR, "%s: %s[%zu] = %u is %s, %s %s; expected an %s",
                function, list_name, index, vr, array->name,
                found == AK_CAUSALITY_PARAMETER ? "a" : "an", ak_causality_name(found),
                ak_causality_name(causality));
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

/* The usual get of every communication point: arrays of outputs (their first value references),
 * exactly nValues elements in all. Anything else takes the checked path. *upto: the highest group
 * among them; *one_run: they follow each other in the value array (one copy serves). */
static bool usual_get(const fmi3ValueReference vr[], size_t nvr, size_t n_values, ak_group *upto,
                      bool *one_run) {
    size_t total = 0;
    *upto = AK_GROUP_MAIN;
    *one_run = true;
    if (nvr == 0) {
        return false; /* nothing to read: the checked path answers it */
    }
    for (size_t i = 0; i < nvr; i++) {
        const ak3_array *array = ak3_array_of(vr[i]);
        if (array == NULL || AK_MODEL.variables[vr[i]].causality != AK_CAUSALITY_OUTPUT) {
            return false;
        }
        if (AK_MODEL.variables[vr[i]].group > *upto) {
            *upto = AK_MODEL.variables[vr[i]].group;
        }
        *one_run &= vr[i] == vr[0] + total;
        total += array->n_elements;
    }
    return total == n_values;
}

size_t ak3_expand(const unsigned int vr[], size_t n, unsigned int elements[], size_t capacity) {
    size_t k = 0;
    for (size_t i = 0; i < n; i++) {
        for (unsigned int e = 0; e < AK3_ARRAYS[vr[i]].n_elements && k < capacity; e++) {
            elements[k++] = vr[i] + e;
        }
    }
    return k;
}

unsigned int ak3_elements_at(unsigned int vr) {
    const ak3_array *array = ak3_array_of(vr);
    return array != NULL ? array->n_elements : 0u;
}

const char *ak3_name_of(unsigned int vr) {
    return AK3_ARRAYS[vr].name;
}

void ak3_refuse_real(const ak_instance *instance, const char *function, size_t index,
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

/* The elements of checked value references, array after array. */
static void copy_out(const ak_instance *instance, const fmi3ValueReference vr[], size_t nvr,
                     fmi3Float64 values[]) {
    size_t k = 0;
    for (size_t i = 0; i < nvr; i++) {
        if (vr[i] == AK3_TIME_VALUE_REFERENCE) {
            values[k++] = instance->time;
            continue;
        }
        const unsigned int n = AK3_ARRAYS[vr[i]].n_elements;
        ak_copy_values(&values[k], &instance->data.values[vr[i]], n);
        k += n;
    }
}

/* The usual set: arrays of inputs (value references 0 .. n_inputs - 1, each the first of its
 * array), exactly nValues elements; *one_run: the arrays follow each other in value-reference
 * order, so their elements are consecutive values. Anything else takes the checked path. */
static bool usual_set(const fmi3ValueReference vr[], size_t nvr, size_t n_values, bool *one_run) {
    size_t total = 0;
    *one_run = true;
    if (nvr == 1) { /* one input array, the usual set of an importer: no loop */
        return vr[0] < (fmi3ValueReference)AK_MODEL.n_inputs &&
               AK3_ARRAYS[vr[0]].first_vr == vr[0] && AK3_ARRAYS[vr[0]].n_elements == n_values;
    }
    for (size_t i = 0; i < nvr; i++) {
        if (vr[i] >= (fmi3ValueReference)AK_MODEL.n_inputs || AK3_ARRAYS[vr[i]].first_vr != vr[i]) {
            return false;
        }
        *one_run &= vr[i] == vr[0] + total;
        total += AK3_ARRAYS[vr[i]].n_elements;
    }
    return nvr > 0 && total == n_values; /* values[] holds nValues: read no further than it */
}

/* True for a get of the states alone (one array: AttitudePropagator's q), which are current
 * without an evaluation once they no longer follow the parameters. */
static bool states_alone(const fmi3ValueReference vr[], size_t nvr) {
    return AK_MODEL.n_states > 0 && nvr == 1 && AK_MODEL.state_vrs[0] == vr[0];
}

/* True for a call the state table allows, untraced: the usual paths' check, which logs nothing
 * (a call it does not pass takes the checked path, which logs why it is refused). */
static inline bool untraced_call_allowed(const ak_instance *instance, ak3_function function) {
    return instance != NULL &&
           (FMI3_RULES[function].allowed_states & (unsigned int)instance->state) != 0 &&
           FMI3_RULES[function].interfaces == (AK_MODEL_EXCHANGE | AK_CO_SIMULATION) &&
           !ak_log_on(instance, AK_LOG_CALLS);
}

/* True when vr, nvr, nValues are those of the kept usual get. */
static bool same_get(const ak3_kept_get *kept, const fmi3ValueReference vr[], size_t nvr,
                     size_t n_values) {
    return nvr == kept->nvr && n_values == kept->n_values &&
           ak_same_value_references(vr, kept->vr, nvr);
}

/* True for the usual get of every communication point: output arrays that follow each other,
 * all of their elements (1 <= nvr <= AK3_KEPT_GET_ARRAYS), kept for the next call. */
static bool usual_get_kept(ak3_kept_get *kept, const fmi3ValueReference vr[], size_t nvr,
                           size_t n_values) {
    if (same_get(kept, vr, nvr, n_values)) {
        return true;
    }
    ak_group upto;
    bool one_run;
    if (!usual_get(vr, nvr, n_values, &upto, &one_run)) {
        return false;
    }
    memcpy(kept->vr, vr, nvr * sizeof vr[0]);
    kept->nvr = nvr;
    kept->n_values = n_values;
    kept->upto = upto;
    kept->one_run = one_run;
    kept->states_only = states_alone(vr, nvr);
    return true;
}

fmi3Status fmi3GetFloat64(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                          fmi3Float64 values[], size_t nValues) {
    fmi3_instance *self = c;
    ak_instance *instance = c;
    if (untraced_call_allowed(instance, AK3_GET_FLOAT64) && vr != NULL && values != NULL &&
        nvr > 0 && nvr <= AK3_KEPT_GET_ARRAYS &&
        usual_get_kept(&self->last_get, vr, nvr, nValues)) {
        const ak3_kept_get *kept = &self->last_get;
        const fmi3Status status = kept->states_only && !ak_states_follow_parameters(instance, vr, nvr)
                                      ? fmi3OK
                                      : fmi3_status(ak_instance_update(instance, kept->upto));
        if (kept->one_run) {
            ak_copy_values(values, &instance->data.values[vr[0]], nValues);
        } else {
            copy_out(instance, vr, nvr, values);
        }
        return status;
    }
    return fmi3_status(ak_get_values(instance, &FMI3_RULES[AK3_GET_FLOAT64], vr, nvr, values, nValues));
}

/* True when vr names every input array, in value-reference order (so their elements are the
 * inputs 0 .. n_inputs - 1 in order). */
static bool every_input_array(const fmi3ValueReference vr[], size_t nvr) {
    const unsigned int n_inputs = (unsigned int)AK_MODEL.n_inputs;
    unsigned int next = 0;
    for (size_t i = 0; i < nvr; i++) {
        if (next >= n_inputs || vr[i] != next) {
            return false;
        }
        next += AK3_ARRAYS[next].n_elements;
    }
    return nvr > 0 && next == n_inputs;
}

/* fmi3SetFloat64 but its usual sets: one run of input arrays (in value-reference order), untraced;
 * anything else by the runtime's ak_set_values. Out of line, so that the usual paths stay small
 * functions. */
AK_NOINLINE static fmi3Status set_float64_general(ak_instance *instance,
                                                  const fmi3ValueReference vr[], size_t nvr,
                                                  const fmi3Float64 values[], size_t nValues) {
    bool one_run;
    if (ak_call_passes(instance, &FMI3_RULES[AK3_SET_FLOAT64]) && vr != NULL && values != NULL &&
        !instance->data.any_input_derivative && usual_set(vr, nvr, nValues, &one_run) && one_run &&
        ak_store_inputs(instance, vr[0], values, nValues, 3)) {
        return fmi3OK;
    }
    return fmi3_status(ak_set_values(instance, &FMI3_RULES[AK3_SET_FLOAT64], vr, nvr, values, nValues));
}

/* The other usual set, every input array at once in value-reference order, untraced; anything
 * else goes on to set_float64_general. Out of line and small: the one-vector path stays short. */
AK_NOINLINE static fmi3Status set_every_input(ak_instance *instance, const fmi3ValueReference vr[],
                                              size_t nvr, const fmi3Float64 values[],
                                              size_t nValues) {
    if (untraced_call_allowed(instance, AK3_SET_FLOAT64) && vr != NULL && values != NULL &&
        nValues == (size_t)AK_MODEL.n_inputs && every_input_array(vr, nvr) &&
        !instance->data.any_input_derivative) {
        const ak_store_result stored =
            ak_store_if_finite(instance->data.values, values, (size_t)AK_MODEL.n_inputs);
        if (stored == AK_STORE_CHANGED) {
            ak_instance_inputs_changed(instance);
        }
        if (stored != AK_STORE_REFUSED) {
            return fmi3OK;
        }
    }
    return set_float64_general(instance, vr, nvr, values, nValues);
}

fmi3Status fmi3SetFloat64(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                          const fmi3Float64 values[], size_t nValues) {
    ak_instance *instance = c;
    /* The usual set of every communication point: one input vector of 3, all of it, untraced;
     * stored if every value is finite (else the general path names the bad one). */
    if (untraced_call_allowed(instance, AK3_SET_FLOAT64) && nvr == 1 && vr != NULL &&
        values != NULL && nValues == 3 && vr[0] < (fmi3ValueReference)AK_MODEL.n_inputs &&
        AK3_ARRAYS[vr[0]].first_vr == vr[0] && AK3_ARRAYS[vr[0]].n_elements == 3) {
        const ak_store_result stored = ak_store_if_finite(&instance->data.values[vr[0]], values, 3);
        if (stored == AK_STORE_CHANGED) {
            ak_instance_inputs_changed(instance);
        }
        if (stored != AK_STORE_REFUSED) {
            return fmi3OK;
        }
    }
    return set_every_input(instance, vr, nvr, values, nValues);
}

fmi3Status fmi3GetInt64(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                        fmi3Int64 values[], size_t nValues) {
    ak_instance *instance = c;
    const char *self = fmi3_name(AK3_GET_INT64);
    if (!ak_values_call_valid(instance, &FMI3_RULES[AK3_GET_INT64], vr, nvr, values, nValues)) {
        return fmi3Error;
    }
    size_t total = 0;
    for (size_t i = 0; i < nvr; i++) {
        const ak3_array *array = array_of_type(instance, self, i, vr[i], AK_TYPE_INTEGER);
        if (array == NULL) {
            return fmi3Error;
        }
        total += array->n_elements;
    }
    if (nValues != total && !ak3_count_matches(instance, self, "nValues", nValues, total, vr, nvr)) {
        return fmi3Error;
    }
    for (size_t i = 0; i < nvr; i++) {
        values[i] = (fmi3Int64)instance->data.values[vr[i]]; /* Enumerations are scalars */
    }
    return fmi3OK;
}

fmi3Status fmi3SetInt64(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                        const fmi3Int64 values[], size_t nValues) {
    ak_instance *instance = c;
    const char *self = fmi3_name(AK3_SET_INT64);
    if (!ak_values_call_valid(instance, &FMI3_RULES[AK3_SET_INT64], vr, nvr, values, nValues)) {
        return fmi3Error;
    }
    size_t total = 0;
    for (size_t i = 0; i < nvr; i++) {
        const ak3_array *array = array_of_type(instance, self, i, vr[i], AK_TYPE_INTEGER);
        if (array == NULL) {
            return fmi3Error;
        }
        total += array->n_elements;
    }
    if (nValues != total && !ak3_count_matches(instance, self, "nValues", nValues, total, vr, nvr)) {
        return fmi3Error;
    }
    for (size_t i = 0; i < nvr; i++) {
        /* An Int64 far out of range becomes a large double, which the parameter range refuses. */
        if (!ak_parameter_settable(instance, self, i, &AK_MODEL.variables[vr[i]], (double)values[i])) {
            return fmi3Error;
        }
    }
    for (size_t i = 0; i < nvr; i++) {
        ak_store(instance, self, vr[i], (double)values[i]);
    }
    return fmi3OK;
}
