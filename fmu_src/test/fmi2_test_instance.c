/* See fmi2_test_instance.h. */
#include "fmi2_test_instance.h"

#include <string.h>

#include "kinematics.h"

const fmi2Real AK_TEST_INPUTS[AK_N_INPUTS] = {0.3, -0.7, 1.1, 0.5, -1.5, 2.0, 3.0, -0.25, 0.8};

fmi2Component ak_test_instantiate(const char *name, const fmi2CallbackFunctions *functions,
                                  bool logging_on) {
    return fmi2Instantiate(name, fmi2CoSimulation, AK_GUID, "file:///unused", functions,
                           fmi2False, logging_on ? fmi2True : fmi2False);
}

bool ak_test_bring_to(fmi2Component c, unsigned int state) {
    if (state == AK_IN_INSTANTIATED) {
        return true;
    }
    static const fmi2ValueReference inputs[AK_N_INPUTS] = {0, 1, 2, 3, 4, 5, 6, 7, 8};
    if (fmi2SetupExperiment(c, fmi2False, 0.0, 0.0, fmi2True, AK_TEST_STOP_TIME) != fmi2OK ||
        fmi2EnterInitializationMode(c) != fmi2OK ||
        fmi2SetReal(c, inputs, AK_N_INPUTS, AK_TEST_INPUTS) != fmi2OK) {
        return false;
    }
    if (state == AK_IN_INITIALIZATION_MODE) {
        return true;
    }
    if (fmi2ExitInitializationMode(c) != fmi2OK ||
        fmi2DoStep(c, 0.0, AK_TEST_STEP_COMPLETE_TIME, fmi2True) != fmi2OK) {
        return false;
    }
    if (state == AK_IN_STEP_COMPLETE) {
        return true;
    }
    return state == AK_IN_TERMINATED && fmi2Terminate(c) == fmi2OK;
}

void ak_snapshot_take(ak_snapshot *snapshot, fmi2Component c) {
    memcpy(&snapshot->copy, c, sizeof snapshot->copy);
}

bool ak_snapshot_unchanged(const ak_snapshot *snapshot, fmi2Component c) {
    return memcmp(&snapshot->copy, c, sizeof snapshot->copy) == 0;
}

bool ak_test_outputs_consistent(fmi2Component c) {
    const ak_instance *instance = c;
    double expected[AK_N_VARIABLES];
    memcpy(expected, instance->values, sizeof expected);
    double *e = expected;
    ak_angular_kinematics_123(&e[AK_VR_THETA], &e[AK_VR_THETA_DOT], &e[AK_VR_THETA_DDOT],
                              &e[AK_VR_OMEGA_FIXED], &e[AK_VR_OMEGA_BODY], &e[AK_VR_ALPHA_FIXED],
                              &e[AK_VR_ALPHA_BODY]);
    fmi2ValueReference all[AK_N_VARIABLES];
    for (unsigned int vr = 0; vr < AK_N_VARIABLES; vr++) {
        all[vr] = vr;
    }
    double got[AK_N_VARIABLES];
    return fmi2GetReal(c, all, AK_N_VARIABLES, got) == fmi2OK &&
           memcmp(got, expected, sizeof got) == 0;
}

const char *ak_test_state_name(unsigned int state) {
    switch (state) {
    case AK_IN_INSTANTIATED: return "Instantiated";
    case AK_IN_INITIALIZATION_MODE: return "InitializationMode";
    case AK_IN_STEP_COMPLETE: return "StepComplete";
    case AK_IN_STEP_IN_PROGRESS: return "StepInProgress";
    case AK_IN_STEP_FAILED: return "StepFailed";
    case AK_IN_STEP_CANCELED: return "StepCanceled";
    case AK_IN_TERMINATED: return "Terminated";
    }
    return "(no instance)";
}
