/* The allowed-state table of FMI 3.0: model exchange (section 3.2) and co-simulation (section
 * 4.2). An instance lives in one machine, chosen by the fmi3Instantiate* function that made it.
 * Co-simulation instances never use Event Mode (hasEventMode is not declared and
 * fmi3InstantiateCoSimulation refuses eventModeUsed), so fmi3EnterEventMode,
 * fmi3UpdateDiscreteStates and fmi3EnterStepMode are refused for them by the table. */
#include "fmi3_state_machine.h"

enum {
    INSTANTIATED = AK3_STATE_INSTANTIATED,
    CONFIGURATION_MODE = AK3_STATE_CONFIGURATION_MODE,
    INITIALIZATION_MODE = AK3_STATE_INITIALIZATION_MODE,
    EVENT_MODE = AK3_STATE_EVENT_MODE,
    STEP_MODE = AK3_STATE_STEP_MODE,
    CONTINUOUS_TIME_MODE = AK3_STATE_CONTINUOUS_TIME_MODE,
    RECONFIGURATION_MODE = AK3_STATE_RECONFIGURATION_MODE,
    TERMINATED = AK3_STATE_TERMINATED,
    ANY_STATE = INSTANTIATED | CONFIGURATION_MODE | INITIALIZATION_MODE | EVENT_MODE | STEP_MODE |
                CONTINUOUS_TIME_MODE | RECONFIGURATION_MODE | TERMINATED,
    /* Where variables can be read. */
    READABLE = INITIALIZATION_MODE | EVENT_MODE | STEP_MODE | CONTINUOUS_TIME_MODE | TERMINATED,
    /* Where some variable can be set: parameters in Instantiated and Initialization Mode, inputs
     * also in Event, Step and Continuous-Time Mode (all inputs are continuous). */
    WRITABLE = INSTANTIATED | INITIALIZATION_MODE | EVENT_MODE | STEP_MODE | CONTINUOUS_TIME_MODE,
    /* Where model exchange's states, derivatives and event indicators can be read. */
    ME_READABLE = INITIALIZATION_MODE | EVENT_MODE | CONTINUOUS_TIME_MODE | TERMINATED
};

enum { ME = AK3_INTERFACE_ME, CS = AK3_INTERFACE_CS, BOTH = ME | CS };

const ak3_function_rule AK3_FUNCTION_RULES[AK3_N_FUNCTIONS] = {
    [AK3_SET_DEBUG_LOGGING] = {"fmi3SetDebugLogging", ANY_STATE, BOTH},
    [AK3_FREE_INSTANCE] = {"fmi3FreeInstance", ANY_STATE, BOTH},
    [AK3_ENTER_INITIALIZATION_MODE] = {"fmi3EnterInitializationMode", INSTANTIATED, BOTH},
    [AK3_EXIT_INITIALIZATION_MODE] = {"fmi3ExitInitializationMode", INITIALIZATION_MODE, BOTH},
    [AK3_ENTER_EVENT_MODE] = {"fmi3EnterEventMode", CONTINUOUS_TIME_MODE, ME},
    [AK3_TERMINATE] = {"fmi3Terminate", EVENT_MODE | STEP_MODE | CONTINUOUS_TIME_MODE, BOTH},
    [AK3_RESET] = {"fmi3Reset", ANY_STATE, BOTH},
    [AK3_GET_FLOAT32] = {"fmi3GetFloat32", READABLE, BOTH},
    [AK3_GET_FLOAT64] = {"fmi3GetFloat64", READABLE, BOTH},
    [AK3_GET_INT8] = {"fmi3GetInt8", READABLE, BOTH},
    [AK3_GET_UINT8] = {"fmi3GetUInt8", READABLE, BOTH},
    [AK3_GET_INT16] = {"fmi3GetInt16", READABLE, BOTH},
    [AK3_GET_UINT16] = {"fmi3GetUInt16", READABLE, BOTH},
    [AK3_GET_INT32] = {"fmi3GetInt32", READABLE, BOTH},
    [AK3_GET_UINT32] = {"fmi3GetUInt32", READABLE, BOTH},
    [AK3_GET_INT64] = {"fmi3GetInt64", READABLE, BOTH},
    [AK3_GET_UINT64] = {"fmi3GetUInt64", READABLE, BOTH},
    [AK3_GET_BOOLEAN] = {"fmi3GetBoolean", READABLE, BOTH},
    [AK3_GET_STRING] = {"fmi3GetString", READABLE, BOTH},
    [AK3_GET_BINARY] = {"fmi3GetBinary", READABLE, BOTH},
    [AK3_SET_FLOAT32] = {"fmi3SetFloat32", WRITABLE, BOTH},
    [AK3_SET_FLOAT64] = {"fmi3SetFloat64", WRITABLE, BOTH},
    [AK3_SET_INT8] = {"fmi3SetInt8", WRITABLE, BOTH},
    [AK3_SET_UINT8] = {"fmi3SetUInt8", WRITABLE, BOTH},
    [AK3_SET_INT16] = {"fmi3SetInt16", WRITABLE, BOTH},
    [AK3_SET_UINT16] = {"fmi3SetUInt16", WRITABLE, BOTH},
    [AK3_SET_INT32] = {"fmi3SetInt32", WRITABLE, BOTH},
    [AK3_SET_UINT32] = {"fmi3SetUInt32", WRITABLE, BOTH},
    [AK3_SET_INT64] = {"fmi3SetInt64", WRITABLE, BOTH},
    [AK3_SET_UINT64] = {"fmi3SetUInt64", WRITABLE, BOTH},
    [AK3_SET_BOOLEAN] = {"fmi3SetBoolean", WRITABLE, BOTH},
    [AK3_SET_STRING] = {"fmi3SetString", WRITABLE, BOTH},
    [AK3_SET_BINARY] = {"fmi3SetBinary", WRITABLE, BOTH},
    [AK3_GET_NUMBER_OF_VARIABLE_DEPENDENCIES] = {"fmi3GetNumberOfVariableDependencies", ANY_STATE,
                                                 BOTH},
    [AK3_GET_VARIABLE_DEPENDENCIES] = {"fmi3GetVariableDependencies", ANY_STATE, BOTH},
    [AK3_GET_FMU_STATE] = {"fmi3GetFMUState", ANY_STATE, BOTH},
    [AK3_SET_FMU_STATE] = {"fmi3SetFMUState", ANY_STATE, BOTH},
    [AK3_FREE_FMU_STATE] = {"fmi3FreeFMUState", ANY_STATE, BOTH},
    [AK3_SERIALIZED_FMU_STATE_SIZE] = {"fmi3SerializedFMUStateSize", ANY_STATE, BOTH},
    [AK3_SERIALIZE_FMU_STATE] = {"fmi3SerializeFMUState", ANY_STATE, BOTH},
    [AK3_DESERIALIZE_FMU_STATE] = {"fmi3DeserializeFMUState", ANY_STATE, BOTH},
    [AK3_GET_DIRECTIONAL_DERIVATIVE] = {"fmi3GetDirectionalDerivative", READABLE, BOTH},
    [AK3_GET_ADJOINT_DERIVATIVE] = {"fmi3GetAdjointDerivative", READABLE, BOTH},
    [AK3_UPDATE_DISCRETE_STATES] = {"fmi3UpdateDiscreteStates", EVENT_MODE, ME},
    [AK3_ENTER_CONTINUOUS_TIME_MODE] = {"fmi3EnterContinuousTimeMode", EVENT_MODE, ME},
    [AK3_COMPLETED_INTEGRATOR_STEP] = {"fmi3CompletedIntegratorStep", CONTINUOUS_TIME_MODE, ME},
    [AK3_SET_TIME] = {"fmi3SetTime", EVENT_MODE | CONTINUOUS_TIME_MODE, ME},
    [AK3_SET_CONTINUOUS_STATES] = {"fmi3SetContinuousStates", CONTINUOUS_TIME_MODE, ME},
    [AK3_GET_CONTINUOUS_STATE_DERIVATIVES] = {"fmi3GetContinuousStateDerivatives",
                                              EVENT_MODE | CONTINUOUS_TIME_MODE | TERMINATED, ME},
    [AK3_GET_EVENT_INDICATORS] = {"fmi3GetEventIndicators", ME_READABLE, ME},
    [AK3_GET_CONTINUOUS_STATES] = {"fmi3GetContinuousStates", ME_READABLE, ME},
    [AK3_GET_NOMINALS_OF_CONTINUOUS_STATES] = {"fmi3GetNominalsOfContinuousStates",
                                               INSTANTIATED | ME_READABLE, ME},
    [AK3_GET_NUMBER_OF_EVENT_INDICATORS] = {"fmi3GetNumberOfEventIndicators", ANY_STATE, ME},
    [AK3_GET_NUMBER_OF_CONTINUOUS_STATES] = {"fmi3GetNumberOfContinuousStates", ANY_STATE, ME},
    [AK3_ENTER_STEP_MODE] = {"fmi3EnterStepMode", EVENT_MODE, CS},
    [AK3_GET_OUTPUT_DERIVATIVES] = {"fmi3GetOutputDerivatives", STEP_MODE | TERMINATED, CS},
    [AK3_DO_STEP] = {"fmi3DoStep", STEP_MODE, CS},
};

const char *ak3_state_name(ak3_state state) {
    switch (state) {
    case AK3_STATE_INSTANTIATED: return "Instantiated";
    case AK3_STATE_CONFIGURATION_MODE: return "Configuration Mode";
    case AK3_STATE_INITIALIZATION_MODE: return "Initialization Mode";
    case AK3_STATE_EVENT_MODE: return "Event Mode";
    case AK3_STATE_STEP_MODE: return "Step Mode";
    case AK3_STATE_CONTINUOUS_TIME_MODE: return "Continuous-Time Mode";
    case AK3_STATE_RECONFIGURATION_MODE: return "Reconfiguration Mode";
    case AK3_STATE_TERMINATED: return "Terminated";
    }
    return "unknown";
}

bool ak3_call_checked(const ak3_instance *instance, ak3_function function) {
    if (instance == NULL) {
        return false;
    }
    const ak3_function_rule *rule = &AK3_FUNCTION_RULES[function];
    const bool me = instance->interface == AK3_MODEL_EXCHANGE;
    if ((rule->interfaces & (me ? AK3_INTERFACE_ME : AK3_INTERFACE_CS)) == 0) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error,
                "%s: not available to this instance, made by %s%s", rule->name,
                me ? "fmi3InstantiateModelExchange" : "fmi3InstantiateCoSimulation",
                me ? "" : " without Event Mode");
        return false;
    }
    if ((rule->allowed_states & (unsigned int)instance->state) == 0) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error, "%s: illegal call in state %s", rule->name,
                ak3_state_name(instance->state));
        return false;
    }
    if (ak3_log_on(instance, AK_LOG_CALLS)) {
        ak3_log(instance, AK_LOG_CALLS, fmi3OK, "%s", rule->name);
    }
    return true;
}
