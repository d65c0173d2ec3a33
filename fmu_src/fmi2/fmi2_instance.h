/* One FMU instance: everything an instance owns lives here, nothing in globals, so any
 * number of instances can live side by side. */
#ifndef ANGULAR_KINEMATICS_FMI2_INSTANCE_H
#define ANGULAR_KINEMATICS_FMI2_INSTANCE_H

#include <stdbool.h>

#include "fmi2Functions.h"
#include "model.h"
#include "model_outputs.h"

/* The FMI 2.0 co-simulation and model-exchange states, one bit each so that a set of them is a
 * mask. Instantiated, InitializationMode and Terminated are common to both interfaces; the
 * Step* states are co-simulation's, EventMode and ContinuousTimeMode model exchange's.
 * StepInProgress and StepCanceled belong to asynchronous stepping, which this FMU does not
 * offer; they appear in the masks to keep the table the standard's. */
typedef enum {
    AK_STATE_INSTANTIATED = 1 << 0,
    AK_STATE_INITIALIZATION_MODE = 1 << 1,
    AK_STATE_STEP_COMPLETE = 1 << 2,
    AK_STATE_STEP_IN_PROGRESS = 1 << 3,
    AK_STATE_STEP_FAILED = 1 << 4,
    AK_STATE_STEP_CANCELED = 1 << 5,
    AK_STATE_TERMINATED = 1 << 6,
    AK_STATE_EVENT_MODE = 1 << 7,
    AK_STATE_CONTINUOUS_TIME_MODE = 1 << 8
} ak_state;

/* What a get or set of a Real value reference involves, in increasing order of what a get must
 * bring up to date. */
typedef enum {
    AK_REAL_ABSENT = 0, /* no Real variable has this value reference */
    AK_REAL_INPUT,
    AK_REAL_PARAMETER,
    AK_REAL_MAIN_OUTPUT,
    AK_REAL_LAZY_OUTPUT,
    AK_REAL_DERIVED_OUTPUT,
    AK_N_REAL_ROLES
} ak_real_role;

/* A Real get split into runs of consecutive value references (at most AK_MAX_RUNS). */
enum { AK_MAX_RUNS = 8 };
typedef struct {
    size_t nvr; /* 0: none kept */
    fmi2ValueReference vr[AK_MAX_VARIABLES];
    size_t n_runs;
    size_t lengths[AK_MAX_RUNS];
    unsigned int roles; /* 1 << role for each role read (ak_real_role) */
} ak_get_runs;

typedef struct ak_instance_s {
    fmi2CallbackFunctions functions; /* a copy: the master's struct need not outlive the call */
    char *instance_name;
    bool logging_on_at_instantiation;
    bool log_enabled[AK_N_LOG_CATEGORIES];

    fmi2Type fmu_type; /* which interface the instance was created for */
    ak_state state;
    double time;
    bool stop_time_defined;
    double stop_time;

    /* The role of each value reference, from the model's variable table (ak_instance_reset):
     * the getter and setter read one byte per value instead of a variable's record. */
    unsigned char real_role[AK_MAX_VARIABLES];
    /* roles_before[role][vr]: how many value references below vr have that role. A get of
     * consecutive value references (what fmpy and most masters ask for) learns the roles of the
     * whole run from two entries per role instead of a lookup per value. */
    unsigned char roles_before[AK_N_REAL_ROLES][AK_MAX_VARIABLES + 1];
    /* Values by value reference, input derivatives and the logger, as the model sees them. */
    ak_model_data data;
    /* When the outputs are computed (models/model_outputs.h); on a failed evaluation a read
     * answers fmi2Discard until an input changes. */
    ak_outputs outputs;
    /* FMU states made by this instance and not yet freed (fmi2_fmu_state.c). */
    struct ak_fmu_state_s *live_states;
    /* The last fmi2GetReal that read a few runs of consecutive value references rather than one
     * (fmpy's record of every output skips the parameters among them), so that the same request
     * at the next step costs one comparison (fmi2_values.c). */
    ak_get_runs last_runs;
} ak_instance;

/* The role of a value reference in a Real get or set (AK_REAL_ABSENT for any out of range). */
static inline ak_real_role ak_real_role_of(const ak_instance *instance, unsigned int vr) {
    return vr < AK_MAX_VARIABLES ? (ak_real_role)instance->real_role[vr] : AK_REAL_ABSENT;
}

/* Of the value references first .. first + n - 1 (first + n <= AK_MAX_VARIABLES), the roles that
 * decide what a get does (absent: refused; an output group: brought up to date), one bit
 * (1 << role) per role present; inputs and parameters, which need nothing, are not looked at. */
static inline unsigned int ak_real_roles_of_run(const ak_instance *instance, unsigned int first,
                                                size_t n) {
    static const ak_real_role DECIDING[] = {AK_REAL_ABSENT, AK_REAL_MAIN_OUTPUT,
                                            AK_REAL_LAZY_OUTPUT, AK_REAL_DERIVED_OUTPUT};
    unsigned int roles = 0;
    for (size_t k = 0; k < sizeof DECIDING / sizeof DECIDING[0]; k++) {
        const unsigned char *before = instance->roles_before[DECIDING[k]];
        roles |= (unsigned int)(before[first + n] != before[first]) << DECIDING[k];
    }
    return roles;
}

/* Frees the FMU states the master did not free (fmi2FreeInstance). */
void ak_free_all_fmu_states(ak_instance *instance);

/* Puts the instance in its just-instantiated condition (used by fmi2Instantiate and fmi2Reset). */
void ak_instance_reset(ak_instance *instance);

/* Brings the main output group up to date with the inputs, running the model only if an input
 * or parameter changed; returns the status of the evaluation the outputs come from. */
ak_eval_status ak_instance_update_outputs(ak_instance *instance);

/* The same, and the lazy output group too. */
ak_eval_status ak_instance_update_all_outputs(ak_instance *instance);

/* The same, and the derived outputs too (models/model.h, ak_derived_outputs). */
ak_eval_status ak_instance_update_derived_outputs(ak_instance *instance);

/* The FMI status a read of outputs returns after an evaluation with that result: fmi2OK,
 * fmi2Warning, or fmi2Discard when it failed (both interfaces; see fmi2_instance.c). */
fmi2Status ak_instance_read_status(const ak_instance *instance, ak_eval_status status);

/* True when vr is one of the model's continuous states. */
bool ak_is_state(unsigned int vr);

/* Marks every output stale (an input or parameter changed). */
static inline void ak_instance_inputs_changed(ak_instance *instance) {
    ak_outputs_inputs_changed(&instance->outputs);
}

#endif
