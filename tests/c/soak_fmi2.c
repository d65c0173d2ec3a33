/* Soak: millions of steps through one instance with inputs changing every step.
 *
 *   soak_fmi2 [steps [--no-rss-check]]      (default 10000000)
 *
 * Checked: every call fmi2OK; the outputs of every step bit for bit what the core computes from
 * that step's inputs (no drift, no stale value); the instance's time exactly the sum of the
 * steps; not one message at the default logging level; no allocation after instantiation; and
 * the resident memory at the end no larger than after the first 10% of the steps (with 32 KiB
 * of slack for the C library). Prints steps/s and resident memory at start and end. Under
 * valgrind or a sanitizer the resident memory is mostly the tool's: --no-rss-check then
 * reports it without judging it. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime, sysconf */

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <fcntl.h>
#include <unistd.h>

#include "fmi2Functions.h"
#include "fmi2_test_callbacks.h"
#include "fmi2_test_instance.h"
#include "kinematics_123.h"

static const long RSS_SLACK_KIB = 32; /* a few pages: the kernel may account a page late */
static const long INPUT_PERIOD = 1000000;

/* Read with open/read into a stack buffer: stdio would allocate, and the measurement must not
 * disturb what it measures. */
static long resident_kib(void) {
    char text[128] = {0};
    const int fd = open("/proc/self/statm", O_RDONLY);
    if (fd < 0) {
        return -1;
    }
    const ssize_t got = read(fd, text, sizeof text - 1);
    close(fd);
    long size = 0, resident = -1;
    if (got <= 0 || sscanf(text, "%ld %ld", &size, &resident) != 2) {
        return -1;
    }
    return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

static double seconds_since(const struct timespec *start) {
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (double)(now.tv_sec - start->tv_sec) + 1e-9 * (double)(now.tv_nsec - start->tv_nsec);
}

/* The outputs of the model's main group (AngularKinematics: omega and alpha, 12; EulerRates: 13). */
static fmi2ValueReference OUTPUTS[AK_MAX_VARIABLES];

int main(int argc, char **argv) {
    const long steps = argc > 1 ? atol(argv[1]) : 10000000L;
    const bool check_rss = !(argc > 2 && strcmp(argv[2], "--no-rss-check") == 0);
    if (steps < 100) {
        fprintf(stderr, "usage: %s [steps >= 100]\n", argv[0]);
        return 2;
    }
    const double step_size = 1e-3;
    const size_t n_outputs = ak_test_main_outputs(OUTPUTS);
    /* A model with the 1-2-3 kernel's layout (default sequence body123): every step whose angles
     * have the same sines in libm as in the FMU against the hand-written core; the other steps
     * and other models against a fresh evaluation of the model (ak_test_outputs_consistent). */
    const bool against_core = ak_test_has_kinematics_123_layout();
    ak_recorder recorder;
    ak_recorder_clear(&recorder);
    const fmi2CallbackFunctions functions = ak_test_callbacks(&recorder);
    fmi2Component c = ak_test_instantiate("soak", &functions, false);
    /* No stop time: the run goes as far as it is told. */
    if (c == NULL || fmi2SetupExperiment(c, fmi2False, 0.0, 0.0, fmi2False, 0.0) != fmi2OK ||
        fmi2EnterInitializationMode(c) != fmi2OK || fmi2ExitInitializationMode(c) != fmi2OK) {
        printf("FAIL soak: setup\n");
        return 1;
    }
    const long allocations_after_setup = ak_test_total_allocations();
    double time = 0.0;
    long failed_calls = 0, drifted_steps = 0, core_steps = 0, rss_start = -1;
    /* A first reading pages in what reading needs (sscanf, locale), so that it is not counted
     * as growth between the two readings that matter. */
    (void)resident_kib();
    struct timespec start;
    clock_gettime(CLOCK_MONOTONIC, &start);
    for (long step = 0; step < steps; step++) {
        if (step == steps / 10) {
            rss_start = resident_kib();
        }
        /* Inputs sweep several turns, fast and slow, and repeat every INPUT_PERIOD steps, so that
         * after the first period the same code paths (of libm too) are run again: any growth of
         * the resident memory after that is the FMU's. */
        const double phase = (double)(step % INPUT_PERIOD) * 1e-4;
        fmi2Real inputs[AK_TEST_MAX_INPUTS];
        for (int j = 0; j < (int)ak_test_n_inputs(); j++) {
            /* theta[2] (j = 1) within 1.1 rad of 0: away from EulerRates' singularity; the phase j
             * keeps the inputs apart (QuaternionKinematics: q = (0.1, 0.1, 0.1, 0.1) is singular). */
            inputs[j] = (j == 1 ? 1.0 : 1.0 + j) * sin(phase * (1.0 + 0.37 * j)) +
                        0.1 * cos(phase * 97.0 + j);
        }
        fmi2Real outputs[AK_MAX_VARIABLES], expected[AK_MAX_VARIABLES];
        failed_calls += fmi2SetReal(c, AK_TEST_INPUT_VRS, ak_test_n_inputs(), inputs) != fmi2OK;
        failed_calls += fmi2DoStep(c, time, step_size, fmi2True) != fmi2OK;
        time += step_size;
        failed_calls += fmi2GetReal(c, OUTPUTS, n_outputs, outputs) != fmi2OK;
        if (against_core && ak_test_libm_sines_agree(&inputs[0])) {
            ak_angular_kinematics_123(&inputs[0], &inputs[3], &inputs[6], &expected[0],
                                      &expected[3], &expected[6], &expected[9]);
            drifted_steps += memcmp(outputs, expected, n_outputs * sizeof outputs[0]) != 0;
            core_steps++;
        } else {
            drifted_steps += !ak_test_outputs_consistent(c);
        }
    }
    const double seconds = seconds_since(&start);
    const long rss_end = resident_kib();
    fmi2Real last_time = 0.0;
    failed_calls += fmi2GetRealStatus(c, fmi2LastSuccessfulTime, &last_time) != fmi2OK;
    const long allocations_during_run = ak_test_total_allocations() - allocations_after_setup;
    failed_calls += fmi2Terminate(c) != fmi2OK;
    fmi2FreeInstance(c);
    const bool rss_flat = !check_rss || (rss_start > 0 && rss_end > 0 && rss_end <= rss_start + RSS_SLACK_KIB);
    printf("soak_fmi2: %ld steps in %.2f s (%.3g steps/s; a step = fmi2SetReal of %zu inputs, "
           "fmi2DoStep, fmi2GetReal of %zu outputs; %s)\n",
           steps, seconds, (double)steps / seconds, ak_test_n_inputs(), n_outputs,
           AK_MODEL.model_identifier);
    printf("soak_fmi2: resident memory %ld KiB after %ld steps, %ld KiB at the end%s\n",
           rss_start, steps / 10, rss_end, !check_rss ? " (not checked)" : rss_flat ? "" : " (GREW)");
    printf("soak_fmi2: %ld failed calls, %ld steps whose outputs differ from the expected, "
           "%zu messages logged, %ld allocations during the run, %ld left after freeing, "
           "final time %.17g (expected %.17g)\n",
           failed_calls, drifted_steps, recorder.count, allocations_during_run,
           ak_test_live_allocations(), last_time, time);
    if (against_core) {
        printf("soak_fmi2: %ld steps against the hand-written core (libm's sines = the FMU's), "
               "the others against a fresh evaluation\n", core_steps);
    }
    const bool ok = failed_calls == 0 && drifted_steps == 0 && recorder.count == 0 &&
                    (!against_core || core_steps > 0) &&
                    allocations_during_run == 0 && ak_test_live_allocations() == 0 &&
                    last_time == time && rss_flat;
    if (!ok) {
        printf("FAIL soak\n");
    }
    return ok ? 0 : 1;
}
