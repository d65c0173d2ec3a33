/* FMI 2.0 model exchange. The model's continuous states (ak_model.n_states, 0 for the algebraic
 * models AngularKinematics and EulerRates) are values like every other, at the value references
 * ak_model.state_vrs; their derivatives come from ak_model.derivatives. No model has event
 * indicators: no event ever happens, and the event functions only move the time and check their
 * arguments. */
#include <math.h>
#include <stddef.h>

#include "fmi2Functions.h"
#include "fmi2_instance.h"
#include "fmi2_logging.h"
#include "fmi2_state_machine.h"

/* An array that must be empty: event indicators always, states of a model without any. */
static bool no_elements(const ak_instance *instance, ak_function function, const char *what,
                        size_t n) {
    if (n != 0) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error, "%s: %s = %zu, but this FMU has %s (%s must be 0)",
               ak_function_name(function), what, n,
               AK_MODEL.n_states == 0 ? "no continuous states and no event indicators"
                                      : "no event indicators",
               what);
        return false;
    }
    return true;
}

/* An array of states, derivatives or nominals: length the number of states, given if not empty. */
static bool state_array(const ak_instance *instance, ak_function function, const char *name,
                        const void *array, size_t nx) {
    if (AK_MODEL.n_states == 0) {
        return no_elements(instance, function, "nx", nx);
    }
    if (nx != (size_t)AK_MODEL.n_states) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error,
               "%s: nx = %zu, but this FMU has %d continuous states (numberOfContinuousStates)",
               ak_function_name(function), nx, AK_MODEL.n_states);
        return false;
    }
    if (nx > 0 && array == NULL) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error, "%s: %s is NULL with nx = %zu",
               ak_function_name(function), name, nx);
        return false;
    }
    return true;
}

fmi2Status fmi2EnterEventMode(fmi2Component c) {
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_ENTER_EVENT_MODE)) {
        return fmi2Error;
    }
    instance->state = AK_STATE_EVENT_MODE;
    return fmi2OK;
}

fmi2Status fmi2NewDiscreteStates(fmi2Component c, fmi2EventInfo *eventInfo) {
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_NEW_DISCRETE_STATES)) {
        return fmi2Error;
    }
    if (eventInfo == NULL) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error, "fmi2NewDiscreteStates: eventInfo is NULL");
        return fmi2Error;
    }
    /* No discrete states, no time events, nothing that could ask for another iteration. */
    eventInfo->newDiscreteStatesNeeded = fmi2False;
    eventInfo->terminateSimulation = fmi2False;
    eventInfo->nominalsOfContinuousStatesChanged = fmi2False;
    eventInfo->valuesOfContinuousStatesChanged = fmi2False;
    eventInfo->nextEventTimeDefined = fmi2False;
    eventInfo->nextEventTime = 0.0;
    return fmi2OK;
}

fmi2Status fmi2EnterContinuousTimeMode(fmi2Component c) {
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_ENTER_CONTINUOUS_TIME_MODE)) {
        return fmi2Error;
    }
    instance->state = AK_STATE_CONTINUOUS_TIME_MODE;
    return fmi2OK;
}

fmi2Status fmi2CompletedIntegratorStep(fmi2Component c, fmi2Boolean noSetFMUStatePriorToCurrentPoint,
                                       fmi2Boolean *enterEventMode,
                                       fmi2Boolean *terminateSimulation) {
    (void)noSetFMUStatePriorToCurrentPoint; /* an FMU state is a copy: nothing to release */
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_COMPLETED_INTEGRATOR_STEP)) {
        return fmi2Error;
    }
    if (enterEventMode == NULL || terminateSimulation == NULL) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error, "fmi2CompletedIntegratorStep: %s is NULL",
               enterEventMode == NULL ? "enterEventMode" : "terminateSimulation");
        return fmi2Error;
    }
    *enterEventMode = fmi2False;
    *terminateSimulation = fmi2False;
    return fmi2OK;
}

fmi2Status fmi2SetTime(fmi2Component c, fmi2Real time) {
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_SET_TIME)) {
        return fmi2Error;
    }
    if (!isfinite(time)) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error, "fmi2SetTime: time = %g is not finite", time);
        return fmi2Error;
    }
    /* No output depends on the time itself, so the outputs stay valid. The time may go back:
     * an integrator may evaluate the model at earlier points after rejecting a step. */
    ak_log(instance, AK_LOG_CALLS, fmi2OK, "fmi2SetTime: time = %.17g", time);
    instance->time = time;
    return fmi2OK;
}

fmi2Status fmi2SetContinuousStates(fmi2Component c, const fmi2Real x[], size_t nx) {
    ak_instance *instance = c;
    const ak_function self = AK_FMI2_SET_CONTINUOUS_STATES;
    if (!ak_call_allowed(instance, self) || !state_array(instance, self, "x", x, nx)) {
        return fmi2Error;
    }
    for (size_t k = 0; k < nx; k++) {
        if (!isfinite(x[k])) {
            ak_log(instance, AK_LOG_ERROR, fmi2Error,
                   "fmi2SetContinuousStates: x[%zu] = %g (%s) is not finite; no state set", k,
                   x[k], AK_MODEL.variables[AK_MODEL.state_vrs[k]].name);
            return fmi2Error;
        }
    }
    for (size_t k = 0; k < nx; k++) {
        double *value = &instance->data.values[AK_MODEL.state_vrs[k]];
        if (*value != x[k]) {
            *value = x[k];
            ak_instance_inputs_changed(instance);
        }
    }
    return fmi2OK;
}

fmi2Status fmi2GetDerivatives(fmi2Component c, fmi2Real derivatives[], size_t nx) {
    ak_instance *instance = c;
    const ak_function self = AK_FMI2_GET_DERIVATIVES;
    if (!ak_call_allowed(instance, self) ||
        !state_array(instance, self, "derivatives", derivatives, nx)) {
        return fmi2Error;
    }
    if (nx > 0) {
        AK_MODEL.derivatives(&instance->data); /* cheap, and exact for the current states */
    }
    for (size_t k = 0; k < nx; k++) {
        derivatives[k] = instance->data.values[AK_MODEL.derivative_vrs[k]];
    }
    return fmi2OK;
}

fmi2Status fmi2GetEventIndicators(fmi2Component c, fmi2Real eventIndicators[], size_t ni) {
    (void)eventIndicators;
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_GET_EVENT_INDICATORS) ||
        !no_elements(instance, AK_FMI2_GET_EVENT_INDICATORS, "ni", ni)) {
        return fmi2Error;
    }
    return fmi2OK;
}

fmi2Status fmi2GetContinuousStates(fmi2Component c, fmi2Real x[], size_t nx) {
    ak_instance *instance = c;
    const ak_function self = AK_FMI2_GET_CONTINUOUS_STATES;
    if (!ak_call_allowed(instance, self) || !state_array(instance, self, "x", x, nx)) {
        return fmi2Error;
    }
    /* In InitializationMode the states follow the parameters: bring them up to date. */
    if (nx > 0 && (instance->state & AK_STATE_INITIALIZATION_MODE) != 0 &&
        ak_instance_update_outputs(instance) == AK_EVAL_FAILED) {
        return fmi2Discard; /* the model logged why */
    }
    for (size_t k = 0; k < nx; k++) {
        x[k] = instance->data.values[AK_MODEL.state_vrs[k]];
    }
    return fmi2OK;
}

fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component c, fmi2Real x_nominal[], size_t nx) {
    ak_instance *instance = c;
    const ak_function self = AK_FMI2_GET_NOMINALS_OF_CONTINUOUS_STATES;
    if (!ak_call_allowed(instance, self) || !state_array(instance, self, "x_nominal", x_nominal, nx)) {
        return fmi2Error;
    }
    for (size_t k = 0; k < nx; k++) {
        x_nominal[k] = AK_MODEL.state_nominals[k];
    }
    return fmi2OK;
}
