/* FMU states for both FMI versions, in the format each layer names. A state holds its byte image:
 * one layout (codegen/state_layout.py's), one validator. The instance name, callbacks and logging
 * settings belong to the instance, not to the simulation: setting a state leaves them. */
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

/* A pointer the importer gives back is looked up in the instance's list by address, never
 * dereferenced first: a stray or freed pointer is refused without reading its memory. */
struct ak_fmu_state_s {
    struct ak_fmu_state_s *next;
    unsigned char bytes[MAX_SIZE];
};
typedef struct ak_fmu_state_s ak_fmu_state;

/* Where input k's derivative of order n + 1 is. */
static size_t offset_derivative(int k, int n) {
    return OFFSET_VALUES + 8u * (size_t)AK_MODEL.n_value_references +
           8u * (size_t)(AK_MAX_INPUT_DERIVATIVE_ORDER * k + n);
}

static size_t offset_checksum(const ak_instance *instance) {
    const bool derivatives = instance->layer->state_format.input_derivatives;
    return offset_derivative(derivatives ? AK_MODEL.n_inputs : 0, 0);
}

static size_t state_size(const ak_instance *instance) {
    return offset_checksum(instance) + 4u;
}

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

static bool valid(const ak_instance *instance, const char *function, const unsigned char *bytes,
                  size_t size) {
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
    const char *token = (const char *)bytes + OFFSET_TOKEN; /* NUL-padded, or all 40 bytes */
    if (strncmp(token, AK_MODEL.guid, TOKEN_FIELD) != 0) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: the FMU state is of an FMU with %s \"%.40s\", not this one's (%s) \"%s\"",
               function, format->token_name, token, AK_MODEL.model_identifier, AK_MODEL.guid);
        return false;
    }
    const uint32_t interface = ak_get_u32(bytes + OFFSET_INTERFACE);
    if (interface != image_interface(instance->interface)) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: the FMU state is of a %s instance (%s %u); this instance is for %s",
               function,
               interface == 0   ? "model-exchange"
               : interface == 1 ? "co-simulation"
                                : "unknown",
               format->interface_name, interface,
               instance->interface == AK_MODEL_EXCHANGE ? "model exchange" : "co-simulation");
        return false;
    }
    const uint32_t state = ak_get_u32(bytes + OFFSET_STATE);
    const uint32_t stop_time_defined = ak_get_u32(bytes + OFFSET_STOP_TIME_DEFINED);
    const double time = ak_get_f64(bytes + OFFSET_TIME);
    const double stop_time = ak_get_f64(bytes + OFFSET_STOP_TIME);
    if (decoded_state(instance->layer, state, interface) == 0 || stop_time_defined > 1 ||
        ak_get_u32(bytes + OFFSET_RESERVED) != 0 || !isfinite(time) || !isfinite(stop_time)) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: the FMU state holds an impossible header (state 0x%x, time %g, stop time %g, "
               "stop time defined %u)",
               function, state, time, stop_time, stop_time_defined);
        return false;
    }
    for (int vr = 0; vr < AK_MODEL.n_value_references; vr++) {
        const ak_variable *variable = ak_variable_of((unsigned int)vr);
        const double value = ak_get_f64(bytes + OFFSET_VALUES + 8 * (size_t)vr);
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
        }
    }
    return true;
}

/* The link to a state pointer the importer gives back: ours, still alive; or NULL, logged. */
static ak_fmu_state **known_state(ak_instance *instance, const char *function, const void *state) {
    ak_fmu_state **link = &instance->live_states;
    while (*link != NULL && *link != state) {
        link = &(*link)->next;
    }
    if (*link != NULL) {
        return link;
    }
    ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
           "%s: %s %s is not an FMU state made by %s or %s of this FMU (or it was freed)",
           function, instance->layer->state_format.kind_argument, state == NULL ? "NULL" : "given",
           instance->layer->state_format.getter, instance->layer->state_format.deserializer);
    return NULL;
}

/* Fills the state the importer passes back for reuse, or a new one: with bytes, or encoded. */
static ak_status fill_state(ak_instance *instance, const char *function, void **state,
                            const unsigned char *bytes) {
    ak_fmu_state *s = *state;
    if (s != NULL && known_state(instance, function, s) == NULL) {
        return AK_STATUS_ERROR;
    }
    if (s == NULL) {
        s = instance->layer->allocate(instance, sizeof(ak_fmu_state));
        if (s == NULL) {
            ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
                   "%s: out of memory allocating an FMU state", function);
            return AK_STATUS_ERROR;
        }
        s->next = instance->live_states;
        instance->live_states = s;
    }
    if (bytes != NULL) {
        memcpy(s->bytes, bytes, state_size(instance));
    } else {
        encode(instance, s->bytes);
    }
    *state = s;
    return AK_STATUS_OK;
}

ak_status ak_get_fmu_state(ak_instance *instance, const ak_function_rule *call, void **state) {
    if (!ak_call_allowed(instance, call) ||
        !ak_not_null(instance, call->name, state, instance->layer->state_format.kind_argument)) {
        return AK_STATUS_ERROR;
    }
    return fill_state(instance, call->name, state, NULL);
}

ak_status ak_set_fmu_state(ak_instance *instance, const ak_function_rule *call, void *state) {
    if (!ak_call_allowed(instance, call)) {
        return AK_STATUS_ERROR;
    }
    ak_fmu_state **link = known_state(instance, call->name, state);
    if (link == NULL || !valid(instance, call->name, (*link)->bytes, state_size(instance))) {
        return AK_STATUS_ERROR;
    }
    const unsigned char *bytes = (*link)->bytes;
    instance->state = decoded_state(instance->layer, ak_get_u32(bytes + OFFSET_STATE),
                                    image_interface(instance->interface));
    instance->time = ak_get_f64(bytes + OFFSET_TIME);
    instance->stop_time_defined = ak_get_u32(bytes + OFFSET_STOP_TIME_DEFINED) == 1;
    instance->stop_time = ak_get_f64(bytes + OFFSET_STOP_TIME);
    for (int vr = 0; vr < AK_MODEL.n_value_references; vr++) {
        instance->data.values[vr] = ak_get_f64(bytes + OFFSET_VALUES + 8 * (size_t)vr);
    }
    if (instance->layer->state_format.input_derivatives) {
        for (int k = 0; k < AK_MODEL.n_inputs; k++) {
            for (int n = 0; n < AK_MAX_INPUT_DERIVATIVE_ORDER; n++) {
                const double d = ak_get_f64(bytes + offset_derivative(k, n));
                instance->data.input_derivatives[k][n] = d;
            }
        }
        ak_input_derivatives_changed(instance);
    }
    /* Recomputed, not trusted: the bytes hold the last valid outputs, kept if evaluation fails. */
    ak_instance_inputs_changed(instance);
    return AK_STATUS_OK;
}

ak_status ak_free_fmu_state(ak_instance *instance, const ak_function_rule *call, void **state) {
    if (!ak_call_allowed(instance, call) ||
        !ak_not_null(instance, call->name, state, instance->layer->state_format.kind_argument)) {
        return AK_STATUS_ERROR;
    }
    if (*state == NULL) {
        return AK_STATUS_OK; /* nothing to free, as with free(NULL) */
    }
    ak_fmu_state **link = known_state(instance, call->name, *state);
    if (link == NULL) {
        return AK_STATUS_ERROR;
    }
    ak_fmu_state *s = *link;
    *link = s->next;
    instance->layer->release(instance, s);
    *state = NULL;
    return AK_STATUS_OK;
}

ak_status ak_serialized_fmu_state_size(ak_instance *instance, const ak_function_rule *call,
                                       void *state, size_t *size) {
    if (!ak_call_allowed(instance, call) || !ak_not_null(instance, call->name, size, "size") ||
        known_state(instance, call->name, state) == NULL) {
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
    ak_fmu_state **link = known_state(instance, call->name, state);
    if (link == NULL || !ak_not_null(instance, call->name, bytes, "serializedState")) {
        return AK_STATUS_ERROR;
    }
    if (size < state_size(instance)) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: size = %zu is too small; the state needs %zu bytes (%s)", call->name, size,
               state_size(instance), instance->layer->state_format.sizer);
        return AK_STATUS_ERROR;
    }
    memcpy(bytes, (*link)->bytes, state_size(instance));
    return AK_STATUS_OK;
}

ak_status ak_deserialize_fmu_state(ak_instance *instance, const ak_function_rule *call,
                                   const unsigned char bytes[], size_t size, void **state) {
    if (!ak_call_allowed(instance, call) ||
        !ak_not_null(instance, call->name, bytes, "serializedState") ||
        !ak_not_null(instance, call->name, state, instance->layer->state_format.kind_argument) ||
        !valid(instance, call->name, bytes, size)) {
        return AK_STATUS_ERROR;
    }
    return fill_state(instance, call->name, state, bytes);
}

void ak_free_all_fmu_states(ak_instance *instance) {
    while (instance->live_states != NULL) {
        ak_fmu_state *s = instance->live_states;
        instance->live_states = s->next;
        instance->layer->release(instance, s);
    }
}
