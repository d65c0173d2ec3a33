/* FMI 2.0 life cycle: the layer's description, the instance's life and the FMU states. */
#include <string.h>

#include "fmi2_layer.h"

/* FMI 2.0 lets the master treat a message as a printf format: every '%' doubled. */
static void send_to(const fmi2CallbackFunctions *functions, const char *instance_name,
                    fmi2Status status, ak_log_category category, const char *message) {
    char escaped[2048];
    size_t out = 0;
    for (size_t in = 0; message[in] != '\0' && out + 2 < sizeof escaped; in++) {
        escaped[out++] = message[in];
        if (message[in] == '%') {
            escaped[out++] = '%';
        }
    }
    escaped[out] = '\0';
    functions->logger(functions->componentEnvironment, instance_name != NULL ? instance_name : "",
                      status, AK_LOG_CATEGORY_NAMES[category], escaped);
}

static void send(const ak_instance *instance, ak_log_category category, ak_status status,
                 const char *message) {
    send_to(&((const fmi2_instance *)instance)->functions, instance->instance_name,
            fmi2_status(status), category, message);
}

static void *allocate(const ak_instance *instance, size_t size) {
    return ((const fmi2_instance *)instance)->functions.allocateMemory(1, size);
}

static void release(const ak_instance *instance, void *memory) {
    ((const fmi2_instance *)instance)->functions.freeMemory(memory);
}

static const ak_layer FMI2_LAYER = {
    .state_names = {"Instantiated", "ConfigurationMode", "InitializationMode", "EventMode",
                    "StepComplete", "ContinuousTimeMode", "ReconfigurationMode", "Terminated",
                    "StepInProgress", "StepFailed", "StepCanceled"},
    .other_interface = {"a co-simulation function, but this instance was created for model "
                        "exchange (fmi2ModelExchange)",
                        "a model-exchange function, but this instance was created for "
                        "co-simulation (fmi2CoSimulation)"},
    .vr_name = "vr",
    .vr_count_name = "nvr",
    .values_name = "value",
    .values_count_name = "nvr",
    .state_setter_note = " and a continuous state (fmi2SetContinuousStates sets states in model "
                         "exchange)",
    .step_discarded_state = AK_STEP_FAILED,
    .state_format = {"AKinFMUs", 2u, "FMU state", "GUID", "fmuType", "FMUstate",
                     "fmi2GetFMUstate", "fmi2DeSerializeFMUstate", "fmi2SerializedFMUstateSize",
                     true},
    .image_states = {AK_INSTANTIATED, AK_INITIALIZATION_MODE, AK_STEP_MODE, AK_STEP_IN_PROGRESS,
                     AK_STEP_FAILED, AK_STEP_CANCELED, AK_TERMINATED, AK_EVENT_MODE,
                     AK_CONTINUOUS_TIME_MODE},
    .possible_states = {AK_INSTANTIATED | AK_INITIALIZATION_MODE | AK_TERMINATED | AK_EVENT_MODE |
                            AK_CONTINUOUS_TIME_MODE,
                        AK_INSTANTIATED | AK_INITIALIZATION_MODE | AK_TERMINATED | AK_STEP_MODE |
                            AK_STEP_FAILED | AK_STEP_CANCELED},
    /* FMI 2.0.4: "logger should only be called for log categories that were enabled". */
    .errors_always_logged = false,
    .send = send,
    .allocate = allocate,
    .release = release,
};

const char *fmi2GetTypesPlatform(void) {
    return fmi2TypesPlatform;
}

const char *fmi2GetVersion(void) {
    return fmi2Version;
}

/* Before an instance exists: the master's logger, if it gave one. */
typedef struct {
    const fmi2CallbackFunctions *functions;
    const char *instance_name;
} unborn;

static void send_unborn(const void *context, const char *message) {
    const unborn *u = context;
    if (u->functions->logger != NULL) {
        send_to(u->functions, u->instance_name, fmi2Error, AK_LOG_ERROR, message);
    }
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation,
                              const fmi2CallbackFunctions *functions, fmi2Boolean visible,
                              fmi2Boolean loggingOn) {
    (void)fmuResourceLocation; /* the FMU needs no resources */
    (void)visible;             /* nor any user interface */
    const char *self = "fmi2Instantiate";
    if (functions == NULL) {
        return NULL; /* no logger to say why */
    }
    const unborn who = {functions, instanceName};
    if (functions->allocateMemory == NULL || functions->freeMemory == NULL) {
        ak_log_without_instance(send_unborn, &who, "%s: functions->allocateMemory and "
                                "functions->freeMemory must not be NULL", self);
        return NULL;
    }
    if (instanceName == NULL || instanceName[0] == '\0') {
        ak_log_without_instance(send_unborn, &who, "%s: instanceName must be a non-empty string",
                                self);
        return NULL;
    }
    if (fmuType != fmi2CoSimulation && fmuType != fmi2ModelExchange) {
        ak_log_without_instance(send_unborn, &who, "%s: fmuType = %d is neither "
                                "fmi2ModelExchange (0) nor fmi2CoSimulation (1)", self,
                                (int)fmuType);
        return NULL;
    }
    if (fmuGUID == NULL || strcmp(fmuGUID, AK_MODEL.guid) != 0) {
        ak_log_without_instance(send_unborn, &who, "%s: fmuGUID = \"%s\" does not match the "
                                "GUID \"%s\" of this FMU's binary (%s)", self,
                                fmuGUID ? fmuGUID : "(null)", AK_MODEL.guid,
                                AK_MODEL.model_identifier);
        return NULL;
    }
    fmi2_instance *instance = functions->allocateMemory(1, sizeof(fmi2_instance));
    if (instance != NULL) {
        instance->functions = *functions;
        if (ak_instance_start(&instance->base, &FMI2_LAYER, self, instanceName,
                              fmuType == fmi2ModelExchange ? AK_MODEL_EXCHANGE : AK_CO_SIMULATION,
                              functions->logger != NULL, loggingOn != fmi2False)) {
            return instance;
        }
        functions->freeMemory(instance);
    }
    ak_log_without_instance(send_unborn, &who, "%s: out of memory allocating the instance", self);
    return NULL;
}

void fmi2FreeInstance(fmi2Component c) {
    if (fmi2_allowed(c, AK_FMI2_FREE_INSTANCE)) {
        ak_instance_release(c);
        ((fmi2_instance *)c)->functions.freeMemory(c);
    }
}

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t nCategories,
                               const fmi2String categories[]) {
    return fmi2_status(ak_set_debug_logging(c, &FMI2_RULES[AK_FMI2_SET_DEBUG_LOGGING],
                                            loggingOn != fmi2False, nCategories, categories));
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined,
                               fmi2Real tolerance, fmi2Real startTime,
                               fmi2Boolean stopTimeDefined, fmi2Real stopTime) {
    return fmi2_status(ak_setup_experiment(c, &FMI2_RULES[AK_FMI2_SETUP_EXPERIMENT],
                                           toleranceDefined != fmi2False, tolerance, startTime,
                                           stopTimeDefined != fmi2False, stopTime,
                                           AK_INSTANTIATED));
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
    return fmi2_status(ak_enter_state(c, &FMI2_RULES[AK_FMI2_ENTER_INITIALIZATION_MODE],
                                      AK_INITIALIZATION_MODE));
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
    return fmi2_status(
        ak_exit_initialization_mode(c, &FMI2_RULES[AK_FMI2_EXIT_INITIALIZATION_MODE]));
}

fmi2Status fmi2Terminate(fmi2Component c) {
    return fmi2_status(ak_enter_state(c, &FMI2_RULES[AK_FMI2_TERMINATE], AK_TERMINATED));
}

fmi2Status fmi2Reset(fmi2Component c) {
    return fmi2_status(ak_reset(c, &FMI2_RULES[AK_FMI2_RESET]));
}

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *FMUstate) {
    return fmi2_status(ak_get_fmu_state(c, &FMI2_RULES[AK_FMI2_GET_FMU_STATE], FMUstate));
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate FMUstate) {
    return fmi2_status(ak_set_fmu_state(c, &FMI2_RULES[AK_FMI2_SET_FMU_STATE], FMUstate));
}

fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *FMUstate) {
    return fmi2_status(ak_free_fmu_state(c, &FMI2_RULES[AK_FMI2_FREE_FMU_STATE], FMUstate));
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate FMUstate, size_t *size) {
    return fmi2_status(ak_serialized_fmu_state_size(
        c, &FMI2_RULES[AK_FMI2_SERIALIZED_FMU_STATE_SIZE], FMUstate, size));
}

fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate FMUstate, fmi2Byte serializedState[],
                                 size_t size) {
    return fmi2_status(ak_serialize_fmu_state(c, &FMI2_RULES[AK_FMI2_SERIALIZE_FMU_STATE],
                                              FMUstate, (unsigned char *)serializedState, size));
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte serializedState[], size_t size,
                                   fmi2FMUstate *FMUstate) {
    return fmi2_status(ak_deserialize_fmu_state(c, &FMI2_RULES[AK_FMI2_DE_SERIALIZE_FMU_STATE],
                                                (const unsigned char *)serializedState, size,
                                                FMUstate));
}
