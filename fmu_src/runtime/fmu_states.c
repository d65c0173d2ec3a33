/* FMU states for both FMI versions: get, set, free, serialize, deserialize, and their byte image.
 * A state holds its serialized form, so there is one layout and one validator; each layer names
 * its format (ak_state_format). The layout (little-endian, no pointers: header, the values by
 * value reference, FMI 2's input derivatives, CRC-32) is codegen/state_layout.py's, which
 * documents it in docs/capabilities.md#fmu-state; tests/python/test_documentation.py reads the
 * offsets back from real states.
 *
 * The instance name, the callbacks and the debug-logging settings belong to the instance, not to
 * the simulation: setting a state leaves them. A byte string is checked from its length to its
 * last value before anything is decoded; a refusal says which check failed and changes nothing. */
#include <math.h>
#include <string.h>

#include "ak_bytes.h"
#include "runtime.h"

enum {
    OFFSET_MAGIC = 0,
    OFFSET_VERSION = 8,
    OFFSET_SIZE = 12,
    OFFSET_TOKEN = 16,
    OFFSET_INTERFACE = 56,
    OFFSET_STATE = 60,
    OFFSET_TIME = 64,
    OFFSET_STOP_TIME = 72,
    OFFSET_STOP_TIME_DEFINED = 80,
    OFFSET_RESERVED = 84,
    OFFSET_VALUES = 88,
    TOKEN_FIELD = 40,
    MAX_SIZE = OFFSET_VALUES + 8 * AK_MAX_VARIABLES +
               8 * AK_MAX_INPUTS * AK_MAX_INPUT_DERIVATIVE_ORDER + 4
};

/* The in-memory FMU state, in the instance's list of live states. A pointer the importer gives
 * back is looked up in that list by address, never dereferenced first: a stray or freed pointer
 * is refused without reading the memory it points to. */
struct ak_fmu_state_s {
    struct ak_fmu_state_s *next;
    unsigned char bytes[MAX_SIZE];
};
typedef struct ak_fmu_state_s ak_fmu_state;

/* The decoded content of a checked image. */
typedef struct {
    ak_state state;
    double time;
    double stop_time;
    bool stop_time_defined;
    double values[AK_MAX_VARIABLES];
    double input_derivatives[AK_MAX_INPUTS][AK_MAX_INPUT_DERIVATIVE_ORDER];
} ak_state_content;

/* Where input k's derivative of order n + 1 is. */
static size_t offset_derivative(int k, int n) {
    return OFFSET_VALUES + 8u * (size_t)AK_MODEL.n_value_references +
           8u * (size_t)(AK_MAX_INPUT_DERIVATIVE_ORDER * k + n);
}

/* After the input derivatives, if the format has them. */
static size_t offset_checksum(const ak_instance *instance) {
    const bool derivatives = instance->layer->state_format.input_derivatives;
    return offset_derivative(derivatives ? AK_MODEL.n_inputs : 0, 0);
}

static size_t state_size(const ak_instance *instance) {
    return offset_checksum(instance) + 4u;
}

/* The image's interface field: 0 model exchange, 1 co-simulation. */
static uint32_t image_interface(ak_interface interface) {
    return interface == AK_MODEL_EXCHANGE ? 0u : 1u;
}

static void encode(const ak_instance *instance, unsigned char bytes[MAX_SIZE]) {
    const ak_state_format *format = &instance->layer->state_format;
    const size_t size = state_size(instance);
    memset(bytes, 0, size);
    memcpy(bytes + OFFSET_MAGIC, format->magic, 8);
    ak_put_u32(bytes + OFFSET_VERSION, format->version);
    ak_put_u32(bytes + OFFSET_SIZE, (uint32_t)size);
    memcpy(bytes + OFFSET_TOKEN, AK_MODEL.guid, strlen(AK_MODEL.guid));
    ak_put_u32(bytes + OFFSET_INTERFACE, image_interface(instance->interface));
    for (int bit = 0; bit < AK_N_STATES; bit++) { /* the state in the layer's numbering */
        if (instance->layer->image_states[bit] == instance->state) {
            ak_put_u32(bytes + OFFSET_STATE, 1u << bit);
        }
    }
    ak_put_f64(bytes + OFFSET_TIME, instance->time);
    ak_put_f64(bytes + OFFSET_STOP_TIME, instance->stop_time);
    ak_put_u32(bytes + OFFSET_STOP_TIME_DEFINED, instance->stop_time_defined ? 1u : 0u);
    for (int vr = 0; vr < AK_MODEL.n_value_references; vr++) {
        ak_put_f64(bytes + OFFSET_VALUES + 8 * (size_t)vr, instance->data.values[vr]);
    }
    for (int k = 0; format->input_derivatives && k < AK_MODEL.n_inputs; k++) {
        for (int n = 0; n < AK_MAX_INPUT_DERIVATIVE_ORDER; n++) {
            ak_put_f64(bytes + offset_derivative(k, n), instance->data.input_derivatives[k][n]);
        }
    }
    ak_put_u32(bytes + offset_checksum(instance), ak_crc32(bytes, offset_checksum(instance)));
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

/* The checks of the image as such: length, magic, version, size, checksum, token. */
static bool image_intact(const ak_instance *instance, const char *function,
                         const unsigned char *bytes, size_t size) {
    const ak_state_format *format = &instance->layer->state_format;
    if (size < OFFSET_TOKEN || memcmp(bytes + OFFSET_MAGIC, format->magic, 8) != 0) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR, "%s: the %zu bytes are not an %s %s (%s)",
               function, size, AK_MODEL.model_identifier, format->kind,
               size < OFFSET_TOKEN ? "too short for the header" : "wrong magic bytes");
        return false;
    }
    const uint32_t version = ak_get_u32(bytes + OFFSET_VERSION);
    if (version != format->version) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: FMU state format version %u is not supported (this binary reads version %u)",
               function, version, format->version);
        return false;
    }
    const size_t expected = state_size(instance);
    const uint32_t declared = ak_get_u32(bytes + OFFSET_SIZE);
    if (size != expected || declared != expected) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: the FMU state is %zu bytes long and declares %u bytes; format version %u of "
               "%s has %zu bytes (truncated or extended)",
               function, size, declared, format->version, AK_MODEL.model_identifier, expected);
        return false;
    }
    const uint32_t stored = ak_get_u32(bytes + offset_checksum(instance));
    const uint32_t computed = ak_crc32(bytes, offset_checksum(instance));
    if (stored != computed) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: the FMU state is corrupt: its CRC-32 is 0x%08x, the bytes give 0x%08x",
               function, stored, computed);
        return false;
    }
    char token[TOKEN_FIELD + 1];
    memcpy(token, bytes + OFFSET_TOKEN, TOKEN_FIELD);
    token[TOKEN_FIELD] = '\0';
    if (strcmp(token, AK_MODEL.guid) != 0) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: the FMU state is of an FMU with %s \"%s\", not this one's (%s) \"%s\"",
               function, format->token_name, token, AK_MODEL.model_identifier, AK_MODEL.guid);
        return false;
    }
    return true;
}

/* Checks a byte string from its length to its last value and decodes it into *content; on
 * failure logs why. Nothing of the instance is touched. */
static bool decode(const ak_instance *instance, const char *function, const unsigned char *bytes,
                   size_t size, ak_state_content *content) {
    if (!image_intact(instance, function, bytes, size)) {
        return false;
    }
    const ak_state_format *format = &instance->layer->state_format;
    const uint32_t interface = ak_get_u32(bytes + OFFSET_INTERFACE);
    if (interface != image_interface(instance->interface)) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: the FMU state is of a %s instance (%s %u); this instance is for %s",
               function, interface_adjective(interface), format->interface_name, interface,
               interface_noun(image_interface(instance->interface)));
        return false;
    }
    const uint32_t state = ak_get_u32(bytes + OFFSET_STATE);
    const uint32_t stop_time_defined = ak_get_u32(bytes + OFFSET_STOP_TIME_DEFINED);
    content->state = decoded_state(instance->layer, state, interface);
    content->time = ak_get_f64(bytes + OFFSET_TIME);
    content->stop_time = ak_get_f64(bytes + OFFSET_STOP_TIME);
    content->stop_time_defined = stop_time_defined == 1;
    if (content->state == 0 || stop_time_defined > 1 || ak_get_u32(bytes + OFFSET_RESERVED) != 0 ||
        !isfinite(content->time) || !isfinite(content->stop_time)) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: the FMU state holds an impossible header (state 0x%x, time %g, stop time %g, "
               "stop time defined %u)",
               function, state, content->time, content->stop_time, stop_time_defined);
        return false;
    }
    for (int vr = 0; vr < AK_MODEL.n_value_references; vr++) {
        const ak_variable *variable = ak_variable_of((unsigned int)vr);
        const double value = ak_get_f64(bytes + OFFSET_VALUES + 8 * (size_t)vr);
        content->values[vr] = value;
        if (variable == NULL) {
            continue; /* a hole of the table: never read */
        }
        if (!isfinite(value)) {
            ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
                   "%s: the FMU state holds %s = %g, which is not finite", function,
                   variable->name, value);
            return false;
        }
        const bool integral = variable->type != AK_TYPE_INTEGER || value == floor(value);
        if (variable->causality == AK_CAUSALITY_PARAMETER &&
            (!integral || ak_parameter_refusal(variable, value) != NULL)) {
            ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
                   "%s: the FMU state holds the parameter %s = %.17g, which it cannot have",
                   function, variable->name, value);
            return false;
        }
    }
    for (int k = 0; format->input_derivatives && k < AK_MODEL.n_inputs; k++) {
        for (int n = 0; n < AK_MAX_INPUT_DERIVATIVE_ORDER; n++) {
            const double d = ak_get_f64(bytes + offset_derivative(k, n));
            if (!isfinite(d)) {
                ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
                       "%s: the FMU state holds a derivative of order %d of %s = %g, which is not "
                       "finite",
                       function, n + 1, AK_MODEL.variables[k].name, d);
                return false;
            }
            content->input_derivatives[k][n] = d;
        }
    }
    return true;
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
    instance->state = content.state;
    instance->time = content.time;
    instance->stop_time_defined = content.stop_time_defined;
    instance->stop_time = content.stop_time;
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
