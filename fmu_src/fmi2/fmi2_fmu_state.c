/* FMI 2.0 FMU state: get, set, free, serialize, deserialize (canGetAndSetFMUstate,
 * canSerializeFMUstate).
 *
 * An FMU state holds its serialized form, so there is one layout and one validator for both:
 * the byte image of models/model_state_image.h, with magic "AKinFMUs", format version 2
 * (version 1 held the 21 values of the 1-2-3-only FMU), the fmuType in the interface field and
 * the input derivatives: 92 + 8 N + 16 I bytes for N value references and I inputs (804
 * AngularKinematics, 436 EulerRates).
 *
 * What is not in a state: the instance name, the callbacks and the debug-logging settings
 * belong to the instance, not to the simulation, and stay as they are when a state is set.
 * Byte strings that are too short or long, carry another magic, version or GUID, fail the
 * checksum, or hold values the instance could never have are refused with fmi2Error and a
 * message saying which; the instance and the caller's state are then left as they were. */
#include <stdint.h>
#include <string.h>

#include "fmi2Functions.h"
#include "fmi2_instance.h"
#include "fmi2_logging.h"
#include "fmi2_state_machine.h"
#include "model_state_image.h"

/* The byte image is shared with the FMI 3 layer (models/model_state_image.c). */
static const ak_state_format FORMAT = {"AKinFMUs", 2u, "FMU state", "GUID", true};

static size_t state_size(void) {
    return ak_state_image_size(&FORMAT);
}

/* The in-memory FMU state: the bytes, in the instance's list of live states. A pointer the
 * master gives back is looked up in that list by address, never dereferenced first: a stray or
 * freed pointer is refused without reading the memory it points to. */
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

static void encode(const ak_instance *instance, unsigned char bytes[AK_STATE_IMAGE_MAX_SIZE]) {
    const ak_state_header header = {(uint32_t)instance->fmu_type, (uint32_t)instance->state,
                                    instance->time, instance->stop_time,
                                    instance->stop_time_defined};
    ak_state_image_write(&FORMAT, &header, &instance->data, bytes);
}

static const char *interface_name(uint32_t fmu_type) {
    return fmu_type == (uint32_t)fmi2ModelExchange ? "model exchange" : "co-simulation";
}

/* One state of the state machine, and one an instance of this fmuType can be in. */
static bool state_possible(uint32_t state, uint32_t fmu_type) {
    const uint32_t common = AK_STATE_INSTANTIATED | AK_STATE_INITIALIZATION_MODE |
                            AK_STATE_TERMINATED;
    const uint32_t own = fmu_type == (uint32_t)fmi2ModelExchange
                             ? AK_STATE_EVENT_MODE | AK_STATE_CONTINUOUS_TIME_MODE
                             : AK_STATE_STEP_COMPLETE | AK_STATE_STEP_FAILED |
                                   AK_STATE_STEP_CANCELED;
    return state != 0 && (state & (state - 1)) == 0 && (state & ~(common | own)) == 0;
}

/* Checks a byte string from its length to its last value and decodes it; on failure logs why
 * (as function) and leaves content unspecified. Nothing of the instance is touched. */
static bool decode(const ak_instance *instance, ak_function function, const unsigned char *bytes,
                   size_t size, ak_state_content *content) {
    const char *name = ak_function_name(function);
    if (!ak_state_image_check(&FORMAT, &instance->data, name, bytes, size, &content->header)) {
        return false;
    }
    const uint32_t fmu_type = content->header.interface;
    if (fmu_type != (uint32_t)instance->fmu_type) {
        ak_log(instance, AK_LOG_ERROR, fmi2Error,
               "%s: the FMU state is of a %s instance (fmuType %u); this instance is for %s",
               name, fmu_type <= 1 ? interface_name(fmu_type) : "unknown", fmu_type,
               interface_name((uint32_t)instance->fmu_type));
        return false;
    }
    return ak_state_image_read(&FORMAT, &instance->data, name, bytes, &content->header,
                               state_possible, content->values, content->input_derivatives);
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
    instance->state = (ak_state)content.header.state;
    instance->time = content.header.time;
    instance->stop_time_defined = content.header.stop_time_defined;
    instance->stop_time = content.header.stop_time;
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
