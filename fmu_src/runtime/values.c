/* Getters and setters of scalar value references, and the pieces the FMI 3 layer's array getters
 * and setters share with them. Every call checks all of its arguments before it touches a
 * value, so a refused call changes nothing. The variables are the model's: Real inputs, Real
 * outputs, and parameters of variability fixed (Real or Integer), which can be set only in
 * Instantiated and Initialization Mode. */
#include <float.h>
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

/* The length n (1 <= n <= nvr) of a run of consecutive value references that starts vr: found by
 * bisection on vr[k] == vr[0] + k, which holds for a prefix of k when vr increases (fmpy's record
 * of every output skips the parameters among them), then checked whole, so that any vr gives a
 * true run. A value reference past the table is a run of 1. */
static size_t run_length(const unsigned int vr[], size_t nvr) {
    size_t in_run = 1, past = nvr; /* vr[in_run - 1] is in the run; vr[past] is not (or none) */
    while (in_run < past) {
        const size_t mid = in_run + (past - in_run) / 2;
        if (vr[mid] == vr[0] + mid) {
            in_run = mid + 1;
        } else {
            past = mid;
        }
    }
    return consecutive(vr, in_run) ? in_run : 1;
}

/* vr as at most AK_MAX_RUNS runs of consecutive value references into *runs, with their roles;
 * when it takes more, no runs (n_runs 0: value by value is cheaper) and the roles one by one. */
static void split_into_runs(const ak_instance *instance, const unsigned int vr[], size_t nvr,
                            ak_get_runs *runs) {
    runs->n_runs = 0;
    runs->roles = 0;
    for (size_t i = 0; i < nvr; i += runs->lengths[runs->n_runs++]) {
        if (runs->n_runs == AK_MAX_RUNS) {
            runs->n_runs = 0;
            runs->roles = 0;
            for (size_t k = 0; k < nvr; k++) {
                runs->roles |= 1u << ak_real_role_of(instance, vr[k]);
            }
            return;
        }
        const size_t n = run_length(&vr[i], nvr - i);
        runs->lengths[runs->n_runs] = n;
        runs->roles |= vr[i] < AK_MAX_VARIABLES ? ak_real_roles_of_run(instance, vr[i], n)
                                                : 1u << AK_REAL_ABSENT;
    }
}

/* The runs of a get that is not one run (nvr > 0): the instance's last ones when it asks the same
 * again (importers ask the same at every step); else found in *scratch, and kept unless the call
 * is to be refused (a refused call changes nothing). */
static const ak_get_runs *runs_of(ak_instance *instance, const unsigned int vr[], size_t nvr,
                                  ak_get_runs *scratch) {
    ak_get_runs *last = &instance->last_runs;
    if (nvr == last->nvr && memcmp(vr, last->vr, nvr * sizeof vr[0]) == 0) {
        return last;
    }
    split_into_runs(instance, vr, nvr, scratch);
    if (nvr > AK_MAX_VARIABLES || (scratch->roles & (1u << AK_REAL_ABSENT)) != 0) {
        return scratch;
    }
    memcpy(last->vr, vr, nvr * sizeof vr[0]);
    memcpy(last->lengths, scratch->lengths, scratch->n_runs * sizeof last->lengths[0]);
    last->n_runs = scratch->n_runs;
    last->roles = scratch->roles;
    last->nvr = nvr;
    return last;
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

/* Brings up to date what a get of these roles reads: nothing for inputs, parameters and states
 * after initialization, the main group for its outputs (and for states that still follow their
 * start parameters), both groups for a lazy output, everything for a derived one. */
static ak_status update_for(ak_instance *instance, unsigned int roles, const unsigned int vr[],
                            size_t nvr) {
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

/* ak_get_reals but its usual path: every argument checked. Out of line, so that the usual path
 * stays a small function. */
AK_NOINLINE static ak_status get_reals_checked(ak_instance *instance, const ak_function_rule *call,
                                               const unsigned int vr[], size_t nvr,
                                               double value[]) {
    if (!ak_scalar_call_valid(instance, call, vr, nvr, value)) {
        return AK_STATUS_ERROR;
    }
    const char *const function = call->name;
    /* One bit per role read: the highest decides what must be brought up to date (nothing for
     * inputs, parameters and states after initialization, the main group for its outputs, both groups for a lazy output).
     * Consecutive value references are the usual get: their roles come from the run's ends and
     * their values from one copy. */
    const bool run = consecutive(vr, nvr);
    /* Else a few runs (fmpy's record of every output), each read like one. */
    ak_get_runs scratch;
    const ak_get_runs *runs = run || nvr == 0 ? NULL : runs_of(instance, vr, nvr, &scratch);
    const unsigned int roles = run ? ak_real_roles_of_run(instance, vr[0], nvr)
                               : runs != NULL ? runs->roles
                                              : 0u;
    if (roles & (1u << AK_REAL_ABSENT)) { /* the first such value reference, and why */
        size_t i = 0;
        while (ak_real_role_of(instance, vr[i]) != AK_REAL_ABSENT) {
            i++;
        }
        (void)ak_variable_of_type(instance, function, vr[i], i, AK_TYPE_REAL);
        return AK_STATUS_ERROR;
    }
    const ak_status status = update_for(instance, roles, vr, nvr);
    if (run) {
        memcpy(value, &instance->data.values[vr[0]], nvr * sizeof value[0]);
    } else if (runs != NULL && runs->n_runs > 0) {
        for (size_t r = 0, i = 0; r < runs->n_runs; i += runs->lengths[r++]) {
            memcpy(&value[i], &instance->data.values[vr[i]], runs->lengths[r] * sizeof value[0]);
        }
    } else {
        for (size_t i = 0; i < nvr; i++) {
            value[i] = instance->data.values[vr[i]];
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

ak_status ak_get_reals(ak_instance *instance, const ak_function_rule *call,
                       const unsigned int vr[], size_t nvr, double value[]) {
    /* The usual gets, untraced: consecutive value references of known variables, or the same
     * runs as the last get of a few runs (kept only when every value reference was known). */
    if (ak_call_passes(instance, call) && vr != NULL && value != NULL) {
        ak_status status;
        if (nvr == USUAL_RUN ? get_run(instance, vr, USUAL_RUN, value, &status)
                             : get_run(instance, vr, nvr, value, &status)) {
            return status;
        }
        if (!consecutive(vr, nvr)) {
            const ak_get_runs *last = &instance->last_runs;
            if (nvr > 0 && nvr == last->nvr && last->n_runs > 0 &&
                ak_same_value_references(vr, last->vr, nvr)) {
                status = update_for(instance, last->roles, vr, nvr);
                for (size_t r = 0, i = 0; r < last->n_runs; i += last->lengths[r++]) {
                    ak_copy_values(&value[i], &instance->data.values[vr[i]], last->lengths[r]);
                }
                return status;
            }
        }
    }
    return get_reals_checked(instance, call, vr, nvr, value);
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

/* The usual set: every value reference an input (value references 0 .. n_inputs - 1) and every
 * value finite. Accumulated without a branch per value. */
static bool only_finite_inputs(const unsigned int vr[], size_t nvr, const double value[]) {
    const unsigned int n_inputs = (unsigned int)AK_MODEL.n_inputs;
    bool ok = true;
    for (size_t i = 0; i < nvr; i++) {
        ok &= (vr[i] < n_inputs) & (fabs(value[i]) <= DBL_MAX);
    }
    return ok;
}

/* Each value of a set that is not the usual one, checked in turn: the first bad one is logged
 * and refused. */
static bool check_each_real(const ak_instance *instance, const char *function,
                            const unsigned int vr[], size_t nvr, const double value[]) {
    for (size_t i = 0; i < nvr; i++) {
        if (ak_real_role_of(instance, vr[i]) == AK_REAL_INPUT && isfinite(value[i])) {
            continue;
        }
        const ak_variable *variable = ak_variable_of_type(instance, function, vr[i], i, AK_TYPE_REAL);
        if (variable == NULL) {
            return false;
        }
        if (variable->causality == AK_CAUSALITY_OUTPUT ||
            variable->causality == AK_CAUSALITY_LOCAL) {
            ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
                   "%s: %s[%zu] = %u is %s, %s %s%s: only inputs and parameters can be set; no "
                   "value set",
                   function, instance->layer->vr_name, i, vr[i], variable->name,
                   variable->causality == AK_CAUSALITY_OUTPUT ? "an" : "a",
                   ak_causality_name(variable->causality),
                   ak_state_index(AK_MODEL.state_vrs, vr[i]) >= 0
                       ? instance->layer->state_setter_note
                       : "");
            return false;
        }
        if (!isfinite(value[i])) {
            ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
                   "%s: %s = %g (%s[%zu] = %u) is not finite; no value set", function,
                   variable->name, value[i], instance->layer->vr_name, i, vr[i]);
            return false;
        }
        if (variable->causality == AK_CAUSALITY_PARAMETER &&
            !ak_parameter_settable(instance, function, i, variable, value[i])) {
            return false;
        }
    }
    return true;
}

/* ak_set_reals but its usual path. Out of line, so that the usual path stays a small function. */
AK_NOINLINE static ak_status set_reals_checked(ak_instance *instance, const ak_function_rule *call,
                                               const unsigned int vr[], size_t nvr,
                                               const double value[]) {
    if (!ak_scalar_call_valid(instance, call, vr, nvr, value)) {
        return AK_STATUS_ERROR;
    }
    const char *const function = call->name;
    /* Untraced, and no input derivative to forget: a usual set stores values, nothing more. */
    const bool trace = ak_log_on(instance, AK_LOG_CALLS);
    const bool plain_store = !trace && !instance->data.any_input_derivative;
    /* (A run of finite inputs, untraced, took ak_set_reals' usual path: not here.) */
    const bool usual = only_finite_inputs(vr, nvr, value);
    if (!usual && !check_each_real(instance, function, vr, nvr, value)) {
        return AK_STATUS_ERROR;
    }
    if (usual && plain_store) {
        /* Store every value; the outputs go stale only if one differs. */
        bool changed = false;
        for (size_t i = 0; i < nvr; i++) {
            changed |= !ak_same_double(instance->data.values[vr[i]], value[i]);
            instance->data.values[vr[i]] = value[i];
        }
        if (changed) {
            ak_instance_inputs_changed(instance);
        }
        return AK_STATUS_OK;
    }
    for (size_t i = 0; i < nvr; i++) {
        ak_store(instance, function, vr[i], value[i]);
        if (instance->data.any_input_derivative && vr[i] < (unsigned int)AK_MODEL.n_inputs) {
            ak_forget_input_derivatives(instance, vr[i]);
        }
    }
    return AK_STATUS_OK;
}

/* True when vr is a run first, first + 1, .. of inputs (value references 0 .. n_inputs - 1). */
static AK_ALWAYS_INLINE bool inputs_run(const unsigned int vr[], size_t nvr, size_t n_inputs) {
    return nvr > 0 && nvr <= n_inputs && vr[0] <= n_inputs - nvr && consecutive(vr, nvr);
}

ak_status ak_set_reals(ak_instance *instance, const ak_function_rule *call,
                       const unsigned int vr[], size_t nvr, const double value[]) {
    /* The usual sets of an importer: a run of inputs in value-reference order (all of them, or
     * one vector), finite, untraced, no input derivative to forget. With every input the count
     * is a constant, so the compiler unrolls the comparison, the check and the copy. */
    const size_t n_inputs = (size_t)AK_MODEL.n_inputs;
    if (ak_call_passes(instance, call) && !instance->data.any_input_derivative && vr != NULL &&
        value != NULL &&
        (nvr == n_inputs ? memcmp(vr, EVERY_VALUE_REFERENCE, n_inputs * sizeof vr[0]) == 0
                         : inputs_run(vr, nvr, n_inputs)) &&
        ak_store_inputs(instance, vr[0], value, nvr, n_inputs)) {
        return AK_STATUS_OK;
    }
    return set_reals_checked(instance, call, vr, nvr, value);
}
