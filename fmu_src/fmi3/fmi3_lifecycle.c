/* FMI 3.0 entry points of the instance life cycle and its FMU states. */
#include <stdlib.h>
#include <string.h>

#include "fmi3_layer.h"

const char *fmi3GetVersion(void) {
    return fmi3Version;
}

/* Before an instance exists: the importer's logger, if it gave one. */
static void send_unborn(const void *context, const char *message) {
    const fmi3_logger *logger = context;
    if (logger->log_message != NULL) {
        logger->log_message(logger->environment, fmi3Error, AK_LOG_CATEGORY_NAMES[AK_LOG_ERROR],
                            message);
    }
}

static fmi3_instance *instantiate(const char *function, fmi3String instanceName,
                                  fmi3String instantiationToken, fmi3Boolean loggingOn,
                                  const fmi3_logger *who, ak_interface interface) {
    if (instanceName == NULL || instanceName[0] == '\0') {
        ak_log_without_instance(send_unborn, who, "%s: instanceName must be a non-empty string",
                                function);
        return NULL;
    }
    if (instantiationToken == NULL || strcmp(instantiationToken, AK_MODEL.guid) != 0) {
        ak_log_without_instance(send_unborn, who,
                                "%s: instantiationToken = \"%s\" does not match the token \"%s\" "
                                "of this FMU's binary (%s)",
                                function, instantiationToken ? instantiationToken : "(null)",
                                AK_MODEL.guid, AK_MODEL.model_identifier);
        return NULL;
    }
    fmi3_instance *instance = calloc(1, sizeof(fmi3_instance));
    if (instance != NULL) {
        instance->logger = *who;
    }
    if (instance == NULL ||
        !ak_instance_start(&instance->base, &FMI3_LAYER, function, instanceName, interface,
                           who->log_message != NULL, loggingOn != fmi3False)) {
        ak_log_without_instance(send_unborn, who, "%s: out of memory allocating the instance",
                                function);
        free(instance);
        return NULL;
    }
    return instance;
}

fmi3Instance fmi3InstantiateModelExchange(fmi3String instanceName, fmi3String instantiationToken,
                                          fmi3String resourcePath, fmi3Boolean visible,
                                          fmi3Boolean loggingOn,
                                          fmi3InstanceEnvironment instanceEnvironment,
                                          fmi3LogMessageCallback logMessage) {
    (void)resourcePath, (void)visible; /* no resources, no user interface */
    const fmi3_logger who = {instanceEnvironment, logMessage};
    return instantiate("fmi3InstantiateModelExchange", instanceName, instantiationToken,
                       loggingOn, &who, AK_MODEL_EXCHANGE);
}

fmi3Instance fmi3InstantiateCoSimulation(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath,
    fmi3Boolean visible, fmi3Boolean loggingOn, fmi3Boolean eventModeUsed,
    fmi3Boolean earlyReturnAllowed, const fmi3ValueReference requiredIntermediateVariables[],
    size_t nRequiredIntermediateVariables, fmi3InstanceEnvironment instanceEnvironment,
    fmi3LogMessageCallback logMessage, fmi3IntermediateUpdateCallback intermediateUpdate) {
    /* The FMU never returns early nor calls back during a step. */
    (void)resourcePath, (void)visible, (void)earlyReturnAllowed;
    (void)requiredIntermediateVariables, (void)intermediateUpdate;
    const char *self = "fmi3InstantiateCoSimulation";
    const fmi3_logger who = {instanceEnvironment, logMessage};
    if (eventModeUsed) {
        ak_log_without_instance(send_unborn, &who,
                                "%s: eventModeUsed = true, but this FMU has no events "
                                "(hasEventMode is not declared)",
                                self);
        return NULL;
    }
    if (nRequiredIntermediateVariables != 0) {
        ak_log_without_instance(send_unborn, &who,
                                "%s: nRequiredIntermediateVariables = %zu, but this FMU provides "
                                "no intermediate update (must be 0)",
                                self, nRequiredIntermediateVariables);
        return NULL;
    }
    return instantiate(self, instanceName, instantiationToken, loggingOn, &who, AK_CO_SIMULATION);
}

fmi3Instance fmi3InstantiateScheduledExecution(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath,
    fmi3Boolean visible, fmi3Boolean loggingOn, fmi3InstanceEnvironment instanceEnvironment,
    fmi3LogMessageCallback logMessage, fmi3ClockUpdateCallback clockUpdate,
    fmi3LockPreemptionCallback lockPreemption, fmi3UnlockPreemptionCallback unlockPreemption) {
    (void)instanceName, (void)instantiationToken, (void)resourcePath, (void)visible;
    (void)loggingOn, (void)clockUpdate, (void)lockPreemption, (void)unlockPreemption;
    const fmi3_logger who = {instanceEnvironment, logMessage};
    send_unborn(&who, "fmi3InstantiateScheduledExecution: not supported: this FMU has no "
                      "ScheduledExecution interface (use fmi3InstantiateCoSimulation or "
                      "fmi3InstantiateModelExchange)");
    return NULL;
}

void fmi3FreeInstance(fmi3Instance c) {
    if (fmi3_allowed(c, AK3_FREE_INSTANCE)) {
        ak_instance_release(c);
        free(c);
    }
}

fmi3Status fmi3SetDebugLogging(fmi3Instance c, fmi3Boolean loggingOn, size_t nCategories,
                               const fmi3String categories[]) {
    return fmi3_status(ak_set_debug_logging(c, &FMI3_RULES[AK3_SET_DEBUG_LOGGING],
                                            loggingOn != fmi3False, nCategories, categories));
}

fmi3Status fmi3EnterInitializationMode(fmi3Instance c, fmi3Boolean toleranceDefined,
                                       fmi3Float64 tolerance, fmi3Float64 startTime,
                                       fmi3Boolean stopTimeDefined, fmi3Float64 stopTime) {
    return fmi3_status(ak_setup_experiment(c, &FMI3_RULES[AK3_ENTER_INITIALIZATION_MODE],
                                           toleranceDefined != fmi3False, tolerance, startTime,
                                           stopTimeDefined != fmi3False, stopTime,
                                           AK_INITIALIZATION_MODE));
}

fmi3Status fmi3ExitInitializationMode(fmi3Instance c) {
    return fmi3_status(ak_exit_initialization_mode(c, &FMI3_RULES[AK3_EXIT_INITIALIZATION_MODE]));
}

fmi3Status fmi3EnterEventMode(fmi3Instance c) {
    return fmi3_status(ak_enter_state(c, &FMI3_RULES[AK3_ENTER_EVENT_MODE], AK_EVENT_MODE));
}

fmi3Status fmi3Terminate(fmi3Instance c) {
    return fmi3_status(ak_enter_state(c, &FMI3_RULES[AK3_TERMINATE], AK_TERMINATED));
}

fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance c) {
    return fmi3_status(ak_enter_state(c, &FMI3_RULES[AK3_ENTER_CONTINUOUS_TIME_MODE],
                                      AK_CONTINUOUS_TIME_MODE));
}

fmi3Status fmi3EnterStepMode(fmi3Instance c) {
    /* Only from Event Mode, which co-simulation instances never enter: the table refuses it. */
    return fmi3_status(ak_enter_state(c, &FMI3_RULES[AK3_ENTER_STEP_MODE], AK_STEP_MODE));
}

fmi3Status fmi3Reset(fmi3Instance c) {
    return fmi3_status(ak_reset(c, &FMI3_RULES[AK3_RESET]));
}

fmi3Status fmi3GetFMUState(fmi3Instance c, fmi3FMUState *FMUState) {
    return fmi3_status(ak_get_fmu_state(c, &FMI3_RULES[AK3_GET_FMU_STATE], FMUState));
}

fmi3Status fmi3SetFMUState(fmi3Instance c, fmi3FMUState FMUState) {
    return fmi3_status(ak_set_fmu_state(c, &FMI3_RULES[AK3_SET_FMU_STATE], FMUState));
}

fmi3Status fmi3FreeFMUState(fmi3Instance c, fmi3FMUState *FMUState) {
    return fmi3_status(ak_free_fmu_state(c, &FMI3_RULES[AK3_FREE_FMU_STATE], FMUState));
}

fmi3Status fmi3SerializedFMUStateSize(fmi3Instance c, fmi3FMUState FMUState, size_t *size) {
    return fmi3_status(ak_serialized_fmu_state_size(c, &FMI3_RULES[AK3_SERIALIZED_FMU_STATE_SIZE],
                                                    FMUState, size));
}

fmi3Status fmi3SerializeFMUState(fmi3Instance c, fmi3FMUState s, fmi3Byte bytes[], size_t size) {
    return fmi3_status(ak_serialize_fmu_state(c, &FMI3_RULES[AK3_SERIALIZE_FMU_STATE], s, bytes,
                                              size));
}

fmi3Status fmi3DeserializeFMUState(fmi3Instance c, const fmi3Byte serializedState[], size_t size,
                                   fmi3FMUState *FMUState) {
    return fmi3_status(ak_deserialize_fmu_state(c, &FMI3_RULES[AK3_DESERIALIZE_FMU_STATE],
                                                serializedState, size, FMUState));
}
