/* The bad-input table; see fmi2_bad_input_table.h. Each row's arguments are the ones its `call`
 * text shows. Arrays are compound literals sized exactly to the count the call passes. */
#include "fmi2_bad_input_table.h"

#include <math.h>


enum {
    INSTANTIATED = AK_IN_INSTANTIATED,
    INITIALIZATION_MODE = AK_IN_INITIALIZATION_MODE,
    STEP_COMPLETE = AK_IN_STEP_COMPLETE,
    TERMINATED = AK_IN_TERMINATED,
    ME_INSTANTIATED = AK_ME | AK_IN_INSTANTIATED,
    EVENT_MODE = AK_ME | AK_IN_EVENT_MODE,
    CONTINUOUS_TIME_MODE = AK_ME | AK_IN_CONTINUOUS_TIME_MODE,
    ME_TERMINATED = AK_ME | AK_IN_TERMINATED
};

const char AK_THIS_GUID[] = "(the model's GUID)";

const ak_bad_call AK_BAD_CALLS[] = {
    /* --- life cycle ------------------------------------------------------------------------ */
    {INSTANTIATED, "fmi2SetupExperiment(c, fmi2True, NAN, 0, fmi2False, 0)",
     AK_OP_SETUP_EXPERIMENT, {.flag = {fmi2True, fmi2False}, .real = {NAN, 0.0, 0.0}}, fmi2Error,
     "fmi2SetupExperiment: tolerance = nan must be finite and >= 0", false},
    {INSTANTIATED, "fmi2SetupExperiment(c, fmi2True, -1e-6, 0, fmi2False, 0)",
     AK_OP_SETUP_EXPERIMENT, {.flag = {fmi2True, fmi2False}, .real = {-1e-6, 0.0, 0.0}},
     fmi2Error,
     "fmi2SetupExperiment: tolerance = -1e-06 must be finite and >= 0", false},
    {INSTANTIATED, "fmi2SetupExperiment(c, fmi2False, 0, INFINITY, fmi2False, 0)",
     AK_OP_SETUP_EXPERIMENT, {.flag = {fmi2False, fmi2False}, .real = {0.0, INFINITY, 0.0}},
     fmi2Error, "fmi2SetupExperiment: startTime = inf is not finite", false},
    {INSTANTIATED, "fmi2SetupExperiment(c, fmi2False, 0, 2, fmi2True, 1)",
     AK_OP_SETUP_EXPERIMENT, {.flag = {fmi2False, fmi2True}, .real = {0.0, 2.0, 1.0}}, fmi2Error,
     "fmi2SetupExperiment: stopTime = 1 must be finite and >= startTime = 2", false},
    {INSTANTIATED, "fmi2SetupExperiment(c, fmi2False, 0, 0, fmi2True, NAN)",
     AK_OP_SETUP_EXPERIMENT, {.flag = {fmi2False, fmi2True}, .real = {0.0, 0.0, NAN}}, fmi2Error,
     "fmi2SetupExperiment: stopTime = nan must be finite and >= startTime = 0", false},
    {INSTANTIATED, "fmi2ExitInitializationMode(c)", AK_OP_EXIT_INITIALIZATION_MODE, {0},
     fmi2Error,
     "fmi2ExitInitializationMode: illegal call in state Instantiated", false},
    {INSTANTIATED, "fmi2Terminate(c)", AK_OP_TERMINATE, {0}, fmi2Error,
     "fmi2Terminate: illegal call in state Instantiated", false},
    {INITIALIZATION_MODE, "fmi2EnterInitializationMode(c)", AK_OP_ENTER_INITIALIZATION_MODE, {0},
     fmi2Error,
     "fmi2EnterInitializationMode: illegal call in state InitializationMode", false},
    {STEP_COMPLETE, "fmi2SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0)",
     AK_OP_SETUP_EXPERIMENT, {0}, fmi2Error,
     "fmi2SetupExperiment: illegal call in state StepComplete", false},
    {TERMINATED, "fmi2Terminate(c)", AK_OP_TERMINATE, {0}, fmi2Error,
     "fmi2Terminate: illegal call in state Terminated", false},

    /* --- logging ---------------------------------------------------------------------------- */
    {STEP_COMPLETE, "fmi2SetDebugLogging(c, fmi2True, 2, NULL)", AK_OP_SET_DEBUG_LOGGING,
     {.flag = {fmi2True}, .n_categories = 2}, fmi2Error,
     "fmi2SetDebugLogging: categories is NULL with nCategories = 2", false},
    {STEP_COMPLETE, "fmi2SetDebugLogging(c, fmi2True, 2, {\"logCalls\", \"logEverything\"})",
     AK_OP_SET_DEBUG_LOGGING,
     {.flag = {fmi2True}, .n_categories = 2,
      .categories = (const fmi2String[]){"logCalls", "logEverything"}},
     fmi2Error,
     "fmi2SetDebugLogging: categories[1] = \"logEverything\" is not a log category of this FMU "
     "(logStatusError, logStatusWarning, logCalls)", false},
    {STEP_COMPLETE, "fmi2SetDebugLogging(c, fmi2False, 1, {NULL})", AK_OP_SET_DEBUG_LOGGING,
     {.flag = {fmi2False}, .n_categories = 1, .categories = (const fmi2String[]){NULL}},
     fmi2Error,
     "fmi2SetDebugLogging: categories[0] = \"(null)\" is not a log category of this FMU "
     "(logStatusError, logStatusWarning, logCalls)", false},

    /* --- setting and getting values ------------------------------------------------------------ */
    {STEP_COMPLETE, "fmi2SetReal(c, NULL, 1, {1})", AK_OP_SET_REAL,
     {.nvr = 1, .values = (fmi2Real[]){1.0}}, fmi2Error, "fmi2SetReal: vr is NULL with nvr = 1", false},
    {STEP_COMPLETE, "fmi2SetReal(c, {0}, 1, NULL)", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){0}, .nvr = 1}, fmi2Error,
     "fmi2SetReal: value is NULL with nvr = 1", false},
    {TERMINATED, "fmi2SetReal(c, {0}, 1, {1})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){0}, .nvr = 1, .values = (fmi2Real[]){1.0}}, fmi2Error,
     "fmi2SetReal: illegal call in state Terminated", false},
    {STEP_COMPLETE, "fmi2GetReal(c, NULL, 1, v)", AK_OP_GET_REAL,
     {.nvr = 1, .values = (fmi2Real[1]){0}}, fmi2Error, "fmi2GetReal: vr is NULL with nvr = 1", false},
    {STEP_COMPLETE, "fmi2GetReal(c, {9}, 1, NULL)", AK_OP_GET_REAL,
     {.vr = (const fmi2ValueReference[]){9}, .nvr = 1}, fmi2Error,
     "fmi2GetReal: value is NULL with nvr = 1", false},
    {INSTANTIATED, "fmi2GetReal(c, {9}, 1, v)", AK_OP_GET_REAL,
     {.vr = (const fmi2ValueReference[]){9}, .nvr = 1, .values = (fmi2Real[1]){0}}, fmi2Error,
     "fmi2GetReal: illegal call in state Instantiated", false},
    {STEP_COMPLETE, "fmi2GetBoolean(c, {0}, 1, v)", AK_OP_GET_BOOLEAN,
     {.vr = (const fmi2ValueReference[]){0}, .nvr = 1, .values = (fmi2Boolean[1]){0}},
     fmi2Error,
     "fmi2GetBoolean: vr[0] = 0 is not a value reference of this FMU, which has no Boolean "
     "variables", false},
    {STEP_COMPLETE, "fmi2SetBoolean(c, {0}, 1, {fmi2True})", AK_OP_SET_BOOLEAN,
     {.vr = (const fmi2ValueReference[]){0}, .nvr = 1, .values = (fmi2Boolean[]){fmi2True}},
     fmi2Error,
     "fmi2SetBoolean: vr[0] = 0 is not a value reference of this FMU, which has no Boolean "
     "variables", false},
    {STEP_COMPLETE, "fmi2GetString(c, {0}, 1, v)", AK_OP_GET_STRING,
     {.vr = (const fmi2ValueReference[]){0}, .nvr = 1, .values = (fmi2String[1]){NULL}},
     fmi2Error,
     "fmi2GetString: vr[0] = 0 is not a value reference of this FMU, which has no String "
     "variables", false},
    {STEP_COMPLETE, "fmi2SetString(c, {0}, 1, {\"x\"})", AK_OP_SET_STRING,
     {.vr = (const fmi2ValueReference[]){0}, .nvr = 1, .values = (fmi2String[]){"x"}},
     fmi2Error,
     "fmi2SetString: vr[0] = 0 is not a value reference of this FMU, which has no String "
     "variables", false},
    {STEP_COMPLETE, "fmi2SetString(c, NULL, 1, {\"x\"})", AK_OP_SET_STRING,
     {.nvr = 1, .values = (fmi2String[]){"x"}}, fmi2Error,
     "fmi2SetString: vr is NULL with nvr = 1", false},

    /* --- stepping (the instance is at time 1, stopTime 10) ------------------------------------- */
    {STEP_COMPLETE, "fmi2DoStep(c, NAN, 0.1, fmi2True)", AK_OP_DO_STEP,
     {.real = {NAN, 0.1}, .flag = {fmi2True}}, fmi2Error,
     "fmi2DoStep: currentCommunicationPoint = nan and communicationStepSize = 0.1 must be "
     "finite", false},
    {STEP_COMPLETE, "fmi2DoStep(c, 1, INFINITY, fmi2True)", AK_OP_DO_STEP,
     {.real = {1.0, INFINITY}, .flag = {fmi2True}}, fmi2Error,
     "fmi2DoStep: currentCommunicationPoint = 1 and communicationStepSize = inf must be finite", false},
    {STEP_COMPLETE, "fmi2DoStep(c, 1, 0, fmi2True)", AK_OP_DO_STEP,
     {.real = {1.0, 0.0}, .flag = {fmi2True}}, fmi2Error,
     "fmi2DoStep: communicationStepSize = 0 must be > 0", false},
    {STEP_COMPLETE, "fmi2DoStep(c, 1, -0.1, fmi2True)", AK_OP_DO_STEP,
     {.real = {1.0, -0.1}, .flag = {fmi2True}}, fmi2Error,
     "fmi2DoStep: communicationStepSize = -0.1 must be > 0", false},
    {STEP_COMPLETE, "fmi2DoStep(c, 0.5, 0.1, fmi2True)", AK_OP_DO_STEP,
     {.real = {0.5, 0.1}, .flag = {fmi2True}}, fmi2Error,
     "fmi2DoStep: currentCommunicationPoint = 0.5 does not continue from the last "
     "communication point 1", false},
    {STEP_COMPLETE, "fmi2DoStep(c, 1, 10, fmi2True)", AK_OP_DO_STEP,
     {.real = {1.0, 10.0}, .flag = {fmi2True}}, fmi2Error,
     "fmi2DoStep: the step from 1 by communicationStepSize = 10 ends at 11, past stopTime = 10", false},
    {INSTANTIATED, "fmi2DoStep(c, 0, 0.1, fmi2True)", AK_OP_DO_STEP,
     {.real = {0.0, 0.1}, .flag = {fmi2True}}, fmi2Error,
     "fmi2DoStep: illegal call in state Instantiated", false},
    {TERMINATED, "fmi2DoStep(c, 1, 0.1, fmi2True)", AK_OP_DO_STEP,
     {.real = {1.0, 0.1}, .flag = {fmi2True}}, fmi2Error,
     "fmi2DoStep: illegal call in state Terminated", false},
    {STEP_COMPLETE, "fmi2CancelStep(c)", AK_OP_CANCEL_STEP, {0}, fmi2Error,
     "fmi2CancelStep: illegal call in state StepComplete", false},

    /* --- status ------------------------------------------------------------------------------ */
    {STEP_COMPLETE, "fmi2GetStatus(c, fmi2DoStepStatus, &s)", AK_OP_GET_STATUS,
     {.kind = fmi2DoStepStatus, .out = (fmi2Status[1]){fmi2OK}}, fmi2Discard,
     "fmi2GetStatus: status kind 0 is not available: steps are never asynchronous", false},
    {STEP_COMPLETE, "fmi2GetRealStatus(c, fmi2LastSuccessfulTime, NULL)", AK_OP_GET_REAL_STATUS,
     {.kind = fmi2LastSuccessfulTime}, fmi2Error, "fmi2GetRealStatus: value is NULL", false},
    {STEP_COMPLETE, "fmi2GetRealStatus(c, fmi2DoStepStatus, &r)", AK_OP_GET_REAL_STATUS,
     {.kind = fmi2DoStepStatus, .out = (fmi2Real[1]){0}}, fmi2Discard,
     "fmi2GetRealStatus: status kind 0 is not available: steps are never asynchronous", false},
    {STEP_COMPLETE, "fmi2GetIntegerStatus(c, fmi2LastSuccessfulTime, &i)",
     AK_OP_GET_INTEGER_STATUS, {.kind = fmi2LastSuccessfulTime, .out = (fmi2Integer[1]){0}},
     fmi2Discard,
     "fmi2GetIntegerStatus: status kind 2 is not available: steps are never asynchronous", false},
    {STEP_COMPLETE, "fmi2GetBooleanStatus(c, fmi2DoStepStatus, &b)", AK_OP_GET_BOOLEAN_STATUS,
     {.kind = fmi2DoStepStatus, .out = (fmi2Boolean[1]){0}}, fmi2Discard,
     "fmi2GetBooleanStatus: status kind 0 is not available: steps are never asynchronous", false},
    {STEP_COMPLETE, "fmi2GetStringStatus(c, fmi2PendingStatus, &s)", AK_OP_GET_STRING_STATUS,
     {.kind = fmi2PendingStatus, .out = (fmi2String[1]){NULL}}, fmi2Discard,
     "fmi2GetStringStatus: status kind 1 is not available: steps are never asynchronous", false},

    /* --- FMU state ---------------------------------------------------------------------------- */
    {STEP_COMPLETE, "fmi2GetFMUstate(c, NULL)", AK_OP_GET_FMU_STATE, {0}, fmi2Error, "fmi2GetFMUstate: FMUstate is NULL", false},
    {STEP_COMPLETE, "fmi2SetFMUstate(c, NULL)", AK_OP_SET_FMU_STATE, {0}, fmi2Error,
     "fmi2SetFMUstate: FMUstate NULL is not an FMU state made by "
     "fmi2GetFMUstate or fmi2DeSerializeFMUstate of this FMU (or it was "
     "freed)", false},
    {STEP_COMPLETE, "fmi2FreeFMUstate(c, NULL)", AK_OP_FREE_FMU_STATE, {0}, fmi2Error, "fmi2FreeFMUstate: FMUstate is NULL", false},
    {STEP_COMPLETE, "fmi2SerializedFMUstateSize(c, NULL, &size)",
     AK_OP_SERIALIZED_FMU_STATE_SIZE, {.out = (size_t[1]){0}}, fmi2Error,
     "fmi2SerializedFMUstateSize: FMUstate NULL is not an FMU state made by "
     "fmi2GetFMUstate or fmi2DeSerializeFMUstate of this FMU (or it was "
     "freed)", false},
    {STEP_COMPLETE, "fmi2SerializedFMUstateSize(c, state, NULL)", AK_OP_SERIALIZED_FMU_STATE_SIZE,
     {0}, fmi2Error, "fmi2SerializedFMUstateSize: size is NULL", .with_fmu_state = true},
    {STEP_COMPLETE, "fmi2SerializeFMUstate(c, NULL, bytes, 8)", AK_OP_SERIALIZE_FMU_STATE,
     {.bytes = (fmi2Byte[8]){0}, .n_bytes = 8}, fmi2Error,
     "fmi2SerializeFMUstate: FMUstate NULL is not an FMU state made by "
     "fmi2GetFMUstate or fmi2DeSerializeFMUstate of this FMU (or it was "
     "freed)", false},
    {STEP_COMPLETE, "fmi2SerializeFMUstate(c, state, NULL, 4096)", AK_OP_SERIALIZE_FMU_STATE,
     {.n_bytes = 4096}, fmi2Error, "fmi2SerializeFMUstate: serializedState is NULL", .with_fmu_state = true},
    {STEP_COMPLETE, "fmi2DeSerializeFMUstate(c, NULL, 8, &state)", AK_OP_DE_SERIALIZE_FMU_STATE,
     {.n_bytes = 8, .out = (fmi2FMUstate[1]){NULL}}, fmi2Error, "fmi2DeSerializeFMUstate: serializedState is NULL", false},
    {STEP_COMPLETE, "fmi2DeSerializeFMUstate(c, bytes, 8, NULL)", AK_OP_DE_SERIALIZE_FMU_STATE,
     {.bytes = (fmi2Byte[8]){0}, .n_bytes = 8}, fmi2Error, "fmi2DeSerializeFMUstate: FMUstate is NULL", false},
    {STEP_COMPLETE, "fmi2SerializeFMUstate(c, state, bytes, 8)", AK_OP_SERIALIZE_FMU_STATE,
     {.bytes = (fmi2Byte[8]){0}, .n_bytes = 8}, fmi2Error,
     "fmi2SerializeFMUstate: size = 8 is too small; the state needs @STATE_BYTES@ "
     "bytes (fmi2SerializedFMUstateSize)", .with_fmu_state = true},
    {STEP_COMPLETE, "fmi2DeSerializeFMUstate(c, {0, 0, 0, 0, 0, 0, 0, 0}, 8, &state)",
     AK_OP_DE_SERIALIZE_FMU_STATE,
     {.bytes = (fmi2Byte[8]){0}, .n_bytes = 8, .out = (fmi2FMUstate[1]){NULL}}, fmi2Error,
     "fmi2DeSerializeFMUstate: the 8 bytes are not an @MODEL@ FMU state "
     "(too short for the header)", false},
    {STEP_COMPLETE, "fmi2DeSerializeFMUstate(c, 64 bytes \"AKFMUSTA...\", 64, &state)",
     AK_OP_DE_SERIALIZE_FMU_STATE,
     {.bytes = (fmi2Byte[64]){"AKFMUSTATE"}, .n_bytes = 64, .out = (fmi2FMUstate[1]){NULL}},
     fmi2Error,
     "fmi2DeSerializeFMUstate: the 64 bytes are not an @MODEL@ FMU state "
     "(wrong magic bytes)", false},

    /* --- model exchange (an instance created with fmi2ModelExchange); the rows marked
     * without_states_only hold for a model without continuous states ------------------------ */
    {EVENT_MODE, "fmi2NewDiscreteStates(c, NULL)", AK_OP_NEW_DISCRETE_STATES, {0}, fmi2Error, "fmi2NewDiscreteStates: eventInfo is NULL", false},
    {CONTINUOUS_TIME_MODE, "fmi2CompletedIntegratorStep(c, fmi2True, NULL, &terminate)",
     AK_OP_COMPLETED_INTEGRATOR_STEP, {.flag = {fmi2True}, .out2 = (fmi2Boolean[1]){0}},
     fmi2Error, "fmi2CompletedIntegratorStep: enterEventMode is NULL", false},
    {CONTINUOUS_TIME_MODE, "fmi2CompletedIntegratorStep(c, fmi2True, &enter, NULL)",
     AK_OP_COMPLETED_INTEGRATOR_STEP, {.flag = {fmi2True}, .out = (fmi2Boolean[1]){0}},
     fmi2Error, "fmi2CompletedIntegratorStep: terminateSimulation is NULL", false},
    {CONTINUOUS_TIME_MODE, "fmi2SetTime(c, NAN)", AK_OP_SET_TIME, {.real = {NAN}}, fmi2Error, "fmi2SetTime: time = nan is not finite", false},
    {EVENT_MODE, "fmi2SetTime(c, -INFINITY)", AK_OP_SET_TIME, {.real = {-INFINITY}}, fmi2Error,
     "fmi2SetTime: time = -inf is not finite", false},
    {CONTINUOUS_TIME_MODE, "fmi2SetContinuousStates(c, {1}, 1)", AK_OP_SET_CONTINUOUS_STATES,
     {.nvr = 1, .values2 = (fmi2Real[]){1.0}}, fmi2Error,
     "fmi2SetContinuousStates: nx = 1, but this FMU has no continuous "
     "states and no event indicators (nx must be 0)", false, .without_states_only = true},
    {CONTINUOUS_TIME_MODE, "fmi2GetDerivatives(c, dx, 1)", AK_OP_GET_DERIVATIVES,
     {.nvr = 1, .values2 = (fmi2Real[1]){0}}, fmi2Error,
     "fmi2GetDerivatives: nx = 1, but this FMU has no continuous states and "
     "no event indicators (nx must be 0)", false, .without_states_only = true},
    {EVENT_MODE, "fmi2GetEventIndicators(c, z, 3)", AK_OP_GET_EVENT_INDICATORS,
     {.nvr = 3, .values2 = (fmi2Real[3]){0}}, fmi2Error,
     "fmi2GetEventIndicators: ni = 3, but this FMU has no continuous states "
     "and no event indicators (ni must be 0)", false, .without_states_only = true},
    {ME_TERMINATED, "fmi2GetContinuousStates(c, x, 1)", AK_OP_GET_CONTINUOUS_STATES,
     {.nvr = 1, .values2 = (fmi2Real[1]){0}}, fmi2Error,
     "fmi2GetContinuousStates: nx = 1, but this FMU has no continuous "
     "states and no event indicators (nx must be 0)", false, .without_states_only = true},
    {ME_INSTANTIATED, "fmi2GetNominalsOfContinuousStates(c, x, 2)",
     AK_OP_GET_NOMINALS_OF_CONTINUOUS_STATES, {.nvr = 2, .values2 = (fmi2Real[2]){0}}, fmi2Error,
     "fmi2GetNominalsOfContinuousStates: nx = 2, but this FMU has no continuous states and "
     "no event indicators (nx must be 0)", false, .without_states_only = true},
    {CONTINUOUS_TIME_MODE, "fmi2EnterContinuousTimeMode(c)", AK_OP_ENTER_CONTINUOUS_TIME_MODE,
     {0}, fmi2Error,
     "fmi2EnterContinuousTimeMode: illegal call in state ContinuousTimeMode", false},
    {CONTINUOUS_TIME_MODE, "fmi2NewDiscreteStates(c, &eventInfo)", AK_OP_NEW_DISCRETE_STATES,
     {.out = (fmi2EventInfo[1]){{0}}}, fmi2Error,
     "fmi2NewDiscreteStates: illegal call in state ContinuousTimeMode", false},
    {EVENT_MODE, "fmi2DoStep(c, 0, 0.1, fmi2True)", AK_OP_DO_STEP,
     {.real = {0.0, 0.1}, .flag = {fmi2True}}, fmi2Error,
     "fmi2DoStep: a co-simulation function, but this instance was created "
     "for model exchange (fmi2ModelExchange)", false},
    {ME_TERMINATED, "fmi2GetRealStatus(c, fmi2LastSuccessfulTime, &r)", AK_OP_GET_REAL_STATUS,
     {.kind = fmi2LastSuccessfulTime, .out = (fmi2Real[1]){0}}, fmi2Error,
     "fmi2GetRealStatus: a co-simulation function, but this instance was "
     "created for model exchange (fmi2ModelExchange)", false},
    {STEP_COMPLETE, "fmi2SetTime(c, 2)", AK_OP_SET_TIME, {.real = {2.0}}, fmi2Error,
     "fmi2SetTime: a model-exchange function, but this instance was created "
     "for co-simulation (fmi2CoSimulation)", false},
    {STEP_COMPLETE, "fmi2GetDerivatives(c, NULL, 0)", AK_OP_GET_DERIVATIVES, {0}, fmi2Error,
     "fmi2GetDerivatives: a model-exchange function, but this instance was "
     "created for co-simulation (fmi2CoSimulation)", false},
};
const size_t AK_N_BAD_CALLS = sizeof AK_BAD_CALLS / sizeof AK_BAD_CALLS[0];

#define GUID_MISMATCH(shown) \
    "fmi2Instantiate: fmuGUID = \"" shown "\" does not match the GUID \""

const ak_bad_instantiate AK_BAD_INSTANTIATES[] = {
    {"fmi2Instantiate(\"i\", fmi2CoSimulation, GUID, uri, NULL, fmi2False, fmi2False)", "i",
     fmi2CoSimulation, AK_THIS_GUID, AK_NULL_CALLBACKS, -1, 0, NULL, false},
    {"fmi2Instantiate(\"i\", ..., functions without allocateMemory and freeMemory, ...)", "i",
     fmi2CoSimulation, AK_THIS_GUID, AK_CALLBACKS_WITHOUT_MEMORY, -1, 0,
     "fmi2Instantiate: functions->allocateMemory and functions->freeMemory must not be NULL", false},
    {"fmi2Instantiate(NULL, fmi2CoSimulation, GUID, ...)", NULL, fmi2CoSimulation, AK_THIS_GUID,
     AK_GOOD_CALLBACKS, -1, 0, "fmi2Instantiate: instanceName must be a non-empty string", false},
    {"fmi2Instantiate(\"\", fmi2CoSimulation, GUID, ...)", "", fmi2CoSimulation, AK_THIS_GUID,
     AK_GOOD_CALLBACKS, -1, 0, "fmi2Instantiate: instanceName must be a non-empty string", false},
    {"fmi2Instantiate(\"i\", 7, GUID, ...)", "i", 7, AK_THIS_GUID, AK_GOOD_CALLBACKS, -1, 0, "fmi2Instantiate: fmuType = 7 is neither fmi2ModelExchange (0) nor fmi2CoSimulation (1)", false},
    {"fmi2Instantiate(\"i\", fmi2CoSimulation, \"{00000000-0000-0000-0000-000000000000}\", ...)",
     "i", fmi2CoSimulation, "{00000000-0000-0000-0000-000000000000}", AK_GOOD_CALLBACKS, -1, 0,
     GUID_MISMATCH("{00000000-0000-0000-0000-000000000000}"), true},
    {"fmi2Instantiate(\"i\", fmi2CoSimulation, NULL, ...)", "i", fmi2CoSimulation, NULL,
     AK_GOOD_CALLBACKS, -1, 0, GUID_MISMATCH("(null)"), true},
    {"fmi2Instantiate(\"i\", fmi2CoSimulation, NULL, ..., functions without logger, ...)", "i",
     fmi2CoSimulation, NULL, AK_CALLBACKS_WITHOUT_LOGGER, -1, 0, NULL, false},
    {"fmi2Instantiate(...) when every allocateMemory returns NULL", "i", fmi2CoSimulation,
     AK_THIS_GUID, AK_GOOD_CALLBACKS, 0, -1, "fmi2Instantiate: out of memory allocating the instance", false},
    {"fmi2Instantiate(...) when only the first allocateMemory returns NULL", "i",
     fmi2CoSimulation, AK_THIS_GUID, AK_GOOD_CALLBACKS, 0, 1,
     "fmi2Instantiate: out of memory allocating the instance", false},
    {"fmi2Instantiate(...) when only the second allocateMemory returns NULL", "i",
     fmi2CoSimulation, AK_THIS_GUID, AK_GOOD_CALLBACKS, 1, 1,
     "fmi2Instantiate: out of memory allocating the instance", false},
};
const size_t AK_N_BAD_INSTANTIATES = sizeof AK_BAD_INSTANTIATES / sizeof AK_BAD_INSTANTIATES[0];
