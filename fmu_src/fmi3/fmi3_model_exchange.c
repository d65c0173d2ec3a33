/* FMI 3.0 model exchange. The models have no event indicators, so no event ever happens.
 * Continuous states come from the model hooks (models/model.h): AK_MODEL.n_states (0 for the
 * algebraic models), the states and their derivatives are the values at state_vrs[k] and
 * derivative_vrs[k], AK_MODEL.derivatives computes the latter, state_nominals[k] the nominals. */
#include <math.h>

#include "fmi3Functions.h"
#include "fmi3_instance.h"
#include "fmi3_logging.h"
#include "fmi3_state_machine.h"

static size_t n_states(void) {
    return (size_t)AK_MODEL.n_states;
}

/* The caller's array must have exactly n_states() elements and be given when there are any. */
static bool states_array_valid(const ak3_instance *instance, ak3_function function,
                               const void *array, const char *array_name, size_t n) {
    if (n != n_states()) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error,
                "%s: nContinuousStates = %zu, but this FMU has %zu continuous states",
                ak3_function_name(function), n, n_states());
        return false;
    }
    if (n > 0 && array == NULL) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error, "%s: %s is NULL with nContinuousStates = %zu",
                ak3_function_name(function), array_name, n);
        return false;
    }
    return true;
}

fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance c) {
    ak3_instance *instance = c;
    if (!ak3_call_allowed(instance, AK3_ENTER_CONTINUOUS_TIME_MODE)) {
        return fmi3Error;
    }
    instance->state = AK3_STATE_CONTINUOUS_TIME_MODE;
    return fmi3OK;
}

fmi3Status fmi3UpdateDiscreteStates(fmi3Instance c, fmi3Boolean *discreteStatesNeedUpdate,
                                    fmi3Boolean *terminateSimulation,
                                    fmi3Boolean *nominalsOfContinuousStatesChanged,
                                    fmi3Boolean *valuesOfContinuousStatesChanged,
                                    fmi3Boolean *nextEventTimeDefined,
                                    fmi3Float64 *nextEventTime) {
    ak3_instance *instance = c;
    if (!ak3_call_allowed(instance, AK3_UPDATE_DISCRETE_STATES)) {
        return fmi3Error;
    }
    const char *missing = discreteStatesNeedUpdate == NULL            ? "discreteStatesNeedUpdate"
                          : terminateSimulation == NULL               ? "terminateSimulation"
                          : nominalsOfContinuousStatesChanged == NULL ? "nominalsOfContinuousStatesChanged"
                          : valuesOfContinuousStatesChanged == NULL   ? "valuesOfContinuousStatesChanged"
                          : nextEventTimeDefined == NULL              ? "nextEventTimeDefined"
                          : nextEventTime == NULL                     ? "nextEventTime"
                                                                      : NULL;
    if (missing != NULL) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error, "fmi3UpdateDiscreteStates: %s is NULL",
                missing);
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
    ak3_instance *instance = c;
    if (!ak3_call_allowed(instance, AK3_COMPLETED_INTEGRATOR_STEP)) {
        return fmi3Error;
    }
    if (enterEventMode == NULL || terminateSimulation == NULL) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error, "fmi3CompletedIntegratorStep: %s is NULL",
                enterEventMode == NULL ? "enterEventMode" : "terminateSimulation");
        return fmi3Error;
    }
    *enterEventMode = fmi3False;
    *terminateSimulation = fmi3False;
    return fmi3OK;
}

fmi3Status fmi3SetTime(fmi3Instance c, fmi3Float64 time) {
    ak3_instance *instance = c;
    if (!ak3_call_allowed(instance, AK3_SET_TIME)) {
        return fmi3Error;
    }
    if (!isfinite(time)) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error, "fmi3SetTime: time = %g is not finite", time);
        return fmi3Error;
    }
    /* No output depends on the time itself; it may go back after a rejected integrator step. */
    instance->time = time;
    return fmi3OK;
}

fmi3Status fmi3SetContinuousStates(fmi3Instance c, const fmi3Float64 continuousStates[],
                                   size_t nContinuousStates) {
    ak3_instance *instance = c;
    const ak3_function self = AK3_SET_CONTINUOUS_STATES;
    if (!ak3_call_allowed(instance, self) ||
        !states_array_valid(instance, self, continuousStates, "continuousStates",
                            nContinuousStates)) {
        return fmi3Error;
    }
    for (size_t k = 0; k < nContinuousStates; k++) {
        if (!isfinite(continuousStates[k])) {
            ak3_log(instance, AK_LOG_ERROR, fmi3Error,
                    "fmi3SetContinuousStates: continuousStates[%zu] = %g (%s) is not finite; no "
                    "state set",
                    k, continuousStates[k], AK_MODEL.variables[AK_MODEL.state_vrs[k]].name);
            return fmi3Error;
        }
    }
    for (size_t k = 0; k < nContinuousStates; k++) {
        double *value = &instance->data.values[AK_MODEL.state_vrs[k]];
        if (*value != continuousStates[k]) {
            *value = continuousStates[k];
            ak3_instance_inputs_changed(instance);
        }
    }
    return fmi3OK;
}

fmi3Status fmi3GetContinuousStateDerivatives(fmi3Instance c, fmi3Float64 derivatives[],
                                             size_t nContinuousStates) {
    ak3_instance *instance = c;
    const ak3_function self = AK3_GET_CONTINUOUS_STATE_DERIVATIVES;
    if (!ak3_call_allowed(instance, self) ||
        !states_array_valid(instance, self, derivatives, "derivatives", nContinuousStates)) {
        return fmi3Error;
    }
    if (nContinuousStates > 0) {
        AK_MODEL.derivatives(&instance->data);
    }
    for (size_t k = 0; k < nContinuousStates; k++) {
        derivatives[k] = instance->data.values[AK_MODEL.derivative_vrs[k]];
    }
    return fmi3OK;
}

fmi3Status fmi3GetContinuousStates(fmi3Instance c, fmi3Float64 continuousStates[],
                                   size_t nContinuousStates) {
    ak3_instance *instance = c;
    const ak3_function self = AK3_GET_CONTINUOUS_STATES;
    if (!ak3_call_allowed(instance, self) ||
        !states_array_valid(instance, self, continuousStates, "continuousStates",
                            nContinuousStates)) {
        return fmi3Error;
    }
    /* In InitializationMode the states follow the parameters: bring them up to date. */
    if (nContinuousStates > 0 && (instance->state & AK3_STATE_INITIALIZATION_MODE) != 0 &&
        ak3_instance_update_outputs(instance) == AK_EVAL_FAILED) {
        return fmi3Discard; /* the model logged why */
    }
    for (size_t k = 0; k < nContinuousStates; k++) {
        continuousStates[k] = instance->data.values[AK_MODEL.state_vrs[k]];
    }
    return fmi3OK;
}

fmi3Status fmi3GetNominalsOfContinuousStates(fmi3Instance c, fmi3Float64 nominals[],
                                             size_t nContinuousStates) {
    ak3_instance *instance = c;
    const ak3_function self = AK3_GET_NOMINALS_OF_CONTINUOUS_STATES;
    if (!ak3_call_allowed(instance, self) ||
        !states_array_valid(instance, self, nominals, "nominals", nContinuousStates)) {
        return fmi3Error;
    }
    for (size_t k = 0; k < nContinuousStates; k++) {
        nominals[k] = AK_MODEL.state_nominals[k];
    }
    return fmi3OK;
}

fmi3Status fmi3GetEventIndicators(fmi3Instance c, fmi3Float64 eventIndicators[],
                                  size_t nEventIndicators) {
    (void)eventIndicators;
    ak3_instance *instance = c;
    if (!ak3_call_allowed(instance, AK3_GET_EVENT_INDICATORS)) {
        return fmi3Error;
    }
    if (nEventIndicators != 0) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error,
                "fmi3GetEventIndicators: nEventIndicators = %zu, but this FMU has no event "
                "indicators (must be 0)",
                nEventIndicators);
        return fmi3Error;
    }
    return fmi3OK;
}

static fmi3Status give_count(ak3_instance *instance, ak3_function function, size_t *out,
                             const char *out_name, size_t count) {
    if (!ak3_call_allowed(instance, function)) {
        return fmi3Error;
    }
    if (out == NULL) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error, "%s: %s is NULL",
                ak3_function_name(function), out_name);
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
                      "nContinuousStates", n_states());
}
