/* What the FMI 2 layer tells the runtime of itself: state names, message words, the FMU-state
 * format, and how it logs and allocates through the master's callbacks. */
#include <stdio.h>

#include "fmi2_layer.h"

void fmi2_send(const fmi2CallbackFunctions *functions, const char *instance_name,
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
    fmi2_send(&((const fmi2_instance *)instance)->functions, instance->instance_name,
              fmi2_status(status), category, message);
}

static void *allocate(const ak_instance *instance, size_t size) {
    return ((const fmi2_instance *)instance)->functions.allocateMemory(1, size);
}

static void release(const ak_instance *instance, void *memory) {
    ((const fmi2_instance *)instance)->functions.freeMemory(memory);
}

const ak_layer FMI2_LAYER = {
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
    /* Magic "AKinFMUs", version 2 (version 1 held the 21 values of the 1-2-3-only FMU), the
     * fmuType in the interface field, the input derivatives; the state field numbers the states
     * as FMI 2 lists them. */
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
