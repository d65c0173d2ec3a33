/* FMI 2.0 co-simulation stepping and status. A step advances the model's continuous states, if
 * it has any (ak_model.step, with the inputs and their derivatives at the step start), then
 * moves the time and the inputs: held over the step, or moved along the polynomials given by
 * fmi2SetRealInputDerivatives; the outputs at the end are those of the states and inputs there.
 * For a model without states the map from inputs to outputs is algebraic. */
#include <math.h>
#include <string.h>

#include "fmi2Functions.h"
#include "fmi2_derivatives.h"
#include "fmi2_instance.h"
#include "fmi2_logging.h"
#include "fmi2_state_machine.h"

/* Relative tolerance on communication times; the same as fmpy's isclose, so that a step that
 * fmpy lands on the stop time within its own tolerance is accepted. */
static const double TIME_RELATIVE_TOLERANCE = 1e-9;

static bool times_close(double a, double b) {
    /* Not fmax: that is a library call, paid at every step; the two agree on non-NaN values. */
    const double scale = fabs(a) > fabs(b) ? fabs(a) : fabs(b);
    return fabs(a - b) <= TIME_RELATIVE_TOLERANCE * scale;
}

/* A step of a model with states or whose evaluation can fail: the states are advanced, then the
 * outputs are evaluated at the end of the step. When either fails the step is not taken
 * (fmi2Discard, StepFailed): time, states, inputs and outputs stay those of the last successful
 * communication point, which fmi2GetRealStatus(fmi2LastSuccessfulTime) reports;
 * fmi2GetBooleanStatus(fmi2Terminated) stays false, so the master may go back with
 * fmi2SetFMUstate or fmi2Reset, or terminate. */
static fmi2Status step_evaluating(ak_instance *instance, double t, double h) {
    double saved_values[AK_MAX_VARIABLES];
    double saved_derivatives[AK_MAX_INPUTS][AK_MAX_INPUT_DERIVATIVE_ORDER];
    const size_t n_values = sizeof(double) * (size_t)AK_MODEL.n_value_references;
    memcpy(saved_values, instance->data.values, n_values);
    memcpy(saved_derivatives, instance->data.input_derivatives, sizeof saved_derivatives);
    const bool saved_any = instance->data.any_input_derivative;
    ak_eval_status status = AK_EVAL_OK;
    if (AK_MODEL.step != NULL) {
        status = AK_MODEL.step(&instance->data, h); /* failing, it changed nothing */
        ak_instance_inputs_changed(instance);
    }
    const bool step_failed = status == AK_EVAL_FAILED;
    if (status != AK_EVAL_FAILED && !ak_advance_inputs(instance, h)) {
        memcpy(instance->data.values, saved_values, n_values); /* the states moved */
        return fmi2Error;
    }
    if (status != AK_EVAL_FAILED) {
        status = ak_instance_update_outputs(instance);
    }
    if (status == AK_EVAL_FAILED) {
        memcpy(instance->data.values, saved_values, n_values);
        memcpy(instance->data.input_derivatives, saved_derivatives, sizeof saved_derivatives);
        instance->data.any_input_derivative = saved_any;
        /* The outputs are those of the last successful evaluation; a read evaluates again at the
         * restored inputs (and fails again if they are the singular ones). */
        ak_instance_inputs_changed(instance);
        instance->state = AK_STATE_STEP_FAILED;
        ak_log(instance, AK_LOG_WARNING, fmi2Discard,
               "fmi2DoStep: the step from %.17g to %.17g is discarded: the %s; last "
               "successful time %.17g",
               t, t + h,
               step_failed ? "states cannot be advanced over it"
                                       : "outputs cannot be evaluated at its end",
               instance->time);
        return fmi2Discard;
    }
    instance->time = t + h;
    if (ak_log_on(instance, AK_LOG_CALLS)) {
        ak_log(instance, AK_LOG_CALLS, fmi2OK, "fmi2DoStep: from %.17g to %.17g", t, t + h);
    }
    return ak_instance_read_status(instance, status);
}

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                      fmi2Real communicationStepSize, fmi2Boolean noSetFMUStatePriorToCurrentPoint) {
    (void)noSetFMUStatePriorToCurrentPoint; /* an FMU state is a copy: nothing to release */
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_DO_STEP)) {
        return fmi2Error;
    }
    const double t = currentCommunicationPoint, h = communicationStepSize;
    if (!isfinite(t) || !isfinite(h)) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error,
               "fmi2DoStep: currentCommunicationPoint = %g and communicationStepSize = %g "
               "must be finite",
               t, h);
        return fmi2Error;
    }
    if (!(h > 0.0)) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error,
               "fmi2DoStep: communicationStepSize = %g must be > 0", h);
        return fmi2Error;
    }
    if (!times_close(t, instance->time)) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error,
               "fmi2DoStep: currentCommunicationPoint = %.17g does not continue from the last "
               "communication point %.17g",
               t, instance->time);
        return fmi2Error;
    }
    const double end = t + h;
    if (instance->stop_time_defined && end > instance->stop_time &&
        !times_close(end, instance->stop_time)) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error,
               "fmi2DoStep: the step from %.17g by communicationStepSize = %.17g ends at "
               "%.17g, past stopTime = %.17g",
               t, h, end, instance->stop_time);
        return fmi2Error;
    }
    if (AK_MODEL.evaluate_in_step || AK_MODEL.step != NULL) {
        return step_evaluating(instance, t, h);
    }
    /* Without input derivatives the inputs are held: no call (ak_advance_inputs would return at
     * once). */
    if (instance->data.any_input_derivative && !ak_advance_inputs(instance, h)) {
        return fmi2Error;
    }
    if (ak_log_on(instance, AK_LOG_CALLS)) {
        ak_log(instance, AK_LOG_CALLS, fmi2OK, "fmi2DoStep: from %.17g to %.17g", t, end);
    }
    instance->time = end;
    return fmi2OK;
}

fmi2Status fmi2CancelStep(fmi2Component c) {
    /* Steps are never asynchronous, so no instance is ever in StepInProgress: the table rejects
     * every call. */
    ak_instance *instance = c;
    ak_call_allowed(instance, AK_FMI2_CANCEL_STEP);
    return fmi2Error;
}

static fmi2Status status_not_available(const ak_instance *instance, ak_function function,
                                       int kind) {
    ak_log(instance, AK_LOG_WARNING, fmi2Discard,
           "%s: status kind %d is not available: steps are never asynchronous",
           ak_function_name(function), kind);
    return fmi2Discard;
}

static bool status_arguments_valid(const ak_instance *instance, ak_function function,
                                   const void *value) {
    if (!ak_call_allowed(instance, function)) {
        return false;
    }
    if (value == NULL) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error, "%s: value is NULL",
               ak_function_name(function));
        return false;
    }
    return true;
}

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status *value) {
    ak_instance *instance = c;
    if (!status_arguments_valid(instance, AK_FMI2_GET_STATUS, value)) {
        return fmi2Error;
    }
    return status_not_available(instance, AK_FMI2_GET_STATUS, (int)s);
}

fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real *value) {
    ak_instance *instance = c;
    if (!status_arguments_valid(instance, AK_FMI2_GET_REAL_STATUS, value)) {
        return fmi2Error;
    }
    if (s != fmi2LastSuccessfulTime) {
        return status_not_available(instance, AK_FMI2_GET_REAL_STATUS, (int)s);
    }
    *value = instance->time;
    return fmi2OK;
}

fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer *value) {
    ak_instance *instance = c;
    if (!status_arguments_valid(instance, AK_FMI2_GET_INTEGER_STATUS, value)) {
        return fmi2Error;
    }
    return status_not_available(instance, AK_FMI2_GET_INTEGER_STATUS, (int)s);
}

fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean *value) {
    ak_instance *instance = c;
    if (!status_arguments_valid(instance, AK_FMI2_GET_BOOLEAN_STATUS, value)) {
        return fmi2Error;
    }
    if (s != fmi2Terminated) {
        return status_not_available(instance, AK_FMI2_GET_BOOLEAN_STATUS, (int)s);
    }
    *value = fmi2False; /* the FMU never asks to end the simulation */
    return fmi2OK;
}

fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String *value) {
    ak_instance *instance = c;
    if (!status_arguments_valid(instance, AK_FMI2_GET_STRING_STATUS, value)) {
        return fmi2Error;
    }
    return status_not_available(instance, AK_FMI2_GET_STRING_STATUS, (int)s);
}
