/* FMU states for both FMI versions: get, set, free, serialize, deserialize. A state holds its
 * serialized form (runtime/state_image.h), so there is one layout and one validator; each
 * layer names its format (magic, version, whether input derivatives are in it).
 *
 * What is not in a state: the instance name, the callbacks and the debug-logging settings
 * belong to the instance, not to the simulation, and stay as they are when a state is set. A
 * byte string that is too short or long, carries another magic, version or token, fails the
 * checksum, or holds values the instance could never have is refused with a message saying
 * which; the instance and the caller's state are then left as they were. */
#include <string.h>

#include "runtime.h"

/* The in-memory FMU state: the bytes, in the instance's list of live states. A pointer the
 * importer gives back is looked up in that list by address, never dereferenced first: a stray
 * or freed pointer is refused without reading the memory it points to. */
struct ak_fmu_state_s {
    struct ak_fmu_state_s *next;
    unsigned char bytes[AK_STATE_IMAGE_MAX_SIZE];
};
typedef struct ak_fmu_state_s ak_fmu_state;

/* The decoded content of a state. */
typedef struct {
    ak_state_header header;
    double values[AK_MAX_VARIABLES];
    double input_derivatives[AK_MAX_INPUTS][AK_MAX_INPUT_DERIVATIVE_ORDER];
} ak_state_content;

static size_t state_size(const ak_instance *instance) {
    return ak_state_image_size(&instance->layer->state_format);
}

/* The interface and state fields of the image, in the layer's numbering. */
static uint32_t image_interface(ak_interface interface) {
    return interface == AK_MODEL_EXCHANGE ? 0u : 1u;
}

static uint32_t image_state(const ak_instance *instance) {
    for (int bit = 0; bit < AK_N_STATES; bit++) {
        if (instance->layer->image_states[bit] == instance->state) {
            return 1u << bit;
        }
    }
    return 0u; /* never: every state an instance enters has a bit */
}

static void encode(const ak_instance *instance, unsigned char bytes[AK_STATE_IMAGE_MAX_SIZE]) {
    const ak_state_header header = {image_interface(instance->interface), image_state(instance),
                                    instance->time, instance->stop_time,
                                    instance->stop_time_defined};
    ak_state_image_write(&instance->layer->state_format, &header, &instance->data, bytes);
}

/* The interface of an image as an adjective ("a model-exchange instance") and as a noun. */
static const char *interface_adjective(uint32_t interface) {
    return interface == 0 ? "model-exchange" : interface == 1 ? "co-simulation" : "unknown";
}

static const char *interface_noun(uint32_t interface) {
    return interface == 0 ? "model exchange" : "co-simulation";
}

/* The state of an image's state field that an instance of its interface can be in, or 0. */
static ak_state decoded_state(const ak_layer *layer, uint32_t code, uint32_t interface) {
    for (int bit = 0; bit < AK_N_STATES; bit++) {
        if (code == 1u << bit && layer->image_states[bit] != 0 &&
            (layer->possible_states[interface] & (unsigned int)layer->image_states[bit]) != 0) {
            return layer->image_states[bit];
        }
    }
    return (ak_state)0;
}

/* Checks a byte string from its length to its last value and decodes it; on failure logs why
 * (as function) and leaves content unspecified. Nothing of the instance is touched. */
static bool decode(const ak_instance *instance, const char *function, const unsigned char *bytes,
                   size_t size, ak_state_content *content) {
    const ak_state_format *format = &instance->layer->state_format;
    if (!ak_state_image_check(format, &instance->data, function, bytes, size, &content->header)) {
        return false;
    }
    const uint32_t interface = content->header.interface;
    if (interface != image_interface(instance->interface)) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: the FMU state is of a %s instance (%s %u); this instance is for %s",
               function, interface_adjective(interface), format->interface_name, interface,
               interface_noun(image_interface(instance->interface)));
        return false;
    }
    const bool possible = decoded_state(instance->layer, content->header.state, interface) != 0;
    return ak_state_image_read(format, &instance->data, function, bytes, &content->header,
                               possible, content->values, content->input_derivatives);
}

/* A state pointer the importer gives back: ours, still alive, or a logged error. */
static ak_fmu_state *known_state(const ak_instance *instance, const char *function,
                                 const void *state) {
    ak_fmu_state *s = instance->live_states;
    while (s != NULL && s != (const ak_fmu_state *)state) {
        s = s->next;
    }
    if (s == NULL) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: %s %s is not an FMU state made by %s or %s of this FMU (or it was freed)",
               function, instance->layer->state_format.kind_argument,
               state == NULL ? "NULL" : "given", instance->layer->state_format.getter,
               instance->layer->state_format.deserializer);
    }
    return s;
}

/* The state object to fill: the one the importer passes back for reuse, or a new one. */
static ak_fmu_state *state_to_fill(ak_instance *instance, const char *function, void **state) {
    if (*state != NULL) {
        return known_state(instance, function, *state);
    }
    ak_fmu_state *s = instance->layer->allocate(instance, sizeof(ak_fmu_state));
    if (s == NULL) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR, "%s: out of memory allocating an FMU state",
               function);
        return NULL;
    }
    s->next = instance->live_states;
    instance->live_states = s;
    return s;
}

ak_status ak_get_fmu_state(ak_instance *instance, const ak_function_rule *call, void **state) {
    if (!ak_call_allowed(instance, call)) {
        return AK_STATUS_ERROR;
    }
    const char *function = call->name;
    if (!ak_not_null(instance, function, state, instance->layer->state_format.kind_argument)) {
        return AK_STATUS_ERROR;
    }
    ak_fmu_state *s = state_to_fill(instance, function, state);
    if (s == NULL) {
        return AK_STATUS_ERROR;
    }
    encode(instance, s->bytes);
    *state = s;
    return AK_STATUS_OK;
}

ak_status ak_set_fmu_state(ak_instance *instance, const ak_function_rule *call, void *state) {
    if (!ak_call_allowed(instance, call)) {
        return AK_STATUS_ERROR;
    }
    const char *function = call->name;
    const ak_fmu_state *s = known_state(instance, function, state);
    ak_state_content content;
    if (s == NULL || !decode(instance, function, s->bytes, state_size(instance), &content)) {
        return AK_STATUS_ERROR;
    }
    instance->state = decoded_state(instance->layer, content.header.state, content.header.interface);
    instance->time = content.header.time;
    instance->stop_time_defined = content.header.stop_time_defined;
    instance->stop_time = content.header.stop_time;
    memcpy(instance->data.values, content.values,
           sizeof(double) * (size_t)AK_MODEL.n_value_references);
    if (instance->layer->state_format.input_derivatives) {
        memcpy(instance->data.input_derivatives, content.input_derivatives,
               sizeof content.input_derivatives[0] * (size_t)AK_MODEL.n_inputs);
        ak_input_derivatives_changed(instance);
    }
    /* The outputs are recomputed from the restored inputs and parameters, not trusted from the
     * bytes (they hold the last valid ones, which stay if the evaluation fails). */
    ak_instance_inputs_changed(instance);
    return AK_STATUS_OK;
}

ak_status ak_free_fmu_state(ak_instance *instance, const ak_function_rule *call, void **state) {
    if (!ak_call_allowed(instance, call)) {
        return AK_STATUS_ERROR;
    }
    const char *function = call->name;
    if (!ak_not_null(instance, function, state, instance->layer->state_format.kind_argument)) {
        return AK_STATUS_ERROR;
    }
    if (*state == NULL) {
        return AK_STATUS_OK; /* nothing to free, as with free(NULL) */
    }
    ak_fmu_state *s = known_state(instance, function, *state);
    if (s == NULL) {
        return AK_STATUS_ERROR;
    }
    ak_fmu_state **link = &instance->live_states;
    while (*link != s) {
        link = &(*link)->next;
    }
    *link = s->next;
    instance->layer->release(instance, s);
    *state = NULL;
    return AK_STATUS_OK;
}

ak_status ak_serialized_fmu_state_size(ak_instance *instance, const ak_function_rule *call,
                                       void *state, size_t *size) {
    if (!ak_call_allowed(instance, call)) {
        return AK_STATUS_ERROR;
    }
    const char *function = call->name;
    if (!ak_not_null(instance, function, size, "size") ||
        known_state(instance, function, state) == NULL) {
        return AK_STATUS_ERROR;
    }
    *size = state_size(instance);
    return AK_STATUS_OK;
}

ak_status ak_serialize_fmu_state(ak_instance *instance, const ak_function_rule *call, void *state,
                                 unsigned char bytes[], size_t size) {
    if (!ak_call_allowed(instance, call)) {
        return AK_STATUS_ERROR;
    }
    const char *function = call->name;
    const ak_fmu_state *s = known_state(instance, function, state);
    if (s == NULL || !ak_not_null(instance, function, bytes, "serializedState")) {
        return AK_STATUS_ERROR;
    }
    if (size < state_size(instance)) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: size = %zu is too small; the state needs %zu bytes (%s)", function, size,
               state_size(instance), instance->layer->state_format.sizer);
        return AK_STATUS_ERROR;
    }
    memcpy(bytes, s->bytes, state_size(instance));
    return AK_STATUS_OK;
}

ak_status ak_deserialize_fmu_state(ak_instance *instance, const ak_function_rule *call,
                                   const unsigned char bytes[], size_t size, void **state) {
    if (!ak_call_allowed(instance, call)) {
        return AK_STATUS_ERROR;
    }
    const char *function = call->name;
    ak_state_content content;
    if (!ak_not_null(instance, function, bytes, "serializedState") ||
        !ak_not_null(instance, function, state, instance->layer->state_format.kind_argument) ||
        !decode(instance, function, bytes, size, &content)) {
        return AK_STATUS_ERROR;
    }
    ak_fmu_state *s = state_to_fill(instance, function, state);
    if (s == NULL) {
        return AK_STATUS_ERROR;
    }
    memcpy(s->bytes, bytes, state_size(instance));
    *state = s;
    return AK_STATUS_OK;
}

void ak_free_all_fmu_states(ak_instance *instance) {
    while (instance->live_states != NULL) {
        ak_fmu_state *s = instance->live_states;
        instance->live_states = s->next;
        instance->layer->release(instance, s);
    }
}
