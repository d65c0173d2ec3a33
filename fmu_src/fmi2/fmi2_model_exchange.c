/* FMI 2.0 model exchange over runtime/continuous.c. No model has event indicators: the event
 * functions only move the state machine and check their arguments. */
#include "fmi2_layer.h"

fmi2Status fmi2EnterEventMode(fmi2Component c) {
    return fmi2_status(ak_enter_state(c, &FMI2_RULES[AK_FMI2_ENTER_EVENT_MODE], AK_EVENT_MODE));
}

fmi2Status fmi2NewDiscreteStates(fmi2Component c, fmi2EventInfo *eventInfo) {
    if (!fmi2_allowed(c, AK_FMI2_NEW_DISCRETE_STATES) ||
        !ak_not_null(c, fmi2_name(AK_FMI2_NEW_DISCRETE_STATES), eventInfo, "eventInfo")) {
        return fmi2Error;
    }
    /* No discrete states, no time events, nothing that could ask for another iteration: every
     * field false, nextEventTime 0. */
    *eventInfo = (fmi2EventInfo){0};
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
