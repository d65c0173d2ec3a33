/* What the FMI 3 layer tells the runtime of itself: state names, message words, the FMU-state
 * format, and how it logs (the importer's logMessage; unlike FMI 2, the message is not a printf
 * format) and allocates (the C heap). */
#include <stdlib.h>

#include "fmi3_layer.h"

static void send(const ak_instance *instance, ak_log_category category, ak_status status,
                 const char *message) {
    const fmi3_instance *self = (const fmi3_instance *)instance;
    self->log_message(self->environment, fmi3_status(status), AK_LOG_CATEGORY_NAMES[category],
                      message);
}

static void *allocate(const ak_instance *instance, size_t size) {
    (void)instance;
    return calloc(1, size);
}

static void release(const ak_instance *instance, void *memory) {
    (void)instance;
    free(memory);
}

const ak_layer FMI3_LAYER = {
    .state_names = {"Instantiated", "Configuration Mode", "Initialization Mode", "Event Mode",
                    "Step Mode", "Continuous-Time Mode", "Reconfiguration Mode", "Terminated",
                    "Step In Progress", "Step Failed", "Step Canceled"},
    .other_interface = {"not available to this instance, made by fmi3InstantiateModelExchange",
                        "not available to this instance, made by fmi3InstantiateCoSimulation "
                        "without Event Mode"},
    .vr_name = "valueReferences",
    .vr_count_name = "nValueReferences",
    .values_name = "values",
    .values_count_name = "nValues",
    .state_setter_note = " and a continuous state (fmi3SetContinuousStates sets states in model "
                         "exchange)",
    /* A discarded step leaves the instance where it was: FMI 3 has no StepFailed state. */
    .step_discarded_state = AK_STEP_MODE,
    /* Magic "AKinFMU3" (the FMI 2 states' is "AKinFMUs": neither reads the other), format version
     * 1, no input derivatives (FMI 3 co-simulation has none). */
    .state_format = {"AKinFMU3", 1u, "FMI 3 FMU state", "instantiationToken", "interface",
                     "FMUState", "fmi3GetFMUState", "fmi3DeserializeFMUState",
                     "fmi3SerializedFMUStateSize", false},
    .image_states = {AK_INSTANTIATED, AK_CONFIGURATION_MODE, AK_INITIALIZATION_MODE, AK_EVENT_MODE,
                     AK_STEP_MODE, AK_CONTINUOUS_TIME_MODE, AK_RECONFIGURATION_MODE,
                     AK_TERMINATED},
    .possible_states = {AK_INSTANTIATED | AK_INITIALIZATION_MODE | AK_TERMINATED | AK_EVENT_MODE |
                            AK_CONTINUOUS_TIME_MODE,
                        AK_INSTANTIATED | AK_INITIALIZATION_MODE | AK_TERMINATED | AK_STEP_MODE},
    .elements_at = ak3_elements_at,
    .time_vr = &AK3_TIME_VALUE_REFERENCE,
    .refuse_real = ak3_refuse_real,
    .name_of = ak3_name_of,
    .count_matches = ak3_count_matches,
    .errors_always_logged = true,
    .send = send,
    .allocate = allocate,
    .release = release,
};
