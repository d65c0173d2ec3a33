/* The FMI 3 cycle beside the FMI 2 cycle and the bare core (issue 12), timed alternately in one
 * run, repeat after repeat, so that all three see the same machine load:
 *   - core: ak_general_angular_kinematics (body123) on the inputs of the step;
 *   - FMI 2 cycle: fmi2SetReal of the 9 inputs, fmi2DoStep, fmi2GetReal of the 12 outputs
 *     omega_fixed .. alpha_body (build/fmu/binaries/linux64/AngularKinematics.so);
 *   - FMI 3 cycle: three fmi3SetFloat64, one per input array (theta, theta_dot, theta_ddot),
 *     fmi3DoStep, one fmi3GetFloat64 of the four output arrays omega_fixed .. alpha_body
 *     (build/fmu3/binaries/x86_64-linux/AngularKinematics.so).
 * Inputs cycle through the table of bench/bench_inputs.h (that of bench_fmu.c), so every step
 * evaluates. CPU time of the thread;
 * medians over the repeats, the ratios are medians of the per-repeat ratios.
 *
 * Usage: bench_fmi3 FMI2_SO FMI3_SO [STEPS [REPEATS [core|fmi2|fmi3]]]   (bench/run.sh passes
 * the build's). With a loop named, only that loop runs, once: bench/run.sh counts its
 * instructions under callgrind. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime, dlopen */

#include <dlfcn.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "AngularKinematics_variables.h" /* KIN_GUID, generated */
#include "bench_inputs.h"
#include "bench_timing.h"
#include "fmi2FunctionTypes.h"
#include "fmi3FunctionTypes.h"
#include "kinematics_general.h"
#include "sequences.h"

enum { TABLE_ROWS = AK_BENCH_ROWS, MAX_REPEATS = 51 };
static double input_table[TABLE_ROWS][AK_BENCH_INPUTS];
static volatile double sink;


static void *symbol(void *library, const char *name) {
    void *s = dlsym(library, name);
    if (s == NULL) {
        fprintf(stderr, "bench_fmi3: no %s\n", name);
        exit(1);
    }
    return s;
}

#define FUNCTION(type, library, name) ((type *)(uintptr_t)symbol(library, name))

static double time_core(long n) {
    double y[12], sum = 0.0;
    int k = 0;
    const double start = ak_bench_now_ns();
    for (long step = 0; step < n; step++) { /* the same loop as bench_fmu.c's time_core */
        const double *u = input_table[step & (TABLE_ROWS - 1)];
        ak_general_angular_kinematics(&AK_SEQUENCES[0], u, u + 3, u + 6, y, y + 3, y + 6, y + 9);
        sum += y[k];
        k = k == 11 ? 0 : k + 1;
    }
    const double elapsed = ak_bench_now_ns() - start;
    sink = sum;
    return elapsed / (double)n;
}

static void fmi2_log(fmi2ComponentEnvironment e, fmi2String n, fmi2Status s, fmi2String c,
                     fmi2String m, ...) {
    (void)e, (void)n, (void)s, (void)c;
    fprintf(stderr, "FMI 2: %s\n", m);
}

static double time_fmi2(void *library, long n) {
    fmi2CallbackFunctions callbacks = {fmi2_log, calloc, free, NULL, NULL};
    fmi2Component c = FUNCTION(fmi2InstantiateTYPE, library, "fmi2Instantiate")(
        "bench", fmi2CoSimulation, KIN_GUID, "", &callbacks, fmi2False, fmi2False);
    fmi2SetRealTYPE *set = FUNCTION(fmi2SetRealTYPE, library, "fmi2SetReal");
    fmi2GetRealTYPE *get = FUNCTION(fmi2GetRealTYPE, library, "fmi2GetReal");
    fmi2DoStepTYPE *step_fn = FUNCTION(fmi2DoStepTYPE, library, "fmi2DoStep");
    FUNCTION(fmi2SetupExperimentTYPE, library, "fmi2SetupExperiment")(c, fmi2False, 0, 0, fmi2False, 0);
    FUNCTION(fmi2EnterInitializationModeTYPE, library, "fmi2EnterInitializationMode")(c);
    FUNCTION(fmi2ExitInitializationModeTYPE, library, "fmi2ExitInitializationMode")(c);
    const fmi2ValueReference in[9] = {0, 1, 2, 3, 4, 5, 6, 7, 8};
    const fmi2ValueReference out[12] = {9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20};
    double y[12], sum = 0.0, t = 0.0;
    unsigned int statuses = 0;
    const double start = ak_bench_now_ns();
    for (long step = 0; step < n; step++) {
        statuses |= (unsigned int)set(c, in, 9, input_table[step & (TABLE_ROWS - 1)]);
        statuses |= (unsigned int)step_fn(c, t, 1e-3, fmi2True);
        t += 1e-3;
        statuses |= (unsigned int)get(c, out, 12, y);
        sum += y[step % 12];
    }
    const double elapsed = ak_bench_now_ns() - start;
    sink = sum;
    FUNCTION(fmi2FreeInstanceTYPE, library, "fmi2FreeInstance")(c);
    if (statuses != 0) {
        fprintf(stderr, "bench_fmi3: an FMI 2 call failed\n");
        exit(1);
    }
    return elapsed / (double)n;
}

static void fmi3_log(fmi3InstanceEnvironment e, fmi3Status s, fmi3String c, fmi3String m) {
    (void)e, (void)s, (void)c;
    fprintf(stderr, "FMI 3: %s\n", m);
}

static double time_fmi3(void *library, long n) {
    fmi3Instance c = FUNCTION(fmi3InstantiateCoSimulationTYPE, library, "fmi3InstantiateCoSimulation")(
        "bench", KIN_GUID, NULL, fmi3False, fmi3False, fmi3False, fmi3False, NULL, 0, NULL, fmi3_log, NULL);
    fmi3SetFloat64TYPE *set = FUNCTION(fmi3SetFloat64TYPE, library, "fmi3SetFloat64");
    fmi3GetFloat64TYPE *get = FUNCTION(fmi3GetFloat64TYPE, library, "fmi3GetFloat64");
    fmi3DoStepTYPE *step_fn = FUNCTION(fmi3DoStepTYPE, library, "fmi3DoStep");
    FUNCTION(fmi3EnterInitializationModeTYPE, library, "fmi3EnterInitializationMode")(
        c, fmi3False, 0, 0, fmi3False, 0);
    FUNCTION(fmi3ExitInitializationModeTYPE, library, "fmi3ExitInitializationMode")(c);
    const fmi3ValueReference theta = 0, theta_dot = 3, theta_ddot = 6;
    const fmi3ValueReference out[4] = {9, 12, 15, 18};
    double y[12], sum = 0.0, t = 0.0, last;
    fmi3Boolean event, terminate, early;
    unsigned int statuses = 0;
    const double start = ak_bench_now_ns();
    for (long step = 0; step < n; step++) {
        const double *u = input_table[step & (TABLE_ROWS - 1)];
        statuses |= (unsigned int)set(c, &theta, 1, u, 3);
        statuses |= (unsigned int)set(c, &theta_dot, 1, u + 3, 3);
        statuses |= (unsigned int)set(c, &theta_ddot, 1, u + 6, 3);
        statuses |= (unsigned int)step_fn(c, t, 1e-3, fmi3True, &event, &terminate, &early, &last);
        t = last;
        statuses |= (unsigned int)get(c, out, 4, y, 12);
        sum += y[step % 12];
    }
    const double elapsed = ak_bench_now_ns() - start;
    sink = sum;
    FUNCTION(fmi3FreeInstanceTYPE, library, "fmi3FreeInstance")(c);
    if (statuses != 0) {
        fprintf(stderr, "bench_fmi3: an FMI 3 call failed\n");
        exit(1);
    }
    return elapsed / (double)n;
}

int main(int argc, char **argv) {
    if (argc < 3) {
        fprintf(stderr, "usage: bench_fmi3 FMI2_SO FMI3_SO [STEPS [REPEATS]]\n");
        return 2;
    }
    const long steps = argc > 3 ? (long)atof(argv[3]) : 1000000;
    int repeats = argc > 4 ? atoi(argv[4]) : 7;
    repeats = repeats < 1 ? 1 : repeats > MAX_REPEATS ? MAX_REPEATS : repeats;
    void *fmi2 = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
    void *fmi3 = dlopen(argv[2], RTLD_NOW | RTLD_LOCAL);
    if (fmi2 == NULL || fmi3 == NULL) {
        fprintf(stderr, "bench_fmi3: %s\n", dlerror());
        return 1;
    }
    if (ak_bench_fill_inputs(input_table) != 0) {
        fprintf(stderr, "bench_fmi3: the input table has equal consecutive values\n");
        return 1;
    }
    if (argc > 5) { /* one loop alone */
        const char *only = argv[5];
        const double ns = strcmp(only, "core") == 0   ? time_core(steps)
                          : strcmp(only, "fmi2") == 0 ? time_fmi2(fmi2, steps)
                          : strcmp(only, "fmi3") == 0 ? time_fmi3(fmi3, steps)
                                                      : -1.0;
        if (ns < 0.0) {
            fprintf(stderr, "bench_fmi3: unknown loop %s (core, fmi2 or fmi3)\n", only);
            return 2;
        }
        printf("%s: %.1f ns/step\n", only, ns);
        return 0;
    }
    double core[MAX_REPEATS], c2[MAX_REPEATS], c3[MAX_REPEATS], r2[MAX_REPEATS], r3[MAX_REPEATS];
    time_core(steps / 10); /* warm-up */
    for (int r = 0; r < repeats; r++) {
        core[r] = time_core(steps);
        c2[r] = time_fmi2(fmi2, steps);
        c3[r] = time_fmi3(fmi3, steps);
        r2[r] = c2[r] / core[r];
        r3[r] = c3[r] / core[r];
    }
    printf("FMI 3 cycle (3 fmi3SetFloat64 of the input arrays, fmi3DoStep, 1 fmi3GetFloat64 of the\n"
           "4 output arrays) and FMI 2 cycle (fmi2SetReal of 9, fmi2DoStep, fmi2GetReal of 12) vs. the\n"
           "bare core (body123), timed alternately; %ld steps per run, %d repeats, medians:\n\n",
           steps, repeats);
    printf("| core ns/step | FMI 2 cycle ns/step | FMI 3 cycle ns/step | FMI 2 / core | FMI 3 / core |\n");
    printf("|---|---|---|---|---|\n");
    printf("| %.1f | %.1f | %.1f | %.3f | %.3f |\n", ak_bench_median(core, repeats), ak_bench_median(c2, repeats),
           ak_bench_median(c3, repeats), ak_bench_median(r2, repeats), ak_bench_median(r3, repeats));
    return 0;
}
