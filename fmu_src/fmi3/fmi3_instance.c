/* FMI 3 instance initial condition and the lazy evaluation of the outputs. */
#include "fmi3_instance.h"

#include "fmi3_logging.h"

/* The model's messages go out through the instance's logger, with the FMI 3 status. */
static void log_for_model(void *owner, ak_log_category category, ak_status status,
                          const char *message) {
    static const fmi3Status STATUS[] = {fmi3OK, fmi3Warning, fmi3Discard, fmi3Error};
    ak3_log((const ak3_instance *)owner, category, STATUS[status], "%s", message);
}

void ak3_instance_reset(ak3_instance *instance) {
    ak_log_categories_reset(instance->log_enabled, instance->logging_on_at_instantiation);
    instance->data.log = log_for_model;
    instance->data.owner = instance;
    instance->state = AK3_STATE_INSTANTIATED;
    instance->time = 0.0;
    instance->stop_time_defined = false;
    instance->stop_time = 0.0;
    ak_model_data_reset(&instance->data);
    ak_outputs_reset(&instance->outputs);
}

/* The outputs up to date (models/model_outputs.c), an evaluation traced in logCalls. */
static ak_eval_status update(ak3_instance *instance, ak_group upto) {
    unsigned int ran;
    const bool in_initialization =
        (instance->state & (AK3_STATE_INSTANTIATED | AK3_STATE_INITIALIZATION_MODE)) != 0;
    const ak_eval_status status =
        ak_outputs_update(&instance->outputs, &instance->data, in_initialization, upto, &ran);
    if ((ran & AK_RAN_MAIN) && ak3_log_on(instance, AK_LOG_CALLS)) {
        ak3_log(instance, AK_LOG_CALLS, fmi3OK, "kinematics evaluated (evaluation %lu%s)",
                instance->outputs.evaluations, (ran & AK_RAN_ALL) ? ", with the lazy outputs" : "");
    }
    return status;
}

ak_eval_status ak3_instance_update_outputs(ak3_instance *instance) {
    return update(instance, AK_GROUP_MAIN);
}

ak_eval_status ak3_instance_update_all_outputs(ak3_instance *instance) {
    return update(instance, AK_GROUP_LAZY);
}

ak_eval_status ak3_instance_update_outputs_upto(ak3_instance *instance, ak_group upto) {
    return update(instance, upto);
}

fmi3Status ak3_read_status(ak_eval_status status) {
    switch (status) {
    case AK_EVAL_OK:
        return fmi3OK;
    case AK_EVAL_WARNING:
        return fmi3Warning;
    case AK_EVAL_FAILED:
    default:
        /* As in FMI 2: the function is outside its domain, the instance stays usable. */
        return fmi3Discard;
    }
}
