/* libFuzzer harness: the input is decoded into a sequence of FMI calls on a few instance slots,
 * with arbitrary arguments: value references in and out of range, counts, NULL arrays, NaN, Inf,
 * huge and denormal values, steps of any size and sign from any time, reset and free at any
 * point, FMU state handles and serialized bytes. Built with ASan+UBSan (-DAK_SANITIZE=fuzzer);
 * run by scripts/fuzz.sh. Besides the sanitizers, after every call it checks that
 *   - the status is one the FMU may return (never fmi2Fatal, fmi2Pending or garbage);
 *   - a call refused with fmi2Error left the instance bit for bit unchanged, one answered with
 *     fmi2Discard its inputs, parameters and time (ak_snapshot_same_inputs);
 *   - in every state where values can be read, the outputs are what the core computes from
 *     the instance's inputs (the lazy evaluation never serves stale outputs);
 *   - the logger only ever gets well-formed messages, which the master formats as printf does;
 * and at the end of each input, once every slot is freed, that no allocation is left.
 *
 * Encoding (every byte string decodes; missing bytes read as 0), per call:
 *   op byte (op = byte % (AK_N_OPS + 2); AK_N_OPS is fmi2Instantiate, AK_N_OPS + 1 the
 *   round trip of a serialized FMU state with changed bytes, see corrupt_round_trip), slot
 *   byte, then fmi2Instantiate's 6 bytes, the round trip's bytes, or the generic arguments of
 *   decode_args().
 * fuzz_seeds.py writes seed inputs in this encoding. With AK_FUZZ_TRACE set in the environment,
 * each call and its status is printed, to read what a crashing input does. */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2Functions.h"
#include "fmi2_test_callbacks.h"
#include "fmi2_test_instance.h"
#include "fmi2_test_ops.h"

enum { N_SLOTS = 3, N_STATES_PER_SLOT = 4, MAX_CALLS = 200, MAX_COUNT = 25 };

typedef struct {
    const uint8_t *data;
    size_t size;
} ak_input;

static uint8_t take_byte(ak_input *in) {
    if (in->size == 0) {
        return 0;
    }
    in->size--;
    return *in->data++;
}

static uint32_t take_u32(ak_input *in) {
    uint32_t value = 0;
    for (int i = 0; i < 4; i++) {
        value |= (uint32_t)take_byte(in) << (8 * i);
    }
    return value;
}

/* The values most likely to break arithmetic and comparisons; "the slot's time" is index
 * TIME_OF_SLOT so that steps can continue from where the instance is. */
static const double SPECIAL_REALS[] = {
    0.0, -0.0, 1.0, -1.0, 0.1, 0.5, 1e-3, 10.0, 1.5707963267948966, -1.5707963267948966,
    3.141592653589793, 1e6, -1e6, 1e200, -1e200, DBL_MAX, -DBL_MAX, DBL_MIN, 4.9e-324,
    -4.9e-324, 1e-310, 9007199254740992.0, NAN, -NAN, INFINITY, -INFINITY, 1.0 + DBL_EPSILON,
    1e-9, 2.0};
enum { N_SPECIAL_REALS = sizeof SPECIAL_REALS / sizeof SPECIAL_REALS[0], TIME_OF_SLOT = 0x7f };

static double take_real(ak_input *in, double slot_time) {
    const uint8_t choice = take_byte(in);
    if (choice == TIME_OF_SLOT) {
        return slot_time;
    }
    if (choice < TIME_OF_SLOT) {
        return SPECIAL_REALS[choice % N_SPECIAL_REALS];
    }
    uint64_t bits = (uint64_t)take_u32(in) | (uint64_t)take_u32(in) << 32;
    double value;
    memcpy(&value, &bits, sizeof value);
    return value;
}

static fmi2ValueReference take_vr(ak_input *in) {
    const uint8_t choice = take_byte(in);
    return choice < 0xf0 ? (fmi2ValueReference)(choice % 24) : take_u32(in);
}

static const fmi2String STRINGS[] = {"logStatusError", "logStatusWarning", "logCalls",
                                     "logEverything", "", "%s%n", NULL};
enum { N_STRINGS = sizeof STRINGS / sizeof STRINGS[0] };

static size_t value_size(ak_value_type type) {
    switch (type) {
    case AK_NO_VALUES: return 1;
    case AK_REAL_VALUES: return sizeof(fmi2Real);
    case AK_INTEGER_VALUES: return sizeof(fmi2Integer);
    case AK_BOOLEAN_VALUES: return sizeof(fmi2Boolean);
    case AK_STRING_VALUES: return sizeof(fmi2String);
    }
    return 1;
}

/* An array of exactly `count` values of `type` (so ASan sees any read past it). */
static void *take_values(ak_input *in, ak_value_type type, size_t count, double slot_time) {
    unsigned char *array = malloc(count * value_size(type) + 1);
    for (size_t i = 0; array != NULL && i < count; i++) {
        switch (type) {
        case AK_NO_VALUES: array[i] = take_byte(in); break;
        case AK_REAL_VALUES: ((fmi2Real *)(void *)array)[i] = take_real(in, slot_time); break;
        case AK_INTEGER_VALUES: ((fmi2Integer *)(void *)array)[i] = (fmi2Integer)take_u32(in); break;
        case AK_BOOLEAN_VALUES:
            ((fmi2Boolean *)(void *)array)[i] = (fmi2Boolean)(int8_t)take_byte(in);
            break;
        case AK_STRING_VALUES:
            ((fmi2String *)(void *)array)[i] = STRINGS[take_byte(in) % N_STRINGS];
            break;
        }
    }
    return array;
}

typedef struct {
    fmi2Component instance;
    fmi2FMUstate states[N_STATES_PER_SLOT];
} ak_slot;

/* Everything the generic decoding allocated, freed after the call. */
typedef struct {
    ak_args args;
    fmi2ValueReference *vr, *vr2;
    fmi2String *categories;
    ak_result result, result2;
} ak_decoded;

enum {
    NULL_VR = 1 << 0,
    NULL_VALUES = 1 << 1,
    NULL_VR2 = 1 << 2,
    NULL_KNOWN = 1 << 3,
    NULL_VALUES2 = 1 << 4,
    NULL_OUT = 1 << 5,
    NULL_CATEGORIES = 1 << 6,
    NULL_BYTES = 1 << 7
};

static void decode_args(ak_input *in, const ak_op *op, ak_slot *slot, ak_decoded *d) {
    const double time = slot->instance ? ((const ak_instance *)slot->instance)->time : 0.0;
    memset(d, 0, sizeof *d);
    ak_args *a = &d->args;
    const uint8_t nulls = take_byte(in);
    a->nvr = take_byte(in) % MAX_COUNT;
    d->vr = malloc(a->nvr * sizeof *d->vr + 1);
    for (size_t i = 0; d->vr != NULL && i < a->nvr; i++) {
        d->vr[i] = take_vr(in);
    }
    a->vr = (nulls & NULL_VR) ? NULL : d->vr;
    a->values = take_values(in, op->values_type, a->nvr, time);
    a->values2 = take_values(in, op->values2_type, a->nvr, time);
    a->nvr2 = take_byte(in) % MAX_COUNT;
    d->vr2 = malloc(a->nvr2 * sizeof *d->vr2 + 1);
    for (size_t i = 0; d->vr2 != NULL && i < a->nvr2; i++) {
        d->vr2[i] = take_vr(in);
    }
    a->vr2 = (nulls & NULL_VR2) ? NULL : d->vr2;
    a->known = take_values(in, AK_REAL_VALUES, a->nvr2, time);
    a->n_categories = take_byte(in) % 5;
    d->categories = malloc(a->n_categories * sizeof *d->categories + 1);
    for (size_t i = 0; d->categories != NULL && i < a->n_categories; i++) {
        d->categories[i] = STRINGS[take_byte(in) % N_STRINGS];
    }
    a->categories = (nulls & NULL_CATEGORIES) ? NULL : d->categories;
    a->n_bytes = take_byte(in);
    a->bytes = take_values(in, AK_NO_VALUES, a->n_bytes, time);
    for (int i = 0; i < 3; i++) {
        a->real[i] = take_real(in, time);
    }
    for (int i = 0; i < 3; i++) {
        a->flag[i] = (fmi2Boolean)(int8_t)take_byte(in);
    }
    a->kind = take_byte(in) % 6;
    fmi2FMUstate *state = &slot->states[take_byte(in) % N_STATES_PER_SLOT];
    a->state = *state;
    if (!(nulls & NULL_OUT)) {
        a->out = op->out_is_fmu_state ? (void *)state : (void *)&d->result;
        a->out2 = &d->result2;
    }
    /* The pointers kept in d for freeing; the arguments may hide them behind NULL. */
    if (nulls & NULL_VALUES) {
        free(a->values);
        a->values = NULL;
    }
    if (nulls & NULL_VALUES2) {
        free(a->values2);
        a->values2 = NULL;
    }
    if (nulls & NULL_KNOWN) {
        free(a->known);
        a->known = NULL;
    }
    if (nulls & NULL_BYTES) {
        free(a->bytes);
        a->bytes = NULL;
    }
}

static void free_decoded(ak_decoded *d) {
    free(d->vr);
    free(d->vr2);
    free(d->categories);
    free(d->args.values);
    free(d->args.values2);
    free(d->args.known);
    free(d->args.bytes);
}

static void violated(void) {
    abort(); /* libFuzzer reports the input that got here */
}

static void release_slot(ak_slot *slot) {
    if (slot->instance == NULL) {
        return;
    }
    for (int k = 0; k < N_STATES_PER_SLOT; k++) {
        if (slot->states[k] != NULL) {
            fmi2FreeFMUstate(slot->instance, &slot->states[k]);
            slot->states[k] = NULL;
        }
    }
    fmi2FreeInstance(slot->instance);
    slot->instance = NULL;
}

static void instantiate(ak_input *in, ak_slot *slot, ak_recorder *recorder) {
    char long_name[1500]; /* longer than any message buffer of the FMU, with a '%' */
    memset(long_name, 'n', sizeof long_name - 1);
    long_name[10] = '%';
    long_name[sizeof long_name - 1] = '\0';
    const char *const names[] = {"fuzz", "", NULL, "100% %s%n", long_name};
    const char *const guids[] = {AK_MODEL.guid, "{00000000-0000-0000-0000-000000000000}", NULL};
    const char *name = names[take_byte(in) % 5];
    const int type = take_byte(in) % 3;
    const char *guid = guids[take_byte(in) % 3];
    const uint8_t callbacks_choice = take_byte(in) % 5;
    const uint8_t failure = take_byte(in);
    const long fail_after = failure % 3;                    /* allocations that succeed, */
    const long failing = (failure >> 2) % 3 == 2 ? -1 : (failure >> 2) % 3 + 1; /* then fail */
    const fmi2Boolean logging_on = (fmi2Boolean)(take_byte(in) & 1);
    release_slot(slot);
    fmi2CallbackFunctions functions = ak_test_callbacks(recorder);
    if (callbacks_choice == 1) {
        functions.allocateMemory = NULL;
        functions.freeMemory = NULL;
    }
    if (callbacks_choice == 4) {
        functions.logger = NULL;
    }
    if (callbacks_choice == 3) {
        ak_test_fail_allocations(fail_after, failing);
    }
    slot->instance = fmi2Instantiate(name, (fmi2Type)type, guid, "file:///unused",
                                     callbacks_choice == 2 ? NULL : &functions, fmi2False,
                                     logging_on);
    ak_test_fail_allocations(-1, 0);
}

enum {
    READABLE = AK_INITIALIZATION_MODE | AK_STEP_MODE | AK_STEP_FAILED |
               AK_STEP_CANCELED | AK_TERMINATED | AK_EVENT_MODE |
               AK_CONTINUOUS_TIME_MODE
};

static void check_instance(fmi2Component c) {
    const ak_instance *instance = c;
    const unsigned int state = (unsigned int)instance->state;
    if (state == 0 || (state & (state - 1)) != 0 || (state & ~(unsigned int)(AK_INSTANTIATED | READABLE)) != 0 ||
        !isfinite(instance->time)) {
        violated();
    }
    if ((state & READABLE) && !ak_test_outputs_consistent(c)) {
        violated();
    }
}

/* fmi2GetFMUstate, fmi2SerializeFMUstate, then up to 8 bytes of the serialized state changed
 * (position and new value from the input; or the length cut or grown), fmi2DeSerializeFMUstate and,
 * when it is accepted, fmi2SetFMUstate. A rejected state must leave the handle NULL and the
 * instance unchanged; an accepted one must give an instance in a legal state (checked by the
 * caller). Every handle is freed. */
static fmi2Status corrupt_round_trip(ak_input *in, fmi2Component c) {
    enum { MAX_BYTES = 4096 };
    fmi2FMUstate state = NULL, restored = NULL;
    size_t size = 0;
    fmi2Byte bytes[MAX_BYTES + 16];
    const uint8_t n_changes = take_byte(in) % 9;
    const uint8_t length_change = take_byte(in);
    if (fmi2GetFMUstate(c, &state) != fmi2OK) {
        return fmi2Error;
    }
    if (fmi2SerializedFMUstateSize(c, state, &size) != fmi2OK || size > MAX_BYTES ||
        fmi2SerializeFMUstate(c, state, bytes, size) != fmi2OK) {
        violated();
    }
    for (int k = 0; k < n_changes; k++) {
        const size_t at = (size_t)take_byte(in) | (size_t)take_byte(in) << 8;
        bytes[at % size] = (fmi2Byte)take_byte(in);
    }
    if (length_change < 16) { /* cut */
        size = size > length_change ? size - length_change : 0;
    } else if (length_change < 32) { /* grown by zeros */
        memset(&bytes[size], 0, (size_t)(length_change - 16));
        size += (size_t)(length_change - 16);
    }
    ak_snapshot before;
    ak_snapshot_take(&before, c);
    const fmi2Status status = fmi2DeSerializeFMUstate(c, bytes, size, &restored);
    if (status != fmi2OK) {
        if (restored != NULL || !ak_snapshot_unchanged(&before, c)) {
            violated();
        }
    } else if (fmi2SetFMUstate(c, restored) != fmi2OK || fmi2FreeFMUstate(c, &restored) != fmi2OK) {
        violated();
    }
    if (fmi2FreeFMUstate(c, &state) != fmi2OK) {
        violated();
    }
    return status;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    ak_input in = {data, size};
    ak_recorder recorder;
    ak_recorder_clear(&recorder);
    ak_slot slots[N_SLOTS];
    memset(slots, 0, sizeof slots);
    const bool trace = getenv("AK_FUZZ_TRACE") != NULL;
    for (int call = 0; call < MAX_CALLS && in.size > 0; call++) {
        const int op_index = take_byte(&in) % (AK_N_OPS + 2);
        const int slot_index = take_byte(&in) % (N_SLOTS + 1);
        ak_slot no_instance = {0};
        ak_slot *slot = slot_index < N_SLOTS ? &slots[slot_index] : &no_instance;
        if (op_index == AK_N_OPS) {
            if (slot != &no_instance) {
                instantiate(&in, slot, &recorder);
            }
            if (trace) {
                fprintf(stderr, "slot %d: fmi2Instantiate -> %s\n", slot_index,
                        slot->instance ? "instance" : "NULL");
            }
            continue;
        }
        if (op_index == AK_N_OPS + 1) {
            if (slot->instance != NULL) {
                const fmi2Status status = corrupt_round_trip(&in, slot->instance);
                if (trace) {
                    fprintf(stderr, "slot %d: corrupted FMU state round trip -> %s\n", slot_index,
                            ak_status_name(status));
                }
                check_instance(slot->instance);
            }
            continue;
        }
        if (op_index == AK_OP_FREE_INSTANCE) {
            /* As a careful master: the FMU states first, then the instance (or NULL). */
            if (slot->instance == NULL) {
                fmi2FreeInstance(NULL);
            }
            release_slot(slot);
            if (trace) {
                fprintf(stderr, "slot %d: fmi2FreeInstance\n", slot_index);
            }
            continue;
        }
        const ak_op *op = &AK_OPS[op_index];
        ak_decoded decoded;
        decode_args(&in, op, slot, &decoded);
        ak_snapshot before;
        if (slot->instance != NULL) {
            ak_snapshot_take(&before, slot->instance);
        }
        const fmi2Status status = op->call(slot->instance, &decoded.args);
        free_decoded(&decoded);
        if (trace) {
            fprintf(stderr, "slot %d: %s -> %s%s\n", slot_index, op->name, ak_status_name(status),
                    slot->instance ? "" : " (no instance)");
        }
        if ((unsigned int)status > (unsigned int)fmi2Error) {
            violated();
        }
        if (slot->instance == NULL) {
            continue;
        }
        if ((status == fmi2Error && !ak_snapshot_unchanged(&before, slot->instance)) ||
            (status == fmi2Discard && !ak_snapshot_same_inputs(&before, slot->instance))) {
            violated();
        }
        check_instance(slot->instance);
    }
    for (int s = 0; s < N_SLOTS; s++) {
        release_slot(&slots[s]);
    }
    if (recorder.contract_violations != 0 || ak_test_live_allocations() != 0) {
        violated();
    }
    return 0;
}
