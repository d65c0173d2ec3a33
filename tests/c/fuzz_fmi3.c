/* libFuzzer harness of the FMI 3 layer (scripts/fuzz.sh, preset fuzz): the input bytes are a
 * program of FMI 3 calls on one co-simulation or model-exchange instance, each call's arguments
 * taken from the following bytes (value references, counts, doubles, integers, states). The
 * buffers the FMU may write are always as long as the count passed with them, so any read or
 * write out of bounds, crash or undefined behaviour is the FMU's. A call answered with fmi3Error
 * must leave the instance bit for bit as it was (the harness links the FMU's sources and
 * compares the whole instance); one that does aborts the run. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi3Functions.h"
#include "fmi3_layer.h"
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

/* A call answered with fmi3Error changed the instance: the oracle's failure, a crash for
 * libFuzzer. `before` is the instance copied just before the call. */
static void check_refused(fmi3Instance instance, fmi3_instance *before, fmi3Status status,
                          int call) {
    if (status == fmi3Error && memcmp(before, instance, sizeof *before) != 0) {
        fprintf(stderr, "call %d answered fmi3Error and changed the instance\n", call);
        abort();
    }
    memcpy(before, instance, sizeof *before); /* for a second call of the same case */
}

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
        fmi3_instance before;
        memcpy(&before, instance, sizeof before);
        fmi3Status status = fmi3OK;
        const int call = byte(&r) % 22;
        switch (call) {
        case 0: status = fmi3SetFloat64(instance, vr, nvr, values, n); break;
        case 1: status = fmi3GetFloat64(instance, vr, nvr, values, n); break;
        case 2: status = fmi3SetInt64(instance, vr, nvr, ints, n); break;
        case 3: status = fmi3GetInt64(instance, vr, nvr, ints, n); break;
        case 4: status = fmi3EnterInitializationMode(instance, byte(&r) & 1, number(&r), number(&r), byte(&r) & 1, number(&r)); break;
        case 5: status = fmi3ExitInitializationMode(instance); break;
        case 6: status = fmi3DoStep(instance, number(&r), number(&r), 1, &b[0], &b[1], &b[2], &t); break;
        case 7: status = fmi3GetOutputDerivatives(instance, vr, nvr, orders, values, n); break;
        case 8: status = fmi3GetDirectionalDerivative(instance, vr, nvr, &vr[nvr / 2], nvr - nvr / 2, values, n, other, byte(&r) % MAX_N); break;
        case 9: status = fmi3GetAdjointDerivative(instance, vr, nvr, &vr[nvr / 2], nvr - nvr / 2, values, n, other, byte(&r) % MAX_N); break;
        case 10: status = fmi3GetFMUState(instance, state); break;
        case 11: status = fmi3SetFMUState(instance, *state); break;
        case 12: status = fmi3FreeFMUState(instance, state); break;
        case 13: {
            unsigned char bytes[800];
            if (*state != NULL && fmi3SerializedFMUStateSize(instance, *state, &count) == fmi3OK &&
                count <= sizeof bytes && fmi3SerializeFMUState(instance, *state, bytes, count) == fmi3OK) {
                bytes[byte(&r) % count] ^= byte(&r); /* damaged, or not when 0 */
                fmi3FMUState copy = NULL;
                status = fmi3DeserializeFMUState(instance, bytes, count - (byte(&r) & 1), &copy);
                if (status == fmi3OK) {
                    status = fmi3SetFMUState(instance, copy);
                    check_refused(instance, &before, status, call);
                    status = fmi3FreeFMUState(instance, &copy);
                }
            }
            break;
        }
        case 14: status = fmi3Terminate(instance); break;
        case 15: status = fmi3Reset(instance); break;
        case 16:
            check_refused(instance, &before, fmi3EnterContinuousTimeMode(instance), call);
            status = fmi3SetTime(instance, number(&r));
            break;
        case 17: status = fmi3UpdateDiscreteStates(instance, &b[0], &b[1], &b[2], &b[3], &b[4], &t); break;
        case 18: status = fmi3GetNumberOfVariableDependencies(instance, vr[0], &count); break;
        case 19: /* continuous states (AttitudePropagator has 4): counts 0 .. 5 */
            check_refused(instance, &before, fmi3SetContinuousStates(instance, values, n % 6), call);
            status = fmi3GetContinuousStateDerivatives(instance, other, n % 6);
            break;
        case 20:
            check_refused(instance, &before, fmi3GetContinuousStates(instance, values, n % 6), call);
            status = fmi3GetNominalsOfContinuousStates(instance, other, n % 6);
            break;
        default:
            check_refused(instance, &before, fmi3EnterEventMode(instance), call);
            status = fmi3CompletedIntegratorStep(instance, 1, &b[0], &b[1]);
            break;
        }
        check_refused(instance, &before, status, call);
    }
    fmi3FreeInstance(instance); /* frees the states left */
    return 0;
}
