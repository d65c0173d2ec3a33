/* The bad-input rows of AttitudePropagator (see fmi2_bad_input_table.h): its value references
 * (inputs omega 0 to 2 and omega_dot 3 to 5; the continuous states q 6 to 9, outputs; der(q) 10
 * to 13, locals; outputs 14 to 41; parameters frame 42, sequence 43 (Integer), q0 44 to 47 (Real);
 * the co-simulation memory 48 to 58, locals), its initial quaternion, checked when the instance
 * leaves InitializationMode, its continuous states in model exchange, the step that cannot be
 * taken (a rotation over the step that is not finite), and its capabilities (directional
 * derivatives, input derivatives; no output derivatives). The call texts show the numbers; the
 * arguments name them through the generated constants (AttitudePropagator_variables.h). */
#include <math.h>

#include "fmi2_bad_input_table.h"
#include "AttitudePropagator_variables.h"
#include "fmi2_test_instance.h"

enum {
    INSTANTIATED = AK_IN_INSTANTIATED,
    INITIALIZATION_MODE = AK_IN_INITIALIZATION_MODE,
    STEP_COMPLETE = AK_IN_STEP_COMPLETE,
    STEP_FAILED = AK_IN_STEP_FAILED,
    TERMINATED = AK_IN_TERMINATED,
    ME_INSTANTIATED = AK_ME | AK_IN_INSTANTIATED,
    ME_INITIALIZATION_MODE = AK_ME | AK_IN_INITIALIZATION_MODE,
    EVENT_MODE = AK_ME | AK_IN_EVENT_MODE,
    CONTINUOUS_TIME_MODE = AK_ME | AK_IN_CONTINUOUS_TIME_MODE,
    ME_TERMINATED = AK_ME | AK_IN_TERMINATED
};

/* A step fails when omega over the step gives a rotation that is not finite: |omega| h
 * overflows (the states cannot be advanced; the model logs why, the layer discards the step). */
const ak_test_failing_step AK_TEST_FAILING_STEP = {
    3, {AP_VR_OMEGA, AP_VR_OMEGA + 1, AP_VR_OMEGA + 2}, {1e308, 1e308, 1e308}};

const ak_bad_call AK_MODEL_BAD_CALLS[] = {
    /* --- values: unknown value references, non-finite inputs, what cannot be set ------------- */
    {STEP_COMPLETE, "fmi2SetReal(c, {0, @PAST@}, 2, {7, 7})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){AP_VR_OMEGA, AP_N_VALUE_REFERENCES}, .nvr = 2,
      .values = (fmi2Real[]){7.0, 7.0}},
     fmi2Error,
     "fmi2SetReal: vr[1] = @PAST@ is not a value reference of this FMU (0 to @LAST@)", false},
    {STEP_COMPLETE, "fmi2GetReal(c, {6, 4294967295}, 2, v)", AK_OP_GET_REAL,
     {.vr = (const fmi2ValueReference[]){AP_VR_Q, 4294967295u}, .nvr = 2,
      .values = (fmi2Real[2]){0}},
     fmi2Error,
     "fmi2GetReal: vr[1] = 4294967295 is not a value reference of this FMU (0 to @LAST@)", false},
    {STEP_COMPLETE, "fmi2GetInteger(c, {@PAST@}, 1, v)", AK_OP_GET_INTEGER,
     {.vr = (const fmi2ValueReference[]){AP_N_VALUE_REFERENCES}, .nvr = 1,
      .values = (fmi2Integer[1]){0}},
     fmi2Error,
     "fmi2GetInteger: vr[0] = @PAST@ is not a value reference of this FMU (0 to @LAST@)", false},
    {STEP_COMPLETE, "fmi2SetReal(c, {0, 1}, 2, {2.5, NAN})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){AP_VR_OMEGA, AP_VR_OMEGA + 1}, .nvr = 2,
      .values = (fmi2Real[]){2.5, NAN}},
     fmi2Error, "fmi2SetReal: omega[2] = nan (vr[1] = 1) is not finite; no value set", false},
    {INITIALIZATION_MODE, "fmi2SetReal(c, {2}, 1, {-INFINITY})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){AP_VR_OMEGA + 2}, .nvr = 1,
      .values = (fmi2Real[]){-INFINITY}},
     fmi2Error, "fmi2SetReal: omega[3] = -inf (vr[0] = 2) is not finite; no value set", false},
    {EVENT_MODE, "fmi2SetReal(c, {5}, 1, {INFINITY})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){AP_VR_OMEGA_DOT + 2}, .nvr = 1,
      .values = (fmi2Real[]){INFINITY}},
     fmi2Error, "fmi2SetReal: omega_dot[3] = inf (vr[0] = 5) is not finite; no value set", false},
    {CONTINUOUS_TIME_MODE, "fmi2SetReal(c, {3}, 1, {NAN})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){AP_VR_OMEGA_DOT}, .nvr = 1, .values = (fmi2Real[]){NAN}},
     fmi2Error, "fmi2SetReal: omega_dot[1] = nan (vr[0] = 3) is not finite; no value set", false},
    {STEP_COMPLETE, "fmi2SetReal(c, {7}, 1, {0.5})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){AP_VR_Q + 1}, .nvr = 1, .values = (fmi2Real[]){0.5}},
     fmi2Error,
     "fmi2SetReal: vr[0] = 7 is q[2], an output and a continuous state (fmi2SetContinuousStates "
     "sets states in model exchange): only inputs and parameters can be set; no value set",
     false},
    {EVENT_MODE, "fmi2SetReal(c, {0, 6}, 2, {1, 1})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){AP_VR_OMEGA, AP_VR_Q}, .nvr = 2,
      .values = (fmi2Real[]){1.0, 1.0}},
     fmi2Error,
     "fmi2SetReal: vr[1] = 6 is q[1], an output and a continuous state (fmi2SetContinuousStates "
     "sets states in model exchange): only inputs and parameters can be set; no value set",
     false},
    {STEP_COMPLETE, "fmi2SetReal(c, {10}, 1, {0.5})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){AP_VR_DER_Q}, .nvr = 1, .values = (fmi2Real[]){0.5}},
     fmi2Error,
     "fmi2SetReal: vr[0] = 10 is der(q[1]), a local: only inputs and parameters can be set; no "
     "value set", false},
    {STEP_COMPLETE, "fmi2SetReal(c, {54}, 1, {0})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){AP_VR_H_PREVIOUS}, .nvr = 1, .values = (fmi2Real[]){0.0}},
     fmi2Error,
     "fmi2SetReal: vr[0] = 54 is h_previous, a local: only inputs and parameters can be set; no "
     "value set", false},
    {STEP_COMPLETE, "fmi2SetReal(c, {23}, 1, {1})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){AP_VR_THETA}, .nvr = 1, .values = (fmi2Real[]){1.0}},
     fmi2Error,
     "fmi2SetReal: vr[0] = 23 is theta[1], an output: only inputs and parameters can be set; no "
     "value set", false},
    {STEP_COMPLETE, "fmi2GetReal(c, {14, 43}, 2, v)", AK_OP_GET_REAL,
     {.vr = (const fmi2ValueReference[]){AP_VR_R, AP_VR_SEQUENCE}, .nvr = 2,
      .values = (fmi2Real[2]){0}},
     fmi2Error, "fmi2GetReal: vr[1] = 43 is sequence, of type Integer, not Real", false},
    {STEP_COMPLETE, "fmi2GetInteger(c, {44}, 1, v)", AK_OP_GET_INTEGER,
     {.vr = (const fmi2ValueReference[]){AP_VR_Q0}, .nvr = 1, .values = (fmi2Integer[1]){0}},
     fmi2Error, "fmi2GetInteger: vr[0] = 44 is q0[1], of type Real, not Integer", false},
    {INSTANTIATED, "fmi2SetInteger(c, {0}, 1, {1})", AK_OP_SET_INTEGER,
     {.vr = (const fmi2ValueReference[]){AP_VR_OMEGA}, .nvr = 1, .values = (fmi2Integer[]){1}},
     fmi2Error, "fmi2SetInteger: vr[0] = 0 is omega[1], of type Real, not Integer", false},

    /* --- the initial quaternion q0 (Real, fixed): finite, and not zero once all four are known */
    {INSTANTIATED, "fmi2SetReal(c, {44}, 1, {NAN})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){AP_VR_Q0}, .nvr = 1, .values = (fmi2Real[]){NAN}},
     fmi2Error, "fmi2SetReal: q0[1] = nan (vr[0] = 44) is not finite; no value set", false},
    {INITIALIZATION_MODE, "fmi2SetReal(c, {44, 45, 46, 47}, 4, {1, 0, INFINITY, 0})",
     AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){AP_VR_Q0, AP_VR_Q0 + 1, AP_VR_Q0 + 2, AP_VR_Q0 + 3},
      .nvr = 4, .values = (fmi2Real[]){1.0, 0.0, INFINITY, 0.0}},
     fmi2Error, "fmi2SetReal: q0[3] = inf (vr[2] = 46) is not finite; no value set", false},
    {STEP_COMPLETE, "fmi2SetReal(c, {44}, 1, {2})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){AP_VR_Q0}, .nvr = 1, .values = (fmi2Real[]){2.0}},
     fmi2Error,
     "fmi2SetReal: q0[1] (vr[0] = 44) is a parameter of variability fixed: it can be set only in "
     "Instantiated and InitializationMode, not in StepComplete; no value set", false},
    {INITIALIZATION_MODE, "fmi2SetReal(c, {44}, 1, {0}); fmi2ExitInitializationMode(c)",
     AK_OP_EXIT_INITIALIZATION_MODE, {0}, fmi2Error,
     "AttitudePropagator: q0 = (0, 0, 0, 0) is not an attitude: the initial quaternion must be "
     "finite and not zero; q0[1] = 1 and the rest 0 is the identity",
     false, .with_setup = true, .setup_op = AK_OP_SET_REAL,
     .setup_args = {.vr = (const fmi2ValueReference[]){AP_VR_Q0}, .nvr = 1,
                    .values = (fmi2Real[]){0.0}},
     .message2 = "fmi2ExitInitializationMode: the parameters give no initial state (see the "
                 "message before); the instance stays in InitializationMode",
     .status2 = fmi2Error},
    {ME_INITIALIZATION_MODE, "fmi2SetReal(c, {44}, 1, {0}); fmi2ExitInitializationMode(c)",
     AK_OP_EXIT_INITIALIZATION_MODE, {0}, fmi2Error,
     "AttitudePropagator: q0 = (0, 0, 0, 0) is not an attitude: the initial quaternion must be "
     "finite and not zero; q0[1] = 1 and the rest 0 is the identity",
     false, .with_setup = true, .setup_op = AK_OP_SET_REAL,
     .setup_args = {.vr = (const fmi2ValueReference[]){AP_VR_Q0}, .nvr = 1,
                    .values = (fmi2Real[]){0.0}},
     .message2 = "fmi2ExitInitializationMode: the parameters give no initial state (see the "
                 "message before); the instance stays in InitializationMode",
     .status2 = fmi2Error},
    {INITIALIZATION_MODE, "fmi2SetReal(c, {44}, 1, {0}); fmi2GetReal(c, {6}, 1, v)",
     AK_OP_GET_REAL,
     {.vr = (const fmi2ValueReference[]){AP_VR_Q}, .nvr = 1, .values = (fmi2Real[1]){0}},
     fmi2Discard,
     "AttitudePropagator: q0 = (0, 0, 0, 0) is not an attitude: the initial quaternion must be "
     "finite and not zero; q0[1] = 1 and the rest 0 is the identity",
     false, .with_setup = true, .setup_op = AK_OP_SET_REAL,
     .setup_args = {.vr = (const fmi2ValueReference[]){AP_VR_Q0}, .nvr = 1,
                    .values = (fmi2Real[]){0.0}},
     .message_status = fmi2Error /* the model's message (logStatusError) for a read answered
                                  * with fmi2Discard: docs/bad_input.md */},

    /* --- the parameters frame (1 fixed, 2 body) and sequence (1 to 24), fixed ----------------- */
    {INSTANTIATED, "fmi2SetInteger(c, {43}, 1, {25})", AK_OP_SET_INTEGER,
     {.vr = (const fmi2ValueReference[]){AP_VR_SEQUENCE}, .nvr = 1, .values = (fmi2Integer[]){25}},
     fmi2Error,
     "fmi2SetInteger: sequence = 25 (vr[0] = 43) is not an item of the Enumeration Sequence (1 "
     "body123 .. 24 space323); no value set", false},
    {INITIALIZATION_MODE, "fmi2SetInteger(c, {43, 42}, 2, {3, 0})", AK_OP_SET_INTEGER,
     {.vr = (const fmi2ValueReference[]){AP_VR_SEQUENCE, AP_VR_FRAME}, .nvr = 2,
      .values = (fmi2Integer[]){3, 0}},
     fmi2Error,
     "fmi2SetInteger: frame = 0 (vr[1] = 42) is not an item of the Enumeration Frame (1 fixed, 2 "
     "body); no value set", false},
    {ME_INSTANTIATED, "fmi2SetInteger(c, {42}, 1, {3})", AK_OP_SET_INTEGER,
     {.vr = (const fmi2ValueReference[]){AP_VR_FRAME}, .nvr = 1, .values = (fmi2Integer[]){3}},
     fmi2Error,
     "fmi2SetInteger: frame = 3 (vr[0] = 42) is not an item of the Enumeration Frame (1 fixed, 2 "
     "body); no value set", false},
    {STEP_COMPLETE, "fmi2SetInteger(c, {42}, 1, {1})", AK_OP_SET_INTEGER,
     {.vr = (const fmi2ValueReference[]){AP_VR_FRAME}, .nvr = 1, .values = (fmi2Integer[]){1}},
     fmi2Error,
     "fmi2SetInteger: frame (vr[0] = 42) is a parameter of variability fixed: it can be set only "
     "in Instantiated and InitializationMode, not in StepComplete; no value set", false},
    {EVENT_MODE, "fmi2SetInteger(c, {43}, 1, {2})", AK_OP_SET_INTEGER,
     {.vr = (const fmi2ValueReference[]){AP_VR_SEQUENCE}, .nvr = 1, .values = (fmi2Integer[]){2}},
     fmi2Error,
     "fmi2SetInteger: sequence (vr[0] = 43) is a parameter of variability fixed: it can be set "
     "only in Instantiated and InitializationMode, not in EventMode; no value set", false},

    /* --- model exchange: the four continuous states q -------------------------------------- */
    {CONTINUOUS_TIME_MODE, "fmi2SetContinuousStates(c, {1, 0, 0}, 3)",
     AK_OP_SET_CONTINUOUS_STATES, {.nvr = 3, .values2 = (fmi2Real[]){1.0, 0.0, 0.0}}, fmi2Error,
     "fmi2SetContinuousStates: nx = 3, but this FMU has 4 continuous states "
     "(numberOfContinuousStates)", false},
    {CONTINUOUS_TIME_MODE, "fmi2SetContinuousStates(c, NULL, 4)", AK_OP_SET_CONTINUOUS_STATES,
     {.nvr = 4}, fmi2Error, "fmi2SetContinuousStates: x is NULL with nx = 4", false},
    {CONTINUOUS_TIME_MODE, "fmi2SetContinuousStates(c, {1, NAN, 0, 0}, 4)",
     AK_OP_SET_CONTINUOUS_STATES, {.nvr = 4, .values2 = (fmi2Real[]){1.0, NAN, 0.0, 0.0}},
     fmi2Error, "fmi2SetContinuousStates: x[1] = nan (q[2]) is not finite; no state set", false},
    {CONTINUOUS_TIME_MODE, "fmi2SetContinuousStates(c, {1, 0, 0, -INFINITY}, 4)",
     AK_OP_SET_CONTINUOUS_STATES, {.nvr = 4, .values2 = (fmi2Real[]){1.0, 0.0, 0.0, -INFINITY}},
     fmi2Error, "fmi2SetContinuousStates: x[3] = -inf (q[4]) is not finite; no state set", false},
    {CONTINUOUS_TIME_MODE, "fmi2GetDerivatives(c, dx, 5)", AK_OP_GET_DERIVATIVES,
     {.nvr = 5, .values2 = (fmi2Real[5]){0}}, fmi2Error,
     "fmi2GetDerivatives: nx = 5, but this FMU has 4 continuous states (numberOfContinuousStates)",
     false},
    {EVENT_MODE, "fmi2GetDerivatives(c, NULL, 4)", AK_OP_GET_DERIVATIVES, {.nvr = 4}, fmi2Error,
     "fmi2GetDerivatives: derivatives is NULL with nx = 4", false},
    {EVENT_MODE, "fmi2GetEventIndicators(c, z, 1)", AK_OP_GET_EVENT_INDICATORS,
     {.nvr = 1, .values2 = (fmi2Real[1]){0}}, fmi2Error,
     "fmi2GetEventIndicators: ni = 1, but this FMU has no event indicators (ni must be 0)", false},
    {ME_TERMINATED, "fmi2GetContinuousStates(c, x, 0)", AK_OP_GET_CONTINUOUS_STATES, {0},
     fmi2Error,
     "fmi2GetContinuousStates: nx = 0, but this FMU has 4 continuous states "
     "(numberOfContinuousStates)", false},
    {ME_INSTANTIATED, "fmi2GetNominalsOfContinuousStates(c, x, 2)",
     AK_OP_GET_NOMINALS_OF_CONTINUOUS_STATES, {.nvr = 2, .values2 = (fmi2Real[2]){0}}, fmi2Error,
     "fmi2GetNominalsOfContinuousStates: nx = 2, but this FMU has 4 continuous states "
     "(numberOfContinuousStates)", false},
    {ME_INSTANTIATED, "fmi2GetNominalsOfContinuousStates(c, NULL, 4)",
     AK_OP_GET_NOMINALS_OF_CONTINUOUS_STATES, {.nvr = 4}, fmi2Error,
     "fmi2GetNominalsOfContinuousStates: x_nominal is NULL with nx = 4", false},
    {CONTINUOUS_TIME_MODE,
     "fmi2SetContinuousStates(c, {0, 0, 0, 0}, 4); fmi2GetReal(c, {23}, 1, v)", AK_OP_GET_REAL,
     {.vr = (const fmi2ValueReference[]){AP_VR_THETA}, .nvr = 1, .values = (fmi2Real[1]){0}},
     fmi2Discard,
     "AttitudePropagator: the state q = (0, 0, 0, 0) has |q| = 0: it is not an attitude; the "
     "outputs keep their last valid values",
     false, .with_setup = true, .setup_op = AK_OP_SET_CONTINUOUS_STATES,
     .setup_args = {.nvr = 4, .values2 = (fmi2Real[]){0.0, 0.0, 0.0, 0.0}}},
    {STEP_COMPLETE, "fmi2GetContinuousStates(c, x, 4)", AK_OP_GET_CONTINUOUS_STATES,
     {.nvr = 4, .values2 = (fmi2Real[4]){0}}, fmi2Error,
     "fmi2GetContinuousStates: a model-exchange function, but this instance was created for "
     "co-simulation (fmi2CoSimulation)", false},

    /* --- a step that cannot be taken: omega = (1e308, 1e308, 1e308) over 0.5 ---------------- */
    {STEP_COMPLETE,
     "fmi2SetReal(c, {0, 1, 2}, 3, {1e308, 1e308, 1e308}); fmi2DoStep(c, 1, 0.5, fmi2True)",
     AK_OP_DO_STEP, {.real = {1.0, 0.5}, .flag = {fmi2True}}, fmi2Discard,
     "AttitudePropagator: omega = (1e+308, 1e+308, 1e+308) over the communication step size 0.5 "
     "gives a rotation that is not finite; the state q is left as it was",
     false, .with_setup = true, .setup_op = AK_OP_SET_REAL,
     .setup_args = {.vr = (const fmi2ValueReference[]){AP_VR_OMEGA, AP_VR_OMEGA + 1,
                                                       AP_VR_OMEGA + 2},
                    .nvr = 3, .values = (fmi2Real[]){1e308, 1e308, 1e308}},
     .message2 = "fmi2DoStep: the step from 1 to 1.5 is discarded: the states cannot be advanced "
                 "over it; last successful time 1",
     .status2 = fmi2Discard},
    {STEP_FAILED, "fmi2DoStep(c, 1, 0.5, fmi2True)", AK_OP_DO_STEP,
     {.real = {1.0, 0.5}, .flag = {fmi2True}}, fmi2Error,
     "fmi2DoStep: illegal call in state StepFailed", false},
    {STEP_FAILED, "fmi2SetReal(c, {0}, 1, {0})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){AP_VR_OMEGA}, .nvr = 1, .values = (fmi2Real[]){0.0}},
     fmi2Error, "fmi2SetReal: illegal call in state StepFailed", false},

    /* --- directional derivatives (provided: knowns are the inputs and, in model exchange, the
     * states), input derivatives (provided), output derivatives (not provided) ------------- */
    {STEP_COMPLETE, "fmi2GetDirectionalDerivative(c, {0}, 1, {0}, 1, {1}, dv)",
     AK_OP_GET_DIRECTIONAL_DERIVATIVE,
     {.vr = (const fmi2ValueReference[]){AP_VR_OMEGA}, .nvr = 1,
      .vr2 = (const fmi2ValueReference[]){AP_VR_OMEGA}, .nvr2 = 1, .known = (fmi2Real[]){1.0},
      .values2 = (fmi2Real[1]){0}},
     fmi2Error,
     "fmi2GetDirectionalDerivative: vUnknown_ref[0] = 0 is omega[1], an input; expected an "
     "output", false},
    {STEP_COMPLETE, "fmi2GetDirectionalDerivative(c, {23}, 1, {14}, 1, {1}, dv)",
     AK_OP_GET_DIRECTIONAL_DERIVATIVE,
     {.vr = (const fmi2ValueReference[]){AP_VR_THETA}, .nvr = 1,
      .vr2 = (const fmi2ValueReference[]){AP_VR_R}, .nvr2 = 1, .known = (fmi2Real[]){1.0},
      .values2 = (fmi2Real[1]){0}},
     fmi2Error,
     "fmi2GetDirectionalDerivative: vKnown_ref[0] = 14 is R[1,1], an output; expected an input",
     false},
    {STEP_COMPLETE, "fmi2GetDirectionalDerivative(c, {23}, 1, {44}, 1, {1}, dv)",
     AK_OP_GET_DIRECTIONAL_DERIVATIVE,
     {.vr = (const fmi2ValueReference[]){AP_VR_THETA}, .nvr = 1,
      .vr2 = (const fmi2ValueReference[]){AP_VR_Q0}, .nvr2 = 1, .known = (fmi2Real[]){1.0},
      .values2 = (fmi2Real[1]){0}},
     fmi2Error,
     "fmi2GetDirectionalDerivative: vKnown_ref[0] = 44 is q0[1], a parameter; expected an input",
     false},
    {CONTINUOUS_TIME_MODE, "fmi2GetDirectionalDerivative(c, {10}, 1, {6, 0}, 2, {1, INFINITY}, dv)",
     AK_OP_GET_DIRECTIONAL_DERIVATIVE,
     {.vr = (const fmi2ValueReference[]){AP_VR_DER_Q}, .nvr = 1,
      .vr2 = (const fmi2ValueReference[]){AP_VR_Q, AP_VR_OMEGA}, .nvr2 = 2,
      .known = (fmi2Real[]){1.0, INFINITY}, .values2 = (fmi2Real[1]){0}},
     fmi2Error,
     "fmi2GetDirectionalDerivative: dvKnown[1] = inf (seed of omega[1]) is not finite", false},
    {STEP_COMPLETE, "fmi2GetRealOutputDerivatives(c, {23}, 1, {1}, v)",
     AK_OP_GET_REAL_OUTPUT_DERIVATIVES,
     {.vr = (const fmi2ValueReference[]){AP_VR_THETA}, .nvr = 1,
      .values2 = (fmi2Integer[]){1}, .values = (fmi2Real[1]){0}},
     fmi2Error,
     "fmi2GetRealOutputDerivatives: not provided by AttitudePropagator "
     "(modelDescription.xml: maxOutputDerivativeOrder=\"0\")", false},
    {STEP_COMPLETE, "fmi2SetRealInputDerivatives(c, {6}, 1, {1}, {1})",
     AK_OP_SET_REAL_INPUT_DERIVATIVES,
     {.vr = (const fmi2ValueReference[]){AP_VR_Q}, .nvr = 1, .values2 = (fmi2Integer[]){1},
      .values = (fmi2Real[]){1.0}},
     fmi2Error,
     "fmi2SetRealInputDerivatives: vr[0] = 6 is q[1], an output; expected an input", false},
    {STEP_COMPLETE, "fmi2SetRealInputDerivatives(c, {0}, 1, {3}, {1})",
     AK_OP_SET_REAL_INPUT_DERIVATIVES,
     {.vr = (const fmi2ValueReference[]){AP_VR_OMEGA}, .nvr = 1, .values2 = (fmi2Integer[]){3},
      .values = (fmi2Real[]){1.0}},
     fmi2Error,
     "fmi2SetRealInputDerivatives: order[0] = 3 for omega[1]: this FMU takes orders 1 to 2; no "
     "derivative set", false},
    {STEP_COMPLETE, "fmi2SetRealInputDerivatives(c, {0}, 1, {1}, {NAN})",
     AK_OP_SET_REAL_INPUT_DERIVATIVES,
     {.vr = (const fmi2ValueReference[]){AP_VR_OMEGA}, .nvr = 1, .values2 = (fmi2Integer[]){1},
      .values = (fmi2Real[]){NAN}},
     fmi2Error,
     "fmi2SetRealInputDerivatives: derivative of order 1 of omega[1] = nan (vr[0] = 0) is not "
     "finite; no derivative set", false},

    /* --- FMU state: a foreign state given to a model-exchange instance ------------------- */
    {EVENT_MODE, "fmi2DeSerializeFMUstate(c, 64 bytes \"AKFMUSTA...\", 64, &state)",
     AK_OP_DE_SERIALIZE_FMU_STATE,
     {.bytes = (fmi2Byte[64]){"AKFMUSTATE"}, .n_bytes = 64, .out = (fmi2FMUstate[1]){NULL}},
     fmi2Error,
     "fmi2DeSerializeFMUstate: the 64 bytes are not an AttitudePropagator FMU state "
     "(wrong magic bytes)", false},
};
const size_t AK_N_MODEL_BAD_CALLS = sizeof AK_MODEL_BAD_CALLS / sizeof AK_MODEL_BAD_CALLS[0];
