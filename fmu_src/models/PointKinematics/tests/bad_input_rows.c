/* The bad-input rows of PointKinematics (see fmi2_bad_input_table.h): its value references (inputs 0
 * to 23, outputs 24 to 41, no parameter), the step that fails when a product of the inputs
 * overflows, and the capability it does not have (output derivatives). */
#include <math.h>

#include "fmi2_bad_input_table.h"
#include "PointKinematics_variables.h"
#include "fmi2_test_instance.h"

enum {
    STEP_COMPLETE = AK_IN_STEP_COMPLETE,
    STEP_FAILED = AK_IN_STEP_FAILED,
    EVENT_MODE = AK_ME | AK_IN_EVENT_MODE
};

/* A step fails when omega x r overflows: omega[1] = r[2] = 1e200 gives v_P[3] = 1e400. */
const ak_test_failing_step AK_TEST_FAILING_STEP = {2, {PK_VR_OMEGA, PK_VR_R + 1}, {1e200, 1e200}};

const ak_bad_call AK_MODEL_BAD_CALLS[] = {
    /* --- values ------------------------------------------------------------------------------ */
    {STEP_COMPLETE, "fmi2SetReal(c, {0, @PAST@}, 2, {7, 7})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){0, PK_N_VALUE_REFERENCES}, .nvr = 2, .values = (fmi2Real[]){7.0, 7.0}},
     fmi2Error,
     "fmi2SetReal: vr[1] = @PAST@ is not a value reference of this FMU (0 to @LAST@)", false},
    {STEP_COMPLETE, "fmi2SetReal(c, {24}, 1, {1})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){24}, .nvr = 1, .values = (fmi2Real[]){1.0}}, fmi2Error,
     "fmi2SetReal: vr[0] = 24 is v_P[1], an output: only inputs and parameters can be "
     "set; no value set", false},
    {STEP_COMPLETE, "fmi2SetReal(c, {0, 2}, 2, {2.5, NAN})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){0, 2}, .nvr = 2, .values = (fmi2Real[]){2.5, NAN}},
     fmi2Error,
     "fmi2SetReal: omega[3] = nan (vr[1] = 2) is not finite; no value set", false},
    {EVENT_MODE, "fmi2SetReal(c, {23}, 1, {INFINITY})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){23}, .nvr = 1, .values = (fmi2Real[]){INFINITY}},
     fmi2Error,
     "fmi2SetReal: g[3] = inf (vr[0] = 23) is not finite; no value set", false},
    {STEP_COMPLETE, "fmi2GetInteger(c, {12}, 1, v)", AK_OP_GET_INTEGER,
     {.vr = (const fmi2ValueReference[]){12}, .nvr = 1, .values = (fmi2Integer[1]){0}},
     fmi2Error,
     "fmi2GetInteger: vr[0] = 12 is r[1], of type Real, not Integer", false},

    /* --- a step that failed: omega x r overflows ------------------------------------------------ */
    {STEP_FAILED, "fmi2GetReal(c, {26}, 1, v)", AK_OP_GET_REAL,
     {.vr = (const fmi2ValueReference[]){26}, .nvr = 1, .values = (fmi2Real[1]){0}}, fmi2Discard,
     "PointKinematics: v_P[3] = inf: a product of the inputs overflows (|omega| = 1e+200, "
     "|alpha| = 2.54951, |r| = 1e+200, |r_dot| = 0.384057); the outputs keep their last valid "
     "values", false},
    {STEP_FAILED, "fmi2DoStep(c, 1, 0.5, fmi2True)", AK_OP_DO_STEP,
     {.real = {1.0, 0.5}, .flag = {fmi2True}}, fmi2Error, "fmi2DoStep: illegal call in state StepFailed", false},
    {STEP_FAILED, "fmi2SetReal(c, {1}, 1, {0})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){1}, .nvr = 1, .values = (fmi2Real[]){0.0}}, fmi2Error,
     "fmi2SetReal: illegal call in state StepFailed", false},

    /* --- the capability PointKinematics does not have ----------------------------------------- */
    {STEP_COMPLETE, "fmi2GetRealOutputDerivatives(c, {24}, 1, {1}, v)",
     AK_OP_GET_REAL_OUTPUT_DERIVATIVES,
     {.vr = (const fmi2ValueReference[]){24}, .nvr = 1, .values2 = (fmi2Integer[]){1},
      .values = (fmi2Real[1]){0}},
     fmi2Error,
     "fmi2GetRealOutputDerivatives: not provided by PointKinematics "
     "(modelDescription.xml: maxOutputDerivativeOrder=\"0\")", false},
    {STEP_COMPLETE, "fmi2SetRealInputDerivatives(c, {24}, 1, {1}, {1})",
     AK_OP_SET_REAL_INPUT_DERIVATIVES,
     {.vr = (const fmi2ValueReference[]){24}, .nvr = 1, .values2 = (fmi2Integer[]){1},
      .values = (fmi2Real[]){1.0}},
     fmi2Error,
     "fmi2SetRealInputDerivatives: vr[0] = 24 is v_P[1], an output; "
     "expected an input", false},
};
const size_t AK_N_MODEL_BAD_CALLS = sizeof AK_MODEL_BAD_CALLS / sizeof AK_MODEL_BAD_CALLS[0];
