/* Helpers shared by the C tests of the FMI layer: create an instance, bring it to a state of the
 * standard's state machine, and tell whether a call left it untouched. They link the FMU's
 * sources, so they can look inside the instance. */
#ifndef ANGULAR_KINEMATICS_FMI2_TEST_INSTANCE_H
#define ANGULAR_KINEMATICS_FMI2_TEST_INSTANCE_H

#include <stdbool.h>

#include "fmi2Functions.h"
#include "fmi2_layer.h"
#include "fmi2_test_ops.h"

/* The inputs every test instance is initialized with: the first AK_MODEL.n_inputs of these values
 * go to the model's inputs, value references 0 to n_inputs - 1 (every model's inputs hold those,
 * models/model.h): AngularKinematics theta, theta_dot, theta_ddot; EulerRates theta, omega,
 * omega_dot (far from its singular theta[2]); AttitudePropagator omega, omega_dot (the first
 * six). Arrays of inputs are sized AK_TEST_MAX_INPUTS and hold ak_test_n_inputs() values. */
enum { AK_TEST_MAX_INPUTS = AK_MAX_INPUTS };
extern const fmi2Real AK_TEST_INPUTS[AK_TEST_MAX_INPUTS];
extern const fmi2ValueReference AK_TEST_INPUT_VRS[AK_TEST_MAX_INPUTS];
static inline size_t ak_test_n_inputs(void) { return (size_t)AK_MODEL.n_inputs; }

/* How an instance of this model fails a step, if it can: brought to StepComplete, these inputs
 * set, then fmi2DoStep from AK_TEST_STEP_COMPLETE_TIME by 0.5 answers fmi2Discard and leaves it
 * in StepFailed. n = 0: no step of the model can fail (StepFailed unreachable). Each model's
 * tests/c/fmi2_bad_input_<model>.c defines it with its rows. */
typedef struct {
    size_t n;
    fmi2ValueReference vr[3];
    fmi2Real value[3];
} ak_test_failing_step;
extern const ak_test_failing_step AK_TEST_FAILING_STEP;
/* theta[2] (value reference 1) at EulerRates' singularity for its default sequence body123. */
#define AK_TEST_SINGULAR_THETA2 1.5707963267948966
/* Set up with startTime 0 and stopTime 10; StepComplete is reached by one step from 0 to 1. */
#define AK_TEST_STOP_TIME 10.0
#define AK_TEST_STEP_COMPLETE_TIME 1.0

/* A co-simulation instance of the model the program is built with (AK_MODEL), or a
 * model-exchange one when `state` has AK_ME (ak_test_instantiate_for). */
fmi2Component ak_test_instantiate(const char *name, const fmi2CallbackFunctions *functions,
                                  bool logging_on);
fmi2Component ak_test_instantiate_for(unsigned int state, const char *name,
                                      const fmi2CallbackFunctions *functions, bool logging_on);

/* From Instantiated to `state` by legal calls; false if any of them fails. Co-simulation:
 * AK_IN_INSTANTIATED, _INITIALIZATION_MODE, _STEP_COMPLETE (a step from 0 to 1), _STEP_FAILED
 * (then the failing step of AK_TEST_FAILING_STEP: models that can fail a step only),
 * _TERMINATED. Model exchange (state | AK_ME): AK_IN_INSTANTIATED, _INITIALIZATION_MODE,
 * _EVENT_MODE, _CONTINUOUS_TIME_MODE, _TERMINATED. */
bool ak_test_bring_to(fmi2Component c, unsigned int state);

/* The states a test instance can be brought to, each with AK_ME for model exchange. */
extern const unsigned int AK_TEST_STATES[];
extern const int AK_TEST_N_STATES;
/* True for a state of AK_TEST_STATES this model can reach (StepFailed: a model with a failing
 * step, AK_TEST_FAILING_STEP). */
bool ak_test_state_reachable(unsigned int state);

/* Bit-for-bit copy of an instance, to compare with after a call that must change nothing. */
typedef struct {
    ak_instance copy;
} ak_snapshot;

void ak_snapshot_take(ak_snapshot *snapshot, fmi2Component c);
bool ak_snapshot_unchanged(const ak_snapshot *snapshot, fmi2Component c);
/* The same inputs, parameters, input derivatives and time. What a call answered with
 * fmi2Discard may change: the cache of the lazy evaluation, EulerRates' output
 * singularity_distance, which is always the current one (the evaluation failed, the other
 * outputs keep their last valid values: ak_test_outputs_consistent checks them), and, for
 * fmi2DoStep, the state (StepFailed). */
bool ak_snapshot_same_inputs(const ak_snapshot *snapshot, fmi2Component c);

/* True when the instance's Real variables, read through fmi2GetReal, are bit for bit what a
 * fresh evaluation of the model computes from the instance's inputs and parameters (or, after
 * a failed evaluation, the last valid outputs with fmi2Discard): the lazy evaluation never serves
 * stale outputs. For AngularKinematics with sequence body123, the main outputs are also compared
 * with the hand-written core ak_angular_kinematics_123. */
bool ak_test_outputs_consistent(fmi2Component c);

/* The standard's name of a state (without the interface), and the same with " (ME)" for a
 * model-exchange instance in the states both interfaces have (for the table). */
/* The value references of the main output group, in value-reference order; how many. */
size_t ak_test_main_outputs(fmi2ValueReference out[AK_MAX_VARIABLES]);

/* True when value references 0 to 20 are the inputs and outputs of the hand-written 1-2-3 kernel
 * (theta, theta_dot, theta_ddot; omega_fixed, omega_body, alpha_fixed, alpha_body): a model with
 * that layout and the sequence body123 is compared with ak_angular_kinematics_123 too. */
bool ak_test_has_kinematics_123_layout(void);

/* Whether libm's sin and cos of the three angles are, to the bit, the project's own
 * (fmu_src/elementary/, which the FMU uses): only then can the hand-written 1-2-3 closed form
 * (kinematics_123.c, which keeps libm's as a fixed anchor) match the FMU bit for bit. */
bool ak_test_libm_sines_agree(const double theta[3]);
/* True when theta[2] is the input of value reference 1 and the model reports its distance to a
 * singularity (singularity_distance): it warns near the singular theta[2] and discards a step at
 * it (AK_TEST_SINGULAR_THETA2). */
bool ak_test_has_singular_theta2(void);

/* The value reference of the variable of that name (the test fails hard if there is none). */
fmi2ValueReference ak_test_vr(const char *name);
/* The same for a variable the model may not have: false when it has none. */
bool ak_test_find_vr(const char *name, fmi2ValueReference *vr);

const char *ak_test_state_name(unsigned int state);
const char *ak_test_state_label(unsigned int state);

#endif
