/* Gets and sets of Real values, for both FMI layers, and what an Integer get or set shares with
 * them. A value reference of the layer names ak_instance.elements consecutive values (FMI 2: one;
 * FMI 3: an array's); each call checks all of its arguments before it touches a value, so a
 * refused call changes nothing. The variables are the model's: Real inputs, Real outputs, and
 * parameters of variability fixed (Real or Integer), which can be set only in Instantiated and
 * Initialization Mode. */
#include <math.h>
#include <string.h>

#include "ak_bytes.h"
#include "runtime.h"

/* Every value reference a value array can hold, in order: vr[] is a run first, first + 1, ..
 * exactly when it equals the slice of this table that starts at first (one memcmp). */
static const unsigned int EVERY_VALUE_REFERENCE[AK_MAX_VARIABLES] = {
    0,  1,  2,  3,  4,  5,  6,  7,  8,  9,  10, 11, 12, 13, 14, 15, 16, 17, 18, 19,
    20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39,
    40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59,
    60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79};
_Static_assert(AK_MAX_VARIABLES == 80, "EVERY_VALUE_REFERENCE lists them all");

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

void ak_forget_input_derivatives(ak_instance *instance, unsigned int input_vr) {
    for (int n = 0; n < AK_MAX_INPUT_DERIVATIVE_ORDER; n++) {
        instance->data.input_derivatives[input_vr][n] = 0.0;
    }
    ak_input_derivatives_changed(instance);
}

static const char *type_name(ak_type type) {
    return type == AK_TYPE_INTEGER ? "Integer" : "Real";
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
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR, "%s: %s[%zu] = %u is %s, of type %s, not %s",
               function, instance->layer->vr_name, index, vr, variable->name,
               type_name(variable->type), type_name(type));
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
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR, "%s: %s = %.17g (%s[%zu] = %u) %s; no value set",
               function, variable->name, value, instance->layer->vr_name, index,
               variable->value_reference, why);
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
        ak_forget_input_derivatives(instance, vr);
    }
}

bool ak_states_follow_parameters(const ak_instance *instance, const unsigned int vr[], size_t nvr) {
    if ((instance->state & (AK_INSTANTIATED | AK_INITIALIZATION_MODE)) == 0) {
        return false;
    }
    for (size_t i = 0; i < nvr; i++) {
        if (ak_real_role_of(instance, vr[i]) == AK_REAL_STATE_OUTPUT) {
            return true;
        }
    }
    return false;
}

/* Runs up to this long are compared element by element, longer ones with one memcmp. */
enum { SHORT_RUN = 8 };

/* True when vr holds first, first + 1, .. (nvr >= 1) within the value array. */
static AK_ALWAYS_INLINE bool consecutive(const unsigned int vr[], size_t nvr) {
    if (nvr == 0 || (size_t)vr[0] + nvr > AK_MAX_VARIABLES ||
        vr[nvr - 1] != vr[0] + nvr - 1) { /* cheap, and enough to rule most others out */
        return false;
    }
    if (nvr > SHORT_RUN) {
        return memcmp(vr, &EVERY_VALUE_REFERENCE[vr[0]], nvr * sizeof vr[0]) == 0;
    }
    bool run = true;
    for (size_t i = 1; i + 1 < nvr; i++) {
        run &= vr[i] == vr[0] + i;
    }
    return run;
}

/* ak_store_if_finite with the count a constant for a vector or a quaternion (as ak_copy_values). */
static AK_ALWAYS_INLINE ak_store_result store_values(double *target, const double value[],
                                                     size_t n) {
    switch (n) {
    case 3:
        return ak_store_if_finite(target, value, 3);
    case 4:
        return ak_store_if_finite(target, value, 4);
    default:
        return ak_store_if_finite(target, value, n);
    }
}

/* Logs why vr (vr_name[i]) names no Real value to get or set: the layer's words, FMI 2's by
 * default. */
static void refuse_real(const ak_instance *instance, const char *function, size_t i,
                        unsigned int vr, bool set) {
    if (instance->layer->refuse_real != NULL) {
        instance->layer->refuse_real(instance, function, i, vr, set);
    } else {
        (void)ak_variable_of_type(instance, function, vr, i, AK_TYPE_REAL);
    }
}

static bool is_time(const ak_instance *instance, unsigned int vr) {
    return instance->layer->time_vr != NULL && vr == *instance->layer->time_vr;
}

/* Whether the n values of the layer's calls (values_count_name) are those of vr[] (total). */
static bool count_matches(const ak_instance *instance, const char *function,
                          const unsigned int vr[], size_t nvr, size_t n, size_t total) {
    return n == total || instance->layer->count_matches == NULL ||
           instance->layer->count_matches(instance, function, instance->layer->values_count_name,
                                          n, total, vr, nvr);
}

/* Brings up to date what a get of these roles reads: nothing for inputs, parameters and states
 * after initialization, the main group for its outputs (and for states that still follow their
 * start parameters), both groups for a lazy output, everything for a derived one. */
static AK_ALWAYS_INLINE ak_status update_for(ak_instance *instance, unsigned int roles,
                                             const unsigned int vr[], size_t nvr) {
    if (roles & (1u << AK_REAL_DERIVED_OUTPUT)) {
        return ak_instance_update(instance, AK_GROUP_DERIVED);
    }
    if (roles & (1u << AK_REAL_LAZY_OUTPUT)) {
        return ak_instance_update(instance, AK_GROUP_LAZY);
    }
    if ((roles & (1u << AK_REAL_MAIN_OUTPUT)) || ak_states_follow_parameters(instance, vr, nvr)) {
        return ak_instance_update(instance, AK_GROUP_MAIN);
    }
    return AK_STATUS_OK;
}

/* Out of line: the layers' usual gets stay small functions. */
AK_NOINLINE ak_status ak_get_values(ak_instance *instance, const ak_function_rule *call,
                                    const unsigned int vr[], size_t nvr, double values[],
                                    size_t n_values) {
    if (!ak_values_call_valid(instance, call, vr, nvr, values, n_values)) {
        return AK_STATUS_ERROR;
    }
    unsigned int roles = 0;
    size_t total = 0;
    for (size_t i = 0; i < nvr; i++) {
        const ak_real_role role = ak_real_role_of(instance, vr[i]);
        if ((role == AK_REAL_ABSENT || instance->elements[vr[i]] == 0) && !is_time(instance, vr[i])) {
            refuse_real(instance, call->name, i, vr[i], false);
            return AK_STATUS_ERROR;
        }
        roles |= 1u << role; /* an array's first value stands for it: one variable, one role */
        total += role == AK_REAL_ABSENT ? 1u : instance->elements[vr[i]]; /* time: one value */
    }
    if (!count_matches(instance, call->name, vr, nvr, n_values, total)) {
        return AK_STATUS_ERROR;
    }
    const ak_status status = update_for(instance, roles, vr, nvr);
    for (size_t i = 0, k = 0; i < nvr; i++) {
        if (vr[i] >= AK_MAX_VARIABLES) { /* checked above: time, past the value array */
            values[k++] = instance->time;
            continue;
        }
        for (unsigned int e = 0; e < instance->elements[vr[i]]; e++) {
            values[k++] = instance->data.values[vr[i] + e];
        }
    }
    return status;
}

/* The get of a run of consecutive value references of known variables, into *status; false
 * (nothing done) for any other. Inline: called with a constant nvr, the compiler inlines the
 * comparison and the copy instead of calling memcmp and memcpy. */
static AK_ALWAYS_INLINE bool get_run(ak_instance *instance, const unsigned int vr[], size_t nvr,
                                     double value[], ak_status *status) {
    if (!consecutive(vr, nvr)) {
        return false;
    }
    const unsigned int roles = ak_real_roles_of_run(instance, vr[0], nvr);
    if ((roles & (1u << AK_REAL_ABSENT)) != 0) {
        return false;
    }
    *status = update_for(instance, roles, vr, nvr);
    ak_copy_values(value, &instance->data.values[vr[0]], nvr);
    return true;
}

/* A run of four vectors of 3, the get masters most often make at a communication point (two
 * vectors in two frames): with this count a constant, the copy is inlined. Any other count
 * takes the same path with a variable count. */
enum { USUAL_RUN = 12 };

/* A get of a few runs (fmpy's record of every output skips the parameters among them) asked
 * again, as the instance kept it: its roles, its values gathered. False for any other get. */
static bool get_kept(ak_instance *instance, const unsigned int vr[], size_t nvr, double value[],
                     ak_status *status) {
    const ak_kept_get *kept = &instance->kept_get;
    if (nvr == 0 || nvr != kept->nvr || !ak_same_value_references(vr, kept->vr, nvr)) {
        return false;
    }
    *status = update_for(instance, kept->roles, vr, nvr);
    for (size_t i = 0; i < nvr; i++) {
        value[i] = instance->data.values[vr[i]];
    }
    return true;
}

/* Keeps a get that ak_get_values answered (every value reference known) for get_kept. */
static void keep_get(ak_instance *instance, const unsigned int vr[], size_t nvr) {
    ak_kept_get *kept = &instance->kept_get;
    kept->roles = 0;
    for (size_t i = 0; i < nvr; i++) {
        kept->roles |= 1u << ak_real_role_of(instance, vr[i]);
    }
    memcpy(kept->vr, vr, nvr * sizeof vr[0]);
    kept->nvr = nvr;
}

ak_status ak_get_reals(ak_instance *instance, const ak_function_rule *call,
                       const unsigned int vr[], size_t nvr, double value[]) {
    /* The usual gets, untraced: consecutive value references of known variables (the count a
     * constant for the goals' gets, docs/performance.md: four vectors, a quaternion), or the
     * same few runs as the last get. */
    ak_status status;
    const bool untraced = ak_call_passes(instance, call) && vr != NULL && value != NULL;
    if (untraced && (nvr == USUAL_RUN ? get_run(instance, vr, USUAL_RUN, value, &status)
                     : (nvr == 4 ? get_run(instance, vr, 4, value, &status)
                                 : get_run(instance, vr, nvr, value, &status)) ||
                           get_kept(instance, vr, nvr, value, &status))) {
        return status;
    }
    status = ak_get_values(instance, call, vr, nvr, value, nvr);
    if (untraced && status != AK_STATUS_ERROR && nvr <= AK_MAX_VARIABLES) {
        keep_get(instance, vr, nvr);
    }
    return status;
}

/* Whether vr[i] names values a set may write (inputs or parameters); else logs why not. */
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

/* Whether the values values[k ..] of vr[i] may be stored: finite, and a parameter's in its range
 * and settable now; else logs the first that is not. */
static bool storable(const ak_instance *instance, const char *function, size_t i,
                     unsigned int vr, const double values[], size_t k) {
    const ak_layer *layer = instance->layer;
    for (unsigned int e = 0; e < instance->elements[vr]; e++) {
        const ak_variable *variable = &AK_MODEL.variables[vr + e];
        const double value = values[k + e];
        if (!isfinite(value) && layer->elements_at != NULL) { /* its place in values[] too */
            ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
                   "%s: %s = %g (%s[%zu], %s[%zu] = %u) is not finite; no value set", function,
                   variable->name, value, layer->values_name, k + e, layer->vr_name, i, vr);
            return false;
        }
        if (!isfinite(value)) {
            ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
                   "%s: %s = %g (%s[%zu] = %u) is not finite; no value set", function,
                   variable->name, value, layer->vr_name, i, vr);
            return false;
        }
        if (variable->causality == AK_CAUSALITY_PARAMETER &&
            !ak_parameter_settable(instance, function, i, variable, value)) {
            return false;
        }
    }
    return true;
}

/* Whether every value of a set may be stored, checked in the order the layer's messages are
 * numbered in: each value reference and its values in turn (FMI 2), or every value reference,
 * then the count, then the values (FMI 3); logs the first refusal. */
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
    if (!counted) {
        return true;
    }
    if (!count_matches(instance, function, vr, nvr, n_values, total)) {
        return false;
    }
    for (size_t i = 0, k = 0; i < nvr; k += instance->elements[vr[i++]]) {
        if (!storable(instance, function, i, vr[i], values, k)) {
            return false;
        }
    }
    return true;
}

/* Every argument checked first, then each value stored (traced, its input derivatives forgotten).
 * Out of line: the layers' usual sets stay small functions. */
AK_NOINLINE ak_status ak_set_values(ak_instance *instance, const ak_function_rule *call,
                                    const unsigned int vr[], size_t nvr, const double values[],
                                    size_t n_values) {
    if (!ak_values_call_valid(instance, call, vr, nvr, values, n_values) ||
        !check_set(instance, call->name, vr, nvr, values, n_values)) {
        return AK_STATUS_ERROR;
    }
    for (size_t i = 0, k = 0; i < nvr; i++) {
        for (unsigned int e = 0; e < instance->elements[vr[i]]; e++) {
            ak_store(instance, call->name, vr[i] + e, values[k++]);
        }
    }
    return AK_STATUS_OK;
}

bool ak_store_inputs(ak_instance *instance, unsigned int first, const double value[], size_t n,
                     size_t usual_n) {
    /* The caller's usual count, and a vector's or a quaternion's, as constants: the compiler
     * unrolls the check and the copy instead of calling memcpy. */
    double *target = &instance->data.values[first];
    const ak_store_result stored = n == usual_n ? ak_store_if_finite(target, value, usual_n)
                                                : store_values(target, value, n);
    if (stored == AK_STORE_CHANGED) {
        ak_instance_inputs_changed(instance);
    }
    return stored != AK_STORE_REFUSED;
}

/* True when vr is a run first, first + 1, .. of inputs (value references 0 .. n_inputs - 1). */
static AK_ALWAYS_INLINE bool inputs_run(const unsigned int vr[], size_t nvr, size_t n_inputs) {
    return nvr > 0 && nvr <= n_inputs && vr[0] <= n_inputs - nvr && consecutive(vr, nvr);
}

ak_status ak_set_reals(ak_instance *instance, const ak_function_rule *call,
                       const unsigned int vr[], size_t nvr, const double value[]) {
    /* The usual sets of an importer: a run of inputs in value-reference order (all of them, or
     * one vector), finite, untraced, no input derivative to forget. With every input or a
     * vector the count is a constant, so the compiler unrolls the comparison, the check and the
     * copy. */
    const size_t n_inputs = (size_t)AK_MODEL.n_inputs;
    if (ak_call_passes(instance, call) && !instance->data.any_input_derivative && vr != NULL &&
        value != NULL &&
        (nvr == n_inputs ? memcmp(vr, EVERY_VALUE_REFERENCE, n_inputs * sizeof vr[0]) == 0
         : nvr == 3      ? inputs_run(vr, 3, n_inputs)
                         : inputs_run(vr, nvr, n_inputs)) &&
        ak_store_inputs(instance, vr[0], value, nvr, n_inputs)) {
        return AK_STATUS_OK;
    }
    return ak_set_values(instance, call, vr, nvr, value, nvr);
}
