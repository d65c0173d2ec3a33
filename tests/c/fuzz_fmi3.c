/* libFuzzer harness of the FMI 3 layer (scripts/fuzz.sh, preset fuzz): the input bytes are a
 * program of FMI 3 calls on one co-simulation or model-exchange instance, each call's arguments
 * taken from the following bytes (value references, counts, doubles, integers, states). The
 * buffers the FMU may write are always as long as the count passed with them, so any read or
 * write out of bounds, crash or undefined behaviour is the FMU's. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fmi3Functions.h"
#include "model.h"

typedef struct {
    const uint8_t *data;
    size_t size;
} reader;

static uint8_t byte(reader *r) {
    if (r->size == 0) {
        return 0;
    }
    r->size--;
    return *r->data++;
}

static double number(reader *r) {
    uint64_t bits = 0;
    for (int i = 0; i < 8; i++) {
        bits = bits << 8 | byte(r);
    }
    double value;
    memcpy(&value, &bits, sizeof value);
    return value;
}

static void ignore_log(fmi3InstanceEnvironment e, fmi3Status s, fmi3String c, fmi3String m) {
    (void)e, (void)s, (void)c, (void)m;
}

enum { MAX_N = 96 };

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    reader r = {data, size};
    const int me = byte(&r) & 1;
    fmi3Instance instance =
        me ? fmi3InstantiateModelExchange("fuzz", AK_MODEL.guid, NULL, 0, byte(&r) & 1, NULL, ignore_log)
           : fmi3InstantiateCoSimulation("fuzz", AK_MODEL.guid, NULL, 0, byte(&r) & 1, 0, 0, NULL, 0,
                                         NULL, ignore_log, NULL);
    if (instance == NULL) {
        return 0;
    }
    fmi3FMUState states[2] = {NULL, NULL};
    while (r.size > 0) {
        fmi3ValueReference vr[8];
        const size_t nvr = byte(&r) % 9;
        for (size_t i = 0; i < nvr; i++) {
            vr[i] = byte(&r) < 250 ? byte(&r) % 80 : 1000;
        }
        const size_t n = byte(&r) % MAX_N;
        double values[MAX_N], other[MAX_N];
        int64_t ints[MAX_N];
        int32_t orders[8];
        for (size_t i = 0; i < n && i < 12; i++) {
            values[i] = byte(&r) & 1 ? number(&r) : (double)(int8_t)byte(&r) / 16.0;
        }
        for (size_t i = 12; i < n; i++) {
            values[i] = values[i % 12];
        }
        for (size_t i = 0; i < n; i++) {
            ints[i] = (int64_t)(int8_t)byte(&r);
        }
        for (size_t i = 0; i < 8; i++) {
            orders[i] = (int32_t)(byte(&r) % 3);
        }
        fmi3Boolean b[6];
        double t;
        size_t count;
        fmi3FMUState *state = &states[byte(&r) & 1];
        switch (byte(&r) % 22) {
        case 0: fmi3SetFloat64(instance, vr, nvr, values, n); break;
        case 1: fmi3GetFloat64(instance, vr, nvr, values, n); break;
        case 2: fmi3SetInt64(instance, vr, nvr, ints, n); break;
        case 3: fmi3GetInt64(instance, vr, nvr, ints, n); break;
        case 4: fmi3EnterInitializationMode(instance, byte(&r) & 1, number(&r), number(&r), byte(&r) & 1, number(&r)); break;
        case 5: fmi3ExitInitializationMode(instance); break;
        case 6: fmi3DoStep(instance, number(&r), number(&r), 1, &b[0], &b[1], &b[2], &t); break;
        case 7: fmi3GetOutputDerivatives(instance, vr, nvr, orders, values, n); break;
        case 8: fmi3GetDirectionalDerivative(instance, vr, nvr, &vr[nvr / 2], nvr - nvr / 2, values, n, other, byte(&r) % MAX_N); break;
        case 9: fmi3GetAdjointDerivative(instance, vr, nvr, &vr[nvr / 2], nvr - nvr / 2, values, n, other, byte(&r) % MAX_N); break;
        case 10: fmi3GetFMUState(instance, state); break;
        case 11: fmi3SetFMUState(instance, *state); break;
        case 12: fmi3FreeFMUState(instance, state); break;
        case 13: {
            unsigned char bytes[800];
            if (*state != NULL && fmi3SerializedFMUStateSize(instance, *state, &count) == fmi3OK &&
                count <= sizeof bytes && fmi3SerializeFMUState(instance, *state, bytes, count) == fmi3OK) {
                bytes[byte(&r) % count] ^= byte(&r); /* damaged, or not when 0 */
                fmi3FMUState copy = NULL;
                if (fmi3DeserializeFMUState(instance, bytes, count - (byte(&r) & 1), &copy) == fmi3OK) {
                    fmi3SetFMUState(instance, copy);
                    fmi3FreeFMUState(instance, &copy);
                }
            }
            break;
        }
        case 14: fmi3Terminate(instance); break;
        case 15: fmi3Reset(instance); break;
        case 16: fmi3EnterContinuousTimeMode(instance); fmi3SetTime(instance, number(&r)); break;
        case 17: fmi3UpdateDiscreteStates(instance, &b[0], &b[1], &b[2], &b[3], &b[4], &t); break;
        case 18: fmi3GetNumberOfVariableDependencies(instance, vr[0], &count); break;
        case 19: /* continuous states (AttitudePropagator has 4): counts 0 .. 5 */
            fmi3SetContinuousStates(instance, values, n % 6);
            fmi3GetContinuousStateDerivatives(instance, other, n % 6);
            break;
        case 20:
            fmi3GetContinuousStates(instance, values, n % 6);
            fmi3GetNominalsOfContinuousStates(instance, other, n % 6);
            break;
        default: fmi3EnterEventMode(instance); fmi3CompletedIntegratorStep(instance, 1, &b[0], &b[1]); break;
        }
    }
    fmi3FreeInstance(instance); /* frees the states left */
    return 0;
}
