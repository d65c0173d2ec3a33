/* FMI 2.0 getters and setters. Every call checks all of its arguments before it touches a
 * value, so a rejected call changes nothing. The variables are the model's (fmi2_model.h):
 * Real inputs, Real outputs, and parameters of variability fixed (Real or Integer), which can be
 * set only in Instantiated and InitializationMode. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "ak_bytes.h"
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

/* Every value reference a value array can hold, in order: vr[] is a run first, first + 1, ..
 * exactly when it equals the slice of this table that starts at first (one memcmp). */
static const fmi2ValueReference EVERY_VALUE_REFERENCE[AK_MAX_VARIABLES] = {
    0,  1,  2,  3,  4,  5,  6,  7,  8,  9,  10, 11, 12, 13, 14, 15, 16, 17, 18, 19,
    20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39,
    40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59,
    60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79};
_Static_assert(AK_MAX_VARIABLES == 80, "EVERY_VALUE_REFERENCE lists them all");

/* True when vr holds first, first + 1, .. (nvr >= 1) within the value array. */
static bool ak_consecutive(const fmi2ValueReference vr[], size_t nvr) {
    return nvr > 0 && (size_t)vr[0] + nvr <= AK_MAX_VARIABLES &&
           vr[nvr - 1] == vr[0] + nvr - 1 && /* cheap, and enough to rule most others out */
           memcmp(vr, &EVERY_VALUE_REFERENCE[vr[0]], nvr * sizeof vr[0]) == 0;
}

/* The length n (1 <= n <= nvr) of a run of consecutive value references that starts vr: found by
 * bisection on vr[k] == vr[0] + k, which holds for a prefix of k when vr increases (fmpy's record
 * of every output skips the parameters among them), then checked whole, so that any vr gives a
 * true run. A value reference past the table is a run of 1. */
static size_t run_length(const fmi2ValueReference vr[], size_t nvr) {
    size_t in_run = 1, past = nvr; /* vr[in_run - 1] is in the run; vr[past] is not (or none) */
    while (in_run < past) {
        const size_t mid = in_run + (past - in_run) / 2;
        if (vr[mid] == vr[0] + mid) {
            in_run = mid + 1;
        } else {
            past = mid;
        }
    }
    return ak_consecutive(vr, in_run) ? in_run : 1;
}

/* vr as at most AK_MAX_RUNS runs of consecutive value references into *runs, with their roles;
 * when it takes more, no runs (n_runs 0: value by value is cheaper) and the roles one by one. */
static void split_into_runs(const ak_instance *instance, const fmi2ValueReference vr[], size_t nvr,
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
 * again (masters ask the same at every step); else found in *scratch, and kept unless the call is
 * to be refused (a refused call changes nothing). */
static const ak_get_runs *runs_of(ak_instance *instance, const fmi2ValueReference vr[],
                                  size_t nvr, ak_get_runs *scratch) {
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

static const char *type_name(ak_type type) {
    return type == AK_TYPE_INTEGER ? "Integer" : "Real";
}

/* The variable of a value reference of this model whose variable has the function's type, or
 * NULL after logging why not. */
static const ak_variable *variable_of_type(const ak_instance *instance, ak_function function,
                                           fmi2ValueReference vr, size_t index, ak_type type) {
    const ak_variable *variable = ak_variable_of(vr);
    if (variable == NULL) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error,
               "%s: vr[%zu] = %u is not a value reference of this FMU (0 to %d)",
               ak_function_name(function), index, vr, AK_MODEL.n_value_references - 1);
        return NULL;
    }
    if (variable->type != type) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error,
               "%s: vr[%zu] = %u is %s, of type %s, not %s",
               ak_function_name(function), index, vr, variable->name,
               type_name(variable->type), type_name(type));
        return NULL;
    }
    return variable;
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
        const ak_variable *variable = ak_variable_of(vr); /* checked by the caller: never NULL */
        ak_log(instance, AK_LOG_CALLS, fmi2OK, "%s: %s = %.17g", ak_function_name(function),
               variable != NULL ? variable->name : "?", value);
    }
    /* Only a real change makes the outputs stale: masters often set unchanged inputs. */
    if (!ak_same_double(instance->data.values[vr], value)) {
        instance->data.values[vr] = value;
        ak_instance_inputs_changed(instance);
    }
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       fmi2Real value[]) {
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_GET_REAL) ||
        !arrays_given(instance, AK_FMI2_GET_REAL, nvr, vr, value)) {
        return fmi2Error;
    }
    /* One bit per role read: the highest decides what must be brought up to date (nothing for
     * inputs and parameters, the main group for its outputs, both groups for a lazy output).
     * Consecutive value references are the usual get: their roles come from the run's ends and
     * their values from one copy. */
    const bool run = ak_consecutive(vr, nvr);
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
        (void)variable_of_type(instance, AK_FMI2_GET_REAL, vr[i], i, AK_TYPE_REAL);
        return fmi2Error;
    }
    fmi2Status status = fmi2OK;
    if (roles & (1u << AK_REAL_DERIVED_OUTPUT)) {
        status = ak_instance_read_status(instance, ak_instance_update_derived_outputs(instance));
    } else if (roles & (1u << AK_REAL_LAZY_OUTPUT)) {
        status = ak_instance_read_status(instance, ak_instance_update_all_outputs(instance));
    } else if (roles & (1u << AK_REAL_MAIN_OUTPUT)) {
        status = ak_instance_read_status(instance, ak_instance_update_outputs(instance));
    }
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

/* The usual set: every value reference an input (value references 0 .. n_inputs - 1) and every
 * value finite. Accumulated without a branch per value. */
static bool only_finite_inputs(const fmi2ValueReference vr[], size_t nvr, const fmi2Real value[]) {
    const fmi2ValueReference n_inputs = (fmi2ValueReference)AK_MODEL.n_inputs;
    bool ok = true;
    for (size_t i = 0; i < nvr; i++) {
        ok &= (vr[i] < n_inputs) & (fabs(value[i]) <= DBL_MAX);
    }
    return ok;
}

/* Each value of a set that is not the usual one, checked in turn: the first bad one is logged
 * and refused. */
static bool check_each_real(const ak_instance *instance, const fmi2ValueReference vr[],
                            size_t nvr, const fmi2Real value[]) {
    for (size_t i = 0; i < nvr; i++) {
        if (ak_real_role_of(instance, vr[i]) == AK_REAL_INPUT && isfinite(value[i])) {
            continue;
        }
        const ak_variable *variable =
            variable_of_type(instance, AK_FMI2_SET_REAL, vr[i], i, AK_TYPE_REAL);
        if (variable == NULL) {
            return false;
        }
        if (variable->causality == AK_CAUSALITY_OUTPUT ||
            variable->causality == AK_CAUSALITY_LOCAL) {
            ak_log(instance, AK_LOG_ERROR, fmi2Error,
                   "fmi2SetReal: vr[%zu] = %u is %s, %s %s%s: only inputs and parameters can be "
                   "set; no value set",
                   i, vr[i], variable->name,
                   variable->causality == AK_CAUSALITY_OUTPUT ? "an" : "a",
                   ak_causality_name(variable->causality),
                   ak_is_state(vr[i]) ? " and a continuous state (fmi2SetContinuousStates sets "
                                        "states in model exchange)"
                                      : "");
            return false;
        }
        if (!isfinite(value[i])) {
            ak_log(instance, AK_LOG_ERROR, fmi2Error,
                   "fmi2SetReal: %s = %g (vr[%zu] = %u) is not finite; no value set",
                   variable->name, value[i], i, vr[i]);
            return false;
        }
        if (variable->causality == AK_CAUSALITY_PARAMETER &&
            !parameter_settable(instance, AK_FMI2_SET_REAL, i, variable, value[i])) {
            return false;
        }
    }
    return true;
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       const fmi2Real value[]) {
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_SET_REAL) ||
        !arrays_given(instance, AK_FMI2_SET_REAL, nvr, vr, value)) {
        return fmi2Error;
    }
    /* Untraced, and no input derivative to forget: a usual set stores values, nothing more. */
    const bool trace = ak_log_on(instance, AK_LOG_CALLS);
    const bool plain_store = !trace && !instance->data.any_input_derivative;
    /* The usual set of a master: the first nvr inputs in value-reference order. */
    if (plain_store && nvr > 0 && nvr <= (size_t)AK_MODEL.n_inputs &&
        memcmp(vr, EVERY_VALUE_REFERENCE, nvr * sizeof vr[0]) == 0) {
        /* Every input at once is the usual set: with the count a link-time constant, the
         * compiler unrolls the check and the copy instead of calling memcpy. */
        const ak_store_result stored =
            nvr == (size_t)AK_MODEL.n_inputs
                ? ak_store_if_finite(instance->data.values, value, (size_t)AK_MODEL.n_inputs)
                : ak_store_if_finite(instance->data.values, value, nvr);
        if (stored == AK_STORE_CHANGED) {
            ak_instance_inputs_changed(instance);
        }
        if (stored != AK_STORE_REFUSED) {
            return fmi2OK;
        }
    }
    const bool usual = only_finite_inputs(vr, nvr, value);
    if (!usual && !check_each_real(instance, vr, nvr, value)) {
        return fmi2Error;
    }
    if (usual && plain_store) {
        /* Store every value; the outputs go stale only if one differs (masters often set
         * unchanged inputs). */
        bool changed = false;
        for (size_t i = 0; i < nvr; i++) {
            changed |= !ak_same_double(instance->data.values[vr[i]], value[i]);
            instance->data.values[vr[i]] = value[i];
        }
        if (changed) {
            ak_instance_inputs_changed(instance);
        }
        return fmi2OK;
    }
    for (size_t i = 0; i < nvr; i++) {
        store(instance, AK_FMI2_SET_REAL, trace, vr[i], value[i]);
        if (instance->data.any_input_derivative && vr[i] < (fmi2ValueReference)AK_MODEL.n_inputs) {
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
        if (variable_of_type(instance, AK_FMI2_GET_INTEGER, vr[i], i, AK_TYPE_INTEGER) == NULL) {
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
    if (!ak_call_allowed(instance, AK_FMI2_SET_INTEGER) ||
        !arrays_given(instance, AK_FMI2_SET_INTEGER, nvr, vr, value)) {
        return fmi2Error;
    }
    for (size_t i = 0; i < nvr; i++) {
        const ak_variable *variable =
            variable_of_type(instance, AK_FMI2_SET_INTEGER, vr[i], i, AK_TYPE_INTEGER);
        if (variable == NULL ||
            !parameter_settable(instance, AK_FMI2_SET_INTEGER, i, variable, (double)value[i])) {
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
