/* The FMI 2.0 state table, the standard's: StepInProgress and StepCanceled are never entered. */
#include "fmi2_layer.h"

enum {
    ANY_STATE = AK_INSTANTIATED | AK_INITIALIZATION_MODE | AK_STEP_MODE | AK_STEP_IN_PROGRESS |
                AK_STEP_FAILED | AK_STEP_CANCELED | AK_TERMINATED | AK_EVENT_MODE |
                AK_CONTINUOUS_TIME_MODE,
    READABLE = AK_INITIALIZATION_MODE | AK_STEP_MODE | AK_STEP_FAILED | AK_STEP_CANCELED |
               AK_TERMINATED | AK_EVENT_MODE | AK_CONTINUOUS_TIME_MODE,
    /* In ContinuousTimeMode only continuous inputs, which all are. */
    WRITABLE = AK_INSTANTIATED | AK_INITIALIZATION_MODE | AK_STEP_MODE | AK_EVENT_MODE |
               AK_CONTINUOUS_TIME_MODE,
    STATUS = AK_STEP_MODE | AK_STEP_IN_PROGRESS | AK_STEP_FAILED | AK_STEP_CANCELED | AK_TERMINATED,
    FMU_STATE = ANY_STATE & ~AK_STEP_IN_PROGRESS,
    ME_READABLE = AK_INITIALIZATION_MODE | AK_EVENT_MODE | AK_CONTINUOUS_TIME_MODE | AK_TERMINATED
};

enum { CS = AK_CO_SIMULATION, ME = AK_MODEL_EXCHANGE, BOTH = CS | ME };

const ak_function_rule FMI2_RULES[AK_N_FMI2_FUNCTIONS] = {
    [AK_FMI2_SET_DEBUG_LOGGING] = {"fmi2SetDebugLogging", ANY_STATE, BOTH},
    [AK_FMI2_FREE_INSTANCE] = {"fmi2FreeInstance", ANY_STATE & ~AK_STEP_IN_PROGRESS, BOTH},
    [AK_FMI2_SETUP_EXPERIMENT] = {"fmi2SetupExperiment", AK_INSTANTIATED, BOTH},
    [AK_FMI2_ENTER_INITIALIZATION_MODE] = {"fmi2EnterInitializationMode", AK_INSTANTIATED, BOTH},
    [AK_FMI2_EXIT_INITIALIZATION_MODE] = {"fmi2ExitInitializationMode", AK_INITIALIZATION_MODE,
                                          BOTH},
    [AK_FMI2_TERMINATE] = {"fmi2Terminate",
                           AK_STEP_MODE | AK_STEP_FAILED | AK_STEP_CANCELED | AK_EVENT_MODE |
                               AK_CONTINUOUS_TIME_MODE,
                           BOTH},
    [AK_FMI2_RESET] = {"fmi2Reset", ANY_STATE & ~AK_STEP_IN_PROGRESS, BOTH},
    [AK_FMI2_GET_REAL] = {"fmi2GetReal", READABLE, BOTH},
    [AK_FMI2_GET_INTEGER] = {"fmi2GetInteger", READABLE, BOTH},
    [AK_FMI2_GET_BOOLEAN] = {"fmi2GetBoolean", READABLE, BOTH},
    [AK_FMI2_GET_STRING] = {"fmi2GetString", READABLE, BOTH},
    [AK_FMI2_SET_REAL] = {"fmi2SetReal", WRITABLE, BOTH},
    [AK_FMI2_SET_INTEGER] = {"fmi2SetInteger", WRITABLE, BOTH},
    [AK_FMI2_SET_BOOLEAN] = {"fmi2SetBoolean", WRITABLE, BOTH},
    [AK_FMI2_SET_STRING] = {"fmi2SetString", WRITABLE, BOTH},
    [AK_FMI2_GET_FMU_STATE] = {"fmi2GetFMUstate", FMU_STATE, BOTH},
    [AK_FMI2_SET_FMU_STATE] = {"fmi2SetFMUstate", FMU_STATE, BOTH},
    [AK_FMI2_FREE_FMU_STATE] = {"fmi2FreeFMUstate", FMU_STATE, BOTH},
    [AK_FMI2_SERIALIZED_FMU_STATE_SIZE] = {"fmi2SerializedFMUstateSize", FMU_STATE, BOTH},
    [AK_FMI2_SERIALIZE_FMU_STATE] = {"fmi2SerializeFMUstate", FMU_STATE, BOTH},
    [AK_FMI2_DE_SERIALIZE_FMU_STATE] = {"fmi2DeSerializeFMUstate", FMU_STATE, BOTH},
    [AK_FMI2_GET_DIRECTIONAL_DERIVATIVE] = {"fmi2GetDirectionalDerivative", READABLE, BOTH},
    [AK_FMI2_SET_REAL_INPUT_DERIVATIVES] = {"fmi2SetRealInputDerivatives",
                                            AK_INSTANTIATED | AK_INITIALIZATION_MODE | AK_STEP_MODE,
                                            CS},
    [AK_FMI2_GET_REAL_OUTPUT_DERIVATIVES] = {"fmi2GetRealOutputDerivatives",
                                             AK_STEP_MODE | AK_STEP_FAILED | AK_STEP_CANCELED |
                                                 AK_TERMINATED,
                                             CS},
    [AK_FMI2_DO_STEP] = {"fmi2DoStep", AK_STEP_MODE, CS},
    [AK_FMI2_CANCEL_STEP] = {"fmi2CancelStep", AK_STEP_IN_PROGRESS, CS},
    [AK_FMI2_GET_STATUS] = {"fmi2GetStatus", STATUS, CS},
    [AK_FMI2_GET_REAL_STATUS] = {"fmi2GetRealStatus", STATUS, CS},
    [AK_FMI2_GET_INTEGER_STATUS] = {"fmi2GetIntegerStatus", STATUS, CS},
    [AK_FMI2_GET_BOOLEAN_STATUS] = {"fmi2GetBooleanStatus", STATUS, CS},
    [AK_FMI2_GET_STRING_STATUS] = {"fmi2GetStringStatus", STATUS, CS},
    [AK_FMI2_ENTER_EVENT_MODE] = {"fmi2EnterEventMode", AK_EVENT_MODE | AK_CONTINUOUS_TIME_MODE,
                                  ME},
    [AK_FMI2_NEW_DISCRETE_STATES] = {"fmi2NewDiscreteStates", AK_EVENT_MODE, ME},
    [AK_FMI2_ENTER_CONTINUOUS_TIME_MODE] = {"fmi2EnterContinuousTimeMode", AK_EVENT_MODE, ME},
    [AK_FMI2_COMPLETED_INTEGRATOR_STEP] = {"fmi2CompletedIntegratorStep", AK_CONTINUOUS_TIME_MODE,
                                           ME},
    [AK_FMI2_SET_TIME] = {"fmi2SetTime", AK_EVENT_MODE | AK_CONTINUOUS_TIME_MODE, ME},
    [AK_FMI2_SET_CONTINUOUS_STATES] = {"fmi2SetContinuousStates", AK_CONTINUOUS_TIME_MODE, ME},
    [AK_FMI2_GET_DERIVATIVES] = {"fmi2GetDerivatives",
                                 AK_EVENT_MODE | AK_CONTINUOUS_TIME_MODE | AK_TERMINATED, ME},
    [AK_FMI2_GET_EVENT_INDICATORS] = {"fmi2GetEventIndicators", ME_READABLE, ME},
    [AK_FMI2_GET_CONTINUOUS_STATES] = {"fmi2GetContinuousStates", ME_READABLE, ME},
    [AK_FMI2_GET_NOMINALS_OF_CONTINUOUS_STATES] = {"fmi2GetNominalsOfContinuousStates",
                                                   AK_INSTANTIATED | AK_EVENT_MODE |
                                                       AK_CONTINUOUS_TIME_MODE | AK_TERMINATED,
                                                   ME},
};
