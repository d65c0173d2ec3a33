/* The allowed-state table of FMI 3.0. Co-simulation instances never use Event Mode, and no
 * instance enters Configuration or Reconfiguration Mode (no structural parameters). */
#include "fmi3_layer.h"

enum {
    ANY_STATE = AK_INSTANTIATED | AK_CONFIGURATION_MODE | AK_INITIALIZATION_MODE | AK_EVENT_MODE |
                AK_STEP_MODE | AK_CONTINUOUS_TIME_MODE | AK_RECONFIGURATION_MODE | AK_TERMINATED,
    /* In Instantiated, the start values or what was set since. */
    READABLE = AK_INSTANTIATED | AK_INITIALIZATION_MODE | AK_EVENT_MODE | AK_STEP_MODE |
               AK_CONTINUOUS_TIME_MODE | AK_TERMINATED,
    /* Parameters in Instantiated and Initialization Mode, the (continuous) inputs also after. */
    WRITABLE = AK_INSTANTIATED | AK_INITIALIZATION_MODE | AK_EVENT_MODE | AK_STEP_MODE |
               AK_CONTINUOUS_TIME_MODE,
    DERIVABLE = AK_INITIALIZATION_MODE | AK_EVENT_MODE | AK_STEP_MODE | AK_CONTINUOUS_TIME_MODE |
                AK_TERMINATED,
    ME_READABLE = AK_INITIALIZATION_MODE | AK_EVENT_MODE | AK_CONTINUOUS_TIME_MODE | AK_TERMINATED
};

enum { ME = AK_MODEL_EXCHANGE, CS = AK_CO_SIMULATION, BOTH = ME | CS };

const ak_function_rule FMI3_RULES[AK3_N_FUNCTIONS] = {
    [AK3_SET_DEBUG_LOGGING] = {"fmi3SetDebugLogging", ANY_STATE, BOTH},
    [AK3_FREE_INSTANCE] = {"fmi3FreeInstance", ANY_STATE, BOTH},
    [AK3_ENTER_INITIALIZATION_MODE] = {"fmi3EnterInitializationMode", AK_INSTANTIATED, BOTH},
    [AK3_EXIT_INITIALIZATION_MODE] = {"fmi3ExitInitializationMode", AK_INITIALIZATION_MODE, BOTH},
    [AK3_ENTER_EVENT_MODE] = {"fmi3EnterEventMode", AK_CONTINUOUS_TIME_MODE, ME},
    [AK3_TERMINATE] = {"fmi3Terminate", AK_EVENT_MODE | AK_STEP_MODE | AK_CONTINUOUS_TIME_MODE,
                       BOTH},
    [AK3_RESET] = {"fmi3Reset", ANY_STATE, BOTH},
    /* The other types' getters and setters take Float64's states (fmi3_unsupported.c). */
    [AK3_GET_FLOAT64] = {"fmi3GetFloat64", READABLE, BOTH},
    [AK3_GET_INT64] = {"fmi3GetInt64", READABLE, BOTH},
    [AK3_SET_FLOAT64] = {"fmi3SetFloat64", WRITABLE, BOTH},
    [AK3_SET_INT64] = {"fmi3SetInt64", WRITABLE, BOTH},
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
    [AK3_UPDATE_DISCRETE_STATES] = {"fmi3UpdateDiscreteStates", AK_EVENT_MODE, ME},
    [AK3_ENTER_CONTINUOUS_TIME_MODE] = {"fmi3EnterContinuousTimeMode", AK_EVENT_MODE, ME},
    [AK3_COMPLETED_INTEGRATOR_STEP] = {"fmi3CompletedIntegratorStep", AK_CONTINUOUS_TIME_MODE, ME},
    /* In Event Mode time advances only through fmi3UpdateDiscreteStates. */
    [AK3_SET_TIME] = {"fmi3SetTime", AK_CONTINUOUS_TIME_MODE, ME},
    [AK3_SET_CONTINUOUS_STATES] = {"fmi3SetContinuousStates", AK_CONTINUOUS_TIME_MODE, ME},
    [AK3_GET_CONTINUOUS_STATE_DERIVATIVES] = {"fmi3GetContinuousStateDerivatives", ME_READABLE,
                                              ME},
    [AK3_GET_EVENT_INDICATORS] = {"fmi3GetEventIndicators", ME_READABLE, ME},
    [AK3_GET_CONTINUOUS_STATES] = {"fmi3GetContinuousStates", ME_READABLE, ME},
    [AK3_GET_NOMINALS_OF_CONTINUOUS_STATES] = {"fmi3GetNominalsOfContinuousStates", ME_READABLE,
                                               ME},
    /* The standard lists Instantiated and Event Mode; fmusim asks in Continuous-Time Mode too. */
    [AK3_GET_NUMBER_OF_EVENT_INDICATORS] = {"fmi3GetNumberOfEventIndicators", ANY_STATE, ME},
    [AK3_GET_NUMBER_OF_CONTINUOUS_STATES] = {"fmi3GetNumberOfContinuousStates", ANY_STATE, ME},
    [AK3_ENTER_STEP_MODE] = {"fmi3EnterStepMode", AK_EVENT_MODE, CS},
    [AK3_GET_OUTPUT_DERIVATIVES] = {"fmi3GetOutputDerivatives", AK_STEP_MODE | AK_TERMINATED, CS},
    [AK3_DO_STEP] = {"fmi3DoStep", AK_STEP_MODE, CS},
};
