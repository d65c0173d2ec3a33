/* Benchmark of AttitudePropagator (issue 14, bench/run.sh): one co-simulation communication
 * point next to the bare quaternion update, in the same run.
 *
 *   bare update: ak_attitude_step for constant omega over the step (q := q (x) exp(omega h/2),
 *                the exponential's sin, cos and sqrt, the product, the norm correction), linked
 *                from the same static core library the FMU is built from;
 *   FMU step:    fmi2SetReal of omega[1..3], fmi2DoStep, fmi2GetReal of q[1..4] (and, in a
 *                second loop, theta[1..3] too), through the AttitudePropagator.so loaded with
 *                dlopen; with --previous, the same loops through the previous release's .so.
 * The anchors are the bare update and the update plus the angle extraction (issue 24).
 * Both loops cycle through a table of 256 angular velocities, alternate within each repeat, and
 * the figures are medians over the repeats (thread CPU time per iteration); the ratio is the
 * median of the per-repeat ratios. One value per iteration goes to a volatile sink. The FMU's q
 * after the run is checked against the bare loop's (the same step, the same inputs): a
 * difference, or a non-OK status, exits with status 1.
 *
 *     bench_attitude PATH/AttitudePropagator.so [--steps N] [--repeats R] [--previous SO]
 *                    [--only bare|angles|q|q+theta]
 * --only runs one loop once (bench/run.sh and bench/guard.sh count its instructions). */
#define _POSIX_C_SOURCE 200809L

#include <dlfcn.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench_timing.h"
#include "AttitudePropagator_variables.h"
#include "attitude.h"
#include "fmi2FunctionTypes.h"

enum { TABLE_ROWS = 256 };
static const double STEP_SIZE = 1e-3;
static const fmi2ValueReference OMEGA_VRS[3] = {AP_VR_OMEGA, AP_VR_OMEGA + 1, AP_VR_OMEGA + 2};
static const fmi2ValueReference READ_VRS[7] = {AP_VR_Q,     AP_VR_Q + 1,     AP_VR_Q + 2,
                                               AP_VR_Q + 3, AP_VR_THETA,     AP_VR_THETA + 1,
                                               AP_VR_THETA + 2};

typedef struct {
    void *library;
    fmi2InstantiateTYPE *instantiate;
    fmi2FreeInstanceTYPE *free_instance;
    fmi2SetupExperimentTYPE *setup_experiment;
    fmi2EnterInitializationModeTYPE *enter_initialization_mode;
    fmi2ExitInitializationModeTYPE *exit_initialization_mode;
    fmi2SetRealTYPE *set_real;
    fmi2GetRealTYPE *get_real;
    fmi2DoStepTYPE *do_step;
} fmu_api;

static volatile double sink;

static void fail(const char *what) {
    fprintf(stderr, "bench_attitude: %s\n", what);
    exit(1);
}

static void resolve(void *library, const char *name, void *function_pointer, size_t size) {
    void *symbol = dlsym(library, name);
    if (symbol == NULL) {
        fail(name);
    }
    memcpy(function_pointer, &symbol, size); /* POSIX: object to function pointer */
}

static void load_fmu(const char *path, fmu_api *api) {
    api->library = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (api->library == NULL) {
        fail(dlerror());
    }
    resolve(api->library, "fmi2Instantiate", &api->instantiate, sizeof api->instantiate);
    resolve(api->library, "fmi2FreeInstance", &api->free_instance, sizeof api->free_instance);
    resolve(api->library, "fmi2SetupExperiment", &api->setup_experiment,
            sizeof api->setup_experiment);
    resolve(api->library, "fmi2EnterInitializationMode", &api->enter_initialization_mode,
            sizeof api->enter_initialization_mode);
    resolve(api->library, "fmi2ExitInitializationMode", &api->exit_initialization_mode,
            sizeof api->exit_initialization_mode);
    resolve(api->library, "fmi2SetReal", &api->set_real, sizeof api->set_real);
    resolve(api->library, "fmi2GetReal", &api->get_real, sizeof api->get_real);
    resolve(api->library, "fmi2DoStep", &api->do_step, sizeof api->do_step);
}

static void log_message(fmi2ComponentEnvironment environment, fmi2String name, fmi2Status status,
                        fmi2String category, fmi2String message, ...) {
    (void)environment;
    fprintf(stderr, "bench_attitude: FMU message [%s, %s, %d]: %s\n", name, category,
            (int)status, message);
}


static double table[TABLE_ROWS][3];

/* The bare update over n steps: ns per step; q_out receives the final q. */
static double time_bare(long n, double q_out[4]) {
    double q[4] = {1.0, 0.0, 0.0, 0.0};
    const double start = ak_bench_now_ns();
    for (long step = 0; step < n; step++) {
        const double *w = table[step & (TABLE_ROWS - 1)];
        double c[4][3] = {{w[0], w[1], w[2]}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
        ak_attitude_step(AK_FRAME_BODY, c, STEP_SIZE, q, NULL);
        sink = q[step & 3];
    }
    const double elapsed = ak_bench_now_ns() - start;
    memcpy(q_out, q, sizeof q);
    return elapsed / (double)n;
}

/* The bare update and the angles of body123 from it (what reading theta needs): ns per step. */
static double time_bare_with_angles(long n) {
    double q[4] = {1.0, 0.0, 0.0, 0.0}, theta[3] = {0.0, 0.0, 0.0}, R[3][3], distance;
    const double start = ak_bench_now_ns();
    for (long step = 0; step < n; step++) {
        const double *w = table[step & (TABLE_ROWS - 1)];
        double c[4][3] = {{w[0], w[1], w[2]}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
        ak_attitude_step(AK_FRAME_BODY, c, STEP_SIZE, q, NULL);
        ak_quat_to_matrix(q, R);
        ak_attitude_angles(&AK_SEQUENCES[AK_SEQUENCE_DEFAULT], R, theta, theta, &distance);
        sink = theta[step % 3];
    }
    return (ak_bench_now_ns() - start) / (double)n;
}

/* n communication points on a fresh instance, reading the first n_read of q[1..4], theta[1..3]:
 * ns per set/doStep/get. */
static double time_fmu(const fmu_api *api, long n, int n_read, double q_out[4]) {
    const fmi2CallbackFunctions functions = {log_message, calloc, free, NULL, NULL};
    fmi2Component c = api->instantiate("bench", fmi2CoSimulation, AP_GUID, "file:///unused",
                                       &functions, fmi2False, fmi2False);
    if (c == NULL || api->setup_experiment(c, fmi2False, 0.0, 0.0, fmi2False, 0.0) != fmi2OK ||
        api->enter_initialization_mode(c) != fmi2OK || api->exit_initialization_mode(c) != fmi2OK) {
        fail("cannot start the FMU");
    }
    double read[7];
    double t = 0.0;
    fmi2Status status = fmi2OK;
    const double start = ak_bench_now_ns();
    for (long step = 0; step < n; step++) {
        status |= api->set_real(c, OMEGA_VRS, 3, table[step & (TABLE_ROWS - 1)]);
        status |= api->do_step(c, t, STEP_SIZE, fmi2True);
        status |= api->get_real(c, READ_VRS, (size_t)n_read, read);
        t += STEP_SIZE;
        sink = read[step % n_read];
    }
    const double elapsed = ak_bench_now_ns() - start;
    if (status != fmi2OK) {
        fail("a call did not return fmi2OK");
    }
    memcpy(q_out, read, 4 * sizeof(double));
    api->free_instance(c);
    return elapsed / (double)n;
}

enum { BARE, ANGLES, FMU_Q, FMU_THETA, PREV_Q, PREV_THETA, N_LOOPS, MAX_REPEATS = 100 };
static const char *const LOOP_NAMES[N_LOOPS] = {"bare", "angles", "q", "q+theta"};
static const char *const LABELS[N_LOOPS] = {
    "anchor: bare quaternion update (ak_attitude_step, constant omega)",
    "anchor: bare update + R + theta of body123 (ak_attitude_angles)",
    "FMU: set omega[1..3] + fmi2DoStep + get q[1..4]",
    "FMU: set omega[1..3] + fmi2DoStep + get q[1..4], theta[1..3]",
    "previous release: set omega + doStep + get q",
    "previous release: set omega + doStep + get q, theta"};

/* One run of loop `loop`: ns per step; q_out receives the final q (not for ANGLES). */
static double run_loop(int loop, const fmu_api apis[2], long steps, double q_out[4]) {
    switch (loop) {
    case BARE: return time_bare(steps, q_out);
    case ANGLES: return time_bare_with_angles(steps);
    default: return time_fmu(&apis[loop >= PREV_Q], steps, loop % 2 ? 7 : 4, q_out);
    }
}

int main(int argc, char **argv) {
    if (argc < 2) {
        fail("usage: bench_attitude PATH/AttitudePropagator.so [--steps N] [--repeats R] "
             "[--previous SO] [--only LOOP]");
    }
    long steps = 1000000;
    int repeats = 5;
    const char *previous = NULL, *only = NULL;
    for (int i = 2; i + 1 < argc; i += 2) {
        if (strcmp(argv[i], "--steps") == 0) {
            steps = (long)strtod(argv[i + 1], NULL);
        } else if (strcmp(argv[i], "--repeats") == 0) {
            repeats = atoi(argv[i + 1]);
        } else if (strcmp(argv[i], "--previous") == 0) {
            previous = argv[i + 1];
        } else if (strcmp(argv[i], "--only") == 0) {
            only = argv[i + 1];
        } else {
            fail("unknown option");
        }
    }
    if (steps < 1 || repeats < 1 || repeats > MAX_REPEATS) {
        fail("--steps and --repeats must be positive (repeats at most 100)");
    }
    for (int r = 0; r < TABLE_ROWS; r++) {
        table[r][0] = sin(0.1 * r);
        table[r][1] = 0.5 * cos(0.07 * r);
        table[r][2] = 0.3 + 0.2 * sin(0.13 * r);
    }
    fmu_api apis[2];
    load_fmu(argv[1], &apis[0]);
    const int n_loops = previous != NULL ? N_LOOPS : PREV_Q;
    if (previous != NULL) {
        load_fmu(previous, &apis[1]);
    }
    double q[N_LOOPS][4];
    if (only != NULL) {
        for (int loop = 0; loop < PREV_Q; loop++) {
            if (strcmp(only, LOOP_NAMES[loop]) == 0) {
                printf("%s: %.1f ns/step\n", only, run_loop(loop, apis, steps, q[loop]));
                return 0;
            }
        }
        fail("unknown loop for --only (bare, angles, q or q+theta)");
    }
    static double ns[N_LOOPS][MAX_REPEATS], ratio[N_LOOPS][MAX_REPEATS];
    for (int r = 0; r < repeats; r++) {
        for (int loop = 0; loop < n_loops; loop++) {
            ns[loop][r] = run_loop(loop, apis, steps, q[loop]);
            if (loop != ANGLES && memcmp(q[BARE], q[loop], sizeof q[BARE]) != 0) {
                fail("the FMU's q differs from the bare update's");
            }
        }
        for (int loop = 0; loop < n_loops; loop++) { /* reading theta: against update + angles */
            ratio[loop][r] = ns[loop][r] / ns[loop % 2 && loop != ANGLES ? ANGLES : BARE][r];
        }
    }
    printf("AttitudePropagator, %ld steps of %g s, median of %d repeats (thread CPU time), loops\n"
           "alternating; a loop reading theta is divided by the update + angles anchor, the\n"
           "other loops by the bare update:\n",
           steps, STEP_SIZE, repeats);
    printf("| loop | ns per step | / its anchor |\n|---|---:|---:|\n");
    for (int loop = 0; loop < n_loops; loop++) {
        printf("| %s | %.1f | %.2f |\n", LABELS[loop], ak_bench_median(ns[loop], repeats),
               ak_bench_median(ratio[loop], repeats));
    }
    return 0;
}
