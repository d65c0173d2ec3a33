/* Abuse test of AttitudePropagator, linked with the FMU's own sources (the shared harness of
 * test_fmi2_calls / fuzz_fmi2 / test_fmi2_instances assumes the 9 inputs of the two algebraic
 * models; this program covers the model with states until it is generalized):
 *
 *   1. many instances: THREADS threads each create INSTANCES instances, run them interleaved over
 *      STEPS steps with input derivatives, and check every instance's q against one reference
 *      run, bit for bit (no shared state between instances);
 *   2. random calls: CALLS calls of FMI functions drawn at random, in random states of a
 *      co-simulation and a model-exchange instance, with random arguments (NaN, Inf, huge values,
 *      unknown value references, wrong array sizes, NULL arrays, corrupted FMU-state bytes). After
 *      every call: fmi2Error came with a message naming the function; the state q is unit
 *      (co-simulation) or finite (model exchange: the integrator sets it); a refused call changed
 *      no value of the instance that the master can read;
 *   3. every allocation freed at the end (counted).
 * Only the FMI 2 functions and the generated value references (AttitudePropagator_variables.h) are
 * used: what the master sees, read through fmi2GetReal and fmi2GetInteger when the instance is in
 * a state where they answer. Run under the sanitizer builds (cmake -DAK_SANITIZE=...) and valgrind
 * like the other abuse tests.
 *
 *     abuse_attitude [THREADS INSTANCES STEPS CALLS]     (ctest: 4 50 200 200000) */
#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "AttitudePropagator_variables.h"
#include "fmi2Functions.h"
#include "test_check.h"

static long live_allocations = 0;
static pthread_mutex_t allocation_lock = PTHREAD_MUTEX_INITIALIZER;

static void *counting_calloc(size_t n, size_t size) {
    void *p = calloc(n, size);
    if (p != NULL) {
        pthread_mutex_lock(&allocation_lock);
        live_allocations++;
        pthread_mutex_unlock(&allocation_lock);
    }
    return p;
}

static void counting_free(void *p) {
    if (p != NULL) {
        pthread_mutex_lock(&allocation_lock);
        live_allocations--;
        pthread_mutex_unlock(&allocation_lock);
    }
    free(p);
}

/* The last message an instance logged (the environment is a per-instance record). */
typedef struct {
    char text[1024];
    int count;
} last_message;

static void logger(fmi2ComponentEnvironment environment, fmi2String name, fmi2Status status,
                   fmi2String category, fmi2String message, ...) {
    (void)name;
    (void)status;
    (void)category;
    last_message *last = environment;
    if (last != NULL) {
        snprintf(last->text, sizeof last->text, "%s", message);
        last->count++;
    }
}

static fmi2Component instantiate(fmi2Type type, last_message *last) {
    const fmi2CallbackFunctions functions = {logger, counting_calloc, counting_free, NULL, last};
    return fmi2Instantiate("abuse", type, AP_GUID, "file:///unused", &functions, fmi2False,
                           fmi2False);
}

static uint64_t next(uint64_t *seed) {
    *seed = *seed * 6364136223846793005ULL + 1442695040888963407ULL;
    return *seed >> 11;
}

static double uniform(uint64_t *seed) {
    return (double)next(seed) / 9007199254740992.0 * 2.0 - 1.0;
}

/* ---- 1. many instances ------------------------------------------------------------------------ */

static const fmi2ValueReference OMEGA_VRS[3] = {AP_VR_OMEGA, AP_VR_OMEGA + 1, AP_VR_OMEGA + 2};
static const fmi2ValueReference Q_VRS[4] = {AP_VR_Q, AP_VR_Q + 1, AP_VR_Q + 2, AP_VR_Q + 3};

typedef struct {
    int instances;
    int steps;
    double reference[4];
} many_job;

static void drive(fmi2Component c, int step) {
    const double t = 0.01 * step;
    const fmi2Real omega[3] = {sin(t), 0.5, cos(2.0 * t)};
    const fmi2Real slope[3] = {cos(t), 0.0, -2.0 * sin(2.0 * t)};
    const fmi2Integer order[3] = {1, 1, 1};
    if (fmi2SetReal(c, OMEGA_VRS, 3, omega) != fmi2OK ||
        fmi2SetRealInputDerivatives(c, OMEGA_VRS, 3, order, slope) != fmi2OK ||
        fmi2DoStep(c, t, 0.01, fmi2True) != fmi2OK) {
        ak_check(false, "a step of a healthy instance (%ld)", (long)step);
    }
}

static bool start(fmi2Component c) {
    return c != NULL && fmi2SetupExperiment(c, fmi2False, 0.0, 0.0, fmi2False, 0.0) == fmi2OK &&
           fmi2EnterInitializationMode(c) == fmi2OK && fmi2ExitInitializationMode(c) == fmi2OK;
}

static void *many_instances(void *argument) {
    many_job *job = argument;
    fmi2Component *c = calloc((size_t)job->instances, sizeof *c);
    if (c == NULL) {
        ak_check(false, "out of memory");
        return NULL;
    }
    for (int i = 0; i < job->instances; i++) {
        c[i] = instantiate(fmi2CoSimulation, NULL);
        if (!start(c[i])) {
            ak_check(false, "start an instance (%ld)", (long)i);
        }
    }
    for (int step = 0; step < job->steps; step++) {
        for (int i = 0; i < job->instances; i++) {
            if (c[i] != NULL) {
                drive(c[i], step);
            }
        }
    }
    for (int i = 0; i < job->instances; i++) {
        double q[4];
        if (c[i] == NULL || fmi2GetReal(c[i], Q_VRS, 4, q) != fmi2OK ||
            memcmp(q, job->reference, sizeof q) != 0) {
            ak_check(false, "an instance's q differs from the reference run (%ld)", (long)i);
        }
        if (c[i] != NULL) {
            fmi2FreeInstance(c[i]);
        }
    }
    free(c);
    return NULL;
}

static void run_many(int threads, int instances, int steps) {
    many_job job = {instances, steps, {0}};
    fmi2Component reference = instantiate(fmi2CoSimulation, NULL);
    if (!start(reference)) {
        ak_check(false, "start the reference");
        return;
    }
    for (int step = 0; step < steps; step++) {
        drive(reference, step);
    }
    fmi2GetReal(reference, Q_VRS, 4, job.reference);
    fmi2FreeInstance(reference);
    pthread_t thread[64];
    for (int t = 0; t < threads; t++) {
        pthread_create(&thread[t], NULL, many_instances, &job);
    }
    for (int t = 0; t < threads; t++) {
        pthread_join(thread[t], NULL);
    }
}

/* ---- 2. random calls -------------------------------------------------------------------------- */

static double wild(uint64_t *seed) {
    static const double specials[] = {NAN, INFINITY, -INFINITY, 1e308, -1e308, 5e-324, 0.0, -0.0};
    return next(seed) % 4 == 0 ? specials[next(seed) % 8] : 10.0 * uniform(seed);
}

static fmi2ValueReference any_vr(uint64_t *seed) {
    return next(seed) % 8 == 0 ? (fmi2ValueReference)(next(seed) % 1000)
                               : (fmi2ValueReference)(next(seed) % AP_N_VALUE_REFERENCES);
}

/* The instance's time as the calls that succeeded set it (the master's bookkeeping), and the
 * time of the FMU state saved last. */
typedef struct {
    double now;
    double saved;
} clock_of_calls;

/* One random call; returns its status. */
static fmi2Status random_call(fmi2Component c, uint64_t *seed, fmi2FMUstate *saved,
                              clock_of_calls *clock) {
    fmi2ValueReference vr[4];
    fmi2Real values[8];
    fmi2Integer integers[4];
    const size_t n = (size_t)(next(seed) % 5);
    for (size_t i = 0; i < 4; i++) {
        vr[i] = any_vr(seed);
        values[i] = wild(seed);
        integers[i] = (fmi2Integer)(next(seed) % 30) - 3;
    }
    const double time = clock->now;
    switch (next(seed) % 21) {
    case 0: return fmi2SetReal(c, vr, n, values);
    case 1: return fmi2GetReal(c, vr, n, values);
    case 2: return fmi2SetInteger(c, vr, n, integers);
    case 3: return fmi2SetRealInputDerivatives(c, vr, n, integers, values);
    case 4: {
        const double t = next(seed) % 4 ? time : wild(seed), h = 0.1 * fabs(wild(seed));
        const fmi2Status status = fmi2DoStep(c, t, h, fmi2False);
        clock->now = status == fmi2OK ? t + h : clock->now;
        return status;
    }
    case 5: return fmi2SetContinuousStates(c, values, next(seed) % 2 ? 4 : n);
    case 6: return fmi2GetContinuousStates(c, values, next(seed) % 2 ? 4 : n);
    case 7: return fmi2GetDerivatives(c, next(seed) % 8 ? values : NULL, next(seed) % 2 ? 4 : n);
    case 8: return fmi2GetNominalsOfContinuousStates(c, values, next(seed) % 2 ? 4 : n);
    case 9: return fmi2GetEventIndicators(c, values, n);
    case 10: {
        const double t = wild(seed);
        const fmi2Status status = fmi2SetTime(c, t);
        clock->now = status == fmi2OK ? t : clock->now;
        return status;
    }
    case 11: return fmi2EnterInitializationMode(c);
    case 12: return fmi2ExitInitializationMode(c);
    case 13: return fmi2EnterContinuousTimeMode(c);
    case 14: return fmi2EnterEventMode(c);
    case 15: {
        const fmi2Status status = fmi2GetFMUstate(c, saved);
        clock->saved = status == fmi2OK ? clock->now : clock->saved;
        return status;
    }
    case 16: {
        const fmi2Status status = fmi2SetFMUstate(c, *saved);
        clock->now = status == fmi2OK ? clock->saved : clock->now;
        return status;
    }
    case 17: {
        size_t size = 0;
        unsigned char bytes[2048];
        if (*saved == NULL || fmi2SerializedFMUstateSize(c, *saved, &size) != fmi2OK ||
            size > sizeof bytes || fmi2SerializeFMUstate(c, *saved, (fmi2Byte *)bytes, size) != fmi2OK) {
            return fmi2OK; /* nothing to corrupt */
        }
        if (next(seed) % 2) {
            bytes[next(seed) % size] ^= (unsigned char)(1u << (next(seed) % 8));
        }
        fmi2FMUstate restored = NULL;
        const fmi2Status status = fmi2DeSerializeFMUstate(c, (fmi2Byte *)bytes, size, &restored);
        if (restored != NULL) {
            fmi2FreeFMUstate(c, &restored);
        }
        return status;
    }
    case 18: {
        const bool reset = next(seed) % 16 == 0;
        const double start = reset ? 0.0 : wild(seed);
        const fmi2Status status =
            reset ? fmi2Reset(c) : fmi2SetupExperiment(c, fmi2False, 0.0, start, fmi2False, 0.0);
        clock->now = status == fmi2OK ? start : clock->now;
        return status;
    }
    case 19: return fmi2GetDirectionalDerivative(c, vr, n, &vr[n % 4], 4 - n % 4, values, &values[4]);
    default: return next(seed) % 32 == 0 ? fmi2Terminate(c) : fmi2OK;
    }
}

/* What the master can read of an instance: every Real variable and the two Integer parameters,
 * with the statuses of the two reads (fmi2Error in a state where reading is not allowed). */
typedef struct {
    fmi2Status real_status, integer_status;
    fmi2Real real[AP_N_VALUE_REFERENCES];
    fmi2Integer integer[2];
} readable;

static void read_all(fmi2Component c, readable *r) {
    static const fmi2ValueReference INTEGERS[2] = {AP_VR_FRAME, AP_VR_SEQUENCE};
    fmi2ValueReference reals[AP_N_VALUE_REFERENCES];
    size_t n = 0;
    for (fmi2ValueReference vr = 0; vr < AP_N_VALUE_REFERENCES; vr++) {
        if (vr != AP_VR_FRAME && vr != AP_VR_SEQUENCE) {
            reals[n++] = vr;
        }
    }
    memset(r, 0, sizeof *r);
    r->real_status = fmi2GetReal(c, reals, n, r->real);
    r->integer_status = fmi2GetInteger(c, INTEGERS, 2, r->integer);
}

/* Both reads answered and gave the same bits (NaN included). */
static bool same_readings(const readable *a, const readable *b) {
    return a->real_status == b->real_status && a->integer_status == b->integer_status &&
           memcmp(a->real, b->real, sizeof a->real) == 0 &&
           memcmp(a->integer, b->integer, sizeof a->integer) == 0;
}

static void run_random_calls(fmi2Type type, long calls, uint64_t seed) {
    last_message last = {{0}, 0};
    fmi2Component c = instantiate(type, &last);
    fmi2FMUstate saved = NULL;
    clock_of_calls clock = {0.0, 0.0};
    if (c == NULL) {
        ak_check(false, "instantiate");
        return;
    }
    readable before, after;
    for (long k = 0; k < calls; k++) {
        read_all(c, &before);
        const int messages = last.count;
        const fmi2Status status = random_call(c, &seed, &saved, &clock);
        /* The logger callback moves last.count during the call, which cppcheck cannot see. */
        /* cppcheck-suppress knownConditionTrueFalse */
        if (status == fmi2Error && (last.count == messages || strstr(last.text, "fmi2") == NULL)) {
            ak_check(false, "fmi2Error without a message naming the function (%ld)", (long)k);
        }
        read_all(c, &after);
        /* A refused call changes no value the master can read (a refused
         * fmi2ExitInitializationMode included), where it could read them before and after. */
        if (status == fmi2Error && before.real_status <= fmi2Warning &&
            after.real_status <= fmi2Warning && !same_readings(&before, &after)) {
            ak_check(false, "a refused call changed a value (%ld)", (long)k);
        }
        if (after.real_status <= fmi2Discard) {
            const double *q = &after.real[AP_VR_Q];
            const double norm = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
            const bool finite =
                isfinite(q[0]) && isfinite(q[1]) && isfinite(q[2]) && isfinite(q[3]);
            if (!finite || (type == fmi2CoSimulation && fabs(norm - 1.0) > 1e-15)) {
                ak_check(false, "q not unit (co-simulation) or not finite (%ld)", (long)k);
            }
        }
    }
    if (saved != NULL) {
        fmi2FreeFMUstate(c, &saved);
    }
    fmi2FreeInstance(c);
}

int main(int argc, char **argv) {
    const int threads = argc > 4 ? atoi(argv[1]) : 4;
    const int instances = argc > 4 ? atoi(argv[2]) : 50;
    const int steps = argc > 4 ? atoi(argv[3]) : 200;
    const long calls = argc > 4 ? atol(argv[4]) : 200000;
    if (threads < 1 || threads > 64 || instances < 1 || steps < 1 || calls < 0) {
        printf("usage: abuse_attitude [THREADS(1..64) INSTANCES STEPS CALLS]\n");
        return 2;
    }
    run_many(threads, instances, steps);
    run_random_calls(fmi2CoSimulation, calls, 1);
    run_random_calls(fmi2ModelExchange, calls, 2);
    if (live_allocations != 0) {
        ak_check(false, "allocations not freed (%ld)", (long)live_allocations);
    }
    printf("AttitudePropagator abuse: %d threads x %d instances x %d steps, 2 x %ld random calls: "
           "%d failure(s)\n", threads, instances, steps, calls, ak_check_failures());
    return ak_check_exit_status();
}
