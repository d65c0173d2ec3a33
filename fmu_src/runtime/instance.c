/* The instance: start, reset, logging, the call check, and the lazy evaluation of the outputs. */
#include "instance.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* Long enough for the longest message (a value reference list is never echoed whole). */
enum { MESSAGE_CAPACITY = 1024 };

void ak_log(const ak_instance *instance, ak_log_category category, ak_status status,
            const char *format, ...) {
    const bool always = status == AK_STATUS_ERROR && instance->layer->errors_always_logged &&
                        instance->has_logger;
    if (!always && !ak_log_on(instance, category)) {
        return;
    }
    char message[MESSAGE_CAPACITY];
    va_list arguments;
    va_start(arguments, format);
    vsnprintf(message, sizeof message, format, arguments);
    va_end(arguments);
    instance->layer->send(instance, category, status, message);
}

void ak_log_without_instance(void (*send)(const void *context, const char *message),
                             const void *context, const char *format, ...) {
    char message[MESSAGE_CAPACITY];
    va_list arguments;
    va_start(arguments, format);
    vsnprintf(message, sizeof message, format, arguments);
    va_end(arguments);
    send(context, message);
}

static void log_for_model(void *owner, ak_log_category category, ak_status status,
                          const char *message) {
    const ak_instance *instance = owner;
    ak_log(instance, category, status, "%s%s%s", instance->calling ? instance->calling : "",
           instance->calling ? ": " : "", message);
}

bool ak_refuse_null(const ak_instance *instance, const char *function, size_t n,
                    const char *count_name, const char *pointer_name) {
    if (count_name == NULL) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR, "%s: %s is NULL", function, pointer_name);
    } else {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR, "%s: %s is NULL with %s = %zu", function,
               pointer_name, count_name, n);
    }
    return false;
}

const char *ak_state_name(const ak_instance *instance, ak_state state) {
    for (int bit = 0; bit < AK_N_STATES; bit++) {
        if ((unsigned int)state == 1u << bit) {
            return instance->layer->state_names[bit];
        }
    }
    return "unknown";
}

bool ak_call_checked(const ak_instance *instance, const ak_function_rule *rule) {
    if (instance == NULL) {
        return false;
    }
    if ((rule->interfaces & (unsigned int)instance->interface) == 0) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR, "%s: %s", rule->name,
               instance->layer->other_interface[instance->interface == AK_CO_SIMULATION]);
        return false;
    }
    if ((rule->allowed_states & (unsigned int)instance->state) == 0) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR, "%s: illegal call in state %s", rule->name,
               ak_state_name(instance, instance->state));
        return false;
    }
    if (ak_log_on(instance, AK_LOG_CALLS)) {
        ak_log(instance, AK_LOG_CALLS, AK_STATUS_OK, "%s", rule->name);
    }
    return true;
}

static ak_real_role real_role(const ak_variable *variable) {
    if (variable == NULL || variable->type != AK_TYPE_REAL) {
        return AK_REAL_ABSENT;
    }
    const bool state = ak_state_index(AK_MODEL.state_vrs, variable->value_reference) >= 0;
    return variable->causality == AK_CAUSALITY_INPUT                ? AK_REAL_INPUT
           : variable->causality == AK_CAUSALITY_PARAMETER          ? AK_REAL_PARAMETER
           : variable->causality == AK_CAUSALITY_OUTPUT && state    ? AK_REAL_STATE_OUTPUT
           : variable->group == AK_GROUP_DERIVED                    ? AK_REAL_DERIVED_OUTPUT
           : variable->group == AK_GROUP_LAZY                       ? AK_REAL_LAZY_OUTPUT
                                                                    : AK_REAL_MAIN_OUTPUT;
}

void ak_instance_reset(ak_instance *instance) {
    /* Without loggingOn, FMI 2 still reports errors and warnings; FMI 3 only errors (3.0.3: "the
     * FMU must not call logMessage, except for fmi3Error and fmi3Fatal"). */
    for (int category = 0; category < AK_N_LOG_CATEGORIES; category++) {
        instance->log_enabled[category] =
            instance->has_logger &&
            (instance->logging_on_at_instantiation ||
             (category != AK_LOG_CALLS && !instance->layer->errors_always_logged));
    }
    instance->data.log = log_for_model;
    instance->data.owner = instance;
    instance->state = AK_INSTANTIATED;
    instance->time = 0.0;
    instance->stop_time_defined = false;
    instance->stop_time = 0.0;
    instance->calling = NULL;
    instance->kept_get.nvr = 0;
    instance->kept_set.nvr = 0;
    for (unsigned int vr = 0; vr < AK_MAX_VARIABLES; vr++) {
        const ak_variable *variable = ak_variable_of(vr);
        instance->real_role[vr] = (unsigned char)real_role(variable);
        instance->elements[vr] = (unsigned char)(instance->layer->elements_at != NULL
                                                     ? instance->layer->elements_at(vr)
                                                     : variable != NULL);
        instance->data.values[vr] = variable != NULL ? variable->start : 0.0;
    }
    memset(instance->data.input_derivatives, 0, sizeof instance->data.input_derivatives);
    instance->data.any_input_derivative = false;
    if (AK_MODEL.initialize != NULL) {
        (void)AK_MODEL.initialize(&instance->data); /* the start values always give a state */
    }
    instance->outputs = (ak_outputs){true, true, true, AK_EVAL_OK, 0};
}

bool ak_instance_start(ak_instance *instance, const ak_layer *layer, const char *function,
                       const char *name, ak_interface interface, bool has_logger, bool logging_on) {
    instance->layer = layer;
    instance->has_logger = has_logger;
    instance->logging_on_at_instantiation = logging_on;
    instance->interface = interface;
    instance->live_states = NULL;
    ak_instance_reset(instance);
    const size_t size = strlen(name) + 1;
    instance->instance_name = layer->allocate(instance, size);
    if (instance->instance_name == NULL) {
        return false;
    }
    memcpy(instance->instance_name, name, size);
    ak_log(instance, AK_LOG_CALLS, AK_STATUS_OK, "%s: instance \"%s\" created", function, name);
    return true;
}

/* The main group, and the lazy group with it when with_lazy and the model can do both at once. */
static ak_eval_status evaluate(ak_instance *instance, bool with_lazy) {
    ak_outputs *outputs = &instance->outputs;
    /* Until initialization ends the states follow the parameters they start from. */
    if ((instance->state & (AK_INSTANTIATED | AK_INITIALIZATION_MODE)) != 0 &&
        AK_MODEL.initialize != NULL && AK_MODEL.initialize(&instance->data) == AK_EVAL_FAILED) {
        outputs->status = AK_EVAL_FAILED;
        outputs->stale = false;
        return AK_EVAL_FAILED;
    }
    const bool both = with_lazy && AK_MODEL.evaluate_all != NULL;
    outputs->status = both ? AK_MODEL.evaluate_all(&instance->data)
                           : AK_MODEL.evaluate(&instance->data);
    outputs->derived_stale = true;
    outputs->stale = false;
    outputs->lazy_stale = !both || outputs->status == AK_EVAL_FAILED;
    outputs->evaluations++;
    if (!ak_log_on(instance, AK_LOG_CALLS)) {
        return outputs->status;
    }
    if (outputs->status == AK_EVAL_FAILED) { /* the model logged why */
        ak_log(instance, AK_LOG_CALLS, AK_STATUS_DISCARD,
               "kinematics evaluation %lu refused: the outputs keep their last valid values",
               outputs->evaluations);
    } else {
        ak_log(instance, AK_LOG_CALLS, AK_STATUS_OK, "kinematics evaluated (evaluation %lu%s)",
               outputs->evaluations, both ? ", with the lazy outputs" : "");
    }
    return outputs->status;
}

ak_status ak_instance_update(ak_instance *instance, ak_group upto) {
    ak_outputs *outputs = &instance->outputs;
    const bool with_lazy = upto >= AK_GROUP_LAZY;
    const ak_eval_status status = outputs->stale ? evaluate(instance, with_lazy) : outputs->status;
    if (with_lazy && outputs->lazy_stale && status != AK_EVAL_FAILED && AK_MODEL.evaluate_lazy) {
        AK_MODEL.evaluate_lazy(&instance->data);
        outputs->derived_stale = true;
        outputs->lazy_stale = false;
        if (ak_log_on(instance, AK_LOG_CALLS)) {
            ak_log(instance, AK_LOG_CALLS, AK_STATUS_OK, "lazy outputs evaluated");
        }
    }
    if (upto == AK_GROUP_DERIVED && outputs->derived_stale && status != AK_EVAL_FAILED) {
        ak_model_compute_derived(&instance->data);
        outputs->derived_stale = false;
        if (ak_log_on(instance, AK_LOG_CALLS)) {
            ak_log(instance, AK_LOG_CALLS, AK_STATUS_OK, "derived outputs evaluated");
        }
    }
    /* Discard answers "a function is outside of its domain"; Error would make it unusable. */
    _Static_assert((int)AK_EVAL_OK == (int)AK_STATUS_OK &&
                       (int)AK_EVAL_WARNING == (int)AK_STATUS_WARNING &&
                       (int)AK_EVAL_FAILED == (int)AK_STATUS_DISCARD,
                   "an evaluation's status is the status of a read");
    return (ak_status)status;
}

int ak_state_index(const unsigned int *vrs, unsigned int vr) {
    for (int k = 0; k < AK_MODEL.n_states; k++) {
        if (vrs[k] == vr) {
            return k;
        }
    }
    return -1;
}
