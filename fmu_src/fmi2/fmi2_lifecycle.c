/* FMI 2.0 entry points of the instance life cycle: instantiation, initialization,
 * termination, reset, freeing, and the debug-logging switch. */
#include <math.h>
#include <string.h>

#include "fmi2Functions.h"
#include "fmi2_instance.h"
#include "fmi2_logging.h"
#include "fmi2_state_machine.h"

const char *fmi2GetTypesPlatform(void) {
    return fmi2TypesPlatform;
}

const char *fmi2GetVersion(void) {
    return fmi2Version;
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation,
                              const fmi2CallbackFunctions *functions, fmi2Boolean visible,
                              fmi2Boolean loggingOn) {
    (void)fmuResourceLocation; /* the FMU needs no resources */
    (void)visible;             /* nor any user interface */
    if (functions == NULL) {
        return NULL; /* no logger to say why */
    }
    if (functions->allocateMemory == NULL || functions->freeMemory == NULL) {
        ak_log_before_instance(functions, instanceName,
                               "fmi2Instantiate: functions->allocateMemory and "
                               "functions->freeMemory must not be NULL");
        return NULL;
    }
    if (instanceName == NULL || instanceName[0] == '\0') {
        ak_log_before_instance(functions, instanceName,
                               "fmi2Instantiate: instanceName must be a non-empty string");
        return NULL;
    }
    if (fmuType != fmi2CoSimulation && fmuType != fmi2ModelExchange) {
        ak_log_before_instance(functions, instanceName,
                               "fmi2Instantiate: fmuType = %d is neither fmi2ModelExchange (0) "
                               "nor fmi2CoSimulation (1)",
                               (int)fmuType);
        return NULL;
    }
    if (fmuGUID == NULL || strcmp(fmuGUID, AK_MODEL.guid) != 0) {
        ak_log_before_instance(functions, instanceName,
                               "fmi2Instantiate: fmuGUID = \"%s\" does not match the GUID "
                               "\"%s\" of this FMU's binary (%s)",
                               fmuGUID ? fmuGUID : "(null)", AK_MODEL.guid,
                               AK_MODEL.model_identifier);
        return NULL;
    }

    ak_instance *instance = functions->allocateMemory(1, sizeof(ak_instance));
    const size_t name_size = strlen(instanceName) + 1;
    char *name = functions->allocateMemory(name_size, 1);
    if (instance == NULL || name == NULL) {
        ak_log_before_instance(functions, instanceName,
                               "fmi2Instantiate: out of memory allocating the instance");
        if (instance != NULL) {
            functions->freeMemory(instance);
        }
        if (name != NULL) {
            functions->freeMemory(name);
        }
        return NULL;
    }
    memcpy(name, instanceName, name_size);
    instance->functions = *functions;
    instance->instance_name = name;
    instance->logging_on_at_instantiation = loggingOn != fmi2False;
    instance->fmu_type = fmuType;
    ak_instance_reset(instance);
    ak_log(instance, AK_LOG_CALLS, fmi2OK, "fmi2Instantiate: instance \"%s\" created",
           instanceName);
    return instance;
}

void fmi2FreeInstance(fmi2Component c) {
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_FREE_INSTANCE)) {
        return;
    }
    const fmi2CallbackFreeMemory free_memory = instance->functions.freeMemory;
    ak_free_all_fmu_states(instance);
    free_memory(instance->instance_name);
    free_memory(instance);
}

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t nCategories,
                               const fmi2String categories[]) {
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_SET_DEBUG_LOGGING)) {
        return fmi2Error;
    }
    /* The logger of the model's data is the instance's (ak_instance_reset). */
    if (!ak_log_categories_set(&instance->data, "fmi2SetDebugLogging", instance->log_enabled,
                               nCategories, categories, loggingOn != fmi2False)) {
        return fmi2Error;
    }
    return fmi2OK;
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined,
                               fmi2Real tolerance, fmi2Real startTime,
                               fmi2Boolean stopTimeDefined, fmi2Real stopTime) {
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_SETUP_EXPERIMENT)) {
        return fmi2Error;
    }
    if (toleranceDefined && !(isfinite(tolerance) && tolerance >= 0.0)) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error,
               "fmi2SetupExperiment: tolerance = %g must be finite and >= 0", tolerance);
        return fmi2Error;
    }
    if (!isfinite(startTime)) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error,
               "fmi2SetupExperiment: startTime = %g is not finite", startTime);
        return fmi2Error;
    }
    if (stopTimeDefined && !(isfinite(stopTime) && stopTime >= startTime)) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error,
               "fmi2SetupExperiment: stopTime = %.17g must be finite and >= startTime = %.17g",
               stopTime, startTime);
        return fmi2Error;
    }
    /* The map is algebraic: the tolerance has nothing to control. */
    instance->time = startTime;
    instance->stop_time_defined = stopTimeDefined != fmi2False;
    instance->stop_time = stopTime;
    return fmi2OK;
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_ENTER_INITIALIZATION_MODE)) {
        return fmi2Error;
    }
    instance->state = AK_STATE_INITIALIZATION_MODE;
    return fmi2OK;
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_EXIT_INITIALIZATION_MODE)) {
        return fmi2Error;
    }
    /* The states from the parameters: a refusal (logged by the model) leaves the instance in
     * InitializationMode, so that the master can correct the parameters and call again. */
    if (AK_MODEL.initialize != NULL) {
        if (AK_MODEL.initialize(&instance->data) == AK_EVAL_FAILED) {
            ak_log(instance, AK_LOG_ERROR, fmi2Error,
                   "fmi2ExitInitializationMode: the parameters give no initial state (see the "
                   "message before); the instance stays in InitializationMode");
            return fmi2Error;
        }
        ak_instance_inputs_changed(instance);
    }
    /* The outputs at the initial inputs; a failed evaluation is reported by the reads. */
    (void)ak_instance_update_outputs(instance);
    instance->state = instance->fmu_type == fmi2ModelExchange ? AK_STATE_EVENT_MODE
                                                              : AK_STATE_STEP_COMPLETE;
    return fmi2OK;
}

fmi2Status fmi2Terminate(fmi2Component c) {
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_TERMINATE)) {
        return fmi2Error;
    }
    instance->state = AK_STATE_TERMINATED;
    return fmi2OK;
}

fmi2Status fmi2Reset(fmi2Component c) {
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_RESET)) {
        return fmi2Error;
    }
    ak_instance_reset(instance);
    return fmi2OK;
}
