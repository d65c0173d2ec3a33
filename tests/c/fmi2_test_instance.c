/* See fmi2_test_instance.h. */
#include "fmi2_test_instance.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "elementary.h"
#include "kinematics_123.h"

_Static_assert(AK_TEST_MAX_INPUTS == 24, "24 values below, one per input of the largest model");
const fmi2Real AK_TEST_INPUTS[AK_TEST_MAX_INPUTS] = {
    0.3, -0.7, 1.1, 0.5, -1.5, 2.0, 3.0, -0.25, 0.8, 0.9, -1.2, 0.4,
    1.7, -0.6, 0.2, -0.35, 0.15, 0.05, 0.01, -0.02, 0.03, 0.0, 0.0, -9.81};
const fmi2ValueReference AK_TEST_INPUT_VRS[AK_TEST_MAX_INPUTS] = {
    0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23};

const unsigned int AK_TEST_STATES[] = {
    AK_IN_INSTANTIATED,           AK_IN_INITIALIZATION_MODE,
    AK_IN_STEP_COMPLETE,          AK_IN_STEP_FAILED,
    AK_IN_TERMINATED,             AK_ME | AK_IN_INSTANTIATED,
    AK_ME | AK_IN_INITIALIZATION_MODE, AK_ME | AK_IN_EVENT_MODE,
    AK_ME | AK_IN_CONTINUOUS_TIME_MODE, AK_ME | AK_IN_TERMINATED};
const int AK_TEST_N_STATES = (int)(sizeof AK_TEST_STATES / sizeof AK_TEST_STATES[0]);

bool ak_test_state_reachable(unsigned int state) {
    return state != AK_IN_STEP_FAILED || AK_TEST_FAILING_STEP.n > 0;
}

fmi2Component ak_test_instantiate_for(unsigned int state, const char *name,
                                      const fmi2CallbackFunctions *functions, bool logging_on) {
    return fmi2Instantiate(name, (state & AK_ME) ? fmi2ModelExchange : fmi2CoSimulation,
                           AK_MODEL.guid, "file:///unused", functions, fmi2False,
                           logging_on ? fmi2True : fmi2False);
}

fmi2Component ak_test_instantiate(const char *name, const fmi2CallbackFunctions *functions,
                                  bool logging_on) {
    return ak_test_instantiate_for(AK_IN_INSTANTIATED, name, functions, logging_on);
}

bool ak_test_bring_to(fmi2Component c, unsigned int state) {
    const unsigned int s = state & ~(unsigned int)AK_ME;
    if (s == AK_IN_INSTANTIATED) {
        return true;
    }
    if (fmi2SetupExperiment(c, fmi2False, 0.0, 0.0, fmi2True, AK_TEST_STOP_TIME) != fmi2OK ||
        fmi2EnterInitializationMode(c) != fmi2OK ||
        fmi2SetReal(c, AK_TEST_INPUT_VRS, ak_test_n_inputs(), AK_TEST_INPUTS) != fmi2OK) {
        return false;
    }
    if (s == AK_IN_INITIALIZATION_MODE) {
        return true;
    }
    if (fmi2ExitInitializationMode(c) != fmi2OK) {
        return false;
    }
    if (state & AK_ME) { /* now in EventMode */
        if (s == AK_IN_EVENT_MODE) {
            return true;
        }
        if (s == AK_IN_CONTINUOUS_TIME_MODE) {
            return fmi2EnterContinuousTimeMode(c) == fmi2OK;
        }
        return s == AK_IN_TERMINATED && fmi2Terminate(c) == fmi2OK;
    }
    if (fmi2DoStep(c, 0.0, AK_TEST_STEP_COMPLETE_TIME, fmi2True) != fmi2OK) {
        return false;
    }
    if (s == AK_IN_STEP_COMPLETE) {
        return true;
    }
    if (s == AK_IN_STEP_FAILED) {
        return AK_TEST_FAILING_STEP.n > 0 &&
               fmi2SetReal(c, AK_TEST_FAILING_STEP.vr, AK_TEST_FAILING_STEP.n,
                           AK_TEST_FAILING_STEP.value) == fmi2OK &&
               fmi2DoStep(c, AK_TEST_STEP_COMPLETE_TIME, 0.5, fmi2True) == fmi2Discard;
    }
    return s == AK_IN_TERMINATED && fmi2Terminate(c) == fmi2OK;
}

void ak_snapshot_take(ak_snapshot *snapshot, fmi2Component c) {
    memcpy(&snapshot->copy, c, sizeof snapshot->copy);
}

bool ak_snapshot_unchanged(const ak_snapshot *snapshot, fmi2Component c) {
    return memcmp(&snapshot->copy, c, sizeof snapshot->copy) == 0;
}

bool ak_snapshot_same_inputs(const ak_snapshot *snapshot, fmi2Component c) {
    const ak_instance *was = &snapshot->copy, *now = c;
    for (int vr = 0; vr < AK_MODEL.n_value_references; vr++) {
        const ak_variable *variable = ak_variable_of((unsigned int)vr);
        if (variable != NULL && variable->causality != AK_CAUSALITY_OUTPUT &&
            memcmp(&was->data.values[vr], &now->data.values[vr], sizeof was->data.values[vr])) {
            return false;
        }
    }
    return memcmp(was->data.input_derivatives, now->data.input_derivatives,
                  sizeof was->data.input_derivatives) == 0 &&
           memcmp(&was->time, &now->time, sizeof was->time) == 0;
}

bool ak_test_libm_sines_agree(const double theta[3]) {
    for (int k = 0; k < 3; k++) {
        double s, co;
        ak_sincos(theta[k], &s, &co);
        if (memcmp(&s, &(double){sin(theta[k])}, sizeof s) != 0 ||
            memcmp(&co, &(double){cos(theta[k])}, sizeof co) != 0) {
            return false;
        }
    }
    return true;
}

bool ak_test_outputs_consistent(fmi2Component c) {
    const ak_instance *instance = c;
    /* The expected values: a fresh evaluation on a copy (logging off: the FMU's own read logs
     * whatever the model has to say). */
    ak_instance fresh = *instance;
    for (int category = 0; category < AK_N_LOG_CATEGORIES; category++) {
        fresh.log_enabled[category] = false;
    }
    ak_eval_status expected_status = fresh.outputs.status;
    if (fresh.outputs.stale) {
        /* Until fmi2ExitInitializationMode the states follow the parameters they start from
         * (ak_instance_update): a model that cannot start from them fails the read. */
        const bool initializing =
            AK_MODEL.initialize != NULL &&
            (fresh.state & (AK_INSTANTIATED | AK_INITIALIZATION_MODE)) != 0;
        expected_status = initializing && AK_MODEL.initialize(&fresh.data) == AK_EVAL_FAILED
                              ? AK_EVAL_FAILED
                              : AK_MODEL.evaluate(&fresh.data);
    }
    if (expected_status != AK_EVAL_FAILED && AK_MODEL.evaluate_lazy != NULL) {
        AK_MODEL.evaluate_lazy(&fresh.data);
    }
    if (expected_status != AK_EVAL_FAILED) {
        ak_model_compute_derived(&fresh.data);
    }
    fmi2ValueReference all[AK_MAX_VARIABLES];
    size_t n = 0;
    for (int vr = 0; vr < AK_MODEL.n_value_references; vr++) {
        const ak_variable *variable = ak_variable_of((unsigned int)vr);
        if (variable != NULL && variable->type == AK_TYPE_REAL) {
            all[n++] = (fmi2ValueReference)vr;
        }
    }
    double got[AK_MAX_VARIABLES];
    const fmi2Status status = fmi2GetReal(c, all, n, got);
    const fmi2Status expected = expected_status == AK_EVAL_OK        ? fmi2OK
                                : expected_status == AK_EVAL_WARNING ? fmi2Warning
                                                                     : fmi2Discard;
    if (status != expected) {
        return false;
    }
    for (size_t i = 0; i < n; i++) {
        if (memcmp(&got[i], &fresh.data.values[all[i]], sizeof got[i]) != 0) {
            return false;
        }
    }
    if (ak_test_has_kinematics_123_layout() &&
        instance->data.values[ak_test_vr("sequence")] == 1.0 && ak_test_libm_sines_agree(got)) {
        double e[21];
        memcpy(e, got, 9 * sizeof e[0]);
        ak_angular_kinematics_123(&e[0], &e[3], &e[6], &e[9], &e[12], &e[15], &e[18]);
        /* Bit for bit, but for the sign of an exact zero: the general kernel adds structurally
         * zero terms (+0) that the closed form leaves out (CHANGELOG 0.3.0). */
        for (int k = 0; k < 21; k++) {
            if (memcmp(&e[k], &got[k], sizeof e[k]) != 0 && !(e[k] == 0.0 && got[k] == 0.0)) {
                return false;
            }
        }
    }
    return true;
}

const char *ak_test_state_name(unsigned int state) {
    switch (state & ~(unsigned int)AK_ME) {
    case AK_IN_INSTANTIATED: return "Instantiated";
    case AK_IN_INITIALIZATION_MODE: return "InitializationMode";
    case AK_IN_STEP_COMPLETE: return "StepComplete";
    case AK_IN_STEP_IN_PROGRESS: return "StepInProgress";
    case AK_IN_STEP_FAILED: return "StepFailed";
    case AK_IN_STEP_CANCELED: return "StepCanceled";
    case AK_IN_TERMINATED: return "Terminated";
    case AK_IN_EVENT_MODE: return "EventMode";
    case AK_IN_CONTINUOUS_TIME_MODE: return "ContinuousTimeMode";
    }
    return "(no instance)";
}

const char *ak_test_state_label(unsigned int state) {
    static const char *const me_labels[] = {"Instantiated (ME)", "InitializationMode (ME)",
                                            "EventMode", "ContinuousTimeMode", "Terminated (ME)"};
    if (!(state & AK_ME)) {
        return ak_test_state_name(state);
    }
    switch (state & ~(unsigned int)AK_ME) {
    case AK_IN_INSTANTIATED: return me_labels[0];
    case AK_IN_INITIALIZATION_MODE: return me_labels[1];
    case AK_IN_EVENT_MODE: return me_labels[2];
    case AK_IN_CONTINUOUS_TIME_MODE: return me_labels[3];
    case AK_IN_TERMINATED: return me_labels[4];
    }
    return "(no instance)";
}

size_t ak_test_main_outputs(fmi2ValueReference out[AK_MAX_VARIABLES]) {
    size_t n = 0;
    for (int vr = 0; vr < AK_MODEL.n_value_references; vr++) {
        const ak_variable *variable = ak_variable_of((unsigned int)vr);
        if (variable != NULL && variable->causality == AK_CAUSALITY_OUTPUT &&
            variable->group == AK_GROUP_MAIN) {
            out[n++] = (fmi2ValueReference)vr;
        }
    }
    return n;
}

bool ak_test_find_vr(const char *name, fmi2ValueReference *vr) {
    for (int k = 0; k < AK_MODEL.n_value_references; k++) {
        const ak_variable *variable = ak_variable_of((unsigned int)k);
        if (variable != NULL && strcmp(variable->name, name) == 0) {
            *vr = (fmi2ValueReference)k;
            return true;
        }
    }
    return false;
}

fmi2ValueReference ak_test_vr(const char *name) {
    fmi2ValueReference vr = 0;
    if (!ak_test_find_vr(name, &vr)) {
        fprintf(stderr, "%s has no variable %s\n", AK_MODEL.model_identifier, name);
        exit(1);
    }
    return vr;
}

bool ak_test_has_kinematics_123_layout(void) {
    /* Read from the variable table by value reference, without formatting a name: the
     * consistency check of every step asks it. */
    static const char *const arrays[] = {"theta",       "theta_dot",   "theta_ddot", "omega_fixed",
                                         "omega_body",  "alpha_fixed", "alpha_body"};
    for (int a = 0; a < 7; a++) {
        const size_t length = strlen(arrays[a]);
        for (int k = 0; k < 3; k++) {
            const ak_variable *variable = ak_variable_of((unsigned int)(3 * a + k));
            const char *name = variable != NULL ? variable->name : "";
            if (strncmp(name, arrays[a], length) != 0 || name[length] != '[' ||
                name[length + 1] != (char)('1' + k) || strcmp(&name[length + 2], "]") != 0) {
                return false;
            }
        }
    }
    return true;
}

bool ak_test_has_singular_theta2(void) {
    fmi2ValueReference theta2 = 0, distance = 0;
    return ak_test_find_vr("theta[2]", &theta2) && theta2 == 1 &&
           AK_MODEL.variables[theta2].causality == AK_CAUSALITY_INPUT &&
           ak_test_find_vr("singularity_distance", &distance);
}
