/* FMI 3.0 entry points of the instance life cycle: instantiation (model exchange and
 * co-simulation), initialization, event mode entry, termination, reset, freeing, logging. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fmi3Functions.h"
#include "fmi3_instance.h"
#include "fmi3_logging.h"
#include "fmi3_state_machine.h"

const char *fmi3GetVersion(void) {
    return fmi3Version;
}

/* The checks and the allocation common to both interfaces; NULL after logging why. FMI 3 gives
 * no memory callbacks: the instance is on the C heap. */
static ak3_instance *instantiate(const char *function, fmi3String instanceName,
                                 fmi3String instantiationToken, fmi3Boolean loggingOn,
                                 fmi3InstanceEnvironment environment,
                                 fmi3LogMessageCallback logMessage, ak3_interface interface) {
    if (instanceName == NULL || instanceName[0] == '\0') {
        ak3_log_before_instance(environment, logMessage,
                                "%s: instanceName must be a non-empty string", function);
        return NULL;
    }
    if (instantiationToken == NULL || strcmp(instantiationToken, AK_MODEL.guid) != 0) {
        ak3_log_before_instance(environment, logMessage,
                                "%s: instantiationToken = \"%s\" does not match the token "
                                "\"%s\" of this FMU's binary (%s)",
                                function, instantiationToken ? instantiationToken : "(null)",
                                AK_MODEL.guid, AK_MODEL.model_identifier);
        return NULL;
    }
    ak3_instance *instance = calloc(1, sizeof(ak3_instance));
    const size_t name_size = strlen(instanceName) + 1;
    char *name = malloc(name_size);
    if (instance == NULL || name == NULL) {
        ak3_log_before_instance(environment, logMessage,
                                "%s: out of memory allocating the instance", function);
        free(instance);
        free(name);
        return NULL;
    }
    memcpy(name, instanceName, name_size);
    instance->instance_name = name;
    instance->environment = environment;
    instance->log_message = logMessage;
    instance->logging_on_at_instantiation = loggingOn != fmi3False;
    instance->interface = interface;
    ak3_instance_reset(instance);
    ak3_log(instance, AK_LOG_CALLS, fmi3OK, "%s: instance \"%s\" created", function,
            instanceName);
    return instance;
}

fmi3Instance fmi3InstantiateModelExchange(fmi3String instanceName, fmi3String instantiationToken,
                                          fmi3String resourcePath, fmi3Boolean visible,
                                          fmi3Boolean loggingOn,
                                          fmi3InstanceEnvironment instanceEnvironment,
                                          fmi3LogMessageCallback logMessage) {
    (void)resourcePath; /* the FMU needs no resources */
    (void)visible;      /* nor any user interface */
    return instantiate("fmi3InstantiateModelExchange", instanceName, instantiationToken,
                       loggingOn, instanceEnvironment, logMessage, AK3_MODEL_EXCHANGE);
}

fmi3Instance fmi3InstantiateCoSimulation(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath,
    fmi3Boolean visible, fmi3Boolean loggingOn, fmi3Boolean eventModeUsed,
    fmi3Boolean earlyReturnAllowed, const fmi3ValueReference requiredIntermediateVariables[],
    size_t nRequiredIntermediateVariables, fmi3InstanceEnvironment instanceEnvironment,
    fmi3LogMessageCallback logMessage, fmi3IntermediateUpdateCallback intermediateUpdate) {
    (void)resourcePath;
    (void)visible;
    (void)earlyReturnAllowed;           /* the FMU never returns early */
    (void)requiredIntermediateVariables;
    (void)intermediateUpdate;           /* nor calls back during a step */
    const char *self = "fmi3InstantiateCoSimulation";
    if (eventModeUsed) {
        ak3_log_before_instance(instanceEnvironment, logMessage,
                                "%s: eventModeUsed = true, but this FMU has no events "
                                "(hasEventMode is not declared)",
                                self);
        return NULL;
    }
    if (nRequiredIntermediateVariables != 0) {
        ak3_log_before_instance(instanceEnvironment, logMessage,
                                "%s: nRequiredIntermediateVariables = %zu, but this FMU "
                                "provides no intermediate update (must be 0)",
                                self, nRequiredIntermediateVariables);
        return NULL;
    }
    return instantiate(self, instanceName, instantiationToken, loggingOn, instanceEnvironment,
                       logMessage, AK3_CO_SIMULATION);
}

void fmi3FreeInstance(fmi3Instance c) {
    ak3_instance *instance = c;
    if (!ak3_call_allowed(instance, AK3_FREE_INSTANCE)) {
        return;
    }
    ak3_free_all_fmu_states(instance);
    free(instance->instance_name);
    free(instance);
}

fmi3Status fmi3SetDebugLogging(fmi3Instance c, fmi3Boolean loggingOn, size_t nCategories,
                               const fmi3String categories[]) {
    ak3_instance *instance = c;
    if (!ak3_call_allowed(instance, AK3_SET_DEBUG_LOGGING)) {
        return fmi3Error;
    }
    /* The logger of the model's data is the instance's (ak3_instance_reset). */
    if (!ak_log_categories_set(&instance->data, "fmi3SetDebugLogging", instance->log_enabled,
                               nCategories, categories, loggingOn != fmi3False)) {
        return fmi3Error;
    }
    return fmi3OK;
}

fmi3Status fmi3EnterInitializationMode(fmi3Instance c, fmi3Boolean toleranceDefined,
                                       fmi3Float64 tolerance, fmi3Float64 startTime,
                                       fmi3Boolean stopTimeDefined, fmi3Float64 stopTime) {
    ak3_instance *instance = c;
    const char *self = "fmi3EnterInitializationMode";
    if (!ak3_call_allowed(instance, AK3_ENTER_INITIALIZATION_MODE)) {
        return fmi3Error;
    }
    if (toleranceDefined && !(isfinite(tolerance) && tolerance >= 0.0)) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error, "%s: tolerance = %g must be finite and >= 0",
                self, tolerance);
        return fmi3Error;
    }
    if (!isfinite(startTime)) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error, "%s: startTime = %g is not finite", self,
                startTime);
        return fmi3Error;
    }
    if (stopTimeDefined && !(isfinite(stopTime) && stopTime >= startTime)) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error,
                "%s: stopTime = %.17g must be finite and >= startTime = %.17g", self, stopTime,
                startTime);
        return fmi3Error;
    }
    /* No model integrates with an error control (co-simulation steps are closed-form, model
     * exchange is the importer's): the tolerance has nothing to control. */
    instance->time = startTime;
    instance->stop_time_defined = stopTimeDefined != fmi3False;
    instance->stop_time = stopTime;
    instance->state = AK3_STATE_INITIALIZATION_MODE;
    return fmi3OK;
}

fmi3Status fmi3ExitInitializationMode(fmi3Instance c) {
    ak3_instance *instance = c;
    if (!ak3_call_allowed(instance, AK3_EXIT_INITIALIZATION_MODE)) {
        return fmi3Error;
    }
    /* The states from the parameters: a refusal (logged by the model) leaves the instance in
     * Initialization Mode, so that the importer can correct the parameters and call again. */
    if (AK_MODEL.initialize != NULL) {
        if (AK_MODEL.initialize(&instance->data) == AK_EVAL_FAILED) {
            ak3_log(instance, AK_LOG_ERROR, fmi3Error,
                    "fmi3ExitInitializationMode: the parameters give no initial state (see the "
                    "message before); the instance stays in Initialization Mode");
            return fmi3Error;
        }
        ak3_instance_inputs_changed(instance);
    }
    /* The outputs at the initial inputs; a failed evaluation is reported by the reads. */
    (void)ak3_instance_update_outputs(instance);
    instance->state = instance->interface == AK3_MODEL_EXCHANGE ? AK3_STATE_EVENT_MODE
                                                                : AK3_STATE_STEP_MODE;
    return fmi3OK;
}

fmi3Status fmi3EnterEventMode(fmi3Instance c) {
    ak3_instance *instance = c;
    if (!ak3_call_allowed(instance, AK3_ENTER_EVENT_MODE)) {
        return fmi3Error;
    }
    instance->state = AK3_STATE_EVENT_MODE;
    return fmi3OK;
}

fmi3Status fmi3Terminate(fmi3Instance c) {
    ak3_instance *instance = c;
    if (!ak3_call_allowed(instance, AK3_TERMINATE)) {
        return fmi3Error;
    }
    instance->state = AK3_STATE_TERMINATED;
    return fmi3OK;
}

fmi3Status fmi3Reset(fmi3Instance c) {
    ak3_instance *instance = c;
    if (!ak3_call_allowed(instance, AK3_RESET)) {
        return fmi3Error;
    }
    ak3_instance_reset(instance);
    return fmi3OK;
}
