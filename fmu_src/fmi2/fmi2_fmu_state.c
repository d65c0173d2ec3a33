/* FMI 2.0 FMU state: get, set, free, serialize, deserialize (canGetAndSetFMUstate,
 * canSerializeFMUstate).
 *
 * An FMU state holds its serialized form, so there is one layout and one validator for both.
 * The layout (format version 2) is little-endian, with no pointers; N is the model's number of
 * variables (71 AngularKinematics, 25 EulerRates), I its number of inputs (9 both):
 *
 *   offset size  field
 *        0    8  magic "AKinFMUs"
 *        8    4  format version (2; version 1 held the 21 values of the 1-2-3-only FMU)
 *       12    4  total size in bytes (92 + 8 N + 16 I: 804 AngularKinematics, 436 EulerRates)
 *       16   40  GUID of the FMU, NUL-padded
 *       56    4  fmuType of the instance (0 model exchange, 1 co-simulation)
 *       60    4  state-machine state (one ak_state bit)
 *       64    8  time (IEEE 754 double)
 *       72    8  stop time
 *       80    4  stop time defined (0 or 1)
 *       84    4  reserved, 0
 *       88  8 N  the variable values, by value reference: inputs, outputs, parameters
 *   88+8N  16 I  the input derivatives: I inputs x orders 1 and 2
 *  88+8N+16I  4  CRC-32 (IEEE 802.3, reflected, polynomial 0xEDB88320) of the bytes before it
 *
 * What is not in a state: the instance name, the callbacks and the debug-logging settings
 * belong to the instance, not to the simulation, and stay as they are when a state is set.
 * Byte strings that are too short or long, carry another magic, version or GUID, fail the
 * checksum, or hold values the instance could never have are refused with fmi2Error and a
 * message saying which; the instance and the caller's state are then left as they were. */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "ak_bytes.h"
#include "fmi2Functions.h"
#include "fmi2_instance.h"
#include "fmi2_logging.h"
#include "fmi2_state_machine.h"

#define AK_STATE_MAGIC "AKinFMUs"
#define AK_STATE_FORMAT_VERSION 2u
#define AK_STATE_GUID_FIELD 40

enum {
    OFFSET_MAGIC = 0,
    OFFSET_VERSION = 8,
    OFFSET_SIZE = 12,
    OFFSET_GUID = 16,
    OFFSET_FMU_TYPE = 56,
    OFFSET_STATE = 60,
    OFFSET_TIME = 64,
    OFFSET_STOP_TIME = 72,
    OFFSET_STOP_TIME_DEFINED = 80,
    OFFSET_RESERVED = 84,
    OFFSET_VALUES = 88,
    /* The largest state any model can have: the in-memory buffer's size. */
    AK_STATE_MAX_SIZE = OFFSET_VALUES + 8 * AK_MAX_VARIABLES +
                        8 * AK_MAX_INPUTS * AK_MAX_INPUT_DERIVATIVE_ORDER + 4
};

/* The model's offsets (the layout above). */
static size_t offset_input_derivatives(void) {
    return (size_t)OFFSET_VALUES + 8u * (size_t)AK_MODEL.n_value_references;
}

static size_t offset_checksum(void) {
    return offset_input_derivatives() +
           8u * (size_t)AK_MODEL.n_inputs * AK_MAX_INPUT_DERIVATIVE_ORDER;
}

static size_t state_size(void) {
    return offset_checksum() + 4u;
}


/* The in-memory FMU state: the bytes, in the instance's list of live states. A pointer the
 * master gives back is looked up in that list by address, never dereferenced first: a stray or
 * freed pointer is refused without reading the memory it points to. */
struct ak_fmu_state_s {
    struct ak_fmu_state_s *next;
    unsigned char bytes[AK_STATE_MAX_SIZE];
};
typedef struct ak_fmu_state_s ak_fmu_state;

/* The decoded content of a state. */
typedef struct {
    fmi2Type fmu_type;
    ak_state state;
    double time;
    bool stop_time_defined;
    double stop_time;
    double values[AK_MAX_VARIABLES];
    double input_derivatives[AK_MAX_INPUTS][AK_MAX_INPUT_DERIVATIVE_ORDER];
} ak_state_content;

static void encode(const ak_instance *instance, unsigned char bytes[AK_STATE_MAX_SIZE]) {
    memset(bytes, 0, state_size());
    memcpy(bytes + OFFSET_MAGIC, AK_STATE_MAGIC, 8);
    ak_put_u32(bytes + OFFSET_VERSION, AK_STATE_FORMAT_VERSION);
    ak_put_u32(bytes + OFFSET_SIZE, (uint32_t)state_size());
    memcpy(bytes + OFFSET_GUID, AK_MODEL.guid, strlen(AK_MODEL.guid));
    ak_put_u32(bytes + OFFSET_FMU_TYPE, (uint32_t)instance->fmu_type);
    ak_put_u32(bytes + OFFSET_STATE, (uint32_t)instance->state);
    ak_put_f64(bytes + OFFSET_TIME, instance->time);
    ak_put_f64(bytes + OFFSET_STOP_TIME, instance->stop_time);
    ak_put_u32(bytes + OFFSET_STOP_TIME_DEFINED, instance->stop_time_defined ? 1u : 0u);
    for (int vr = 0; vr < AK_MODEL.n_value_references; vr++) {
        ak_put_f64(bytes + OFFSET_VALUES + 8 * (size_t)vr, instance->data.values[vr]);
    }
    for (int k = 0; k < AK_MODEL.n_inputs; k++) {
        for (int n = 0; n < AK_MAX_INPUT_DERIVATIVE_ORDER; n++) {
            ak_put_f64(bytes + offset_input_derivatives() +
                        8u * (size_t)(AK_MAX_INPUT_DERIVATIVE_ORDER * k + n),
                    instance->data.input_derivatives[k][n]);
        }
    }
    ak_put_u32(bytes + offset_checksum(), ak_crc32(bytes, offset_checksum()));
}

static const char *interface_name(uint32_t fmu_type) {
    return fmu_type == (uint32_t)fmi2ModelExchange ? "model exchange" : "co-simulation";
}

static bool is_one_state(uint32_t state) {
    const uint32_t all = AK_STATE_INSTANTIATED | AK_STATE_INITIALIZATION_MODE |
                         AK_STATE_STEP_COMPLETE | AK_STATE_STEP_FAILED | AK_STATE_STEP_CANCELED |
                         AK_STATE_TERMINATED | AK_STATE_EVENT_MODE |
                         AK_STATE_CONTINUOUS_TIME_MODE;
    return state != 0 && (state & (state - 1)) == 0 && (state & ~all) == 0;
}

static bool state_belongs_to(uint32_t state, uint32_t fmu_type) {
    const uint32_t common = AK_STATE_INSTANTIATED | AK_STATE_INITIALIZATION_MODE |
                            AK_STATE_TERMINATED;
    const uint32_t own = fmu_type == (uint32_t)fmi2ModelExchange
                             ? AK_STATE_EVENT_MODE | AK_STATE_CONTINUOUS_TIME_MODE
                             : AK_STATE_STEP_COMPLETE | AK_STATE_STEP_FAILED |
                                   AK_STATE_STEP_CANCELED;
    return (state & (common | own)) != 0;
}

/* Checks a byte string from its length to its last value and decodes it; on failure logs why
 * (as function) and leaves content unspecified. Nothing of the instance is touched. */
static bool decode(const ak_instance *instance, ak_function function, const unsigned char *bytes,
                   size_t size, ak_state_content *content) {
    const char *name = ak_function_name(function);
    if (size < OFFSET_GUID || memcmp(bytes + OFFSET_MAGIC, AK_STATE_MAGIC, 8) != 0) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error,
               "%s: the %zu bytes are not an %s FMU state (%s)", name, size,
               AK_MODEL.model_identifier,
               size < OFFSET_GUID ? "too short for the header" : "wrong magic bytes");
        return false;
    }
    const uint32_t version = ak_get_u32(bytes + OFFSET_VERSION);
    if (version != AK_STATE_FORMAT_VERSION) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error,
               "%s: FMU state format version %u is not supported (this binary reads version %u)",
               name, version, AK_STATE_FORMAT_VERSION);
        return false;
    }
    const uint32_t declared = ak_get_u32(bytes + OFFSET_SIZE);
    if (size != state_size() || declared != state_size()) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error,
               "%s: the FMU state is %zu bytes long and declares %u bytes; format version %u "
               "of %s has %zu bytes (truncated or extended)",
               name, size, declared, AK_STATE_FORMAT_VERSION, AK_MODEL.model_identifier,
               state_size());
        return false;
    }
    const uint32_t stored = ak_get_u32(bytes + offset_checksum());
    const uint32_t computed = ak_crc32(bytes, offset_checksum());
    if (stored != computed) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error,
               "%s: the FMU state is corrupt: its CRC-32 is 0x%08x, the bytes give 0x%08x", name,
               stored, computed);
        return false;
    }
    char guid[AK_STATE_GUID_FIELD + 1];
    memcpy(guid, bytes + OFFSET_GUID, AK_STATE_GUID_FIELD);
    guid[AK_STATE_GUID_FIELD] = '\0';
    if (strcmp(guid, AK_MODEL.guid) != 0) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error,
               "%s: the FMU state is of an FMU with GUID \"%s\", not this one's (%s) \"%s\"",
               name, guid, AK_MODEL.model_identifier, AK_MODEL.guid);
        return false;
    }
    const uint32_t fmu_type = ak_get_u32(bytes + OFFSET_FMU_TYPE);
    if (fmu_type != (uint32_t)instance->fmu_type) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error,
               "%s: the FMU state is of a %s instance (fmuType %u); this instance is for %s",
               name, fmu_type <= 1 ? interface_name(fmu_type) : "unknown", fmu_type,
               interface_name((uint32_t)instance->fmu_type));
        return false;
    }
    const uint32_t state = ak_get_u32(bytes + OFFSET_STATE);
    const uint32_t stop_time_defined = ak_get_u32(bytes + OFFSET_STOP_TIME_DEFINED);
    content->time = ak_get_f64(bytes + OFFSET_TIME);
    content->stop_time = ak_get_f64(bytes + OFFSET_STOP_TIME);
    if (!is_one_state(state) || !state_belongs_to(state, fmu_type) || stop_time_defined > 1 ||
        ak_get_u32(bytes + OFFSET_RESERVED) != 0 || !isfinite(content->time) ||
        !isfinite(content->stop_time)) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error,
               "%s: the FMU state holds an impossible header (state 0x%x, time %g, stop time "
               "%g, stop time defined %u)",
               name, state, content->time, content->stop_time, stop_time_defined);
        return false;
    }
    for (int vr = 0; vr < AK_MODEL.n_value_references; vr++) {
        const ak_variable *variable = ak_variable_of((unsigned int)vr);
        content->values[vr] = ak_get_f64(bytes + OFFSET_VALUES + 8 * (size_t)vr);
        if (variable == NULL) {
            continue; /* a hole of the table: never read */
        }
        if (!isfinite(content->values[vr])) {
            ak_log(instance, AK_LOG_ERROR, fmi2Error,
                   "%s: the FMU state holds %s = %g, which is not finite", name, variable->name,
                   content->values[vr]);
            return false;
        }
        const bool integral = variable->type != AK_TYPE_INTEGER ||
                              content->values[vr] == floor(content->values[vr]);
        if (variable->causality == AK_CAUSALITY_PARAMETER &&
            (!integral || AK_MODEL.check_parameter(variable, content->values[vr]) != NULL)) {
            ak_log(instance, AK_LOG_ERROR, fmi2Error,
                   "%s: the FMU state holds the parameter %s = %.17g, which it cannot have", name,
                   variable->name, content->values[vr]);
            return false;
        }
    }
    for (int k = 0; k < AK_MODEL.n_inputs; k++) {
        for (int n = 0; n < AK_MAX_INPUT_DERIVATIVE_ORDER; n++) {
            const double d = ak_get_f64(bytes + offset_input_derivatives() +
                                     8u * (size_t)(AK_MAX_INPUT_DERIVATIVE_ORDER * k + n));
            if (!isfinite(d)) {
                ak_log(instance, AK_LOG_ERROR, fmi2Error,
                       "%s: the FMU state holds a derivative of order %d of %s = %g, which is "
                       "not finite",
                       name, n + 1, AK_MODEL.variables[k].name, d);
                return false;
            }
            content->input_derivatives[k][n] = d;
        }
    }
    content->fmu_type = (fmi2Type)fmu_type;
    content->state = (ak_state)state;
    content->stop_time_defined = stop_time_defined == 1;
    return true;
}

/* An FMUstate pointer the master gives back: ours, still alive, or a logged error. */
static ak_fmu_state *known_state(const ak_instance *instance, ak_function function,
                                 fmi2FMUstate state) {
    ak_fmu_state *s = instance->live_states;
    while (s != NULL && s != (ak_fmu_state *)state) {
        s = s->next;
    }
    if (s == NULL) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error,
               "%s: FMUstate %s is not an FMU state made by fmi2GetFMUstate or "
               "fmi2DeSerializeFMUstate of this FMU (or it was freed)",
               ak_function_name(function), state == NULL ? "NULL" : "given");
        return NULL;
    }
    return s;
}

/* The state object to fill: the one the master passes back for reuse, or a new one. */
static ak_fmu_state *state_to_fill(ak_instance *instance, ak_function function,
                                   fmi2FMUstate *FMUstate) {
    if (*FMUstate != NULL) {
        return known_state(instance, function, *FMUstate);
    }
    ak_fmu_state *s = instance->functions.allocateMemory(1, sizeof(ak_fmu_state));
    if (s == NULL) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error, "%s: out of memory allocating an FMU state",
               ak_function_name(function));
        return NULL;
    }
    s->next = instance->live_states;
    instance->live_states = s;
    return s;
}

static bool pointer_given(const ak_instance *instance, ak_function function, const void *p,
                          const char *what) {
    if (p == NULL) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error, "%s: %s is NULL", ak_function_name(function),
               what);
        return false;
    }
    return true;
}

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *FMUstate) {
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_GET_FMU_STATE) ||
        !pointer_given(instance, AK_FMI2_GET_FMU_STATE, FMUstate, "FMUstate")) {
        return fmi2Error;
    }
    ak_fmu_state *s = state_to_fill(instance, AK_FMI2_GET_FMU_STATE, FMUstate);
    if (s == NULL) {
        return fmi2Error;
    }
    encode(instance, s->bytes);
    *FMUstate = s;
    return fmi2OK;
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate FMUstate) {
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_SET_FMU_STATE)) {
        return fmi2Error;
    }
    const ak_fmu_state *s = known_state(instance, AK_FMI2_SET_FMU_STATE, FMUstate);
    ak_state_content content;
    if (s == NULL || !decode(instance, AK_FMI2_SET_FMU_STATE, s->bytes, state_size(), &content)) {
        return fmi2Error;
    }
    instance->state = content.state;
    instance->time = content.time;
    instance->stop_time_defined = content.stop_time_defined;
    instance->stop_time = content.stop_time;
    for (int vr = 0; vr < AK_MODEL.n_value_references; vr++) {
        instance->data.values[vr] = content.values[vr];
    }
    instance->data.any_input_derivative = false;
    for (int k = 0; k < AK_MODEL.n_inputs; k++) {
        for (int n = 0; n < AK_MAX_INPUT_DERIVATIVE_ORDER; n++) {
            instance->data.input_derivatives[k][n] = content.input_derivatives[k][n];
            if (content.input_derivatives[k][n] != 0.0) {
                instance->data.any_input_derivative = true;
            }
        }
    }
    /* The outputs are recomputed from the restored inputs and parameters, not trusted from the
     * bytes (they hold the last valid ones, which stay if the evaluation fails). */
    ak_instance_inputs_changed(instance);
    return fmi2OK;
}

fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *FMUstate) {
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_FREE_FMU_STATE) ||
        !pointer_given(instance, AK_FMI2_FREE_FMU_STATE, FMUstate, "FMUstate")) {
        return fmi2Error;
    }
    if (*FMUstate == NULL) {
        return fmi2OK; /* nothing to free, as with free(NULL) */
    }
    ak_fmu_state *s = known_state(instance, AK_FMI2_FREE_FMU_STATE, *FMUstate);
    if (s == NULL) {
        return fmi2Error;
    }
    ak_fmu_state **link = &instance->live_states;
    while (*link != s) {
        link = &(*link)->next;
    }
    *link = s->next;
    instance->functions.freeMemory(s);
    *FMUstate = NULL;
    return fmi2OK;
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate FMUstate, size_t *size) {
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_SERIALIZED_FMU_STATE_SIZE) ||
        !pointer_given(instance, AK_FMI2_SERIALIZED_FMU_STATE_SIZE, size, "size") ||
        known_state(instance, AK_FMI2_SERIALIZED_FMU_STATE_SIZE, FMUstate) == NULL) {
        return fmi2Error;
    }
    *size = state_size();
    return fmi2OK;
}

fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate FMUstate, fmi2Byte serializedState[],
                                 size_t size) {
    ak_instance *instance = c;
    if (!ak_call_allowed(instance, AK_FMI2_SERIALIZE_FMU_STATE)) {
        return fmi2Error;
    }
    const ak_fmu_state *s = known_state(instance, AK_FMI2_SERIALIZE_FMU_STATE, FMUstate);
    if (s == NULL ||
        !pointer_given(instance, AK_FMI2_SERIALIZE_FMU_STATE, serializedState,
                       "serializedState")) {
        return fmi2Error;
    }
    if (size < state_size()) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error,
               "fmi2SerializeFMUstate: size = %zu is too small; the state needs %zu bytes "
               "(fmi2SerializedFMUstateSize)",
               size, state_size());
        return fmi2Error;
    }
    memcpy(serializedState, s->bytes, state_size());
    return fmi2OK;
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte serializedState[], size_t size,
                                   fmi2FMUstate *FMUstate) {
    ak_instance *instance = c;
    const ak_function self = AK_FMI2_DE_SERIALIZE_FMU_STATE;
    ak_state_content content;
    if (!ak_call_allowed(instance, self) ||
        !pointer_given(instance, self, serializedState, "serializedState") ||
        !pointer_given(instance, self, FMUstate, "FMUstate") ||
        !decode(instance, self, (const unsigned char *)serializedState, size, &content)) {
        return fmi2Error;
    }
    ak_fmu_state *s = state_to_fill(instance, self, FMUstate);
    if (s == NULL) {
        return fmi2Error;
    }
    memcpy(s->bytes, serializedState, state_size());
    *FMUstate = s;
    return fmi2OK;
}

void ak_free_all_fmu_states(ak_instance *instance) {
    while (instance->live_states != NULL) {
        ak_fmu_state *s = instance->live_states;
        instance->live_states = s->next;
        instance->functions.freeMemory(s);
    }
}
