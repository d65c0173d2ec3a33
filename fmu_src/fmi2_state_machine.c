/* The allowed-state table of the FMI 2.0 co-simulation state machine (FMI 2.0.4, section 4.2.4). */
#include "fmi2_state_machine.h"

#include "fmi2_logging.h"

enum {
    INSTANTIATED = AK_STATE_INSTANTIATED,
    INITIALIZATION_MODE = AK_STATE_INITIALIZATION_MODE,
    STEP_COMPLETE = AK_STATE_STEP_COMPLETE,
    STEP_IN_PROGRESS = AK_STATE_STEP_IN_PROGRESS,
    STEP_FAILED = AK_STATE_STEP_FAILED,
    STEP_CANCELED = AK_STATE_STEP_CANCELED,
    TERMINATED = AK_STATE_TERMINATED,
    ANY_STATE = INSTANTIATED | INITIALIZATION_MODE | STEP_COMPLETE | STEP_IN_PROGRESS |
                STEP_FAILED | STEP_CANCELED | TERMINATED,
    /* Where the values of the variables can be read. */
    READABLE = INITIALIZATION_MODE | STEP_COMPLETE | STEP_FAILED | STEP_CANCELED | TERMINATED,
    /* Where inputs can be set. */
    WRITABLE = INSTANTIATED | INITIALIZATION_MODE | STEP_COMPLETE,
    /* Where the simulation status can be asked. */
    STATUS = STEP_COMPLETE | STEP_IN_PROGRESS | STEP_FAILED | STEP_CANCELED | TERMINATED,
    /* Where the FMU state can be got, set or serialized. */
    FMU_STATE = ANY_STATE & ~STEP_IN_PROGRESS
};

static const struct {
    const char *name;
    unsigned int allowed_states;
} FUNCTIONS[AK_N_FMI2_FUNCTIONS] = {
    [AK_FMI2_SET_DEBUG_LOGGING] = {"fmi2SetDebugLogging", ANY_STATE},
    [AK_FMI2_FREE_INSTANCE] = {"fmi2FreeInstance", ANY_STATE & ~STEP_IN_PROGRESS},
    [AK_FMI2_SETUP_EXPERIMENT] = {"fmi2SetupExperiment", INSTANTIATED},
    [AK_FMI2_ENTER_INITIALIZATION_MODE] = {"fmi2EnterInitializationMode", INSTANTIATED},
    [AK_FMI2_EXIT_INITIALIZATION_MODE] = {"fmi2ExitInitializationMode", INITIALIZATION_MODE},
    [AK_FMI2_TERMINATE] = {"fmi2Terminate", STEP_COMPLETE | STEP_FAILED | STEP_CANCELED},
    [AK_FMI2_RESET] = {"fmi2Reset", ANY_STATE & ~STEP_IN_PROGRESS},
    [AK_FMI2_GET_REAL] = {"fmi2GetReal", READABLE},
    [AK_FMI2_GET_INTEGER] = {"fmi2GetInteger", READABLE},
    [AK_FMI2_GET_BOOLEAN] = {"fmi2GetBoolean", READABLE},
    [AK_FMI2_GET_STRING] = {"fmi2GetString", READABLE},
    [AK_FMI2_SET_REAL] = {"fmi2SetReal", WRITABLE},
    [AK_FMI2_SET_INTEGER] = {"fmi2SetInteger", WRITABLE},
    [AK_FMI2_SET_BOOLEAN] = {"fmi2SetBoolean", WRITABLE},
    [AK_FMI2_SET_STRING] = {"fmi2SetString", WRITABLE},
    [AK_FMI2_GET_FMU_STATE] = {"fmi2GetFMUstate", FMU_STATE},
    [AK_FMI2_SET_FMU_STATE] = {"fmi2SetFMUstate", FMU_STATE},
    [AK_FMI2_FREE_FMU_STATE] = {"fmi2FreeFMUstate", FMU_STATE},
    [AK_FMI2_SERIALIZED_FMU_STATE_SIZE] = {"fmi2SerializedFMUstateSize", FMU_STATE},
    [AK_FMI2_SERIALIZE_FMU_STATE] = {"fmi2SerializeFMUstate", FMU_STATE},
    [AK_FMI2_DE_SERIALIZE_FMU_STATE] = {"fmi2DeSerializeFMUstate", FMU_STATE},
    [AK_FMI2_GET_DIRECTIONAL_DERIVATIVE] = {"fmi2GetDirectionalDerivative", READABLE},
    [AK_FMI2_SET_REAL_INPUT_DERIVATIVES] = {"fmi2SetRealInputDerivatives", WRITABLE},
    [AK_FMI2_GET_REAL_OUTPUT_DERIVATIVES] = {"fmi2GetRealOutputDerivatives",
                                            STEP_COMPLETE | STEP_FAILED | STEP_CANCELED |
                                                TERMINATED},
    [AK_FMI2_DO_STEP] = {"fmi2DoStep", STEP_COMPLETE},
    [AK_FMI2_CANCEL_STEP] = {"fmi2CancelStep", STEP_IN_PROGRESS},
    [AK_FMI2_GET_STATUS] = {"fmi2GetStatus", STATUS},
    [AK_FMI2_GET_REAL_STATUS] = {"fmi2GetRealStatus", STATUS},
    [AK_FMI2_GET_INTEGER_STATUS] = {"fmi2GetIntegerStatus", STATUS},
    [AK_FMI2_GET_BOOLEAN_STATUS] = {"fmi2GetBooleanStatus", STATUS},
    [AK_FMI2_GET_STRING_STATUS] = {"fmi2GetStringStatus", STATUS},
};

const char *ak_function_name(ak_function function) {
    return FUNCTIONS[function].name;
}

const char *ak_state_name(ak_state state) {
    switch (state) {
    case AK_STATE_INSTANTIATED: return "Instantiated";
    case AK_STATE_INITIALIZATION_MODE: return "InitializationMode";
    case AK_STATE_STEP_COMPLETE: return "StepComplete";
    case AK_STATE_STEP_IN_PROGRESS: return "StepInProgress";
    case AK_STATE_STEP_FAILED: return "StepFailed";
    case AK_STATE_STEP_CANCELED: return "StepCanceled";
    case AK_STATE_TERMINATED: return "Terminated";
    }
    return "unknown";
}

bool ak_call_allowed(const ak_instance *instance, ak_function function) {
    if (instance == NULL) {
        return false;
    }
    if ((FUNCTIONS[function].allowed_states & (unsigned int)instance->state) == 0) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error, "%s: illegal call in state %s",
               FUNCTIONS[function].name, ak_state_name(instance->state));
        return false;
    }
    if (ak_log_on(instance, AK_LOG_CALLS)) {
        ak_log(instance, AK_LOG_CALLS, fmi2OK, "%s", FUNCTIONS[function].name);
    }
    return true;
}
