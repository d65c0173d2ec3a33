/* Many instances at once, and many threads each driving their own instances.
 *
 *   test_fmi2_instances [instances [threads [steps]]]      (default 1000 4 100)
 *
 * Each instance gets its own input trajectory. The outputs of every instance over every step
 * are hashed three ways, which must agree bit for bit:
 *   1. one instance alive at a time (the reference);
 *   2. all instances alive at once, stepped in turn by one thread;
 *   3. all instances alive at once, split over the threads, which step them concurrently.
 * Built with -DAK_SANITIZE=thread, run 3 is checked for data races (scripts/check_sanitizers.sh). */
#define _POSIX_C_SOURCE 200809L /* clock_gettime, sysconf */

#include <math.h>
#include <pthread.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "fmi2Functions.h"
#include "fmi2_test_callbacks.h"
#include "fmi2_test_instance.h"

static const double STEP_SIZE = 1e-3;

typedef struct {
    int first, stride, count; /* instances first, first + stride, ... (count of them) */
    int steps;
    bool one_at_a_time;
    long expect_live; /* > 0: allocations that must be live once all instances started */
    uint64_t *hashes; /* indexed by instance number, shared, each slot written by one worker */
    bool ok;
    char failure[160];
} ak_worker;

static void inputs_for(int instance, int step, fmi2Real inputs[AK_TEST_MAX_INPUTS]) {
    for (int j = 0; j < (int)ak_test_n_inputs(); j++) {
        /* theta[2] (j = 1) stays below 1.41 rad: away from EulerRates' singularity; the
         * 0.001 j keeps the inputs apart at the first step (QuaternionKinematics refuses q = 0). */
        inputs[j] = sin(0.37 * instance + 0.011 * step * (j + 1)) * (1.0 + 0.1 * j) +
                    0.0003 * (instance % 1000) + 0.001 * j;
    }
}

static uint64_t hash_bytes(uint64_t hash, const void *data, size_t size) {
    const unsigned char *bytes = data;
    for (size_t i = 0; i < size; i++) { /* FNV-1a */
        hash = (hash ^ bytes[i]) * 1099511628211u;
    }
    return hash;
}

static bool fail(ak_worker *worker, const char *what, int instance, int step) {
    worker->ok = false;
    snprintf(worker->failure, sizeof worker->failure, "%s (instance %d, step %d)", what, instance,
             step);
    return false;
}

/* The outputs of the model's main group (AngularKinematics: omega and alpha, 12; EulerRates: 13). */
static fmi2ValueReference OUTPUTS[AK_MAX_VARIABLES];
static size_t N_OUTPUTS;

static bool start(ak_worker *worker, const fmi2CallbackFunctions *functions, int number,
                  fmi2Component *c) {
    char name[32];
    snprintf(name, sizeof name, "instance-%d", number);
    *c = ak_test_instantiate(name, functions, false);
    fmi2Real inputs[AK_TEST_MAX_INPUTS];
    inputs_for(number, 0, inputs);
    if (*c == NULL || fmi2SetupExperiment(*c, fmi2False, 0.0, 0.0, fmi2False, 0.0) != fmi2OK ||
        fmi2EnterInitializationMode(*c) != fmi2OK ||
        fmi2SetReal(*c, AK_TEST_INPUT_VRS, ak_test_n_inputs(), inputs) != fmi2OK ||
        fmi2ExitInitializationMode(*c) != fmi2OK) {
        return fail(worker, "initialization failed", number, 0);
    }
    return true;
}

static bool advance(ak_worker *worker, fmi2Component c, int number, int step, double *time) {
    fmi2Real inputs[AK_TEST_MAX_INPUTS], outputs[AK_MAX_VARIABLES];
    inputs_for(number, step, inputs);
    if (fmi2SetReal(c, AK_TEST_INPUT_VRS, ak_test_n_inputs(), inputs) != fmi2OK ||
        fmi2DoStep(c, *time, STEP_SIZE, fmi2True) != fmi2OK ||
        fmi2GetReal(c, OUTPUTS, N_OUTPUTS, outputs) != fmi2OK) {
        return fail(worker, "step failed", number, step);
    }
    *time += STEP_SIZE;
    worker->hashes[number] = hash_bytes(worker->hashes[number], outputs, N_OUTPUTS * sizeof outputs[0]);
    return true;
}

static void *work(void *argument) {
    ak_worker *worker = argument;
    ak_recorder recorder;
    ak_recorder_clear(&recorder);
    const fmi2CallbackFunctions functions = ak_test_callbacks(&recorder);
    const int n = worker->one_at_a_time ? 1 : worker->count;
    fmi2Component *instances = calloc((size_t)n, sizeof *instances);
    double *times = calloc((size_t)n, sizeof *times);
    worker->ok = instances != NULL && times != NULL;
    for (int k = 0; worker->ok && k < worker->count; k += n) {
        for (int i = 0; i < n && worker->ok; i++) {
            const int number = worker->first + (k + i) * worker->stride;
            worker->hashes[number] = 1469598103934665603u;
            start(worker, &functions, number, &instances[i]);
        }
        if (worker->ok && worker->expect_live > 0 &&
            ak_test_live_allocations() != worker->expect_live) {
            fail(worker, "not every instance is alive (allocation count)", -1, 0);
        }
        for (int step = 1; step <= worker->steps && worker->ok; step++) {
            for (int i = 0; i < n && worker->ok; i++) {
                advance(worker, instances[i], worker->first + (k + i) * worker->stride, step,
                        &times[i]);
            }
        }
        for (int i = 0; i < n; i++) {
            if (instances[i] != NULL) {
                if (fmi2Terminate(instances[i]) != fmi2OK) {
                    fail(worker, "terminate failed", k + i, worker->steps);
                }
                fmi2FreeInstance(instances[i]);
                instances[i] = NULL;
            }
            times[i] = 0.0;
        }
    }
    if (worker->ok && recorder.count != 0) {
        fail(worker, "messages logged at the default logging level", -1, -1);
    }
    free(instances);
    free(times);
    return NULL;
}

static double seconds_since(const struct timespec *start_time) {
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (double)(now.tv_sec - start_time->tv_sec) +
           1e-9 * (double)(now.tv_nsec - start_time->tv_nsec);
}

/* How many allocations one live instance holds, measured rather than assumed. */
static long allocations_per_instance(void) {
    ak_recorder recorder;
    ak_recorder_clear(&recorder);
    const fmi2CallbackFunctions functions = ak_test_callbacks(&recorder);
    const long before = ak_test_live_allocations();
    fmi2Component c = ak_test_instantiate("probe", &functions, false);
    const long held = ak_test_live_allocations() - before;
    fmi2FreeInstance(c);
    return c != NULL ? held : -1;
}

static bool run(const char *label, int instances, int threads, int steps, bool one_at_a_time,
                uint64_t *hashes) {
    const long per_instance = allocations_per_instance();
    if (per_instance < 1) {
        printf("FAIL %s: cannot instantiate a probe instance\n", label);
        return false;
    }
    ak_worker *workers = calloc((size_t)threads, sizeof *workers);
    pthread_t *ids = calloc((size_t)threads, sizeof *ids);
    if (workers == NULL || ids == NULL) {
        free(workers);
        free(ids);
        return false;
    }
    struct timespec start_time;
    clock_gettime(CLOCK_MONOTONIC, &start_time);
    bool ok = true;
    for (int t = 0; t < threads; t++) {
        workers[t] = (ak_worker){.first = t, .stride = threads, .steps = steps,
                                 .count = (instances - t + threads - 1) / threads,
                                 .one_at_a_time = one_at_a_time, .hashes = hashes,
                                 .expect_live = threads == 1 && !one_at_a_time
                                                    ? per_instance * instances
                                                    : 0};
        if (threads == 1) {
            work(&workers[t]);
        } else if (pthread_create(&ids[t], NULL, work, &workers[t]) != 0) {
            printf("FAIL %s: cannot start thread %d\n", label, t);
            return false;
        }
    }
    for (int t = 0; t < threads; t++) {
        if (threads > 1) {
            pthread_join(ids[t], NULL);
        }
        if (!workers[t].ok) {
            printf("FAIL %s, thread %d: %s\n", label, t, workers[t].failure);
            ok = false;
        }
    }
    const double seconds = seconds_since(&start_time);
    printf("%-44s %6d instances %3d threads %6d steps: %8.3f s, %.3g instance-steps/s\n", label,
           instances, threads, steps, seconds, (double)instances * steps / seconds);
    free(workers);
    free(ids);
    return ok;
}

int main(int argc, char **argv) {
    const int instances = argc > 1 ? atoi(argv[1]) : 1000;
    const int threads = argc > 2 ? atoi(argv[2]) : 4;
    const int steps = argc > 3 ? atoi(argv[3]) : 100;
    if (instances < 1 || threads < 1 || steps < 1 || threads > instances) {
        fprintf(stderr, "usage: %s [instances [threads [steps]]] (threads <= instances)\n", argv[0]);
        return 2;
    }
    N_OUTPUTS = ak_test_main_outputs(OUTPUTS); /* before any thread starts */
    uint64_t *reference = calloc((size_t)instances, sizeof *reference);
    uint64_t *together = calloc((size_t)instances, sizeof *together);
    uint64_t *threaded = calloc((size_t)instances, sizeof *threaded);
    bool ok = reference != NULL && together != NULL && threaded != NULL;
    ok = ok && run("one instance alive at a time", instances, 1, steps, true, reference);
    ok = ok && run("all alive at once, one thread", instances, 1, steps, false, together);
    ok = ok && run("all alive at once, split over threads", instances, threads, steps, false,
                   threaded);
    int mismatches = 0;
    for (int i = 0; ok && i < instances; i++) {
        mismatches += reference[i] != together[i] || reference[i] != threaded[i];
    }
    /* Distinct inputs must give distinct results, or the comparison proves little. */
    int repeats = 0;
    for (int i = 1; ok && i < instances; i++) {
        repeats += reference[i] == reference[i - 1];
    }
    const long leaked = ak_test_live_allocations();
    printf("test_fmi2_instances: %d instances, %d threads, %d steps each: %d results differing "
           "from the one-at-a-time run, %d neighbours alike, %ld allocations left\n",
           instances, threads, steps, mismatches, repeats, leaked);
    free(reference);
    free(together);
    free(threaded);
    return ok && mismatches == 0 && repeats == 0 && leaked == 0 ? 0 : 1;
}
