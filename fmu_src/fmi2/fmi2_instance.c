/* Instance initial condition and the lazy evaluation of the outputs. */
#include "fmi2_instance.h"

#include "fmi2_logging.h"

/* The model's messages go out through the instance's logger, with the FMI 2 status. */
static void log_for_model(void *owner, ak_log_category category, ak_status status,
                          const char *message) {
    static const fmi2Status STATUS[] = {fmi2OK, fmi2Warning, fmi2Discard, fmi2Error};
    ak_log((const ak_instance *)owner, category, STATUS[status], "%s", message);
}

static ak_real_role real_role(const ak_variable *variable) {
    if (variable == NULL || variable->type != AK_TYPE_REAL) {
        return AK_REAL_ABSENT;
    }
    switch (variable->causality) {
    case AK_CAUSALITY_INPUT:
        return AK_REAL_INPUT;
    case AK_CAUSALITY_PARAMETER:
        return AK_REAL_PARAMETER;
    case AK_CAUSALITY_OUTPUT:
    default:
        return variable->group == AK_GROUP_DERIVED ? AK_REAL_DERIVED_OUTPUT
               : variable->group == AK_GROUP_LAZY  ? AK_REAL_LAZY_OUTPUT
                                                   : AK_REAL_MAIN_OUTPUT;
    }
}

void ak_instance_reset(ak_instance *instance) {
    ak_log_categories_reset(instance->log_enabled, instance->logging_on_at_instantiation);
    instance->data.log = log_for_model;
    instance->data.owner = instance;
    instance->state = AK_STATE_INSTANTIATED;
    instance->time = 0.0;
    instance->stop_time_defined = false;
    instance->stop_time = 0.0;
    instance->last_runs.nvr = 0;
    for (int vr = 0; vr < AK_MAX_VARIABLES; vr++) {
        instance->real_role[vr] = (unsigned char)real_role(ak_variable_of((unsigned int)vr));
    }
    for (int role = 0; role < AK_N_REAL_ROLES; role++) {
        instance->roles_before[role][0] = 0;
        for (int vr = 0; vr < AK_MAX_VARIABLES; vr++) {
            instance->roles_before[role][vr + 1] = (unsigned char)(instance->roles_before[role][vr] +
                                                                   (instance->real_role[vr] == role));
        }
    }
    ak_model_data_reset(&instance->data);
    ak_outputs_reset(&instance->outputs);
}

bool ak_is_state(unsigned int vr) {
    for (int k = 0; k < AK_MODEL.n_states; k++) {
        if (AK_MODEL.state_vrs[k] == vr) {
            return true;
        }
    }
    return false;
}

/* The outputs up to date (models/model_outputs.c), what ran traced in logCalls. */
static ak_eval_status update(ak_instance *instance, ak_group upto) {
    unsigned int ran;
    const bool in_initialization =
        (instance->state & (AK_STATE_INSTANTIATED | AK_STATE_INITIALIZATION_MODE)) != 0;
    const ak_eval_status status =
        ak_outputs_update(&instance->outputs, &instance->data, in_initialization, upto, &ran);
    if (ran != 0 && ak_log_on(instance, AK_LOG_CALLS)) {
        if (ran & AK_RAN_MAIN) {
            ak_log(instance, AK_LOG_CALLS, fmi2OK, "kinematics evaluated (evaluation %lu%s)",
                   instance->outputs.evaluations,
                   (ran & AK_RAN_ALL) ? ", with the lazy outputs" : "");
        }
        if (ran & AK_RAN_LAZY) {
            ak_log(instance, AK_LOG_CALLS, fmi2OK, "lazy outputs evaluated");
        }
        if (ran & AK_RAN_DERIVED) {
            ak_log(instance, AK_LOG_CALLS, fmi2OK, "derived outputs evaluated");
        }
    }
    return status;
}

ak_eval_status ak_instance_update_outputs(ak_instance *instance) {
    return update(instance, AK_GROUP_MAIN);
}

ak_eval_status ak_instance_update_all_outputs(ak_instance *instance) {
    return update(instance, AK_GROUP_LAZY);
}

ak_eval_status ak_instance_update_derived_outputs(ak_instance *instance) {
    return update(instance, AK_GROUP_DERIVED);
}

fmi2Status ak_instance_read_status(const ak_instance *instance, ak_eval_status status) {
    switch (status) {
    case AK_EVAL_OK:
        return fmi2OK;
    case AK_EVAL_WARNING:
        return fmi2Warning;
    case AK_EVAL_FAILED:
    default:
        /* FMI 2.0.4, 2.1.3: fmi2Discard is the model-exchange answer to "a function is outside
         * of its domain", and for co-simulation the master "has to decide if the simulation run
         * can be continued"; fmi2Error would make the instance unusable, which it is not. */
        (void)instance;
        return fmi2Discard;
    }
}
