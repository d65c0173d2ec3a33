/* FMI 2.0 derivatives: co-simulation input derivatives (canInterpolateInputs), output
 * derivatives (maxOutputDerivativeOrder = 1) and directional derivatives
 * (providesDirectionalDerivative). The mathematics is the model's (ak_model.jacobian,
 * ak_model.output_derivatives); this file only checks arguments, selects rows and columns and
 * applies seeds. A model without one of them gets the FMI function refused with a message naming
 * the capability flag, which its modelDescription.xml sets to false / 0. */
#include "fmi2_derivatives.h"

#include <math.h>

#include "fmi2Functions.h"
#include "fmi2_logging.h"
#include "fmi2_state_machine.h"

/* The highest order fmi2GetRealOutputDerivatives gives: maxOutputDerivativeOrder. */
#define AK_MAX_OUTPUT_DERIVATIVE_ORDER 1

static void update_any_input_derivative(ak_instance *instance) {
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
    update_any_input_derivative(instance);
}

bool ak_advance_inputs(ak_instance *instance, double h) {
    if (!instance->data.any_input_derivative) {
        return true; /* zero-order hold: nothing moves */
    }
    double value[AK_MAX_INPUTS], slope[AK_MAX_INPUTS];
    for (int k = 0; k < AK_MODEL.n_inputs; k++) {
        const double d1 = instance->data.input_derivatives[k][0];
        const double d2 = instance->data.input_derivatives[k][1];
        value[k] = instance->data.values[k] + h * (d1 + 0.5 * h * d2);
        slope[k] = d1 + h * d2;
        if (!isfinite(value[k]) || !isfinite(slope[k])) {
            ak_log(instance, AK_LOG_ERROR, fmi2Error,
                   "fmi2DoStep: extrapolating %s = %.17g with derivatives %g (order 1) and %g "
                   "(order 2) over communicationStepSize = %g overflows; step not taken",
                   AK_MODEL.variables[k].name, instance->data.values[k], d1, d2, h);
            return false;
        }
    }
    for (int k = 0; k < AK_MODEL.n_inputs; k++) {
        if (value[k] != instance->data.values[k]) {
            instance->data.values[k] = value[k];
            ak_instance_inputs_changed(instance);
        }
        instance->data.input_derivatives[k][0] = slope[k];
    }
    update_any_input_derivative(instance);
    return true;
}

/* NULL arrays are fine only when there is nothing to read or write. */
static bool arrays_given(const ak_instance *instance, ak_function function, size_t n,
                         const char *count_name, const void *first, const char *first_name,
                         const void *second, const char *second_name, const void *third,
                         const char *third_name) {
    const char *missing = NULL;
    if (first == NULL) {
        missing = first_name;
    } else if (second == NULL) {
        missing = second_name;
    } else if (third == NULL && third_name != NULL) {
        missing = third_name;
    }
    if (n > 0 && missing != NULL) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error, "%s: %s is NULL with %s = %zu",
               ak_function_name(function), missing, count_name, n);
        return false;
    }
    return true;
}

/* A value reference of the given causality, or a logged error. */
static bool value_reference_is(const ak_instance *instance, ak_function function,
                               const char *array_name, size_t index, fmi2ValueReference vr,
                               ak_causality causality) {
    if (ak_variable_of(vr) == NULL) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error,
               "%s: %s[%zu] = %u is not a value reference of this FMU (0 to %d)",
               ak_function_name(function), array_name, index, vr,
               AK_MODEL.n_value_references - 1);
        return false;
    }
    if (AK_MODEL.variables[vr].causality != causality) {
        const ak_causality found = AK_MODEL.variables[vr].causality;
        ak_log(instance, AK_LOG_ERROR, fmi2Error, "%s: %s[%zu] = %u is %s, %s %s; expected an %s",
               ak_function_name(function), array_name, index, vr, AK_MODEL.variables[vr].name,
               found == AK_CAUSALITY_PARAMETER ? "a" : "an", ak_causality_name(found),
               ak_causality_name(causality));
        return false;
    }
    return true;
}

/* The index of vr in a model's list of states (or of state derivatives), or -1. */
static int state_index(const unsigned int *vrs, fmi2ValueReference vr) {
    for (int k = 0; k < AK_MODEL.n_states; k++) {
        if (vrs[k] == vr) {
            return k;
        }
    }
    return -1;
}

/* The column of a known (checked: an input or a state) in the model's Jacobian. */
static size_t known_column(fmi2ValueReference vr) {
    const int state = state_index(AK_MODEL.state_vrs, vr);
    return state >= 0 ? (size_t)(AK_MODEL.n_inputs + state) : (size_t)vr;
}

/* The refusal of a function behind a capability flag the model does not claim. */
static fmi2Status not_provided(const ak_instance *instance, ak_function function,
                               const char *flag) {
    ak_log(instance, AK_LOG_ERROR, fmi2Error,
           "%s: not provided by %s (modelDescription.xml: %s)", ak_function_name(function),
           AK_MODEL.model_identifier, flag);
    return fmi2Error;
}

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                       const fmi2Integer order[], const fmi2Real value[]) {
    ak_instance *instance = c;
    const ak_function self = AK_FMI2_SET_REAL_INPUT_DERIVATIVES;
    if (!ak_call_allowed(instance, self)) {
        return fmi2Error;
    }
    if (!AK_MODEL.can_interpolate_inputs) {
        return not_provided(instance, self, "canInterpolateInputs=\"false\"");
    }
    if (
        !arrays_given(instance, self, nvr, "nvr", vr, "vr", order, "order", value, "value")) {
        return fmi2Error;
    }
    for (size_t i = 0; i < nvr; i++) {
        if (!value_reference_is(instance, self, "vr", i, vr[i], AK_CAUSALITY_INPUT)) {
            return fmi2Error;
        }
        if (order[i] < 1 || order[i] > AK_MAX_INPUT_DERIVATIVE_ORDER) {
            ak_log(instance, AK_LOG_ERROR, fmi2Error,
                   "fmi2SetRealInputDerivatives: order[%zu] = %d for %s: this FMU takes orders "
                   "1 to %d; no derivative set",
                   i, (int)order[i], AK_MODEL.variables[vr[i]].name, AK_MAX_INPUT_DERIVATIVE_ORDER);
            return fmi2Error;
        }
        if (!isfinite(value[i])) {
            ak_log(instance, AK_LOG_ERROR, fmi2Error,
                   "fmi2SetRealInputDerivatives: derivative of order %d of %s = %g (vr[%zu] = "
                   "%u) is not finite; no derivative set",
                   (int)order[i], AK_MODEL.variables[vr[i]].name, value[i], i, vr[i]);
            return fmi2Error;
        }
    }
    for (size_t i = 0; i < nvr; i++) {
        ak_log(instance, AK_LOG_CALLS, fmi2OK,
               "fmi2SetRealInputDerivatives: derivative of order %d of %s = %.17g",
               (int)order[i], AK_MODEL.variables[vr[i]].name, value[i]);
        instance->data.input_derivatives[vr[i]][order[i] - 1] = value[i];
    }
    update_any_input_derivative(instance);
    return fmi2OK;
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                        const fmi2Integer order[], fmi2Real value[]) {
    ak_instance *instance = c;
    const ak_function self = AK_FMI2_GET_REAL_OUTPUT_DERIVATIVES;
    if (!ak_call_allowed(instance, self)) {
        return fmi2Error;
    }
    if (AK_MODEL.output_derivatives == NULL) {
        return not_provided(instance, self, "maxOutputDerivativeOrder=\"0\"");
    }
    if (
        !arrays_given(instance, self, nvr, "nvr", vr, "vr", order, "order", value, "value")) {
        return fmi2Error;
    }
    for (size_t i = 0; i < nvr; i++) {
        if (!value_reference_is(instance, self, "vr", i, vr[i], AK_CAUSALITY_OUTPUT)) {
            return fmi2Error;
        }
        if (order[i] < 1 || order[i] > AK_MAX_OUTPUT_DERIVATIVE_ORDER) {
            ak_log(instance, AK_LOG_ERROR, fmi2Error,
                   "fmi2GetRealOutputDerivatives: order[%zu] = %d for %s: this FMU gives order "
                   "%d only (maxOutputDerivativeOrder)",
                   i, (int)order[i], AK_MODEL.variables[vr[i]].name,
                   AK_MAX_OUTPUT_DERIVATIVE_ORDER);
            return fmi2Error;
        }
    }
    /* An output computed from others (models/model_derived.c) needs their values, lazy ones too. */
    const fmi2Status status = ak_instance_read_status(
        instance, ak_model_any_derived(vr, nvr) ? ak_instance_update_all_outputs(instance)
                                                : ak_instance_update_outputs(instance));
    if (status == fmi2Error || status == fmi2Discard) {
        return status;
    }
    ak_model_output_derivatives(&instance->data, vr, nvr, value);
    return status;
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference vUnknown_ref[],
                                        size_t nUnknown, const fmi2ValueReference vKnown_ref[],
                                        size_t nKnown, const fmi2Real dvKnown[],
                                        fmi2Real dvUnknown[]) {
    ak_instance *instance = c;
    const ak_function self = AK_FMI2_GET_DIRECTIONAL_DERIVATIVE;
    if (!ak_call_allowed(instance, self)) {
        return fmi2Error;
    }
    if (AK_MODEL.jacobian == NULL) {
        return not_provided(instance, self, "providesDirectionalDerivative=\"false\"");
    }
    if (
        !arrays_given(instance, self, nUnknown, "nUnknown", vUnknown_ref, "vUnknown_ref",
                      dvUnknown, "dvUnknown", NULL, NULL) ||
        !arrays_given(instance, self, nKnown, "nKnown", vKnown_ref, "vKnown_ref", dvKnown,
                      "dvKnown", NULL, NULL)) {
        return fmi2Error;
    }
    for (size_t i = 0; i < nUnknown; i++) {
        if (state_index(AK_MODEL.derivative_vrs, vUnknown_ref[i]) < 0 &&
            !value_reference_is(instance, self, "vUnknown_ref", i, vUnknown_ref[i],
                                AK_CAUSALITY_OUTPUT)) {
            return fmi2Error;
        }
    }
    for (size_t j = 0; j < nKnown; j++) {
        if (state_index(AK_MODEL.state_vrs, vKnown_ref[j]) < 0 && !value_reference_is(instance, self, "vKnown_ref", j, vKnown_ref[j],
                                             AK_CAUSALITY_INPUT)) {
            return fmi2Error;
        }
        if (!isfinite(dvKnown[j])) {
            ak_log(instance, AK_LOG_ERROR, fmi2Error,
                   "fmi2GetDirectionalDerivative: dvKnown[%zu] = %g (seed of %s) is not finite",
                   j, dvKnown[j], AK_MODEL.variables[vKnown_ref[j]].name);
            return fmi2Error;
        }
    }
    /* An output computed from others (models/model_derived.c) needs their values, lazy ones too;
     * the others come from the inputs alone. */
    if (ak_model_any_derived(vUnknown_ref, nUnknown)) {
        const fmi2Status status =
            ak_instance_read_status(instance, ak_instance_update_all_outputs(instance));
        if (status == fmi2Discard) {
            return status;
        }
    }
    /* Row by row, at most AK_MAX_VARIABLES rows at a time. */
    double J[AK_MAX_VARIABLES][AK_MAX_KNOWNS];
    for (size_t first = 0; first < nUnknown; first += AK_MAX_VARIABLES) {
        const size_t n = nUnknown - first < AK_MAX_VARIABLES ? nUnknown - first : AK_MAX_VARIABLES;
        ak_model_jacobian(&instance->data, &vUnknown_ref[first], n, J);
        /* cppcheck 2.10 takes n for 0 once ak_model_jacobian is visible (n >= 1 here, since
         * first < nUnknown): a false knownConditionTrueFalse. */
        // cppcheck-suppress knownConditionTrueFalse
        for (size_t i = 0; i < n; i++) {
            double sum = 0.0;
            for (size_t j = 0; j < nKnown; j++) {
                sum += J[i][known_column(vKnown_ref[j])] * dvKnown[j];
            }
            dvUnknown[first + i] = sum;
        }
    }
    return fmi2OK;
}
