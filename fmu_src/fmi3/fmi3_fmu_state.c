/* FMI 3.0 FMU state: get, set, free, serialize, deserialize (canGetAndSetFMUState,
 * canSerializeFMUState). As in FMI 2, a state holds its serialized form: one layout, one
 * validator, the byte image of models/model_state_image.h with magic "AKinFMU3" (the FMI 2
 * states' is "AKinFMUs": neither reads the other), format version 1 and no input derivatives
 * (FMI 3 co-simulation has none): 92 + 8 N bytes for N value references (660 AngularKinematics,
 * 292 EulerRates).
 *
 * The instance name, the logger and the logging settings belong to the instance and stay as
 * they are when a state is set. A byte string with another length, magic, version or token, a
 * bad checksum or impossible values is refused with fmi3Error and a message; nothing changes. */
#include <stdlib.h>
#include <string.h>

#include "fmi3Functions.h"
#include "fmi3_instance.h"
#include "fmi3_logging.h"
#include "fmi3_state_machine.h"
#include "model_state_image.h"

static const ak_state_format FORMAT = {"AKinFMU3", 1u, "FMI 3 FMU state", "instantiationToken",
                                       false};

static size_t state_size(void) {
    return ak_state_image_size(&FORMAT);
}

/* A state the importer gives back is looked up in the instance's list by address, never
 * dereferenced first. */
struct ak3_fmu_state_s {
    struct ak3_fmu_state_s *next;
    unsigned char bytes[AK_STATE_IMAGE_MAX_SIZE];
};
typedef struct ak3_fmu_state_s ak3_fmu_state;

typedef struct {
    ak_state_header header;
    double values[AK_MAX_VARIABLES];
} ak3_state_content;

static void encode(const ak3_instance *instance, unsigned char bytes[AK_STATE_IMAGE_MAX_SIZE]) {
    const ak_state_header header = {(uint32_t)instance->interface, (uint32_t)instance->state,
                                    instance->time, instance->stop_time,
                                    instance->stop_time_defined};
    ak_state_image_write(&FORMAT, &header, &instance->data, bytes);
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

/* Checks a byte string from its length to its last value and decodes it; logs why not. */
static bool decode(const ak3_instance *instance, ak3_function function, const unsigned char *bytes,
                   size_t size, ak3_state_content *content) {
    const char *name = ak3_function_name(function);
    if (!ak_state_image_check(&FORMAT, &instance->data, name, bytes, size, &content->header)) {
        return false;
    }
    const uint32_t interface = content->header.interface;
    if (interface != (uint32_t)instance->interface) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error,
                "%s: the FMU state is of a %s instance; this instance is for %s", name,
                interface == AK3_MODEL_EXCHANGE ? "model-exchange" : "co-simulation",
                instance->interface == AK3_MODEL_EXCHANGE ? "model exchange" : "co-simulation");
        return false;
    }
    return ak_state_image_read(&FORMAT, &instance->data, name, bytes, &content->header,
                               state_possible, content->values, NULL);
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
    instance->state = (ak3_state)content.header.state;
    instance->time = content.header.time;
    instance->stop_time_defined = content.header.stop_time_defined;
    instance->stop_time = content.header.stop_time;
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
