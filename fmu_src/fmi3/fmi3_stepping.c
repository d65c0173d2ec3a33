/* FMI 3.0 time: the step and the continuous states. FMI 3 has no input derivatives: a step holds
 * the inputs. The models have no event indicators, so no event ever happens. */
#include "fmi3_layer.h"

fmi3Status fmi3DoStep(fmi3Instance c, fmi3Float64 currentCommunicationPoint,
                      fmi3Float64 communicationStepSize,
                      fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                      fmi3Boolean *eventHandlingNeeded, fmi3Boolean *terminateSimulation,
                      fmi3Boolean *earlyReturn, fmi3Float64 *lastSuccessfulTime) {
    (void)noSetFMUStatePriorToCurrentPoint; /* an FMU state is a copy: nothing to release */
    ak_instance *instance = c;
    const char *self = fmi3_name(AK3_DO_STEP);
    if (!fmi3_allowed(instance, AK3_DO_STEP) ||
        !ak_not_null(instance, self, eventHandlingNeeded, "eventHandlingNeeded") ||
        !ak_not_null(instance, self, terminateSimulation, "terminateSimulation") ||
        !ak_not_null(instance, self, earlyReturn, "earlyReturn") ||
        !ak_not_null(instance, self, lastSuccessfulTime, "lastSuccessfulTime")) {
        return fmi3Error;
    }
    const ak_status status =
        ak_do_step(instance, self, currentCommunicationPoint, communicationStepSize);
    if (status != AK_STATUS_ERROR) {
        *eventHandlingNeeded = fmi3False;
        *terminateSimulation = fmi3False;
        *earlyReturn = fmi3False;
        *lastSuccessfulTime = instance->time;
    }
    return fmi3_status(status);
}

fmi3Status fmi3UpdateDiscreteStates(fmi3Instance c, fmi3Boolean *discreteStatesNeedUpdate,
                                    fmi3Boolean *terminateSimulation,
                                    fmi3Boolean *nominalsOfContinuousStatesChanged,
                                    fmi3Boolean *valuesOfContinuousStatesChanged,
                                    fmi3Boolean *nextEventTimeDefined,
                                    fmi3Float64 *nextEventTime) {
    const char *self = fmi3_name(AK3_UPDATE_DISCRETE_STATES);
    if (!fmi3_allowed(c, AK3_UPDATE_DISCRETE_STATES) ||
        !ak_not_null(c, self, discreteStatesNeedUpdate, "discreteStatesNeedUpdate") ||
        !ak_not_null(c, self, terminateSimulation, "terminateSimulation") ||
        !ak_not_null(c, self, nominalsOfContinuousStatesChanged,
                     "nominalsOfContinuousStatesChanged") ||
        !ak_not_null(c, self, valuesOfContinuousStatesChanged, "valuesOfContinuousStatesChanged") ||
        !ak_not_null(c, self, nextEventTimeDefined, "nextEventTimeDefined") ||
        !ak_not_null(c, self, nextEventTime, "nextEventTime")) {
        return fmi3Error;
    }
    /* No discrete states, no time events, nothing that could ask for another iteration. */
    *discreteStatesNeedUpdate = fmi3False;
    *terminateSimulation = fmi3False;
    *nominalsOfContinuousStatesChanged = fmi3False;
    *valuesOfContinuousStatesChanged = fmi3False;
    *nextEventTimeDefined = fmi3False;
    *nextEventTime = 0.0;
    return fmi3OK;
}

fmi3Status fmi3CompletedIntegratorStep(fmi3Instance c, fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                                       fmi3Boolean *enterEventMode,
                                       fmi3Boolean *terminateSimulation) {
    (void)noSetFMUStatePriorToCurrentPoint;
    const char *self = fmi3_name(AK3_COMPLETED_INTEGRATOR_STEP);
    if (!fmi3_allowed(c, AK3_COMPLETED_INTEGRATOR_STEP) ||
        !ak_not_null(c, self, enterEventMode, "enterEventMode") ||
        !ak_not_null(c, self, terminateSimulation, "terminateSimulation")) {
        return fmi3Error;
    }
    *enterEventMode = fmi3False;
    *terminateSimulation = fmi3False;
    return fmi3OK;
}

fmi3Status fmi3SetTime(fmi3Instance c, fmi3Float64 time) {
    return fmi3_status(ak_set_time(c, &FMI3_RULES[AK3_SET_TIME], time));
}

fmi3Status fmi3SetContinuousStates(fmi3Instance c, const fmi3Float64 x[], size_t nx) {
    return fmi3_status(ak_set_continuous_states(c, &FMI3_RULES[AK3_SET_CONTINUOUS_STATES],
                                                "nContinuousStates", "continuousStates", x, nx));
}

fmi3Status fmi3GetContinuousStateDerivatives(fmi3Instance c, fmi3Float64 derivatives[],
                                             size_t nContinuousStates) {
    const ak_function_rule *call = &FMI3_RULES[AK3_GET_CONTINUOUS_STATE_DERIVATIVES];
    return fmi3_status(ak_get_state_derivatives(c, call, "nContinuousStates", "derivatives",
                                                derivatives, nContinuousStates));
}

fmi3Status fmi3GetContinuousStates(fmi3Instance c, fmi3Float64 x[], size_t nx) {
    return fmi3_status(ak_get_continuous_states(c, &FMI3_RULES[AK3_GET_CONTINUOUS_STATES],
                                                "nContinuousStates", "continuousStates", x, nx));
}

fmi3Status fmi3GetNominalsOfContinuousStates(fmi3Instance c, fmi3Float64 nominals[], size_t nx) {
    return fmi3_status(ak_get_nominals(c, &FMI3_RULES[AK3_GET_NOMINALS_OF_CONTINUOUS_STATES],
                                       "nContinuousStates", "nominals", nominals, nx));
}

fmi3Status fmi3GetEventIndicators(fmi3Instance c, fmi3Float64 eventIndicators[],
                                  size_t nEventIndicators) {
    (void)eventIndicators;
    return fmi3_status(ak_no_event_indicators(c, &FMI3_RULES[AK3_GET_EVENT_INDICATORS],
                                              "nEventIndicators", nEventIndicators));
}

static fmi3Status give_count(ak_instance *instance, ak3_function function, size_t *out,
                             const char *out_name, size_t count) {
    if (!fmi3_allowed(instance, function) ||
        !ak_not_null(instance, fmi3_name(function), out, out_name)) {
        return fmi3Error;
    }
    *out = count;
    return fmi3OK;
}

fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance c, size_t *nEventIndicators) {
    return give_count(c, AK3_GET_NUMBER_OF_EVENT_INDICATORS, nEventIndicators,
                      "nEventIndicators", 0);
}

fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance c, size_t *nContinuousStates) {
    return give_count(c, AK3_GET_NUMBER_OF_CONTINUOUS_STATES, nContinuousStates,
                      "nContinuousStates", (size_t)AK_MODEL.n_states);
}
