/* The bad-input rows of QuaternionKinematics (see fmi2_bad_input_table.h): its value references
 * (inputs 0 to 11, outputs 12 to 43, parameters sequence 44, tolerance 45), its parameters, the
 * step that fails at the singular configuration, and the capability it does not have (output
 * derivatives). */
#include <math.h>

#include "fmi2_bad_input_table.h"
#include "QuaternionKinematics_variables.h"
#include "fmi2_test_instance.h"

enum {
    INSTANTIATED = AK_IN_INSTANTIATED,
    INITIALIZATION_MODE = AK_IN_INITIALIZATION_MODE,
    STEP_COMPLETE = AK_IN_STEP_COMPLETE,
    STEP_FAILED = AK_IN_STEP_FAILED,
    TERMINATED = AK_IN_TERMINATED,
    EVENT_MODE = AK_ME | AK_IN_EVENT_MODE
};

/* A step fails at the singular configuration: every q with q[1] = q[3] and q[2] = q[4] is
 * theta[2] = pi/2 for the default sequence body123; the test inputs have q[1] = 0.3, q[4] = 0.5. */
const ak_test_failing_step AK_TEST_FAILING_STEP = {2, {QK_VR_Q + 1, QK_VR_Q + 2}, {0.5, 0.3}};

const ak_bad_call AK_MODEL_BAD_CALLS[] = {
    /* --- values ------------------------------------------------------------------------------ */
    {STEP_COMPLETE, "fmi2SetReal(c, {0, @PAST@}, 2, {7, 7})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){0, QK_N_VALUE_REFERENCES}, .nvr = 2, .values = (fmi2Real[]){7.0, 7.0}},
     fmi2Error,
     "fmi2SetReal: vr[1] = @PAST@ is not a value reference of this FMU (0 to @LAST@)", false},
    {STEP_COMPLETE, "fmi2SetReal(c, {12}, 1, {1})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){12}, .nvr = 1, .values = (fmi2Real[]){1.0}}, fmi2Error,
     "fmi2SetReal: vr[0] = 12 is omega_fixed[1], an output: only inputs and parameters can be "
     "set; no value set", false},
    {STEP_COMPLETE, "fmi2SetReal(c, {0, 5}, 2, {2.5, NAN})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){0, 5}, .nvr = 2, .values = (fmi2Real[]){2.5, NAN}},
     fmi2Error,
     "fmi2SetReal: q_dot[2] = nan (vr[1] = 5) is not finite; no value set", false},
    {EVENT_MODE, "fmi2SetReal(c, {11}, 1, {INFINITY})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){11}, .nvr = 1, .values = (fmi2Real[]){INFINITY}},
     fmi2Error,
     "fmi2SetReal: q_ddot[4] = inf (vr[0] = 11) is not finite; no value "
     "set", false},
    {STEP_COMPLETE, "fmi2GetInteger(c, {45}, 1, v)", AK_OP_GET_INTEGER,
     {.vr = (const fmi2ValueReference[]){45}, .nvr = 1, .values = (fmi2Integer[1]){0}},
     fmi2Error,
     "fmi2GetInteger: vr[0] = 45 is tolerance, of type Real, not Integer", false},

    /* --- parameters: sequence (1 to 24), tolerance in [0, 1]; fixed --------------------------- */
    {INSTANTIATED, "fmi2SetInteger(c, {44}, 1, {0})", AK_OP_SET_INTEGER,
     {.vr = (const fmi2ValueReference[]){44}, .nvr = 1, .values = (fmi2Integer[]){0}},
     fmi2Error,
     "fmi2SetInteger: sequence = 0 (vr[0] = 44) is not an item of the "
     "Enumeration Sequence (1 body123 .. 24 space323); no value set", false},
    {INITIALIZATION_MODE, "fmi2SetReal(c, {45}, 1, {-1e-9})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){45}, .nvr = 1, .values = (fmi2Real[]){-1e-9}},
     fmi2Error,
     "fmi2SetReal: tolerance = -1.0000000000000001e-09 (vr[0] = 45) is "
     "outside [0, 1], the range of singularity_distance; no value set", false},
    {INSTANTIATED, "fmi2SetReal(c, {45}, 1, {NAN})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){45}, .nvr = 1, .values = (fmi2Real[]){NAN}}, fmi2Error,
     "fmi2SetReal: tolerance = nan (vr[0] = 45) is not finite; no value set", false},
    {STEP_COMPLETE, "fmi2SetReal(c, {45}, 1, {0.5})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){45}, .nvr = 1, .values = (fmi2Real[]){0.5}}, fmi2Error,
     "fmi2SetReal: tolerance (vr[0] = 45) is a parameter of variability fixed: it can be set "
     "only in Instantiated and InitializationMode, not in StepComplete; no value set", false},
    {EVENT_MODE, "fmi2SetInteger(c, {44}, 1, {2})", AK_OP_SET_INTEGER,
     {.vr = (const fmi2ValueReference[]){44}, .nvr = 1, .values = (fmi2Integer[]){2}},
     fmi2Error,
     "fmi2SetInteger: sequence (vr[0] = 44) is a parameter of variability "
     "fixed: it can be set only in Instantiated and InitializationMode, not "
     "in EventMode; no value set", false},

    /* --- a step that failed at the singular configuration (q = (0.3, 0.5, 0.3, 0.5), body123) - */
    {STEP_FAILED, "fmi2GetReal(c, {37}, 1, v)", AK_OP_GET_REAL,
     {.vr = (const fmi2ValueReference[]){37}, .nvr = 1, .values = (fmi2Real[1]){0}}, fmi2Discard,
     "QuaternionKinematics: theta[2] = 1.5707963267948966 is at the singular configuration of "
     "body123 (theta[2] = +-pi/2): singularity_distance = 6.12323e-17; theta_dot and theta_ddot "
     "are not defined there and keep their last valid values", false},
    {STEP_FAILED, "fmi2DoStep(c, 1, 0.5, fmi2True)", AK_OP_DO_STEP,
     {.real = {1.0, 0.5}, .flag = {fmi2True}}, fmi2Error, "fmi2DoStep: illegal call in state StepFailed", false},
    {STEP_FAILED, "fmi2SetReal(c, {1}, 1, {0})", AK_OP_SET_REAL,
     {.vr = (const fmi2ValueReference[]){1}, .nvr = 1, .values = (fmi2Real[]){0.0}}, fmi2Error,
     "fmi2SetReal: illegal call in state StepFailed", false},

    /* --- the capability QuaternionKinematics does not have ------------------------------------ */
    {STEP_COMPLETE, "fmi2GetRealOutputDerivatives(c, {12}, 1, {1}, v)",
     AK_OP_GET_REAL_OUTPUT_DERIVATIVES,
     {.vr = (const fmi2ValueReference[]){12}, .nvr = 1, .values2 = (fmi2Integer[]){1},
      .values = (fmi2Real[1]){0}},
     fmi2Error,
     "fmi2GetRealOutputDerivatives: not provided by QuaternionKinematics "
     "(modelDescription.xml: maxOutputDerivativeOrder=\"0\")", false},
    {STEP_COMPLETE, "fmi2SetRealInputDerivatives(c, {12}, 1, {1}, {1})",
     AK_OP_SET_REAL_INPUT_DERIVATIVES,
     {.vr = (const fmi2ValueReference[]){12}, .nvr = 1, .values2 = (fmi2Integer[]){1},
      .values = (fmi2Real[]){1.0}},
     fmi2Error,
     "fmi2SetRealInputDerivatives: vr[0] = 12 is omega_fixed[1], an output; "
     "expected an input", false},
};
const size_t AK_N_MODEL_BAD_CALLS = sizeof AK_MODEL_BAD_CALLS / sizeof AK_MODEL_BAD_CALLS[0];
