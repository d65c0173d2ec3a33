/* FMI 3.0 getters and setters. A value reference names a whole array (theta: 3 values, R: 9,
 * row-major) and nValues must be exactly the number of elements of all the value references
 * given. Every call checks all of its arguments before it touches a value, so a rejected call
 * changes nothing. Float64 holds the Real variables (and the independent variable time, which
 * can be read only); Int64 the Enumerations (FMI 3, section 2.4.7.1); no variable has another
 * type (fmi3_unsupported.c). */
#include <float.h>
#include <math.h>
#include <string.h>

#include "ak_bytes.h"
#include "ak_compiler.h"
#include "fmi3Functions.h"
#include "fmi3_values.h"

bool ak3_given(const ak3_instance *instance, ak3_function function, size_t n,
               const char *count_name, const void *pointer, const char *pointer_name) {
    if (n > 0 && pointer == NULL) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error, "%s: %s is NULL with %s = %zu",
                ak3_function_name(function), pointer_name, count_name, n);
        return false;
    }
    return true;
}

static const char *type_name(ak_type type) {
    return type == AK_TYPE_INTEGER ? "Enumeration (fmi3GetInt64/fmi3SetInt64)"
                                   : "Float64 (fmi3GetFloat64/fmi3SetFloat64)";
}

/* The array of a value reference whose variable has the function's type; NULL after logging. */
static const ak3_array *array_of_type(const ak3_instance *instance, ak3_function function,
                                      size_t index, unsigned int vr, ak_type type) {
    const ak3_array *array = ak3_array_of(vr);
    if (array == NULL) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error,
                "%s: valueReferences[%zu] = %u is not a value reference of this FMU's FMI 3 "
                "variables (docs/fmi3_variables.md)",
                ak3_function_name(function), index, vr);
        return NULL;
    }
    const ak_variable *variable = &AK_MODEL.variables[vr]; /* known: an array */
    if (variable->type != type) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error,
                "%s: valueReferences[%zu] = %u is %s, of type %s", ak3_function_name(function),
                index, vr, array->name, type_name(variable->type));
        return NULL;
    }
    return array;
}

const ak3_array *ak3_array_of_causality(const ak3_instance *instance, ak3_function function,
                                        const char *list_name, size_t index, unsigned int vr,
                                        ak_causality causality) {
    const ak3_array *array = ak3_array_of(vr);
    if (array == NULL) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error,
                "%s: %s[%zu] = %u is not a value reference of this FMU's FMI 3 variables",
                ak3_function_name(function), list_name, index, vr);
        return NULL;
    }
    const ak_causality found = AK_MODEL.variables[vr].causality;
    if (found != causality) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error, "%s: %s[%zu] = %u is %s, %s %s; expected an %s",
                ak3_function_name(function), list_name, index, vr, array->name,
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

bool ak3_count_matches(const ak3_instance *instance, ak3_function function, const char *count_name,
                       size_t n, size_t total, const unsigned int vr[], size_t n_vr) {
    if (n == total) {
        return true;
    }
    ak3_log(instance, AK_LOG_ERROR, fmi3Error,
            "%s: %s = %zu, but the %zu value references (%s%s%s) have %zu elements (too %s); "
            "nothing read or written",
            ak3_function_name(function), count_name, n, n_vr, n_vr > 0 ? name_of_vr(vr[0]) : "",
            n_vr > 1 ? " .. " : "", n_vr > 1 ? name_of_vr(vr[n_vr - 1]) : "", total,
            n < total ? "few" : "many");
    return false;
}

/* A parameter may be set only in Instantiated and Initialization Mode (variability fixed), to a
 * value the model accepts. */
static bool parameter_settable(const ak3_instance *instance, ak3_function function, size_t index,
                               const ak_variable *variable, double value) {
    if ((instance->state & (AK3_STATE_INSTANTIATED | AK3_STATE_INITIALIZATION_MODE)) == 0) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error,
                "%s: %s (valueReferences[%zu] = %u) is a parameter of variability fixed: it can "
                "be set only in Instantiated and Initialization Mode, not in %s; no value set",
                ak3_function_name(function), variable->name, index, variable->value_reference,
                ak3_state_name(instance->state));
        return false;
    }
    const char *why = AK_MODEL.check_parameter(variable, value);
    if (why != NULL) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error,
                "%s: %s = %.17g (valueReferences[%zu] = %u) %s; no value set",
                ak3_function_name(function), variable->name, value, index,
                variable->value_reference, why);
        return false;
    }
    return true;
}

static void store(ak3_instance *instance, ak3_function function, bool trace, unsigned int vr,
                  double value) {
    if (trace) {
        ak3_log(instance, AK_LOG_CALLS, fmi3OK, "%s: %s = %.17g", ak3_function_name(function),
                AK_MODEL.variables[vr].name, value);
    }
    /* Only a real change makes the outputs stale: importers often set unchanged inputs. */
    if (!ak_same_double(instance->data.values[vr], value)) {
        instance->data.values[vr] = value;
        ak3_instance_inputs_changed(instance);
    }
}

static bool arguments_given(const ak3_instance *instance, ak3_function function, size_t nvr,
                            const void *vr, size_t n_values, const void *values) {
    return ak3_given(instance, function, nvr, "nValueReferences", vr, "valueReferences") &&
           ak3_given(instance, function, n_values, "nValues", values, "values");
}

/* The usual get of every communication point: arrays of outputs (their first value references),
 * exactly nValues elements in all. Anything else takes the checked path. *lazy: one of them is
 * of the lazy group; *one_run: they follow each other in the value array (one copy serves). */
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

/* The elements of checked value references, array after array. */
static void copy_out(const ak3_instance *instance, const fmi3ValueReference vr[], size_t nvr,
                     fmi3Float64 values[]) {
    size_t k = 0;
    for (size_t i = 0; i < nvr; i++) {
        if (vr[i] == AK3_TIME_VALUE_REFERENCE) {
            values[k++] = instance->time;
            continue;
        }
        const unsigned int n = AK3_ARRAYS[vr[i]].n_elements;
        memcpy(&values[k], &instance->data.values[vr[i]], n * sizeof values[0]);
        k += n;
    }
}

/* The usual set: arrays of inputs (value references 0 .. n_inputs - 1, each the first of its
 * array), exactly nValues elements; *one_run: the arrays follow each other in value-reference
 * order, so their elements are consecutive values. Anything else takes the checked path. */
static bool usual_set(const fmi3ValueReference vr[], size_t nvr, size_t n_values, bool *one_run) {
    size_t total = 0;
    *one_run = true;
    for (size_t i = 0; i < nvr; i++) {
        if (vr[i] >= (fmi3ValueReference)AK_MODEL.n_inputs || AK3_ARRAYS[vr[i]].first_vr != vr[i]) {
            return false;
        }
        *one_run &= vr[i] == vr[0] + total;
        total += AK3_ARRAYS[vr[i]].n_elements;
    }
    return nvr > 0 && total == n_values; /* values[] holds nValues: read no further than it */
}

static bool all_finite(const fmi3Float64 values[], size_t n_values) {
    bool finite = true;
    for (size_t k = 0; k < n_values; k++) {
        finite &= fabs(values[k]) <= DBL_MAX;
    }
    return finite;
}

/* Stores checked values of checked value references. As the FMI 2 layer: every value is
 * stored, and the outputs go stale only when one differs in any bit, so both layers evaluate the
 * same bits. */
static void store_all(ak3_instance *instance, const fmi3ValueReference vr[], size_t nvr,
                      const fmi3Float64 values[]) {
    bool changed = false;
    size_t k = 0;
    for (size_t i = 0; i < nvr; i++) {
        double *target = &instance->data.values[vr[i]];
        const unsigned int n = AK3_ARRAYS[vr[i]].n_elements;
        for (unsigned int e = 0; e < n; e++, k++) {
            changed |= !ak_same_double(target[e], values[k]);
            target[e] = values[k];
        }
    }
    if (changed) {
        ak3_instance_inputs_changed(instance);
    }
}

fmi3Status fmi3GetFloat64(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                          fmi3Float64 values[], size_t nValues) {
    ak3_instance *instance = c;
    const ak3_function self = AK3_GET_FLOAT64;
    if (!ak3_call_allowed(instance, self) ||
        !arguments_given(instance, self, nvr, vr, nValues, values)) {
        return fmi3Error;
    }
    ak_group upto;
    bool one_run;
    if (usual_get(vr, nvr, nValues, &upto, &one_run)) {
        const fmi3Status status = ak3_read_status(ak3_instance_update_outputs_upto(instance, upto));
        if (one_run) {
            memcpy(values, &instance->data.values[vr[0]], nValues * sizeof values[0]);
        } else {
            copy_out(instance, vr, nvr, values);
        }
        return status;
    }
    bool main = false;
    ak_group highest = AK_GROUP_MAIN;
    size_t total = 0;
    for (size_t i = 0; i < nvr; i++) {
        if (vr[i] == AK3_TIME_VALUE_REFERENCE) {
            total += 1;
            continue;
        }
        const ak3_array *array = array_of_type(instance, self, i, vr[i], AK_TYPE_REAL);
        if (array == NULL) {
            return fmi3Error;
        }
        const ak_variable *variable = &AK_MODEL.variables[vr[i]];
        /* Outputs and locals (state derivatives, a model's memory) are the model's to compute. */
        if (variable->causality == AK_CAUSALITY_OUTPUT ||
            variable->causality == AK_CAUSALITY_LOCAL) {
            main = true;
            highest = variable->group > highest ? variable->group : highest;
        }
        total += array->n_elements;
    }
    if (nValues != total && !ak3_count_matches(instance, self, "nValues", nValues, total, vr, nvr)) {
        return fmi3Error;
    }
    fmi3Status status = fmi3OK;
    if (main) {
        status = ak3_read_status(ak3_instance_update_outputs_upto(instance, highest));
    }
    copy_out(instance, vr, nvr, values);
    return status;
}

/* fmi3SetFloat64 of anything but the usual set: each argument checked and a bad one named. Out
 * of line, so that the usual path stays a small function. */
AK_NOINLINE static fmi3Status set_float64_checked(ak3_instance *instance,
                                                  const fmi3ValueReference vr[], size_t nvr,
                                                  const fmi3Float64 values[], size_t nValues) {
    const ak3_function self = AK3_SET_FLOAT64;
    size_t total = 0;
    for (size_t i = 0; i < nvr; i++) {
        if (vr[i] == AK3_TIME_VALUE_REFERENCE) {
            ak3_log(instance, AK_LOG_ERROR, fmi3Error,
                    "fmi3SetFloat64: valueReferences[%zu] = %u is time, the independent "
                    "variable, which cannot be set; no value set",
                    i, vr[i]);
            return fmi3Error;
        }
        const ak3_array *array = array_of_type(instance, self, i, vr[i], AK_TYPE_REAL);
        if (array == NULL) {
            return fmi3Error;
        }
        const ak_variable *variable = &AK_MODEL.variables[vr[i]];
        if (variable->causality == AK_CAUSALITY_OUTPUT ||
            variable->causality == AK_CAUSALITY_LOCAL) {
            ak3_log(instance, AK_LOG_ERROR, fmi3Error,
                    "fmi3SetFloat64: valueReferences[%zu] = %u is %s, %s %s%s: only inputs and "
                    "parameters can be set; no value set",
                    i, vr[i], array->name,
                    variable->causality == AK_CAUSALITY_OUTPUT ? "an" : "a",
                    ak_causality_name(variable->causality),
                    ak3_is_state(vr[i]) ? " and a continuous state (fmi3SetContinuousStates sets "
                                          "states in model exchange)"
                                        : "");
            return fmi3Error;
        }
        total += array->n_elements;
    }
    if (nValues != total && !ak3_count_matches(instance, self, "nValues", nValues, total, vr, nvr)) {
        return fmi3Error;
    }
    size_t k = 0;
    for (size_t i = 0; i < nvr; i++) {
        const bool parameter = AK_MODEL.variables[vr[i]].causality == AK_CAUSALITY_PARAMETER;
        for (unsigned int e = 0; e < AK3_ARRAYS[vr[i]].n_elements; e++, k++) {
            if (!isfinite(values[k])) {
                ak3_log(instance, AK_LOG_ERROR, fmi3Error,
                        "fmi3SetFloat64: %s = %g (values[%zu], valueReferences[%zu] = %u) is not "
                        "finite; no value set",
                        AK_MODEL.variables[vr[i] + e].name, values[k], k, i, vr[i]);
                return fmi3Error;
            }
            if (parameter &&
                !parameter_settable(instance, self, i, &AK_MODEL.variables[vr[i] + e], values[k])) {
                return fmi3Error;
            }
        }
    }
    if (ak3_log_on(instance, AK_LOG_CALLS)) {
        k = 0;
        for (size_t i = 0; i < nvr; i++) {
            for (unsigned int e = 0; e < AK3_ARRAYS[vr[i]].n_elements; e++) {
                store(instance, self, true, vr[i] + e, values[k++]);
            }
        }
        return fmi3OK;
    }
    store_all(instance, vr, nvr, values);
    return fmi3OK;
}

fmi3Status fmi3SetFloat64(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                          const fmi3Float64 values[], size_t nValues) {
    ak3_instance *instance = c;
    const ak3_function self = AK3_SET_FLOAT64;
    if (!ak3_call_allowed(instance, self) ||
        !arguments_given(instance, self, nvr, vr, nValues, values)) {
        return fmi3Error;
    }
    bool one_run;
    if (usual_set(vr, nvr, nValues, &one_run) && !ak3_log_on(instance, AK_LOG_CALLS)) {
        if (one_run) { /* one check-and-copy of consecutive values (ak_bytes.h) */
            double *target = &instance->data.values[vr[0]];
            /* One vector of 3 is the usual set: with the count a constant, the compiler
             * unrolls the check and the copy instead of calling memcpy. */
            const ak_store_result stored = nValues == 3
                                               ? ak_store_if_finite(target, values, 3)
                                               : ak_store_if_finite(target, values, nValues);
            if (stored == AK_STORE_CHANGED) {
                ak3_instance_inputs_changed(instance);
            }
            if (stored != AK_STORE_REFUSED) {
                return fmi3OK;
            }
        } else if (all_finite(values, nValues)) {
            store_all(instance, vr, nvr, values);
            return fmi3OK;
        }
    }
    return set_float64_checked(instance, vr, nvr, values, nValues);
}

fmi3Status fmi3GetInt64(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                        fmi3Int64 values[], size_t nValues) {
    ak3_instance *instance = c;
    const ak3_function self = AK3_GET_INT64;
    if (!ak3_call_allowed(instance, self) ||
        !arguments_given(instance, self, nvr, vr, nValues, values)) {
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
    ak3_instance *instance = c;
    const ak3_function self = AK3_SET_INT64;
    if (!ak3_call_allowed(instance, self) ||
        !arguments_given(instance, self, nvr, vr, nValues, values)) {
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
        /* An Int64 far out of range becomes a large double, which check_parameter refuses. */
        if (!parameter_settable(instance, self, i, &AK_MODEL.variables[vr[i]], (double)values[i])) {
            return fmi3Error;
        }
    }
    const bool trace = ak3_log_on(instance, AK_LOG_CALLS);
    for (size_t i = 0; i < nvr; i++) {
        store(instance, self, trace, vr[i], (double)values[i]);
    }
    return fmi3OK;
}
