/* The bad-input rows of AngularKinematics (see fmi2_bad_input_table.h): its value references
 * (inputs 0 to 8, outputs 9 to 69, Integer parameter sequence 70), the sequence parameter, and
 * the directional and output derivatives it provides. */
#include <math.h>

#include "fmi2_bad_input_table.h"
#include "AngularKinematics_variables.h"
#include "fmi2_test_instance.h"

enum {
    INSTANTIATED = AK_IN_INSTANTIATED,
    INITIALIZATION_MODE = AK_IN_INITIALIZATION_MODE,
    STEP_COMPLETE = AK_IN_STEP_COMPLETE,
    TERMINATED = AK_IN_TERMINATED,
    EVENT_MODE = AK_ME | AK_IN_EVENT_MODE
};

/* No step of AngularKinematics can fail: its outputs are defined for every finite input. */
const ak_test_failing_step AK_TEST_FAILING_STEP = {0, {0}, {0}};

const ak_bad_call AK_MODEL_BAD_CALLS[] = {
    /* --- values ------------------------------------------------------------------------------ */
    {STEP_COMPLETE, "fmi2SetReal(c, {0, @PAST@}, 2, {7, 7})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){0, KIN_N_VALUE_REFERENCES}, .nvr = 2, .values = (fmi2Real[]){7.0, 7.0}},
     fmi2Error,
     "fmi2SetReal: vr[1] = @PAST@ is not a value reference of this FMU (0 to @LAST@)", false},
    {STEP_COMPLETE, "fmi2SetReal(c, {4294967295}, 1, {7})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){4294967295u}, .nvr = 1, .values = (fmi2Real[]){7.0}},
     fmi2Error,
     "fmi2SetReal: vr[0] = 4294967295 is not a value reference of this FMU "
     "(0 to @LAST@)", false},
    {STEP_COMPLETE, "fmi2SetReal(c, {9}, 1, {1})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){9}, .nvr = 1, .values = (fmi2Real[]){1.0}}, fmi2Error,
     "fmi2SetReal: vr[0] = 9 is omega_fixed[1], an output: only inputs and parameters can be "
     "set; no value set", false},
    {STEP_COMPLETE, "fmi2SetReal(c, {0, 5}, 2, {2.5, NAN})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){0, 5}, .nvr = 2, .values = (fmi2Real[]){2.5, NAN}},
     fmi2Error,
     "fmi2SetReal: theta_dot[3] = nan (vr[1] = 5) is not finite; no value "
     "set", false},
    {STEP_COMPLETE, "fmi2SetReal(c, {8}, 1, {INFINITY})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){8}, .nvr = 1, .values = (fmi2Real[]){INFINITY}},
     fmi2Error,
     "fmi2SetReal: theta_ddot[3] = inf (vr[0] = 8) is not finite; no value "
     "set", false},
    {EVENT_MODE, "fmi2SetReal(c, {3}, 1, {-INFINITY})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){3}, .nvr = 1, .values = (fmi2Real[]){-INFINITY}},
     fmi2Error,
     "fmi2SetReal: theta_dot[1] = -inf (vr[0] = 3) is not finite; no value "
     "set", false},
    {INSTANTIATED, "fmi2SetReal(c, {70}, 1, {2})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){70}, .nvr = 1, .values = (fmi2Real[]){2.0}},
     fmi2Error,
     "fmi2SetReal: vr[0] = 70 is sequence, of type Integer, not Real", false},
    {STEP_COMPLETE, "fmi2GetReal(c, {9, 1000}, 2, v)", AK_OP_GET_REAL,
     {.vr = (const fmi2ValueReference[]){9, 1000}, .nvr = 2, .values = (fmi2Real[2]){0}},
     fmi2Error,
     "fmi2GetReal: vr[1] = 1000 is not a value reference of this FMU (0 to "
     "@LAST@)", false},
    {STEP_COMPLETE, "fmi2GetReal(c, {21, 70}, 2, v)", AK_OP_GET_REAL,
     {.vr = (const fmi2ValueReference[]){21, 70}, .nvr = 2, .values = (fmi2Real[2]){0}},
     fmi2Error,
     "fmi2GetReal: vr[1] = 70 is sequence, of type Integer, not Real", false},
    {STEP_COMPLETE, "fmi2GetInteger(c, {0}, 1, v)", AK_OP_GET_INTEGER,
     {.vr = (const fmi2ValueReference[]){0}, .nvr = 1, .values = (fmi2Integer[1]){0}},
     fmi2Error,
     "fmi2GetInteger: vr[0] = 0 is theta[1], of type Real, not Integer", false},

    /* --- the parameter sequence (Integer, Enumeration 1 to 24, fixed) --------------------------- */
    {INSTANTIATED, "fmi2SetInteger(c, {70}, 1, {0})", AK_OP_SET_INTEGER,
     {.vr = (const fmi2ValueReference[]){70}, .nvr = 1, .values = (fmi2Integer[]){0}},
     fmi2Error,
     "fmi2SetInteger: sequence = 0 (vr[0] = 70) is not an item of the "
     "Enumeration Sequence (1 body123 .. 24 space323); no value set", false},
    {INITIALIZATION_MODE, "fmi2SetInteger(c, {70}, 1, {25})", AK_OP_SET_INTEGER,
     {.vr = (const fmi2ValueReference[]){70}, .nvr = 1, .values = (fmi2Integer[]){25}},
     fmi2Error,
     "fmi2SetInteger: sequence = 25 (vr[0] = 70) is not an item of the "
     "Enumeration Sequence (1 body123 .. 24 space323); no value set", false},
    {STEP_COMPLETE, "fmi2SetInteger(c, {70}, 1, {2})", AK_OP_SET_INTEGER,
     {.vr = (const fmi2ValueReference[]){70}, .nvr = 1, .values = (fmi2Integer[]){2}},
     fmi2Error,
     "fmi2SetInteger: sequence (vr[0] = 70) is a parameter of variability "
     "fixed: it can be set only in Instantiated and InitializationMode, not "
     "in StepComplete; no value set", false},
    {EVENT_MODE, "fmi2SetInteger(c, {70}, 1, {2})", AK_OP_SET_INTEGER,
     {.vr = (const fmi2ValueReference[]){70}, .nvr = 1, .values = (fmi2Integer[]){2}},
     fmi2Error,
     "fmi2SetInteger: sequence (vr[0] = 70) is a parameter of variability "
     "fixed: it can be set only in Instantiated and InitializationMode, not "
     "in EventMode; no value set", false},
    {INSTANTIATED, "fmi2SetInteger(c, {0}, 1, {1})", AK_OP_SET_INTEGER,
     {.vr = (const fmi2ValueReference[]){0}, .nvr = 1, .values = (fmi2Integer[]){1}}, fmi2Error,
     "fmi2SetInteger: vr[0] = 0 is theta[1], of type Real, not Integer", false},

    /* --- directional derivatives ------------------------------------------------------------- */
    {STEP_COMPLETE, "fmi2GetDirectionalDerivative(c, NULL, 1, {0}, 1, {1}, dv)",
     AK_OP_GET_DIRECTIONAL_DERIVATIVE,
     {.nvr = 1, .vr2 = (const fmi2ValueReference[]){0}, .nvr2 = 1, .known = (fmi2Real[]){1.0},
      .values2 = (fmi2Real[1]){0}},
     fmi2Error,
     "fmi2GetDirectionalDerivative: vUnknown_ref is NULL with nUnknown = 1", false},
    {STEP_COMPLETE, "fmi2GetDirectionalDerivative(c, {0}, 1, {0}, 1, {1}, dv)",
     AK_OP_GET_DIRECTIONAL_DERIVATIVE,
     {.vr = (const fmi2ValueReference[]){0}, .nvr = 1, .vr2 = (const fmi2ValueReference[]){0},
      .nvr2 = 1, .known = (fmi2Real[]){1.0}, .values2 = (fmi2Real[1]){0}},
     fmi2Error,
     "fmi2GetDirectionalDerivative: vUnknown_ref[0] = 0 is theta[1], an "
     "input; expected an output", false},
    {STEP_COMPLETE, "fmi2GetDirectionalDerivative(c, {9}, 1, {12}, 1, {1}, dv)",
     AK_OP_GET_DIRECTIONAL_DERIVATIVE,
     {.vr = (const fmi2ValueReference[]){9}, .nvr = 1, .vr2 = (const fmi2ValueReference[]){12},
      .nvr2 = 1, .known = (fmi2Real[]){1.0}, .values2 = (fmi2Real[1]){0}},
     fmi2Error,
     "fmi2GetDirectionalDerivative: vKnown_ref[0] = 12 is omega_body[1], an "
     "output; expected an input", false},
    {STEP_COMPLETE, "fmi2GetDirectionalDerivative(c, {9}, 1, {70}, 1, {1}, dv)",
     AK_OP_GET_DIRECTIONAL_DERIVATIVE,
     {.vr = (const fmi2ValueReference[]){9}, .nvr = 1, .vr2 = (const fmi2ValueReference[]){70},
      .nvr2 = 1, .known = (fmi2Real[]){1.0}, .values2 = (fmi2Real[1]){0}},
     fmi2Error,
     "fmi2GetDirectionalDerivative: vKnown_ref[0] = 70 is sequence, a "
     "parameter; expected an input", false},
    {STEP_COMPLETE, "fmi2GetDirectionalDerivative(c, {9}, 1, {0, 1}, 2, {1, NAN}, dv)",
     AK_OP_GET_DIRECTIONAL_DERIVATIVE,
     {.vr = (const fmi2ValueReference[]){9}, .nvr = 1, .vr2 = (const fmi2ValueReference[]){0, 1},
      .nvr2 = 2, .known = (fmi2Real[]){1.0, NAN}, .values2 = (fmi2Real[1]){0}},
     fmi2Error,
     "fmi2GetDirectionalDerivative: dvKnown[1] = nan (seed of theta[2]) is "
     "not finite", false},
    {STEP_COMPLETE, "fmi2GetDirectionalDerivative(c, {9}, 1, {0}, 1, NULL, dv)",
     AK_OP_GET_DIRECTIONAL_DERIVATIVE,
     {.vr = (const fmi2ValueReference[]){9}, .nvr = 1, .vr2 = (const fmi2ValueReference[]){0},
      .nvr2 = 1, .values2 = (fmi2Real[1]){0}},
     fmi2Error,
     "fmi2GetDirectionalDerivative: dvKnown is NULL with nKnown = 1", false},
    {INSTANTIATED, "fmi2GetDirectionalDerivative(c, {9}, 1, {0}, 1, {1}, dv)",
     AK_OP_GET_DIRECTIONAL_DERIVATIVE,
     {.vr = (const fmi2ValueReference[]){9}, .nvr = 1, .vr2 = (const fmi2ValueReference[]){0},
      .nvr2 = 1, .known = (fmi2Real[]){1.0}, .values2 = (fmi2Real[1]){0}},
     fmi2Error,
     "fmi2GetDirectionalDerivative: illegal call in state Instantiated", false},

    /* --- input and output derivatives (co-simulation) ------------------------------------------ */
    {STEP_COMPLETE, "fmi2SetRealInputDerivatives(c, {9}, 1, {1}, {1})",
     AK_OP_SET_REAL_INPUT_DERIVATIVES,
     {.vr = (const fmi2ValueReference[]){9}, .nvr = 1, .values2 = (fmi2Integer[]){1},
      .values = (fmi2Real[]){1.0}},
     fmi2Error,
     "fmi2SetRealInputDerivatives: vr[0] = 9 is omega_fixed[1], an output; "
     "expected an input", false},
    {STEP_COMPLETE, "fmi2SetRealInputDerivatives(c, {0, 1}, 2, {1, 3}, {1, 1})",
     AK_OP_SET_REAL_INPUT_DERIVATIVES,
     {.vr = (const fmi2ValueReference[]){0, 1}, .nvr = 2, .values2 = (fmi2Integer[]){1, 3},
      .values = (fmi2Real[]){1.0, 1.0}},
     fmi2Error,
     "fmi2SetRealInputDerivatives: order[1] = 3 for theta[2]: this FMU "
     "takes orders 1 to 2; no derivative set", false},
    {INITIALIZATION_MODE, "fmi2SetRealInputDerivatives(c, {0}, 1, {0}, {1})",
     AK_OP_SET_REAL_INPUT_DERIVATIVES,
     {.vr = (const fmi2ValueReference[]){0}, .nvr = 1, .values2 = (fmi2Integer[]){0},
      .values = (fmi2Real[]){1.0}},
     fmi2Error,
     "fmi2SetRealInputDerivatives: order[0] = 0 for theta[1]: this FMU "
     "takes orders 1 to 2; no derivative set", false},
    {STEP_COMPLETE, "fmi2SetRealInputDerivatives(c, {0, 8}, 2, {1, 2}, {1, NAN})",
     AK_OP_SET_REAL_INPUT_DERIVATIVES,
     {.vr = (const fmi2ValueReference[]){0, 8}, .nvr = 2, .values2 = (fmi2Integer[]){1, 2},
      .values = (fmi2Real[]){1.0, NAN}},
     fmi2Error,
     "fmi2SetRealInputDerivatives: derivative of order 2 of theta_ddot[3] = "
     "nan (vr[1] = 8) is not finite; no derivative set", false},
    {STEP_COMPLETE, "fmi2SetRealInputDerivatives(c, {0}, 1, NULL, {1})",
     AK_OP_SET_REAL_INPUT_DERIVATIVES,
     {.vr = (const fmi2ValueReference[]){0}, .nvr = 1, .values = (fmi2Real[]){1.0}}, fmi2Error,
     "fmi2SetRealInputDerivatives: order is NULL with nvr = 1", false},
    {EVENT_MODE, "fmi2SetRealInputDerivatives(c, {0}, 1, {1}, {1})",
     AK_OP_SET_REAL_INPUT_DERIVATIVES,
     {.vr = (const fmi2ValueReference[]){0}, .nvr = 1, .values2 = (fmi2Integer[]){1},
      .values = (fmi2Real[]){1.0}},
     fmi2Error,
     "fmi2SetRealInputDerivatives: a co-simulation function, but this "
     "instance was created for model exchange (fmi2ModelExchange)", false},
    {STEP_COMPLETE, "fmi2GetRealOutputDerivatives(c, {0}, 1, {1}, v)",
     AK_OP_GET_REAL_OUTPUT_DERIVATIVES,
     {.vr = (const fmi2ValueReference[]){0}, .nvr = 1, .values2 = (fmi2Integer[]){1},
      .values = (fmi2Real[1]){0}},
     fmi2Error,
     "fmi2GetRealOutputDerivatives: vr[0] = 0 is theta[1], an input; "
     "expected an output", false},
    {STEP_COMPLETE, "fmi2GetRealOutputDerivatives(c, {9, 10}, 2, {1, 2}, v)",
     AK_OP_GET_REAL_OUTPUT_DERIVATIVES,
     {.vr = (const fmi2ValueReference[]){9, 10}, .nvr = 2, .values2 = (fmi2Integer[]){1, 2},
      .values = (fmi2Real[2]){0}},
     fmi2Error,
     "fmi2GetRealOutputDerivatives: order[1] = 2 for omega_fixed[2]: this "
     "FMU gives order 1 only (maxOutputDerivativeOrder)", false},
    {TERMINATED, "fmi2GetRealOutputDerivatives(c, {9}, 1, {0}, v)",
     AK_OP_GET_REAL_OUTPUT_DERIVATIVES,
     {.vr = (const fmi2ValueReference[]){9}, .nvr = 1, .values2 = (fmi2Integer[]){0},
      .values = (fmi2Real[1]){0}},
     fmi2Error,
     "fmi2GetRealOutputDerivatives: order[0] = 0 for omega_fixed[1]: this "
     "FMU gives order 1 only (maxOutputDerivativeOrder)", false},
    {STEP_COMPLETE, "fmi2GetRealOutputDerivatives(c, {9}, 1, {1}, NULL)",
     AK_OP_GET_REAL_OUTPUT_DERIVATIVES,
     {.vr = (const fmi2ValueReference[]){9}, .nvr = 1, .values2 = (fmi2Integer[]){1}}, fmi2Error,
     "fmi2GetRealOutputDerivatives: value is NULL with nvr = 1", false},
    {INITIALIZATION_MODE, "fmi2GetRealOutputDerivatives(c, {9}, 1, {1}, v)",
     AK_OP_GET_REAL_OUTPUT_DERIVATIVES,
     {.vr = (const fmi2ValueReference[]){9}, .nvr = 1, .values2 = (fmi2Integer[]){1},
      .values = (fmi2Real[1]){0}},
     fmi2Error,
     "fmi2GetRealOutputDerivatives: illegal call in state InitializationMode", false},
};
const size_t AK_N_MODEL_BAD_CALLS = sizeof AK_MODEL_BAD_CALLS / sizeof AK_MODEL_BAD_CALLS[0];
