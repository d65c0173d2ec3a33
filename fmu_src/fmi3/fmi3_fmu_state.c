/* FMI 3.0 FMU state: get, set, free, serialize, deserialize (canGetAndSetFMUState,
 * canSerializeFMUState). As in FMI 2, a state holds its serialized form: one layout, one
 * validator. Layout (FMI 3 format version 1), little-endian, no pointers; N is the model's number
 * of value references (71 AngularKinematics, 25 EulerRates):
 *
 *   offset size  field
 *        0    8  magic "AKinFMU3" (the FMI 2 states' is "AKinFMUs": neither reads the other)
 *        8    4  format version (1)
 *       12    4  total size in bytes (92 + 8 N: 660 AngularKinematics, 292 EulerRates)
 *       16   40  instantiation token of the FMU, NUL-padded
 *       56    4  interface of the instance (0 model exchange, 1 co-simulation)
 *       60    4  state-machine state (one ak3_state bit)
 *       64    8  time
 *       72    8  stop time
 *       80    4  stop time defined (0 or 1)
 *       84    4  reserved, 0
 *       88  8 N  the values, by value reference
 *     88+8N   4  CRC-32 of the bytes before it
 *
 * The instance name, the logger and the logging settings belong to the instance and stay as
 * they are when a state is set. A byte string with another length, magic, version or token, a
 * bad checksum or impossible values is refused with fmi3Error and a message; nothing changes. */
#include <math.h>
#include <stdlib.h>

#include "ak_bytes.h"
#include "fmi3Functions.h"
#include "fmi3_instance.h"
#include "fmi3_logging.h"
#include "fmi3_state_machine.h"

#define STATE_MAGIC "AKinFMU3"
#define STATE_FORMAT_VERSION 1u
#define TOKEN_FIELD 40

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
    STATE_MAX_SIZE = OFFSET_VALUES + 8 * AK_MAX_VARIABLES + 4
};

static size_t offset_checksum(void) {
    return (size_t)OFFSET_VALUES + 8u * (size_t)AK_MODEL.n_value_references;
}

static size_t state_size(void) {
    return offset_checksum() + 4u;
}

/* A state the importer gives back is looked up in the instance's list by address, never
 * dereferenced first. */
struct ak3_fmu_state_s {
    struct ak3_fmu_state_s *next;
    unsigned char bytes[STATE_MAX_SIZE];
};
typedef struct ak3_fmu_state_s ak3_fmu_state;

typedef struct {
    ak3_state state;
    double time;
    bool stop_time_defined;
    double stop_time;
    double values[AK_MAX_VARIABLES];
} ak3_state_content;

static void encode(const ak3_instance *instance, unsigned char bytes[STATE_MAX_SIZE]) {
    memset(bytes, 0, state_size());
    memcpy(bytes + OFFSET_MAGIC, STATE_MAGIC, 8);
    ak_put_u32(bytes + OFFSET_VERSION, STATE_FORMAT_VERSION);
    ak_put_u32(bytes + OFFSET_SIZE, (uint32_t)state_size());
    memcpy(bytes + OFFSET_TOKEN, AK_MODEL.guid, strlen(AK_MODEL.guid));
    ak_put_u32(bytes + OFFSET_INTERFACE, (uint32_t)instance->interface);
    ak_put_u32(bytes + OFFSET_STATE, (uint32_t)instance->state);
    ak_put_f64(bytes + OFFSET_TIME, instance->time);
    ak_put_f64(bytes + OFFSET_STOP_TIME, instance->stop_time);
    ak_put_u32(bytes + OFFSET_STOP_TIME_DEFINED, instance->stop_time_defined ? 1u : 0u);
    for (int vr = 0; vr < AK_MODEL.n_value_references; vr++) {
        ak_put_f64(bytes + OFFSET_VALUES + 8 * (size_t)vr, instance->data.values[vr]);
    }
    ak_put_u32(bytes + offset_checksum(), ak_crc32(bytes, offset_checksum()));
}

/* The states an instance of an interface can be in (Configuration and Reconfiguration Mode are
 * never entered). */
static bool state_possible(uint32_t state, uint32_t interface) {
    const uint32_t own = interface == AK3_MODEL_EXCHANGE
                             ? AK3_STATE_EVENT_MODE | AK3_STATE_CONTINUOUS_TIME_MODE
                             : AK3_STATE_STEP_MODE;
    const uint32_t allowed =
        own | AK3_STATE_INSTANTIATED | AK3_STATE_INITIALIZATION_MODE | AK3_STATE_TERMINATED;
    return state != 0 && (state & (state - 1)) == 0 && (state & ~allowed) == 0;
}

static bool header_valid(const ak3_instance *instance, const char *name, const unsigned char *bytes,
                         size_t size) {
    if (size < OFFSET_TOKEN || memcmp(bytes + OFFSET_MAGIC, STATE_MAGIC, 8) != 0) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error, "%s: the %zu bytes are not an %s FMI 3 FMU state (%s)",
                name, size, AK_MODEL.model_identifier,
                size < OFFSET_TOKEN ? "too short for the header" : "wrong magic bytes");
        return false;
    }
    const uint32_t version = ak_get_u32(bytes + OFFSET_VERSION);
    if (version != STATE_FORMAT_VERSION) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error,
                "%s: FMU state format version %u is not supported (this binary reads version %u)",
                name, version, STATE_FORMAT_VERSION);
        return false;
    }
    const uint32_t declared = ak_get_u32(bytes + OFFSET_SIZE);
    if (size != state_size() || declared != state_size()) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error,
                "%s: the FMU state is %zu bytes long and declares %u bytes; %s's has %zu bytes "
                "(truncated or extended)",
                name, size, declared, AK_MODEL.model_identifier, state_size());
        return false;
    }
    const uint32_t stored = ak_get_u32(bytes + offset_checksum());
    const uint32_t computed = ak_crc32(bytes, offset_checksum());
    if (stored != computed) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error,
                "%s: the FMU state is corrupt: its CRC-32 is 0x%08x, the bytes give 0x%08x", name,
                stored, computed);
        return false;
    }
    char token[TOKEN_FIELD + 1];
    memcpy(token, bytes + OFFSET_TOKEN, TOKEN_FIELD);
    token[TOKEN_FIELD] = '\0';
    if (strcmp(token, AK_MODEL.guid) != 0) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error,
                "%s: the FMU state is of an FMU with instantiationToken \"%s\", not this one's "
                "\"%s\"",
                name, token, AK_MODEL.guid);
        return false;
    }
    const uint32_t interface = ak_get_u32(bytes + OFFSET_INTERFACE);
    if (interface != (uint32_t)instance->interface) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error,
                "%s: the FMU state is of a %s instance; this instance is for %s", name,
                interface == AK3_MODEL_EXCHANGE ? "model-exchange" : "co-simulation",
                instance->interface == AK3_MODEL_EXCHANGE ? "model exchange" : "co-simulation");
        return false;
    }
    return true;
}

/* Checks a byte string from its length to its last value and decodes it; logs why not. */
static bool decode(const ak3_instance *instance, ak3_function function, const unsigned char *bytes,
                   size_t size, ak3_state_content *content) {
    const char *name = ak3_function_name(function);
    if (!header_valid(instance, name, bytes, size)) {
        return false;
    }
    const uint32_t state = ak_get_u32(bytes + OFFSET_STATE);
    const uint32_t stop_time_defined = ak_get_u32(bytes + OFFSET_STOP_TIME_DEFINED);
    content->time = ak_get_f64(bytes + OFFSET_TIME);
    content->stop_time = ak_get_f64(bytes + OFFSET_STOP_TIME);
    if (!state_possible(state, (uint32_t)instance->interface) || stop_time_defined > 1 ||
        ak_get_u32(bytes + OFFSET_RESERVED) != 0 || !isfinite(content->time) ||
        !isfinite(content->stop_time)) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error,
                "%s: the FMU state holds an impossible header (state 0x%x, time %g, stop time %g, "
                "stop time defined %u)",
                name, state, content->time, content->stop_time, stop_time_defined);
        return false;
    }
    for (int vr = 0; vr < AK_MODEL.n_value_references; vr++) {
        const ak_variable *variable = ak_variable_of((unsigned int)vr);
        content->values[vr] = ak_get_f64(bytes + OFFSET_VALUES + 8 * (size_t)vr);
        if (variable == NULL) {
            continue;
        }
        if (!isfinite(content->values[vr])) {
            ak3_log(instance, AK_LOG_ERROR, fmi3Error,
                    "%s: the FMU state holds %s = %g, which is not finite", name, variable->name,
                    content->values[vr]);
            return false;
        }
        const bool integral = variable->type != AK_TYPE_INTEGER ||
                              content->values[vr] == floor(content->values[vr]);
        if (variable->causality == AK_CAUSALITY_PARAMETER &&
            (!integral || AK_MODEL.check_parameter(variable, content->values[vr]) != NULL)) {
            ak3_log(instance, AK_LOG_ERROR, fmi3Error,
                    "%s: the FMU state holds the parameter %s = %.17g, which it cannot have", name,
                    variable->name, content->values[vr]);
            return false;
        }
    }
    content->state = (ak3_state)state;
    content->stop_time_defined = stop_time_defined == 1;
    return true;
}

static ak3_fmu_state *known_state(const ak3_instance *instance, ak3_function function,
                                  fmi3FMUState state) {
    ak3_fmu_state *s = instance->live_states;
    while (s != NULL && s != (ak3_fmu_state *)state) {
        s = s->next;
    }
    if (s == NULL) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error,
                "%s: FMUState %s is not an FMU state made by fmi3GetFMUState or "
                "fmi3DeserializeFMUState of this instance (or it was freed)",
                ak3_function_name(function), state == NULL ? "NULL" : "given");
    }
    return s;
}

/* The state to fill: the one the importer passes back for reuse, or a new one. */
static ak3_fmu_state *state_to_fill(ak3_instance *instance, ak3_function function,
                                    fmi3FMUState *FMUState) {
    if (*FMUState != NULL) {
        return known_state(instance, function, *FMUState);
    }
    ak3_fmu_state *s = malloc(sizeof(ak3_fmu_state));
    if (s == NULL) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error, "%s: out of memory allocating an FMU state",
                ak3_function_name(function));
        return NULL;
    }
    s->next = instance->live_states;
    instance->live_states = s;
    return s;
}

static bool pointer_given(const ak3_instance *instance, ak3_function function, const void *p,
                          const char *what) {
    if (p == NULL) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error, "%s: %s is NULL", ak3_function_name(function),
                what);
        return false;
    }
    return true;
}

fmi3Status fmi3GetFMUState(fmi3Instance c, fmi3FMUState *FMUState) {
    ak3_instance *instance = c;
    if (!ak3_call_allowed(instance, AK3_GET_FMU_STATE) ||
        !pointer_given(instance, AK3_GET_FMU_STATE, FMUState, "FMUState")) {
        return fmi3Error;
    }
    ak3_fmu_state *s = state_to_fill(instance, AK3_GET_FMU_STATE, FMUState);
    if (s == NULL) {
        return fmi3Error;
    }
    encode(instance, s->bytes);
    *FMUState = s;
    return fmi3OK;
}

fmi3Status fmi3SetFMUState(fmi3Instance c, fmi3FMUState FMUState) {
    ak3_instance *instance = c;
    if (!ak3_call_allowed(instance, AK3_SET_FMU_STATE)) {
        return fmi3Error;
    }
    const ak3_fmu_state *s = known_state(instance, AK3_SET_FMU_STATE, FMUState);
    ak3_state_content content;
    if (s == NULL || !decode(instance, AK3_SET_FMU_STATE, s->bytes, state_size(), &content)) {
        return fmi3Error;
    }
    instance->state = content.state;
    instance->time = content.time;
    instance->stop_time_defined = content.stop_time_defined;
    instance->stop_time = content.stop_time;
    for (int vr = 0; vr < AK_MODEL.n_value_references; vr++) {
        instance->data.values[vr] = content.values[vr];
    }
    /* The outputs are recomputed from the restored inputs and parameters, not trusted. */
    ak3_instance_inputs_changed(instance);
    return fmi3OK;
}

fmi3Status fmi3FreeFMUState(fmi3Instance c, fmi3FMUState *FMUState) {
    ak3_instance *instance = c;
    if (!ak3_call_allowed(instance, AK3_FREE_FMU_STATE) ||
        !pointer_given(instance, AK3_FREE_FMU_STATE, FMUState, "FMUState")) {
        return fmi3Error;
    }
    if (*FMUState == NULL) {
        return fmi3OK; /* nothing to free, as with free(NULL) */
    }
    ak3_fmu_state *s = known_state(instance, AK3_FREE_FMU_STATE, *FMUState);
    if (s == NULL) {
        return fmi3Error;
    }
    ak3_fmu_state **link = &instance->live_states;
    while (*link != s) {
        link = &(*link)->next;
    }
    *link = s->next;
    free(s);
    *FMUState = NULL;
    return fmi3OK;
}

fmi3Status fmi3SerializedFMUStateSize(fmi3Instance c, fmi3FMUState FMUState, size_t *size) {
    ak3_instance *instance = c;
    if (!ak3_call_allowed(instance, AK3_SERIALIZED_FMU_STATE_SIZE) ||
        !pointer_given(instance, AK3_SERIALIZED_FMU_STATE_SIZE, size, "size") ||
        known_state(instance, AK3_SERIALIZED_FMU_STATE_SIZE, FMUState) == NULL) {
        return fmi3Error;
    }
    *size = state_size();
    return fmi3OK;
}

fmi3Status fmi3SerializeFMUState(fmi3Instance c, fmi3FMUState FMUState, fmi3Byte serializedState[],
                                 size_t size) {
    ak3_instance *instance = c;
    if (!ak3_call_allowed(instance, AK3_SERIALIZE_FMU_STATE)) {
        return fmi3Error;
    }
    const ak3_fmu_state *s = known_state(instance, AK3_SERIALIZE_FMU_STATE, FMUState);
    if (s == NULL ||
        !pointer_given(instance, AK3_SERIALIZE_FMU_STATE, serializedState, "serializedState")) {
        return fmi3Error;
    }
    if (size < state_size()) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error,
                "fmi3SerializeFMUState: size = %zu is too small; the state needs %zu bytes "
                "(fmi3SerializedFMUStateSize)",
                size, state_size());
        return fmi3Error;
    }
    memcpy(serializedState, s->bytes, state_size());
    return fmi3OK;
}

fmi3Status fmi3DeserializeFMUState(fmi3Instance c, const fmi3Byte serializedState[], size_t size,
                                   fmi3FMUState *FMUState) {
    ak3_instance *instance = c;
    const ak3_function self = AK3_DESERIALIZE_FMU_STATE;
    ak3_state_content content;
    if (!ak3_call_allowed(instance, self) ||
        !pointer_given(instance, self, serializedState, "serializedState") ||
        !pointer_given(instance, self, FMUState, "FMUState") ||
        !decode(instance, self, (const unsigned char *)serializedState, size, &content)) {
        return fmi3Error;
    }
    ak3_fmu_state *s = state_to_fill(instance, self, FMUState);
    if (s == NULL) {
        return fmi3Error;
    }
    memcpy(s->bytes, serializedState, state_size());
    *FMUState = s;
    return fmi3OK;
}

void ak3_free_all_fmu_states(ak3_instance *instance) {
    while (instance->live_states != NULL) {
        ak3_fmu_state *s = instance->live_states;
        instance->live_states = s->next;
        free(s);
    }
}
