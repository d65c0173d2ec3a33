/* FMI 2.0 co-simulation and model exchange; without event indicators, no event ever happens. */
#include "fmi2_layer.h"

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                      fmi2Real communicationStepSize,
                      fmi2Boolean noSetFMUStatePriorToCurrentPoint) {
    (void)noSetFMUStatePriorToCurrentPoint; /* an FMU state is a copy: nothing to release */
    if (!fmi2_allowed(c, AK_FMI2_DO_STEP)) {
        return fmi2Error;
    }
    return fmi2_status(ak_do_step(c, fmi2_name(AK_FMI2_DO_STEP), currentCommunicationPoint,
                                  communicationStepSize));
}

fmi2Status fmi2CancelStep(fmi2Component c) {
    /* Steps are never asynchronous: no instance is in StepInProgress, the table refuses all. */
    (void)fmi2_allowed(c, AK_FMI2_CANCEL_STEP);
    return fmi2Error;
}

static const fmi2StatusKind NONE = (fmi2StatusKind)-1;

/* OK when the caller is to write the value. */
static fmi2Status status_asked(const ak_instance *instance, ak_fmi2_function function,
                               const void *value, fmi2StatusKind kind, fmi2StatusKind answered) {
    if (!fmi2_allowed(instance, function) ||
        !ak_not_null(instance, fmi2_name(function), value, "value")) {
        return fmi2Error;
    }
    if (kind != answered) {
        ak_log(instance, AK_LOG_WARNING, AK_STATUS_DISCARD,
               "%s: status kind %d is not available: steps are never asynchronous",
               fmi2_name(function), (int)kind);
        return fmi2Discard;
    }
    return answered == NONE ? fmi2Error : fmi2OK;
}

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status *value) {
    return status_asked(c, AK_FMI2_GET_STATUS, value, s, NONE);
}

fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real *value) {
    const fmi2Status status =
        status_asked(c, AK_FMI2_GET_REAL_STATUS, value, s, fmi2LastSuccessfulTime);
    if (status == fmi2OK) {
        *value = ((const ak_instance *)c)->time;
    }
    return status;
}

fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer *value) {
    return status_asked(c, AK_FMI2_GET_INTEGER_STATUS, value, s, NONE);
}

fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean *value) {
    const fmi2Status status = status_asked(c, AK_FMI2_GET_BOOLEAN_STATUS, value, s, fmi2Terminated);
    if (status == fmi2OK) {
        *value = fmi2False; /* the FMU never asks to end the simulation */
    }
    return status;
}

fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String *value) {
    return status_asked(c, AK_FMI2_GET_STRING_STATUS, value, s, NONE);
}

fmi2Status fmi2EnterEventMode(fmi2Component c) {
    return fmi2_status(ak_enter_state(c, &FMI2_RULES[AK_FMI2_ENTER_EVENT_MODE], AK_EVENT_MODE));
}

fmi2Status fmi2NewDiscreteStates(fmi2Component c, fmi2EventInfo *eventInfo) {
    if (!fmi2_allowed(c, AK_FMI2_NEW_DISCRETE_STATES) ||
        !ak_not_null(c, fmi2_name(AK_FMI2_NEW_DISCRETE_STATES), eventInfo, "eventInfo")) {
        return fmi2Error;
    }
    *eventInfo = (fmi2EventInfo){0}; /* no discrete states, no time events: nothing to repeat */
    return fmi2OK;
}

fmi2Status fmi2EnterContinuousTimeMode(fmi2Component c) {
    return fmi2_status(ak_enter_state(c, &FMI2_RULES[AK_FMI2_ENTER_CONTINUOUS_TIME_MODE],
                                      AK_CONTINUOUS_TIME_MODE));
}

fmi2Status fmi2CompletedIntegratorStep(fmi2Component c,
                                       fmi2Boolean noSetFMUStatePriorToCurrentPoint,
                                       fmi2Boolean *enterEventMode,
                                       fmi2Boolean *terminateSimulation) {
    (void)noSetFMUStatePriorToCurrentPoint; /* an FMU state is a copy: nothing to release */
    const char *self = fmi2_name(AK_FMI2_COMPLETED_INTEGRATOR_STEP);
    if (!fmi2_allowed(c, AK_FMI2_COMPLETED_INTEGRATOR_STEP) ||
        !ak_not_null(c, self, enterEventMode, "enterEventMode") ||
        !ak_not_null(c, self, terminateSimulation, "terminateSimulation")) {
        return fmi2Error;
    }
    *enterEventMode = fmi2False;
    *terminateSimulation = fmi2False;
    return fmi2OK;
}

fmi2Status fmi2SetTime(fmi2Component c, fmi2Real time) {
    return fmi2_status(ak_set_time(c, &FMI2_RULES[AK_FMI2_SET_TIME], time));
}

fmi2Status fmi2SetContinuousStates(fmi2Component c, const fmi2Real x[], size_t nx) {
    return fmi2_status(
        ak_set_continuous_states(c, &FMI2_RULES[AK_FMI2_SET_CONTINUOUS_STATES], "nx", "x", x, nx));
}

fmi2Status fmi2GetDerivatives(fmi2Component c, fmi2Real derivatives[], size_t nx) {
    return fmi2_status(ak_get_state_derivatives(c, &FMI2_RULES[AK_FMI2_GET_DERIVATIVES], "nx",
                                                "derivatives", derivatives, nx));
}

fmi2Status fmi2GetEventIndicators(fmi2Component c, fmi2Real eventIndicators[], size_t ni) {
    (void)eventIndicators;
    return fmi2_status(
        ak_no_event_indicators(c, &FMI2_RULES[AK_FMI2_GET_EVENT_INDICATORS], "ni", ni));
}

fmi2Status fmi2GetContinuousStates(fmi2Component c, fmi2Real x[], size_t nx) {
    return fmi2_status(
        ak_get_continuous_states(c, &FMI2_RULES[AK_FMI2_GET_CONTINUOUS_STATES], "nx", "x", x, nx));
}

fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component c, fmi2Real x_nominal[], size_t nx) {
    return fmi2_status(ak_get_nominals(c, &FMI2_RULES[AK_FMI2_GET_NOMINALS_OF_CONTINUOUS_STATES],
                                       "nx", "x_nominal", x_nominal, nx));
}
