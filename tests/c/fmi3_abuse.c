/* Abuse tests of the FMI 3 layer, linked with one model's FMI 3 sources (cmake/abuse_tests_fmi3.cmake),
 * for the sanitizer, valgrind and soak runs (scripts/check_sanitizers.sh, scripts/soak.sh):
 *
 *   fmi3_abuse calls               every FMI 3 function with a NULL instance, and with a live
 *                                  instance and NULL pointers or absurd sizes: no crash, fmi3Error,
 *                                  the live instance bit for bit as before
 *   fmi3_abuse instances N T STEPS N instances over T threads, each stepping with its own
 *                                  sequence and inputs, FMU states got, serialized, restored; each
 *                                  one's output bits equal a lone rerun's
 *   fmi3_abuse parallel STEPS      two instances on two threads, started together (they meet
 *                                  before their first step): each one's output bits equal a
 *                                  lone rerun's
 *   fmi3_abuse soak STEPS          one instance, inputs changing every step: every call fmi3OK
 *                                  (or a warning/discard the model explains), no error logged
 *
 * Exit status 0 on success; every failure is printed. */
#define _POSIX_C_SOURCE 200809L /* pthread_barrier_t */
#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi3Functions.h"
#include "fmi3_layer.h"
#include "model.h"
#include "test_check.h"

typedef struct {
    int errors;
    int messages;
} log_counts;

static void logger(fmi3InstanceEnvironment environment, fmi3Status status, fmi3String category,
                   fmi3String message) {
    (void)category;
    (void)message;
    log_counts *counts = environment;
    if (counts != NULL) {
        counts->messages++;
        counts->errors += status == fmi3Error;
    }
}

static fmi3Instance new_instance(log_counts *counts) {
    return fmi3InstantiateCoSimulation("abuse", AK_MODEL.guid, NULL, fmi3False, fmi3False,
                                       fmi3False, fmi3False, NULL, 0, counts, logger, NULL);
}

/* The first element of each input array (FMI 3 addresses arrays): theta, theta_dot, theta_ddot
 * (0, 3, 6) of AngularKinematics, omega, omega_dot (0, 3) of AttitudePropagator; returns how
 * many. All AK_MODEL.n_inputs input values are set at once. */
static size_t input_arrays(fmi3ValueReference vr[AK_MAX_INPUTS]) {
    size_t n = 0;
    for (int k = 0; k < AK_MODEL.n_inputs; k++) {
        const char *bracket = strchr(AK_MODEL.variables[k].name, '[');
        if (bracket == NULL || strcmp(bracket, "[1]") == 0) {
            vr[n++] = (fmi3ValueReference)k;
        }
    }
    return n;
}

/* The first element of each output array; *n_values gets their number of elements. */
static size_t output_arrays(fmi3ValueReference arrays[AK_MAX_VARIABLES], size_t *n_values) {
    size_t n_arrays = 0;
    *n_values = 0;
    for (int vr = AK_MODEL.n_inputs; vr < AK_MODEL.n_value_references; vr++) {
        const ak_variable *v = ak_variable_of((unsigned int)vr);
        if (v == NULL || v->causality != AK_CAUSALITY_OUTPUT) {
            continue;
        }
        (*n_values)++;
        const char *bracket = strchr(v->name, '[');
        if (bracket == NULL || strcmp(bracket, "[1]") == 0 || strcmp(bracket, "[1,1]") == 0) {
            arrays[n_arrays++] = (fmi3ValueReference)vr;
        }
    }
    return n_arrays;
}

/* The inputs of an instance at a step: exact binary fractions in [-2, 2). */
static void inputs_at(unsigned int instance, unsigned int step, double u[AK_MAX_INPUTS]) {
    uint64_t x = 0x9e3779b97f4a7c15ULL * (instance + 1) ^ (0xbf58476d1ce4e5b9ULL * (step + 1));
    for (int k = 0; k < AK_MAX_INPUTS; k++) {
        x = x * 6364136223846793005ULL + 1442695040888963407ULL;
        u[k] = (double)(x >> 11) * (4.0 / 9007199254740992.0) - 2.0;
    }
}

static int64_t sequence_of(unsigned int instance) {
    return (int64_t)(instance % 24) + 1;
}

/* The parallel mode's barrier, where its two threads meet before their first step (so that their
 * steps overlap from the start); NULL otherwise. */
static pthread_barrier_t *lockstep = NULL;

static void meet(void) {
    if (lockstep != NULL) {
        pthread_barrier_wait(lockstep);
    }
}

/* Runs an instance through its steps; returns a digest of every output bit. */
static uint64_t run_instance(unsigned int id, unsigned int steps, bool with_states) {
    log_counts counts = {0, 0};
    fmi3Instance instance = new_instance(&counts);
    ak_check(instance != NULL, "instantiate %u", id);
    if (instance == NULL) {
        meet(); /* the other thread waits there */
        return 0;
    }
    const int64_t sequence = sequence_of(id);
    /* The sequence parameter (70 AngularKinematics, 22 EulerRates), found by name, if any. */
    for (int vr = 0; vr < AK_MODEL.n_value_references; vr++) {
        const ak_variable *v = ak_variable_of((unsigned int)vr);
        if (v != NULL && strcmp(v->name, "sequence") == 0) {
            const fmi3ValueReference vr_sequence = (fmi3ValueReference)vr;
            ak_check(fmi3SetInt64(instance, &vr_sequence, 1, &sequence, 1) == fmi3OK,
                     "set sequence");
        }
    }
    ak_check(fmi3EnterInitializationMode(instance, fmi3False, 0, 0, fmi3False, 0) == fmi3OK,
             "enter");
    ak_check(fmi3ExitInitializationMode(instance) == fmi3OK, "exit");
    fmi3ValueReference inputs[AK_MAX_INPUTS];
    const size_t n_in = input_arrays(inputs);
    fmi3ValueReference arrays[AK_MAX_VARIABLES];
    size_t n_outputs = 0;
    const size_t n_arrays = output_arrays(arrays, &n_outputs);
    uint64_t digest = 1469598103934665603ULL;
    double t = 0.0;
    meet();
    fmi3FMUState state = NULL;
    for (unsigned int step = 0; step < steps; step++) {
        double u[AK_MAX_INPUTS], y[AK_MAX_VARIABLES];
        inputs_at(id, step, u);
        if (AK_MODEL.evaluate_in_step) {
            u[1] = 0.5 * u[1]; /* EulerRates: keep theta[2] in (-1, 1), away from singularities;
                                * AttitudePropagator: a smaller omega[2] */
        }
        ak_check(fmi3SetFloat64(instance, inputs, n_in, u, (size_t)AK_MODEL.n_inputs) == fmi3OK,
                 "set %u", step);
        fmi3Boolean event, terminate, early;
        double last;
        const fmi3Status s = fmi3DoStep(instance, t, 0.001, fmi3True, &event, &terminate, &early, &last);
        ak_check(s == fmi3OK || s == fmi3Warning, "step %u: %d", step, (int)s);
        t = last;
        const fmi3Status g = fmi3GetFloat64(instance, arrays, n_arrays, y, n_outputs);
        ak_check(g == fmi3OK || g == fmi3Warning, "get %u: %d", step, (int)g);
        for (size_t i = 0; i < n_outputs; i++) {
            uint64_t bits;
            memcpy(&bits, &y[i], sizeof bits);
            digest = (digest ^ bits) * 1099511628211ULL;
        }
        if (with_states && step % 7 == 3) {
            /* Get, serialize, deserialize, set: the instance continues from the same point. */
            ak_check(fmi3GetFMUState(instance, &state) == fmi3OK, "get state");
            size_t size = 0;
            ak_check(fmi3SerializedFMUStateSize(instance, state, &size) == fmi3OK, "size");
            unsigned char *bytes = malloc(size);
            ak_check(bytes != NULL && fmi3SerializeFMUState(instance, state, bytes, size) == fmi3OK,
                     "serialize");
            fmi3FMUState copy = NULL;
            ak_check(fmi3DeserializeFMUState(instance, bytes, size, &copy) == fmi3OK,
                     "deserialize");
            ak_check(fmi3SetFMUState(instance, copy) == fmi3OK, "set state");
            ak_check(fmi3FreeFMUState(instance, &copy) == fmi3OK && copy == NULL, "free state");
            free(bytes);
        }
    }
    /* The last state is left for fmi3FreeInstance to free. */
    ak_check(fmi3Terminate(instance) == fmi3OK, "terminate");
    fmi3FreeInstance(instance);
    ak_check(counts.errors == 0, "instance %u logged %d errors", id, counts.errors);
    return digest;
}

typedef struct {
    unsigned int first, count, steps;
    uint64_t *digests;
} work;

static void *run_work(void *argument) {
    work *w = argument;
    for (unsigned int i = 0; i < w->count; i++) {
        w->digests[w->first + i] = run_instance(w->first + i, w->steps, true);
    }
    return NULL;
}

static void instances(unsigned int n, unsigned int threads, unsigned int steps) {
    uint64_t *digests = calloc(n, sizeof *digests);
    pthread_t *ids = calloc(threads, sizeof *ids);
    work *works = calloc(threads, sizeof *works);
    if (digests == NULL || ids == NULL || works == NULL) {
        ak_check(0, "out of memory");
    } else {
        for (unsigned int k = 0; k < threads; k++) {
            works[k] = (work){k * n / threads, (k + 1) * n / threads - k * n / threads, steps,
                              digests};
            ak_check(pthread_create(&ids[k], NULL, run_work, &works[k]) == 0, "thread");
        }
        for (unsigned int k = 0; k < threads; k++) {
            pthread_join(ids[k], NULL);
        }
        for (unsigned int i = 0; i < n; i++) {
            ak_check(digests[i] == run_instance(i, steps, false),
                     "instance %u differs from its lone rerun", i);
        }
        printf("fmi3_abuse instances: %u instances x %u steps on %u threads, each bit-identical to a lone rerun\n",
               n, steps, threads);
    }
    free(digests);
    free(ids);
    free(works);
}

/* Two instances called in parallel from two threads (FMI 3.0.3, 2_2_common_mechanisms.adoc:
 * "functions of different instances can be called in parallel from different threads within the
 * same process"): the same bits as each alone. */
static void parallel(unsigned int steps) {
    pthread_barrier_t barrier;
    uint64_t digests[2] = {0, 0};
    work works[2] = {{0, 1, steps, digests}, {1, 1, steps, digests}};
    pthread_t ids[2];
    ak_check(pthread_barrier_init(&barrier, NULL, 2) == 0, "barrier");
    lockstep = &barrier;
    for (int k = 0; k < 2; k++) {
        ak_check(pthread_create(&ids[k], NULL, run_work, &works[k]) == 0, "thread");
    }
    for (int k = 0; k < 2; k++) {
        pthread_join(ids[k], NULL);
    }
    lockstep = NULL;
    pthread_barrier_destroy(&barrier);
    for (unsigned int i = 0; i < 2; i++) {
        ak_check(digests[i] == run_instance(i, steps, false),
                 "instance %u differs from its lone rerun", i);
    }
    printf("fmi3_abuse parallel (%s): 2 instances x %u steps on 2 threads at once, each "
           "bit-identical to a lone rerun\n", AK_MODEL.model_identifier, steps);
}

/* Every function with a NULL instance: fmi3Error (or nothing), no crash. */
static void null_instance(void) {
    double d[9] = {0};
    fmi3ValueReference vr[1] = {0};
    size_t n = 0;
    fmi3Boolean b = fmi3False;
    fmi3FMUState s = NULL;
    ak_check(fmi3SetFloat64(NULL, vr, 1, d, 3) == fmi3Error, "set");
    ak_check(fmi3GetFloat64(NULL, vr, 1, d, 3) == fmi3Error, "get");
    ak_check(fmi3DoStep(NULL, 0, 1, fmi3True, &b, &b, &b, d) == fmi3Error, "step");
    ak_check(fmi3GetFMUState(NULL, &s) == fmi3Error, "state");
    ak_check(fmi3GetNumberOfContinuousStates(NULL, &n) == fmi3Error, "states");
    ak_check(fmi3EnterConfigurationMode(NULL) == fmi3Error, "configuration");
    ak_check(fmi3GetClock(NULL, vr, 1, &b) == fmi3Error, "clock");
    ak_check(fmi3Reset(NULL) == fmi3Error, "reset");
    ak_check(fmi3Terminate(NULL) == fmi3Error, "terminate");
    fmi3FreeInstance(NULL);
    ak_check(fmi3InstantiateCoSimulation(NULL, AK_MODEL.guid, NULL, 0, 0, 0, 0, NULL, 0, NULL, NULL,
                                      NULL) == NULL, "no name");
    ak_check(fmi3InstantiateModelExchange("x", NULL, NULL, 0, 0, NULL, NULL) == NULL, "no token");
}

/* A live instance and NULL pointers or absurd counts: fmi3Error and one logged error each, and
 * the instance bit for bit as before. */
static void null_pointers(void) {
    log_counts counts = {0, 0};
    fmi3Instance instance = new_instance(&counts);
    fmi3_instance before;
    memcpy(&before, instance, sizeof before);
    fmi3ValueReference vr[2] = {0, 3};
    double d[9] = {0};
    size_t n;
    ak_check(fmi3SetFloat64(instance, NULL, 2, d, 6) == fmi3Error, "vr NULL");
    ak_check(fmi3SetFloat64(instance, vr, 2, NULL, 6) == fmi3Error, "values NULL");
    ak_check(fmi3SetFloat64(instance, vr, 2, d, SIZE_MAX) == fmi3Error, "SIZE_MAX");
    ak_check(fmi3GetFloat64(instance, vr, 2, d, 0) == fmi3Error, "nValues 0");
    ak_check(fmi3GetFMUState(instance, NULL) == fmi3Error, "state NULL");
    ak_check(fmi3SerializedFMUStateSize(instance, NULL, &n) == fmi3Error, "size of NULL");
    ak_check(fmi3DeserializeFMUState(instance, (const fmi3Byte *)"x", 1, NULL) == fmi3Error,
             "NULL out");
    ak_check(fmi3SetDebugLogging(instance, fmi3True, 3, NULL) == fmi3Error, "categories NULL");
    ak_check(fmi3GetNumberOfVariableDependencies(instance, 0, NULL) == fmi3Error, "of an input");
    ak_check(fmi3EnterInitializationMode(instance, fmi3True, -1.0, 0, fmi3False, 0) == fmi3Error,
             "tol");
    ak_check(fmi3EnterInitializationMode(instance, fmi3False, 0, 0, fmi3True, -1.0) == fmi3Error,
             "stop");
    ak_check(fmi3EnterInitializationMode(instance, fmi3False, 0, NAN, fmi3False, 0) == fmi3Error,
             "nan");
    ak_check(counts.errors == 12, "%d errors logged, expected 12", counts.errors);
    ak_check(memcmp(&before, instance, sizeof before) == 0, "a refused call changed the instance");
    fmi3FreeInstance(instance);
}

static void soak(unsigned long steps) {
    log_counts counts = {0, 0};
    fmi3Instance instance = new_instance(&counts);
    ak_check(fmi3EnterInitializationMode(instance, fmi3False, 0, 0, fmi3False, 0) == fmi3OK,
             "enter");
    ak_check(fmi3ExitInitializationMode(instance) == fmi3OK, "exit");
    fmi3ValueReference inputs[AK_MAX_INPUTS];
    const size_t n_in = input_arrays(inputs);
    fmi3ValueReference outputs[AK_MAX_VARIABLES];
    size_t n_values = 0;
    const size_t n_outputs = output_arrays(outputs, &n_values);
    double t = 0.0, y[AK_MAX_VARIABLES];
    for (unsigned long step = 0; step < steps; step++) {
        double u[AK_MAX_INPUTS];
        inputs_at(7, (unsigned int)step, u);
        u[1] *= 0.5;
        fmi3Boolean b;
        double last;
        if (fmi3SetFloat64(instance, inputs, n_in, u, (size_t)AK_MODEL.n_inputs) != fmi3OK ||
            fmi3DoStep(instance, t, 0.001, fmi3True, &b, &b, &b, &last) > fmi3Warning ||
            fmi3GetFloat64(instance, outputs, n_outputs, y, n_values) > fmi3Warning) {
            ak_check(0, "step %lu failed", step);
            break;
        }
        t = last;
        for (size_t k = 0; k < n_values; k++) {
            if (!isfinite(y[k])) {
                ak_check(0, "step %lu: output %zu = %g", step, k, y[k]);
                break;
            }
        }
    }
    ak_check(counts.errors == 0, "%d errors logged", counts.errors);
    fmi3FreeInstance(instance);
    printf("fmi3_abuse soak (%s): %lu steps, 0 errors\n", AK_MODEL.model_identifier, steps);
}

int main(int argc, char **argv) {
    const char *mode = argc > 1 ? argv[1] : "calls";
    if (strcmp(mode, "calls") == 0) {
        null_instance();
        null_pointers();
        printf("fmi3_abuse calls (%s): NULL instance and NULL pointers refused\n",
               AK_MODEL.model_identifier);
    } else if (strcmp(mode, "instances") == 0 && argc == 5) {
        instances((unsigned int)atoi(argv[2]), (unsigned int)atoi(argv[3]),
                  (unsigned int)atoi(argv[4]));
    } else if (strcmp(mode, "parallel") == 0 && argc == 3) {
        parallel((unsigned int)atoi(argv[2]));
    } else if (strcmp(mode, "soak") == 0 && argc == 3) {
        soak(strtoul(argv[2], NULL, 10));
    } else {
        fprintf(stderr, "usage: fmi3_abuse calls | instances N THREADS STEPS | parallel STEPS | soak STEPS\n");
        return 2;
    }
    return ak_check_exit_status();
}
