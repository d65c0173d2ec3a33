/* The op table; see fmi2_test_ops.h. */
#include "fmi2_test_ops.h"

enum {
    READABLE = AK_IN_INITIALIZATION_MODE | AK_IN_STEP_COMPLETE | AK_IN_STEP_FAILED |
               AK_IN_STEP_CANCELED | AK_IN_TERMINATED | AK_IN_EVENT_MODE |
               AK_IN_CONTINUOUS_TIME_MODE,
    /* Inputs: in ContinuousTimeMode the continuous ones, which all inputs here are. */
    WRITABLE = AK_IN_INSTANTIATED | AK_IN_INITIALIZATION_MODE | AK_IN_STEP_COMPLETE |
               AK_IN_EVENT_MODE | AK_IN_CONTINUOUS_TIME_MODE,
    CS_WRITABLE = AK_IN_INSTANTIATED | AK_IN_INITIALIZATION_MODE | AK_IN_STEP_COMPLETE,
    ME_READABLE = AK_IN_INITIALIZATION_MODE | AK_IN_EVENT_MODE | AK_IN_CONTINUOUS_TIME_MODE |
                  AK_IN_TERMINATED,
    STATUS = AK_IN_STEP_COMPLETE | AK_IN_STEP_IN_PROGRESS | AK_IN_STEP_FAILED |
             AK_IN_STEP_CANCELED | AK_IN_TERMINATED,
    NOT_IN_PROGRESS = AK_IN_ANY & ~AK_IN_STEP_IN_PROGRESS
};

static fmi2Status set_debug_logging(fmi2Component c, const ak_args *a) {
    return fmi2SetDebugLogging(c, a->flag[0], a->n_categories, a->categories);
}
static fmi2Status setup_experiment(fmi2Component c, const ak_args *a) {
    return fmi2SetupExperiment(c, a->flag[0], a->real[0], a->real[1], a->flag[1], a->real[2]);
}
static fmi2Status enter_initialization_mode(fmi2Component c, const ak_args *a) {
    (void)a;
    return fmi2EnterInitializationMode(c);
}
static fmi2Status exit_initialization_mode(fmi2Component c, const ak_args *a) {
    (void)a;
    return fmi2ExitInitializationMode(c);
}
static fmi2Status terminate(fmi2Component c, const ak_args *a) {
    (void)a;
    return fmi2Terminate(c);
}
static fmi2Status reset(fmi2Component c, const ak_args *a) {
    (void)a;
    return fmi2Reset(c);
}
static fmi2Status get_real(fmi2Component c, const ak_args *a) {
    return fmi2GetReal(c, a->vr, a->nvr, a->values);
}
static fmi2Status get_integer(fmi2Component c, const ak_args *a) {
    return fmi2GetInteger(c, a->vr, a->nvr, a->values);
}
static fmi2Status get_boolean(fmi2Component c, const ak_args *a) {
    return fmi2GetBoolean(c, a->vr, a->nvr, a->values);
}
static fmi2Status get_string(fmi2Component c, const ak_args *a) {
    return fmi2GetString(c, a->vr, a->nvr, a->values);
}
static fmi2Status set_real(fmi2Component c, const ak_args *a) {
    return fmi2SetReal(c, a->vr, a->nvr, a->values);
}
static fmi2Status set_integer(fmi2Component c, const ak_args *a) {
    return fmi2SetInteger(c, a->vr, a->nvr, a->values);
}
static fmi2Status set_boolean(fmi2Component c, const ak_args *a) {
    return fmi2SetBoolean(c, a->vr, a->nvr, a->values);
}
static fmi2Status set_string(fmi2Component c, const ak_args *a) {
    return fmi2SetString(c, a->vr, a->nvr, a->values);
}
static fmi2Status get_fmu_state(fmi2Component c, const ak_args *a) {
    return fmi2GetFMUstate(c, a->out);
}
static fmi2Status set_fmu_state(fmi2Component c, const ak_args *a) {
    return fmi2SetFMUstate(c, a->state);
}
static fmi2Status free_fmu_state(fmi2Component c, const ak_args *a) {
    return fmi2FreeFMUstate(c, a->out);
}
static fmi2Status serialized_fmu_state_size(fmi2Component c, const ak_args *a) {
    return fmi2SerializedFMUstateSize(c, a->state, a->out);
}
static fmi2Status serialize_fmu_state(fmi2Component c, const ak_args *a) {
    return fmi2SerializeFMUstate(c, a->state, a->bytes, a->n_bytes);
}
static fmi2Status de_serialize_fmu_state(fmi2Component c, const ak_args *a) {
    return fmi2DeSerializeFMUstate(c, a->bytes, a->n_bytes, a->out);
}
static fmi2Status get_directional_derivative(fmi2Component c, const ak_args *a) {
    return fmi2GetDirectionalDerivative(c, a->vr, a->nvr, a->vr2, a->nvr2, a->known, a->values2);
}
static fmi2Status set_real_input_derivatives(fmi2Component c, const ak_args *a) {
    return fmi2SetRealInputDerivatives(c, a->vr, a->nvr, a->values2, a->values);
}
static fmi2Status get_real_output_derivatives(fmi2Component c, const ak_args *a) {
    return fmi2GetRealOutputDerivatives(c, a->vr, a->nvr, a->values2, a->values);
}
static fmi2Status do_step(fmi2Component c, const ak_args *a) {
    return fmi2DoStep(c, a->real[0], a->real[1], a->flag[0]);
}
static fmi2Status cancel_step(fmi2Component c, const ak_args *a) {
    (void)a;
    return fmi2CancelStep(c);
}
static fmi2Status get_status(fmi2Component c, const ak_args *a) {
    return fmi2GetStatus(c, (fmi2StatusKind)a->kind, a->out);
}
static fmi2Status get_real_status(fmi2Component c, const ak_args *a) {
    return fmi2GetRealStatus(c, (fmi2StatusKind)a->kind, a->out);
}
static fmi2Status get_integer_status(fmi2Component c, const ak_args *a) {
    return fmi2GetIntegerStatus(c, (fmi2StatusKind)a->kind, a->out);
}
static fmi2Status get_boolean_status(fmi2Component c, const ak_args *a) {
    return fmi2GetBooleanStatus(c, (fmi2StatusKind)a->kind, a->out);
}
static fmi2Status get_string_status(fmi2Component c, const ak_args *a) {
    return fmi2GetStringStatus(c, (fmi2StatusKind)a->kind, a->out);
}
static fmi2Status enter_event_mode(fmi2Component c, const ak_args *a) {
    (void)a;
    return fmi2EnterEventMode(c);
}
static fmi2Status new_discrete_states(fmi2Component c, const ak_args *a) {
    return fmi2NewDiscreteStates(c, a->out);
}
static fmi2Status enter_continuous_time_mode(fmi2Component c, const ak_args *a) {
    (void)a;
    return fmi2EnterContinuousTimeMode(c);
}
/* out: enterEventMode, out2: terminateSimulation (fmi2Boolean each). */
static fmi2Status completed_integrator_step(fmi2Component c, const ak_args *a) {
    return fmi2CompletedIntegratorStep(c, a->flag[0], a->out, a->out2);
}
static fmi2Status set_time(fmi2Component c, const ak_args *a) {
    return fmi2SetTime(c, a->real[0]);
}
static fmi2Status set_continuous_states(fmi2Component c, const ak_args *a) {
    return fmi2SetContinuousStates(c, a->values2, a->nvr);
}
static fmi2Status get_derivatives(fmi2Component c, const ak_args *a) {
    return fmi2GetDerivatives(c, a->values2, a->nvr);
}
static fmi2Status get_event_indicators(fmi2Component c, const ak_args *a) {
    return fmi2GetEventIndicators(c, a->values2, a->nvr);
}
static fmi2Status get_continuous_states(fmi2Component c, const ak_args *a) {
    return fmi2GetContinuousStates(c, a->values2, a->nvr);
}
static fmi2Status get_nominals_of_continuous_states(fmi2Component c, const ak_args *a) {
    return fmi2GetNominalsOfContinuousStates(c, a->values2, a->nvr);
}
/* fmi2FreeInstance returns nothing: the op reports fmi2OK. */
static fmi2Status free_instance(fmi2Component c, const ak_args *a) {
    (void)a;
    fmi2FreeInstance(c);
    return fmi2OK;
}

const ak_op AK_OPS[AK_N_OPS] = {
    [AK_OP_SET_DEBUG_LOGGING] = {"fmi2SetDebugLogging", AK_IN_ANY, AK_FOR_BOTH, AK_NO_VALUES, AK_NO_VALUES,
                                 set_debug_logging, false},
    [AK_OP_SETUP_EXPERIMENT] = {"fmi2SetupExperiment", AK_IN_INSTANTIATED, AK_FOR_BOTH, AK_NO_VALUES,
                                AK_NO_VALUES, setup_experiment, false},
    [AK_OP_ENTER_INITIALIZATION_MODE] = {"fmi2EnterInitializationMode", AK_IN_INSTANTIATED,
                                         AK_FOR_BOTH, AK_NO_VALUES, AK_NO_VALUES, enter_initialization_mode, false},
    [AK_OP_EXIT_INITIALIZATION_MODE] = {"fmi2ExitInitializationMode", AK_IN_INITIALIZATION_MODE,
                                        AK_FOR_BOTH, AK_NO_VALUES, AK_NO_VALUES, exit_initialization_mode, false},
    [AK_OP_TERMINATE] = {"fmi2Terminate",
                         AK_IN_STEP_COMPLETE | AK_IN_STEP_FAILED | AK_IN_STEP_CANCELED |
                             AK_IN_EVENT_MODE | AK_IN_CONTINUOUS_TIME_MODE,
                         AK_FOR_BOTH, AK_NO_VALUES, AK_NO_VALUES, terminate, false},
    [AK_OP_RESET] = {"fmi2Reset", NOT_IN_PROGRESS, AK_FOR_BOTH, AK_NO_VALUES, AK_NO_VALUES, reset, false},
    [AK_OP_GET_REAL] = {"fmi2GetReal", READABLE, AK_FOR_BOTH, AK_REAL_VALUES, AK_NO_VALUES, get_real, false},
    [AK_OP_GET_INTEGER] = {"fmi2GetInteger", READABLE, AK_FOR_BOTH, AK_INTEGER_VALUES, AK_NO_VALUES,
                           get_integer, false},
    [AK_OP_GET_BOOLEAN] = {"fmi2GetBoolean", READABLE, AK_FOR_BOTH, AK_BOOLEAN_VALUES, AK_NO_VALUES,
                           get_boolean, false},
    [AK_OP_GET_STRING] = {"fmi2GetString", READABLE, AK_FOR_BOTH, AK_STRING_VALUES, AK_NO_VALUES, get_string, false},
    [AK_OP_SET_REAL] = {"fmi2SetReal", WRITABLE, AK_FOR_BOTH, AK_REAL_VALUES, AK_NO_VALUES, set_real, false},
    [AK_OP_SET_INTEGER] = {"fmi2SetInteger", WRITABLE, AK_FOR_BOTH, AK_INTEGER_VALUES, AK_NO_VALUES,
                           set_integer, false},
    [AK_OP_SET_BOOLEAN] = {"fmi2SetBoolean", WRITABLE, AK_FOR_BOTH, AK_BOOLEAN_VALUES, AK_NO_VALUES,
                           set_boolean, false},
    [AK_OP_SET_STRING] = {"fmi2SetString", WRITABLE, AK_FOR_BOTH, AK_STRING_VALUES, AK_NO_VALUES, set_string, false},
    [AK_OP_GET_FMU_STATE] = {"fmi2GetFMUstate", NOT_IN_PROGRESS, AK_FOR_BOTH, AK_NO_VALUES, AK_NO_VALUES,
                             get_fmu_state, true},
    [AK_OP_SET_FMU_STATE] = {"fmi2SetFMUstate", NOT_IN_PROGRESS, AK_FOR_BOTH, AK_NO_VALUES, AK_NO_VALUES,
                             set_fmu_state, false},
    [AK_OP_FREE_FMU_STATE] = {"fmi2FreeFMUstate", NOT_IN_PROGRESS, AK_FOR_BOTH, AK_NO_VALUES, AK_NO_VALUES,
                              free_fmu_state, true},
    [AK_OP_SERIALIZED_FMU_STATE_SIZE] = {"fmi2SerializedFMUstateSize", NOT_IN_PROGRESS,
                                         AK_FOR_BOTH, AK_NO_VALUES, AK_NO_VALUES, serialized_fmu_state_size, false},
    [AK_OP_SERIALIZE_FMU_STATE] = {"fmi2SerializeFMUstate", NOT_IN_PROGRESS, AK_FOR_BOTH, AK_NO_VALUES,
                                   AK_NO_VALUES, serialize_fmu_state, false},
    [AK_OP_DE_SERIALIZE_FMU_STATE] = {"fmi2DeSerializeFMUstate", NOT_IN_PROGRESS, AK_FOR_BOTH, AK_NO_VALUES,
                                      AK_NO_VALUES, de_serialize_fmu_state, true},
    [AK_OP_GET_DIRECTIONAL_DERIVATIVE] = {"fmi2GetDirectionalDerivative", READABLE, AK_FOR_BOTH, AK_NO_VALUES,
                                          AK_REAL_VALUES, get_directional_derivative, false},
    [AK_OP_SET_REAL_INPUT_DERIVATIVES] = {"fmi2SetRealInputDerivatives", CS_WRITABLE,
                                          AK_FOR_CS, AK_REAL_VALUES, AK_INTEGER_VALUES,
                                          set_real_input_derivatives, false},
    [AK_OP_GET_REAL_OUTPUT_DERIVATIVES] = {"fmi2GetRealOutputDerivatives",
                                           AK_IN_STEP_COMPLETE | AK_IN_STEP_FAILED |
                                               AK_IN_STEP_CANCELED | AK_IN_TERMINATED,
                                           AK_FOR_CS, AK_REAL_VALUES, AK_INTEGER_VALUES,
                                           get_real_output_derivatives, false},
    [AK_OP_DO_STEP] = {"fmi2DoStep", AK_IN_STEP_COMPLETE, AK_FOR_CS, AK_NO_VALUES, AK_NO_VALUES, do_step, false},
    [AK_OP_CANCEL_STEP] = {"fmi2CancelStep", AK_IN_STEP_IN_PROGRESS, AK_FOR_CS, AK_NO_VALUES, AK_NO_VALUES,
                           cancel_step, false},
    [AK_OP_GET_STATUS] = {"fmi2GetStatus", STATUS, AK_FOR_CS, AK_NO_VALUES, AK_NO_VALUES, get_status, false},
    [AK_OP_GET_REAL_STATUS] = {"fmi2GetRealStatus", STATUS, AK_FOR_CS, AK_NO_VALUES, AK_NO_VALUES,
                               get_real_status, false},
    [AK_OP_GET_INTEGER_STATUS] = {"fmi2GetIntegerStatus", STATUS, AK_FOR_CS, AK_NO_VALUES, AK_NO_VALUES,
                                  get_integer_status, false},
    [AK_OP_GET_BOOLEAN_STATUS] = {"fmi2GetBooleanStatus", STATUS, AK_FOR_CS, AK_NO_VALUES, AK_NO_VALUES,
                                  get_boolean_status, false},
    [AK_OP_GET_STRING_STATUS] = {"fmi2GetStringStatus", STATUS, AK_FOR_CS, AK_NO_VALUES, AK_NO_VALUES,
                                 get_string_status, false},
    [AK_OP_ENTER_EVENT_MODE] = {"fmi2EnterEventMode",
                                AK_IN_EVENT_MODE | AK_IN_CONTINUOUS_TIME_MODE, AK_FOR_ME,
                                AK_NO_VALUES, AK_NO_VALUES, enter_event_mode, false},
    [AK_OP_NEW_DISCRETE_STATES] = {"fmi2NewDiscreteStates", AK_IN_EVENT_MODE, AK_FOR_ME,
                                   AK_NO_VALUES, AK_NO_VALUES, new_discrete_states, false},
    [AK_OP_ENTER_CONTINUOUS_TIME_MODE] = {"fmi2EnterContinuousTimeMode", AK_IN_EVENT_MODE,
                                          AK_FOR_ME, AK_NO_VALUES, AK_NO_VALUES,
                                          enter_continuous_time_mode, false},
    [AK_OP_COMPLETED_INTEGRATOR_STEP] = {"fmi2CompletedIntegratorStep",
                                         AK_IN_CONTINUOUS_TIME_MODE, AK_FOR_ME, AK_NO_VALUES,
                                         AK_NO_VALUES, completed_integrator_step, false},
    [AK_OP_SET_TIME] = {"fmi2SetTime", AK_IN_EVENT_MODE | AK_IN_CONTINUOUS_TIME_MODE, AK_FOR_ME,
                        AK_NO_VALUES, AK_NO_VALUES, set_time, false},
    [AK_OP_SET_CONTINUOUS_STATES] = {"fmi2SetContinuousStates", AK_IN_CONTINUOUS_TIME_MODE,
                                     AK_FOR_ME, AK_NO_VALUES, AK_REAL_VALUES,
                                     set_continuous_states, false},
    [AK_OP_GET_DERIVATIVES] = {"fmi2GetDerivatives",
                               AK_IN_EVENT_MODE | AK_IN_CONTINUOUS_TIME_MODE | AK_IN_TERMINATED,
                               AK_FOR_ME, AK_NO_VALUES, AK_REAL_VALUES, get_derivatives, false},
    [AK_OP_GET_EVENT_INDICATORS] = {"fmi2GetEventIndicators", ME_READABLE, AK_FOR_ME,
                                    AK_NO_VALUES, AK_REAL_VALUES, get_event_indicators, false},
    [AK_OP_GET_CONTINUOUS_STATES] = {"fmi2GetContinuousStates", ME_READABLE, AK_FOR_ME,
                                     AK_NO_VALUES, AK_REAL_VALUES, get_continuous_states, false},
    [AK_OP_GET_NOMINALS_OF_CONTINUOUS_STATES] = {
        "fmi2GetNominalsOfContinuousStates",
        AK_IN_INSTANTIATED | AK_IN_EVENT_MODE | AK_IN_CONTINUOUS_TIME_MODE | AK_IN_TERMINATED,
        AK_FOR_ME, AK_NO_VALUES, AK_REAL_VALUES, get_nominals_of_continuous_states, false},
    [AK_OP_FREE_INSTANCE] = {"fmi2FreeInstance", NOT_IN_PROGRESS, AK_FOR_BOTH, AK_NO_VALUES, AK_NO_VALUES,
                             free_instance, false},
};

const char *ak_status_name(fmi2Status status) {
    switch (status) {
    case fmi2OK: return "fmi2OK";
    case fmi2Warning: return "fmi2Warning";
    case fmi2Discard: return "fmi2Discard";
    case fmi2Error: return "fmi2Error";
    case fmi2Fatal: return "fmi2Fatal";
    case fmi2Pending: return "fmi2Pending";
    }
    return "unknown status";
}
