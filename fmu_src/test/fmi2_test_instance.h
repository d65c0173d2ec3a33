/* Helpers shared by the C tests of the FMI layer: create an instance, bring it to a state of the
 * standard's state machine, and tell whether a call left it untouched. They link the FMU's
 * sources, so they can look inside the instance. */
#ifndef ANGULAR_KINEMATICS_FMI2_TEST_INSTANCE_H
#define ANGULAR_KINEMATICS_FMI2_TEST_INSTANCE_H

#include <stdbool.h>

#include "fmi2Functions.h"
#include "fmi2_instance.h"
#include "fmi2_test_ops.h"

/* The inputs every test instance is initialized with (theta, theta_dot, theta_ddot). */
extern const fmi2Real AK_TEST_INPUTS[AK_N_INPUTS];
/* Set up with startTime 0 and stopTime 10; StepComplete is reached by one step from 0 to 1. */
#define AK_TEST_STOP_TIME 10.0
#define AK_TEST_STEP_COMPLETE_TIME 1.0

fmi2Component ak_test_instantiate(const char *name, const fmi2CallbackFunctions *functions,
                                  bool logging_on);

/* From Instantiated to `state` (one of AK_IN_INSTANTIATED, _INITIALIZATION_MODE,
 * _STEP_COMPLETE, _TERMINATED) by legal calls; false if any of them fails. */
bool ak_test_bring_to(fmi2Component c, unsigned int state);

/* Bit-for-bit copy of an instance, to compare with after a call that must change nothing. */
typedef struct {
    ak_instance copy;
} ak_snapshot;

void ak_snapshot_take(ak_snapshot *snapshot, fmi2Component c);
bool ak_snapshot_unchanged(const ak_snapshot *snapshot, fmi2Component c);

/* True when the instance's outputs, read through fmi2GetReal, are bit for bit what the core
 * computes from the instance's inputs. */
bool ak_test_outputs_consistent(fmi2Component c);

const char *ak_test_state_name(unsigned int state);

#endif
