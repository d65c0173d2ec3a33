/* The allowed-state table of FMI 3.0: model exchange and co-simulation, as fmi-standard's
 * docs/2_3_common_states.adoc, 3_2 and 4_2 list the allowed calls of each state. An instance
 * lives in one machine, chosen by the fmi3Instantiate* function that made it. Co-simulation
 * instances never use Event Mode (hasEventMode is not declared and fmi3InstantiateCoSimulation
 * refuses eventModeUsed), so fmi3EnterEventMode, fmi3UpdateDiscreteStates and fmi3EnterStepMode
 * are refused for them by the table. ConfigurationMode and ReconfigurationMode exist only for
 * structural parameters, which these models do not have: no instance ever enters them. */
#include "fmi3_layer.h"

enum {
    INSTANTIATED = AK_INSTANTIATED,
    CONFIGURATION_MODE = AK_CONFIGURATION_MODE,
    INITIALIZATION_MODE = AK_INITIALIZATION_MODE,
    EVENT_MODE = AK_EVENT_MODE,
    STEP_MODE = AK_STEP_MODE,
    CONTINUOUS_TIME_MODE = AK_CONTINUOUS_TIME_MODE,
    RECONFIGURATION_MODE = AK_RECONFIGURATION_MODE,
    TERMINATED = AK_TERMINATED,
    ANY_STATE = INSTANTIATED | CONFIGURATION_MODE | INITIALIZATION_MODE | EVENT_MODE | STEP_MODE |
                CONTINUOUS_TIME_MODE | RECONFIGURATION_MODE | TERMINATED,
    /* Where variables can be read: in Instantiated the start values, or what was set since
     * ("Functions fmi3Get{VariableType}: Returns the current start values as defined in
     * modelDescription.xml or as set by fmi3Set{VariableType}", 2_3, State: Instantiated). */
    READABLE = INSTANTIATED | INITIALIZATION_MODE | EVENT_MODE | STEP_MODE | CONTINUOUS_TIME_MODE |
               TERMINATED,
    /* Where some variable can be set: parameters in Instantiated and Initialization Mode, inputs
     * also in Event, Step and Continuous-Time Mode (all inputs are continuous). */
    WRITABLE = INSTANTIATED | INITIALIZATION_MODE | EVENT_MODE | STEP_MODE | CONTINUOUS_TIME_MODE,
    /* Where the partial derivatives are defined (2_2): not in Instantiated. */
    DERIVABLE = INITIALIZATION_MODE | EVENT_MODE | STEP_MODE | CONTINUOUS_TIME_MODE | TERMINATED,
    /* Where model exchange's states, their derivatives, nominals and event indicators can be
     * read (2_3: Initialization Mode, the Initialized super state, Terminated). */
    ME_READABLE = INITIALIZATION_MODE | EVENT_MODE | CONTINUOUS_TIME_MODE | TERMINATED
};

enum { ME = AK_MODEL_EXCHANGE, CS = AK_CO_SIMULATION, BOTH = ME | CS };

const ak_function_rule FMI3_RULES[AK3_N_FUNCTIONS] = {
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
    [AK3_GET_DIRECTIONAL_DERIVATIVE] = {"fmi3GetDirectionalDerivative", DERIVABLE, BOTH},
    [AK3_GET_ADJOINT_DERIVATIVE] = {"fmi3GetAdjointDerivative", DERIVABLE, BOTH},
    [AK3_UPDATE_DISCRETE_STATES] = {"fmi3UpdateDiscreteStates", EVENT_MODE, ME},
    [AK3_ENTER_CONTINUOUS_TIME_MODE] = {"fmi3EnterContinuousTimeMode", EVENT_MODE, ME},
    [AK3_COMPLETED_INTEGRATOR_STEP] = {"fmi3CompletedIntegratorStep", CONTINUOUS_TIME_MODE, ME},
    /* 3_2, State: Continuous-Time Mode: "t := (time, 0) | fmi3SetTime"; in Event Mode time
     * advances only through fmi3UpdateDiscreteStates. */
    [AK3_SET_TIME] = {"fmi3SetTime", CONTINUOUS_TIME_MODE, ME},
    [AK3_SET_CONTINUOUS_STATES] = {"fmi3SetContinuousStates", CONTINUOUS_TIME_MODE, ME},
    [AK3_GET_CONTINUOUS_STATE_DERIVATIVES] = {"fmi3GetContinuousStateDerivatives", ME_READABLE,
                                              ME},
    [AK3_GET_EVENT_INDICATORS] = {"fmi3GetEventIndicators", ME_READABLE, ME},
    [AK3_GET_CONTINUOUS_STATES] = {"fmi3GetContinuousStates", ME_READABLE, ME},
    [AK3_GET_NOMINALS_OF_CONTINUOUS_STATES] = {"fmi3GetNominalsOfContinuousStates", ME_READABLE,
                                               ME},
    /* The standard lists these in Instantiated and Event Mode only; importers (fmusim) ask them
     * in Continuous-Time Mode too, and the answer never changes. */
    [AK3_GET_NUMBER_OF_EVENT_INDICATORS] = {"fmi3GetNumberOfEventIndicators", ANY_STATE, ME},
    [AK3_GET_NUMBER_OF_CONTINUOUS_STATES] = {"fmi3GetNumberOfContinuousStates", ANY_STATE, ME},
    [AK3_ENTER_STEP_MODE] = {"fmi3EnterStepMode", EVENT_MODE, CS},
    [AK3_GET_OUTPUT_DERIVATIVES] = {"fmi3GetOutputDerivatives", STEP_MODE | TERMINATED, CS},
    [AK3_DO_STEP] = {"fmi3DoStep", STEP_MODE, CS},
};
