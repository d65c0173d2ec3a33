/* FMI 2.0 model exchange. The model has no continuous states and no event indicators: its
 * outputs are algebraic functions of its inputs. So the integrator has nothing to integrate, no
 * event ever happens, and the functions below only move the time and check their arguments. */
#include <math.h>

#include "fmi2Functions.h"
#include "fmi2_instance.h"
#include "fmi2_logging.h"
#include "fmi2_state_machine.h"

/* Every array of states, derivatives, nominals or event indicators has length 0. */
static bool no_elements(const ak_instance *instance, ak_function function, const char *what,
                        size_t n) {
    if (n != 0) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error,
               "%s: %s = %zu, but this FMU has no continuous states and no event indicators "
               "(%s must be 0)",
               ak_function_name(function), what, n, what);
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
    (void)x; /* there are none */
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_SET_CONTINUOUS_STATES) ||
        !no_elements(instance, AK_FMI2_SET_CONTINUOUS_STATES, "nx", nx)) {
        return fmi2Error;
    }
    return fmi2OK;
}

fmi2Status fmi2GetDerivatives(fmi2Component c, fmi2Real derivatives[], size_t nx) {
    (void)derivatives;
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_GET_DERIVATIVES) ||
        !no_elements(instance, AK_FMI2_GET_DERIVATIVES, "nx", nx)) {
        return fmi2Error;
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
    (void)x;
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_GET_CONTINUOUS_STATES) ||
        !no_elements(instance, AK_FMI2_GET_CONTINUOUS_STATES, "nx", nx)) {
        return fmi2Error;
    }
    return fmi2OK;
}

fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component c, fmi2Real x_nominal[], size_t nx) {
    (void)x_nominal;
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_GET_NOMINALS_OF_CONTINUOUS_STATES) ||
        !no_elements(instance, AK_FMI2_GET_NOMINALS_OF_CONTINUOUS_STATES, "nx", nx)) {
        return fmi2Error;
    }
    return fmi2OK;
}
