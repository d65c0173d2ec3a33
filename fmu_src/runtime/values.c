/* Gets and sets of Real values, one path for both FMI layers. A request checked once is kept, so
 * that the same request at the next communication point costs one comparison. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "ak_bytes.h"
#include "runtime.h"

/* Constant counts: a few moves, not a memcpy (gcc made one of 12 a slow rep movs). */
static AK_ALWAYS_INLINE void copy_values(double *to, const double *from, size_t n) {
    if (n == 12) {
        for (size_t k = 0; k < 12; k++) {
            to[k] = from[k];
        }
    } else if (n == 4) {
        for (size_t k = 0; k < 4; k++) {
            to[k] = from[k];
        }
    } else {
        for (size_t k = 0; k < n; k++) {
            to[k] = from[k];
        }
    }
}

void ak_input_derivatives_changed(ak_instance *instance) {
    if (AK_MODEL.outputs_use_input_derivatives) {
        ak_instance_inputs_changed(instance);
    }
    instance->data.any_input_derivative = false;
    for (int k = 0; k < AK_MODEL.n_inputs; k++) {
        for (int n = 0; n < AK_MAX_INPUT_DERIVATIVE_ORDER; n++) {
            if (instance->data.input_derivatives[k][n] != 0.0) {
                instance->data.any_input_derivative = true;
            }
        }
    }
}

const ak_variable *ak_variable_of_type(const ak_instance *instance, const char *function,
                                       unsigned int vr, size_t index, ak_type type) {
    const ak_variable *variable = ak_variable_of(vr);
    if (variable == NULL) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: %s[%zu] = %u is not a value reference of this FMU (0 to %d)", function,
               instance->layer->vr_name, index, vr, AK_MODEL.n_value_references - 1);
        return NULL;
    }
    if (variable->type != type) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: %s[%zu] = %u is %s, of type %s, not %s", function, instance->layer->vr_name,
               index, vr, variable->name, variable->type == AK_TYPE_INTEGER ? "Integer" : "Real",
               type == AK_TYPE_INTEGER ? "Integer" : "Real");
        return NULL;
    }
    return variable;
}

bool ak_parameter_settable(const ak_instance *instance, const char *function, size_t index,
                           const ak_variable *variable, double value) {
    if ((instance->state & (AK_INSTANTIATED | AK_INITIALIZATION_MODE)) == 0) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: %s (%s[%zu] = %u) is a parameter of variability fixed: it can be set only in "
               "%s and %s, not in %s; no value set",
               function, variable->name, instance->layer->vr_name, index,
               variable->value_reference, ak_state_name(instance, AK_INSTANTIATED),
               ak_state_name(instance, AK_INITIALIZATION_MODE),
               ak_state_name(instance, instance->state));
        return false;
    }
    const char *why = ak_parameter_refusal(variable, value);
    if (why != NULL) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: %s = %.17g (%s[%zu] = %u) %s; no value set", function, variable->name, value,
               instance->layer->vr_name, index, variable->value_reference, why);
        return false;
    }
    return true;
}

void ak_store(ak_instance *instance, const char *function, unsigned int vr, double value) {
    if (ak_log_on(instance, AK_LOG_CALLS)) {
        ak_log(instance, AK_LOG_CALLS, AK_STATUS_OK, "%s: %s = %.17g", function,
               AK_MODEL.variables[vr].name, value);
    }
    /* Only a real change makes the outputs stale: importers often set unchanged inputs. */
    if (!ak_same_double(instance->data.values[vr], value)) {
        instance->data.values[vr] = value;
        ak_instance_inputs_changed(instance);
    }
    /* The importer restated the input at a new point without a slope: it is held from there. */
    if (instance->data.any_input_derivative && vr < (unsigned int)AK_MODEL.n_inputs) {
        double *derivatives = instance->data.input_derivatives[vr];
        memset(derivatives, 0, sizeof instance->data.input_derivatives[vr]);
        ak_input_derivatives_changed(instance);
    }
}

static void refuse_real(const ak_instance *instance, const char *function, size_t i,
                        unsigned int vr, bool set) {
    if (instance->layer->refuse_real != NULL) {
        instance->layer->refuse_real(instance, function, i, vr, set);
    } else {
        (void)ak_variable_of_type(instance, function, vr, i, AK_TYPE_REAL);
    }
}

static bool count_matches(const ak_instance *instance, const char *function,
                          const unsigned int vr[], size_t nvr, size_t n, size_t total) {
    return n == total || instance->layer->count_matches == NULL ||
           instance->layer->count_matches(instance, function, instance->layer->values_count_name,
                                          n, total, vr, nvr);
}

static AK_ALWAYS_INLINE ak_status update_for(ak_instance *instance, unsigned int roles) {
    if (roles & (1u << AK_REAL_DERIVED_OUTPUT)) {
        return ak_instance_update(instance, AK_GROUP_DERIVED);
    }
    if (roles & (1u << AK_REAL_LAZY_OUTPUT)) {
        return ak_instance_update(instance, AK_GROUP_LAZY);
    }
    /* Until initialization ended the states follow the parameters. */
    if ((roles & (1u << AK_REAL_MAIN_OUTPUT)) ||
        ((roles & (1u << AK_REAL_STATE_OUTPUT)) &&
         (instance->state & (AK_INSTANTIATED | AK_INITIALIZATION_MODE)) != 0)) {
        return ak_instance_update(instance, AK_GROUP_MAIN);
    }
    return AK_STATUS_OK;
}

static bool check_get(const ak_instance *instance, const char *function, const unsigned int vr[],
                      size_t nvr, size_t n_values, unsigned int *roles, bool *one_run) {
    size_t total = 0;
    *roles = 0;
    *one_run = nvr > 0;
    for (size_t i = 0; i < nvr; i++) {
        const ak_real_role role = ak_real_role_of(instance, vr[i]);
        const bool time = instance->layer->time_vr != NULL && vr[i] == *instance->layer->time_vr;
        if ((role == AK_REAL_ABSENT || instance->elements[vr[i]] == 0) && !time) {
            refuse_real(instance, function, i, vr[i], false);
            return false;
        }
        *roles |= 1u << role; /* an array's first value stands for it: one variable, one role */
        *one_run &= role != AK_REAL_ABSENT && vr[i] == vr[0] + total;
        total += role == AK_REAL_ABSENT ? 1u : instance->elements[vr[i]]; /* time: one value */
    }
    return count_matches(instance, function, vr, nvr, n_values, total);
}

/* No branch per value reference: with a constant nvr the compiler compares a vector at a time. */
static AK_ALWAYS_INLINE bool same_request(const ak_kept_request *kept, const unsigned int vr[],
                                          size_t nvr, size_t n_values) {
    if (nvr == 0 || nvr != kept->nvr || n_values != kept->n_values) {
        return false;
    }
    unsigned int differ = 0;
    for (size_t i = 0; i < nvr; i++) {
        differ |= vr[i] ^ kept->vr[i];
    }
    return differ == 0;
}

/* Keeps a checked request (none of no value reference: vr may be NULL then). */
static void keep_request(ak_kept_request *kept, const unsigned int vr[], size_t nvr,
                         size_t n_values, unsigned int roles, bool one_run) {
    if (nvr > 0 && nvr <= AK_MAX_VARIABLES) {
        memcpy(kept->vr, vr, nvr * sizeof vr[0]);
        kept->nvr = nvr, kept->n_values = n_values, kept->roles = roles, kept->one_run = one_run;
    }
}

static AK_ALWAYS_INLINE ak_status read_values(ak_instance *instance, unsigned int roles,
                                              bool one_run, const unsigned int vr[], size_t nvr,
                                              double values[], size_t n_values) {
    const ak_status status = update_for(instance, roles);
    if (one_run) {
        copy_values(values, &instance->data.values[vr[0]], n_values);
        return status;
    }
    for (size_t i = 0, k = 0; i < nvr; i++) {
        const unsigned int n = vr[i] < AK_MAX_VARIABLES ? instance->elements[vr[i]] : 0u;
        if (n == 1) { /* FMI 2's scalars: no loop */
            values[k++] = instance->data.values[vr[i]];
        } else if (n == 0) { /* checked: time, past the value array */
            values[k++] = instance->time;
        } else if (k + n <= n_values) { /* checked already; said for gcc's -Wstringop-overflow */
            copy_values(&values[k], &instance->data.values[vr[i]], n);
            k += n;
        }
    }
    return status;
}

static AK_NOINLINE ak_status get_checked(ak_instance *instance, const ak_function_rule *call,
                                         const unsigned int vr[], size_t nvr, double values[],
                                         size_t n_values) {
    unsigned int roles;
    bool one_run;
    if (!ak_values_call_valid(instance, call, vr, nvr, values, n_values) ||
        !check_get(instance, call->name, vr, nvr, n_values, &roles, &one_run)) {
        return AK_STATUS_ERROR;
    }
    if (!ak_log_on(instance, AK_LOG_CALLS)) {
        keep_request(&instance->kept_get, vr, nvr, n_values, roles, one_run);
    }
    return read_values(instance, roles, one_run, vr, nvr, values, n_values);
}

static bool settable(const ak_instance *instance, const char *function, size_t i,
                     unsigned int vr) {
    const ak_real_role role = ak_real_role_of(instance, vr);
    if (role == AK_REAL_ABSENT || instance->elements[vr] == 0) {
        refuse_real(instance, function, i, vr, true);
        return false;
    }
    if (role == AK_REAL_INPUT || role == AK_REAL_PARAMETER) {
        return true;
    }
    const ak_causality causality = AK_MODEL.variables[vr].causality;
    const char *name = instance->layer->name_of != NULL ? instance->layer->name_of(vr)
                                                        : AK_MODEL.variables[vr].name;
    ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
           "%s: %s[%zu] = %u is %s, %s %s%s: only inputs and parameters can be set; no value set",
           function, instance->layer->vr_name, i, vr, name,
           causality == AK_CAUSALITY_OUTPUT ? "an" : "a", ak_causality_name(causality),
           ak_state_index(AK_MODEL.state_vrs, vr) >= 0 ? instance->layer->state_setter_note : "");
    return false;
}

static bool storable(const ak_instance *instance, const char *function, size_t i,
                     unsigned int vr, const double values[], size_t k) {
    const ak_layer *layer = instance->layer;
    for (unsigned int e = 0; e < instance->elements[vr]; e++) {
        const ak_variable *variable = &AK_MODEL.variables[vr + e];
        const double value = values[k + e];
        if (!isfinite(value)) {
            char place[64] = ""; /* FMI 3: its place in values[] too */
            if (layer->elements_at != NULL) {
                snprintf(place, sizeof place, "%s[%zu], ", layer->values_name, k + e);
            }
            ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
                   "%s: %s = %g (%s%s[%zu] = %u) is not finite; no value set", function,
                   variable->name, value, place, layer->vr_name, i, vr);
            return false;
        }
        if (variable->causality == AK_CAUSALITY_PARAMETER &&
            !ak_parameter_settable(instance, function, i, variable, value)) {
            return false;
        }
    }
    return true;
}

/* In the order the layer's messages number them: each value reference and its values in turn
 * (FMI 2), or every value reference, then the count, then the values (FMI 3). */
static bool check_set(const ak_instance *instance, const char *function, const unsigned int vr[],
                      size_t nvr, const double values[], size_t n_values) {
    const bool counted = instance->layer->count_matches != NULL;
    size_t total = 0;
    for (size_t i = 0; i < nvr; i++) {
        if (!settable(instance, function, i, vr[i]) ||
            (!counted && !storable(instance, function, i, vr[i], values, total))) {
            return false;
        }
        total += instance->elements[vr[i]];
    }
    if (counted && !count_matches(instance, function, vr, nvr, n_values, total)) {
        return false;
    }
    for (size_t i = 0, k = 0; counted && i < nvr; k += instance->elements[vr[i++]]) {
        if (!storable(instance, function, i, vr[i], values, k)) {
            return false;
        }
    }
    return true;
}

ak_status ak_get_values(ak_instance *instance, const ak_function_rule *call,
                        const unsigned int vr[], size_t nvr, double values[], size_t n_values) {
    /* The get of the last step asked again, untraced: known good. */
    if (ak_call_passes(instance, call) && vr != NULL && values != NULL) {
        const ak_kept_request *kept = &instance->kept_get;
        /* The goals' counts as constants, so that the compiler unrolls (docs/performance.md). */
        if (nvr == 12 ? same_request(kept, vr, 12, n_values)
            : nvr == 4 ? same_request(kept, vr, 4, n_values)
            : nvr == 1 ? same_request(kept, vr, 1, n_values) /* FMI 3's get of one array */
                       : same_request(kept, vr, nvr, n_values)) {
            return read_values(instance, kept->roles, kept->one_run, vr, nvr, values, n_values);
        }
    }
    return get_checked(instance, call, vr, nvr, values, n_values);
}

/* All or nothing (false: one is not finite); constant counts, so that the compiler unrolls. */
static AK_ALWAYS_INLINE bool store_inputs(ak_instance *instance, unsigned int first,
                                          const double values[], size_t n) {
    double *target = &instance->data.values[first];
    const size_t n_inputs = (size_t)AK_MODEL.n_inputs;
    const ak_store_result stored = n == n_inputs ? ak_store_if_finite(target, values, n_inputs)
                                   : n == 3        ? ak_store_if_finite(target, values, 3)
                                                   : ak_store_if_finite(target, values, n);
    if (stored == AK_STORE_CHANGED) {
        ak_instance_inputs_changed(instance);
    }
    return stored != AK_STORE_REFUSED;
}

static AK_NOINLINE ak_status set_checked(ak_instance *instance, const ak_function_rule *call,
                                         const unsigned int vr[], size_t nvr,
                                         const double values[], size_t n_values) {
    if (!ak_values_call_valid(instance, call, vr, nvr, values, n_values) ||
        !check_set(instance, call->name, vr, nvr, values, n_values)) {
        return AK_STATUS_ERROR;
    }
    bool inputs_run = nvr > 0 && !ak_log_on(instance, AK_LOG_CALLS);
    for (size_t i = 0, k = 0; i < nvr; i++) {
        inputs_run &= vr[i] == vr[0] + k && vr[i] < (unsigned int)AK_MODEL.n_inputs;
        for (unsigned int e = 0; e < instance->elements[vr[i]]; e++) {
            ak_store(instance, call->name, vr[i] + e, values[k++]);
        }
    }
    if (inputs_run) { /* for the next set of the same inputs */
        keep_request(&instance->kept_set, vr, nvr, n_values, 0, true);
    }
    return AK_STATUS_OK;
}

ak_status ak_set_values(ak_instance *instance, const ak_function_rule *call,
                        const unsigned int vr[], size_t nvr, const double values[],
                        size_t n_values) {
    /* The last step's inputs again, or one input array, untraced, no input derivative to forget:
     * the values are checked as they are stored; the full check names one not finite. */
    const size_t n_inputs = (size_t)AK_MODEL.n_inputs;
    if (ak_call_passes(instance, call) && vr != NULL && values != NULL &&
        !instance->data.any_input_derivative &&
        (nvr == 3 /* FMI 3's three input arrays: the FMI 3 / FMI 2 goal */
             ? same_request(&instance->kept_set, vr, 3, n_values)
         : nvr == n_inputs ? same_request(&instance->kept_set, vr, n_inputs, n_values)
         : nvr == 1 ? vr[0] < n_inputs && n_values > 0 && instance->elements[vr[0]] == n_values
                    : same_request(&instance->kept_set, vr, nvr, n_values)) &&
        store_inputs(instance, vr[0], values, n_values)) {
        return AK_STATUS_OK;
    }
    return set_checked(instance, call, vr, nvr, values, n_values);
}
