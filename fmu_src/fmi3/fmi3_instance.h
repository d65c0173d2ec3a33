/* One FMI 3.0 instance: everything an instance owns lives here, nothing in globals. The model
 * sees only its ak_model_data (models/model.h), the same as under the FMI 2 layer. */
#ifndef ANGULAR_KINEMATICS_FMI3_INSTANCE_H
#define ANGULAR_KINEMATICS_FMI3_INSTANCE_H

#include <stdbool.h>

#include "fmi3Functions.h"
#include "model.h"
#include "model_outputs.h"

/* The FMI 3.0 states (section 3.2 model exchange, 4.2 co-simulation), one bit each so that a set
 * of them is a mask. ConfigurationMode and ReconfigurationMode exist only for structural
 * parameters, which these models do not have: they appear in the table to keep it the
 * standard's, and no instance ever enters them. */
typedef enum {
    AK3_STATE_INSTANTIATED = 1 << 0,
    AK3_STATE_CONFIGURATION_MODE = 1 << 1,
    AK3_STATE_INITIALIZATION_MODE = 1 << 2,
    AK3_STATE_EVENT_MODE = 1 << 3,
    AK3_STATE_STEP_MODE = 1 << 4,
    AK3_STATE_CONTINUOUS_TIME_MODE = 1 << 5,
    AK3_STATE_RECONFIGURATION_MODE = 1 << 6,
    AK3_STATE_TERMINATED = 1 << 7
} ak3_state;

typedef enum { AK3_MODEL_EXCHANGE = 0, AK3_CO_SIMULATION = 1 } ak3_interface;

typedef struct ak3_instance_s {
    char *instance_name;
    fmi3InstanceEnvironment environment;
    fmi3LogMessageCallback log_message;
    bool logging_on_at_instantiation;
    bool log_enabled[AK_N_LOG_CATEGORIES];

    ak3_interface interface;
    ak3_state state;
    double time;
    bool stop_time_defined;
    double stop_time;

    /* Values by value reference (an array at values[vr ..]), and the logger, as the model sees
     * them. FMI 3 has no input derivatives: data.input_derivatives stay zero. */
    ak_model_data data;
    /* When the outputs are computed (models/model_outputs.h), as in the FMI 2 layer. */
    ak_outputs outputs;
    /* FMU states made by this instance and not yet freed (fmi3_fmu_state.c). */
    struct ak3_fmu_state_s *live_states;
} ak3_instance;

/* Puts the instance in its just-instantiated condition (instantiation and fmi3Reset). */
void ak3_instance_reset(ak3_instance *instance);

/* Frees the FMU states the importer did not free (fmi3FreeInstance). */
void ak3_free_all_fmu_states(ak3_instance *instance);

/* Brings the main output group (and with _all the lazy one) up to date with the inputs,
 * evaluating only if an input or parameter changed; returns the status the outputs come from. */
ak_eval_status ak3_instance_update_outputs(ak3_instance *instance);
ak_eval_status ak3_instance_update_all_outputs(ak3_instance *instance);
/* The groups up to `upto` (AK_GROUP_DERIVED: every output). */
ak_eval_status ak3_instance_update_outputs_upto(ak3_instance *instance, ak_group upto);

/* fmi3OK, fmi3Warning, or fmi3Discard for an evaluation that failed (outputs of the last
 * successful one). */
fmi3Status ak3_read_status(ak_eval_status status);

/* True when the value reference is the first element of a continuous state (an FMI 3 array). */
static inline bool ak3_is_state(unsigned int vr) {
    for (int k = 0; k < AK_MODEL.n_states; k++) {
        if (AK_MODEL.state_vrs[k] == vr) {
            return true;
        }
    }
    return false;
}

static inline void ak3_instance_inputs_changed(ak3_instance *instance) {
    ak_outputs_inputs_changed(&instance->outputs);
}

#endif
