/* FMI 2.0 entry points of the instance life cycle: instantiation, initialization, termination,
 * reset, freeing, and the debug-logging switch. */
#include <string.h>

#include "fmi2_layer.h"

const char *fmi2GetTypesPlatform(void) {
    return fmi2TypesPlatform;
}

const char *fmi2GetVersion(void) {
    return fmi2Version;
}

/* Before an instance exists: the master's logger, if it gave one, named by the instance name. */
typedef struct {
    const fmi2CallbackFunctions *functions;
    const char *instance_name;
} unborn;

static void send_unborn(const void *context, const char *message) {
    const unborn *u = context;
    if (u->functions->logger != NULL) {
        fmi2_send(u->functions, u->instance_name, fmi2Error, AK_LOG_ERROR, message);
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
        ak_log_without_instance(send_unborn, &who,
                            "%s: functions->allocateMemory and functions->freeMemory must not "
                            "be NULL",
                            self);
        return NULL;
    }
    if (instanceName == NULL || instanceName[0] == '\0') {
        ak_log_without_instance(send_unborn, &who,
                            "%s: instanceName must be a non-empty string", self);
        return NULL;
    }
    if (fmuType != fmi2CoSimulation && fmuType != fmi2ModelExchange) {
        ak_log_without_instance(send_unborn, &who,
                            "%s: fmuType = %d is neither fmi2ModelExchange (0) nor "
                            "fmi2CoSimulation (1)",
                            self, (int)fmuType);
        return NULL;
    }
    if (fmuGUID == NULL || strcmp(fmuGUID, AK_MODEL.guid) != 0) {
        ak_log_without_instance(send_unborn, &who,
                            "%s: fmuGUID = \"%s\" does not match the GUID \"%s\" of this FMU's "
                            "binary (%s)",
                            self, fmuGUID ? fmuGUID : "(null)", AK_MODEL.guid,
                            AK_MODEL.model_identifier);
        return NULL;
    }
    fmi2_instance *instance = functions->allocateMemory(1, sizeof(fmi2_instance));
    if (instance != NULL) {
        instance->functions = *functions;
    }
    if (instance == NULL ||
        !ak_instance_start(&instance->base, &FMI2_LAYER, self, instanceName,
                           fmuType == fmi2ModelExchange ? AK_MODEL_EXCHANGE : AK_CO_SIMULATION,
                           functions->logger != NULL, loggingOn != fmi2False)) {
        ak_log_without_instance(send_unborn, &who,
                            "%s: out of memory allocating the instance", self);
        if (instance != NULL) {
            functions->freeMemory(instance);
        }
        return NULL;
    }
    return instance;
}

void fmi2FreeInstance(fmi2Component c) {
    ak_instance *instance = c;
    if (!fmi2_allowed(instance, AK_FMI2_FREE_INSTANCE)) {
        return;
    }
    ak_instance_release(instance);
    ((fmi2_instance *)c)->functions.freeMemory(c);
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
