/* Benchmark of AttitudePropagator (issue 14, bench/run.sh): one co-simulation communication
 * point next to the bare quaternion update, in the same run.
 *
 *   bare update: the frozen copy (attitude_anchor.h) of the core's step for constant omega over
 *                the step (q := q (x) exp(omega h/2): the exponential's sin, cos and sqrt, the
 *                product, the norm correction);
 *   FMU step:    fmi2SetReal of omega[1..3], fmi2DoStep, fmi2GetReal of q[1..4] (and, in a
 *                second loop, theta[1..3] too), through the AttitudePropagator.so loaded with
 *                dlopen; with --previous, the same loops through the previous release's .so.
 * The anchors are the bare update and the update plus the angle extraction (issue 24), frozen
 * in bench/attitude_anchor.c so that they do not move with the FMU's core; before timing, they
 * are checked against the core's ak_attitude_step and ak_attitude_angles (at most ANCHOR_ULPS
 * apart). Both loops cycle through a table of 256 angular velocities, alternate within each
 * repeat, and the figures are medians over the repeats (thread CPU time per iteration); the ratio
 * is the median of the per-repeat ratios. One value per iteration goes to a volatile sink. The
 * FMU's q after the run is checked against the core's step over the same inputs: a difference,
 * or a non-OK status, exits with status 1.
 *
 * With --fmi3, the same loops through the FMI 3 binary: one fmi3SetFloat64 of the array omega,
 * fmi3DoStep, one fmi3GetFloat64 of q (and theta); --previous3 the previous release's.
 *
 *     bench_attitude PATH/AttitudePropagator.so [--steps N] [--repeats R] [--previous SO]
 *                    [--fmi3 SO] [--previous3 SO] [--only bare|angles|q|q+theta|q3|q+theta3]
 * --only runs one loop once (bench/run.sh and bench/guard.sh count its instructions). */
#define _POSIX_C_SOURCE 200809L

#include <dlfcn.h>
#include <limits.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench_timing.h"
#include "AttitudePropagator_variables.h"
#include "attitude.h"
#include "attitude_step.h"
#include "attitude_anchor.h"
#include "fmi2FunctionTypes.h"
#include "fmi3FunctionTypes.h"

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

typedef struct {
    void *library;
    fmi3InstantiateCoSimulationTYPE *instantiate;
    fmi3FreeInstanceTYPE *free_instance;
    fmi3EnterInitializationModeTYPE *enter_initialization_mode;
    fmi3ExitInitializationModeTYPE *exit_initialization_mode;
    fmi3SetFloat64TYPE *set_float64;
    fmi3GetFloat64TYPE *get_float64;
    fmi3DoStepTYPE *do_step;
} fmu3_api;

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

static void load_fmu3(const char *path, fmu3_api *api) {
    api->library = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (api->library == NULL) {
        fail(dlerror());
    }
    resolve(api->library, "fmi3InstantiateCoSimulation", &api->instantiate,
            sizeof api->instantiate);
    resolve(api->library, "fmi3FreeInstance", &api->free_instance, sizeof api->free_instance);
    resolve(api->library, "fmi3EnterInitializationMode", &api->enter_initialization_mode,
            sizeof api->enter_initialization_mode);
    resolve(api->library, "fmi3ExitInitializationMode", &api->exit_initialization_mode,
            sizeof api->exit_initialization_mode);
    resolve(api->library, "fmi3SetFloat64", &api->set_float64, sizeof api->set_float64);
    resolve(api->library, "fmi3GetFloat64", &api->get_float64, sizeof api->get_float64);
    resolve(api->library, "fmi3DoStep", &api->do_step, sizeof api->do_step);
}

static void log_message3(fmi3InstanceEnvironment environment, fmi3Status status,
                         fmi3String category, fmi3String message) {
    (void)environment;
    fprintf(stderr, "bench_attitude: FMI 3 message [%s, %d]: %s\n", category, (int)status,
            message);
}

static void log_message(fmi2ComponentEnvironment environment, fmi2String name, fmi2Status status,
                        fmi2String category, fmi2String message, ...) {
    (void)environment;
    fprintf(stderr, "bench_attitude: FMU message [%s, %s, %d]: %s\n", name, category,
            (int)status, message);
}


static double table[TABLE_ROWS][3];

/* The anchors against the core, at most this many units in the last place apart: the anchors
 * keep glibc's sin, cos and atan2, the core has its own (fmu_src/elementary/), which round
 * differently now and then (measured: 1 ulp at most over the check's steps and attitudes). */
enum { ANCHOR_ULPS = 2 };

/* How many doubles lie between a and b (0: the same bits; +0 and -0 are 1 apart). */
static unsigned long long ulps_apart(double a, double b) {
    long long ia, ib;
    memcpy(&ia, &a, sizeof a);
    memcpy(&ib, &b, sizeof b);
    ia = ia < 0 ? LLONG_MIN - ia - 1 : ia; /* monotonic in the value */
    ib = ib < 0 ? LLONG_MIN - ib - 1 : ib;
    return ia > ib ? (unsigned long long)ia - (unsigned long long)ib
                   : (unsigned long long)ib - (unsigned long long)ia;
}

static unsigned long long worst_apart(const double *a, const double *b, int n) {
    unsigned long long worst = 0;
    for (int k = 0; k < n; k++) {
        const unsigned long long apart = ulps_apart(a[k], b[k]);
        worst = apart > worst ? apart : worst;
    }
    return worst;
}

/* The core's step over n steps of the table (what the FMU runs): the final q. */
static void core_steps(long n, double q[4]) {
    q[0] = 1.0;
    q[1] = q[2] = q[3] = 0.0;
    for (long step = 0; step < n; step++) {
        const double *w = table[step & (TABLE_ROWS - 1)];
        double c[4][3] = {{w[0], w[1], w[2]}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
        ak_attitude_step(AK_FRAME_BODY, c, STEP_SIZE, q, NULL);
    }
}

/* The anchors against the core: 4096 steps of the table with a 20 times longer step (angles
 * through every quadrant), then attitudes at the singular configuration of body123. Exits with
 * status 1 when they are more than ANCHOR_ULPS apart. */
static void check_anchors(void) {
    double q_anchor[4] = {1.0, 0.0, 0.0, 0.0}, q_core[4] = {1.0, 0.0, 0.0, 0.0};
    double theta_anchor[3] = {0.0, 0.0, 0.0}, theta_core[3] = {0.0, 0.0, 0.0};
    unsigned long long worst = 0;
    for (int step = 0; step < 4096; step++) {
        const double *w = table[step & (TABLE_ROWS - 1)];
        double c[4][3] = {{w[0], w[1], w[2]}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
        ak_anchor_attitude_step(w, 20 * STEP_SIZE, q_anchor);
        ak_attitude_step(AK_FRAME_BODY, c, 20 * STEP_SIZE, q_core, NULL);
        double R_anchor[3][3], R_core[3][3], d_anchor, d_core;
        ak_anchor_quat_to_matrix(q_core, R_anchor);
        ak_quat_to_matrix(q_core, R_core);
        ak_anchor_angles_123(R_anchor, theta_anchor, theta_anchor, &d_anchor);
        ak_attitude_angles(&AK_SEQUENCES[AK_SEQUENCE_DEFAULT], R_core, theta_core, theta_core,
                           &d_core);
        const unsigned long long apart[4] = {worst_apart(q_anchor, q_core, 4),
                                             worst_apart(&R_anchor[0][0], &R_core[0][0], 9),
                                             worst_apart(theta_anchor, theta_core, 3),
                                             ulps_apart(d_anchor, d_core)};
        for (int k = 0; k < 4; k++) {
            worst = apart[k] > worst ? apart[k] : worst;
        }
        memcpy(q_anchor, q_core, sizeof q_core); /* compare the steps, not their drift */
        memcpy(theta_anchor, theta_core, sizeof theta_core);
    }
    for (int k = 0; k < 8; k++) { /* theta2 = +-pi/2 to rounding: theta1 held */
        /* q = (rotation by 0.3 k about axis 1) (x) (rotation by +-pi/2 about axis 2) */
        const double half = 0.25 * 3.14159265358979323846, tilt = k < 4 ? half : -half;
        const double ca = cos(0.15 * k), sa = sin(0.15 * k), cb = cos(tilt), sb = sin(tilt);
        const double q[4] = {ca * cb, sa * cb, ca * sb, sa * sb};
        const double previous[3] = {0.2 * k - 0.5, tilt > 0 ? 1.5 : -1.5, 0.7 - 0.3 * k};
        double R_anchor[3][3], R_core[3][3], t_anchor[3], t_core[3], d_anchor, d_core;
        ak_anchor_quat_to_matrix(q, R_anchor);
        ak_quat_to_matrix(q, R_core);
        const bool singular_anchor = ak_anchor_angles_123(R_anchor, previous, t_anchor, &d_anchor);
        const bool singular_core = ak_attitude_angles(&AK_SEQUENCES[AK_SEQUENCE_DEFAULT], R_core,
                                                      previous, t_core, &d_core);
        if (!singular_anchor || !singular_core) {
            fail("check_anchors: a test attitude is not singular");
        }
        const unsigned long long apart = worst_apart(t_anchor, t_core, 3);
        worst = apart > worst ? apart : worst;
    }
    if (worst > ANCHOR_ULPS) {
        fprintf(stderr, "bench_attitude: the frozen anchors and the core are %llu ulp apart "
                        "(allowed: %d; see ANCHOR_ULPS)\n", worst, ANCHOR_ULPS);
        exit(1);
    }
}

/* The bare update over n steps: ns per step; q_out receives the final q. */
static double time_bare(long n, double q_out[4]) {
    double q[4] = {1.0, 0.0, 0.0, 0.0};
    const double start = ak_bench_now_ns();
    for (long step = 0; step < n; step++) {
        ak_anchor_attitude_step(table[step & (TABLE_ROWS - 1)], STEP_SIZE, q);
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
        ak_anchor_attitude_step(table[step & (TABLE_ROWS - 1)], STEP_SIZE, q);
        ak_anchor_quat_to_matrix(q, R);
        ak_anchor_angles_123(R, theta, theta, &distance);
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

/* n communication points through FMI 3 on a fresh instance: one fmi3SetFloat64 of omega,
 * fmi3DoStep, one fmi3GetFloat64 of q (and theta when with_theta): ns per step. */
static double time_fmu3(const fmu3_api *api, long n, bool with_theta, double q_out[4]) {
    fmi3Instance c = api->instantiate("bench", AP_GUID, NULL, fmi3False, fmi3False, fmi3False,
                                      fmi3False, NULL, 0, NULL, log_message3, NULL);
    if (c == NULL || api->enter_initialization_mode(c, fmi3False, 0.0, 0.0, fmi3False, 0.0) !=
                         fmi3OK ||
        api->exit_initialization_mode(c) != fmi3OK) {
        fail("cannot start the FMI 3 FMU");
    }
    const fmi3ValueReference omega = AP_VR_OMEGA, read_vrs[2] = {AP_VR_Q, AP_VR_THETA};
    const size_t n_vrs = with_theta ? 2 : 1, n_values = with_theta ? 7 : 4;
    double read[7];
    double t = 0.0;
    unsigned int status = 0;
    fmi3Boolean event, terminate, early;
    fmi3Float64 last;
    const double start = ak_bench_now_ns();
    for (long step = 0; step < n; step++) {
        status |= (unsigned int)api->set_float64(c, &omega, 1, table[step & (TABLE_ROWS - 1)], 3);
        status |= (unsigned int)api->do_step(c, t, STEP_SIZE, fmi3True, &event, &terminate,
                                             &early, &last);
        status |= (unsigned int)api->get_float64(c, read_vrs, n_vrs, read, n_values);
        t += STEP_SIZE;
        sink = read[step % (long)n_values];
    }
    const double elapsed = ak_bench_now_ns() - start;
    if (status != (unsigned int)fmi3OK) {
        fail("an FMI 3 call did not return fmi3OK");
    }
    memcpy(q_out, read, 4 * sizeof(double));
    api->free_instance(c);
    return elapsed / (double)n;
}

/* The loops: the anchors, then FMI 2 and FMI 3 of the current build and of the previous release,
 * each reading q, then q and theta. */
enum {
    BARE, ANGLES, FMU_Q, FMU_THETA, FMU3_Q, FMU3_THETA, PREV_Q, PREV_THETA, PREV3_Q, PREV3_THETA,
    N_LOOPS, MAX_REPEATS = 100
};
static const char *const LOOP_NAMES[N_LOOPS] = {"bare", "angles", "q", "q+theta", "q3", "q+theta3"};
static const char *const LABELS[N_LOOPS] = {
    "anchor: bare quaternion update (frozen copy of ak_attitude_step, constant omega)",
    "anchor: bare update + R + theta of body123 (frozen copy of ak_attitude_angles)",
    "FMI 2: set omega[1..3] + fmi2DoStep + get q[1..4]",
    "FMI 2: set omega[1..3] + fmi2DoStep + get q[1..4], theta[1..3]",
    "FMI 3: set omega + fmi3DoStep + get q",
    "FMI 3: set omega + fmi3DoStep + get q, theta",
    "previous release, FMI 2: set omega + doStep + get q",
    "previous release, FMI 2: set omega + doStep + get q, theta",
    "previous release, FMI 3: set omega + doStep + get q",
    "previous release, FMI 3: set omega + doStep + get q, theta"};

/* A loop that reads theta (divided by the update + angles anchor). */
static bool reads_theta(int loop) {
    return loop >= FMU_Q && (loop - FMU_Q) % 2 == 1;
}

/* The FMU binaries of the loops: [0] current, [1] previous release; NULL library: not given. */
typedef struct {
    fmu_api fmi2[2];
    fmu3_api fmi3[2];
} binaries;

/* One run of loop `loop`: ns per step; q_out receives the final q (not for ANGLES). */
static double run_loop(int loop, const binaries *b, long steps, double q_out[4]) {
    switch (loop) {
    case BARE: return time_bare(steps, q_out);
    case ANGLES: return time_bare_with_angles(steps);
    case FMU_Q: case FMU_THETA: case PREV_Q: case PREV_THETA:
        return time_fmu(&b->fmi2[loop >= PREV_Q], steps, reads_theta(loop) ? 7 : 4, q_out);
    default: return time_fmu3(&b->fmi3[loop >= PREV_Q], steps, reads_theta(loop), q_out);
    }
}

/* Whether the binaries of the loop were given. */
static bool loop_given(int loop, const binaries *b) {
    if (loop < FMU3_Q) {
        return true;
    }
    const int previous = loop >= PREV_Q;
    return loop == PREV_Q || loop == PREV_THETA ? b->fmi2[1].library != NULL
                                                : b->fmi3[previous].library != NULL;
}

int main(int argc, char **argv) {
    if (argc < 2) {
        fail("usage: bench_attitude PATH/AttitudePropagator.so [--steps N] [--repeats R] "
             "[--previous SO] [--fmi3 SO] [--previous3 SO] [--only LOOP]");
    }
    long steps = 1000000;
    int repeats = 5;
    const char *previous = NULL, *only = NULL, *fmi3 = NULL, *previous3 = NULL;
    for (int i = 2; i + 1 < argc; i += 2) {
        if (strcmp(argv[i], "--steps") == 0) {
            steps = (long)strtod(argv[i + 1], NULL);
        } else if (strcmp(argv[i], "--repeats") == 0) {
            repeats = atoi(argv[i + 1]);
        } else if (strcmp(argv[i], "--previous") == 0) {
            previous = argv[i + 1];
        } else if (strcmp(argv[i], "--fmi3") == 0) {
            fmi3 = argv[i + 1];
        } else if (strcmp(argv[i], "--previous3") == 0) {
            previous3 = argv[i + 1];
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
    static binaries b; /* zeroed: a NULL library is a binary not given */
    load_fmu(argv[1], &b.fmi2[0]);
    if (previous != NULL) {
        load_fmu(previous, &b.fmi2[1]);
    }
    if (fmi3 != NULL) {
        load_fmu3(fmi3, &b.fmi3[0]);
    }
    if (previous3 != NULL) {
        load_fmu3(previous3, &b.fmi3[1]);
    }
    check_anchors();
    double q[N_LOOPS][4];
    if (only != NULL) {
        for (int loop = 0; loop < FMU3_THETA + 1; loop++) {
            if (strcmp(only, LOOP_NAMES[loop]) == 0) {
                if (!loop_given(loop, &b)) {
                    fail("--only q3 and q+theta3 need --fmi3 SO");
                }
                printf("%s: %.1f ns/step\n", only, run_loop(loop, &b, steps, q[loop]));
                return 0;
            }
        }
        fail("unknown loop for --only (bare, angles, q, q+theta, q3 or q+theta3)");
    }
    static double ns[N_LOOPS][MAX_REPEATS], ratio[N_LOOPS][MAX_REPEATS];
    double q_core[4];
    core_steps(steps, q_core);
    for (int r = 0; r < repeats; r++) {
        for (int loop = 0; loop < N_LOOPS; loop++) {
            if (!loop_given(loop, &b)) {
                continue;
            }
            ns[loop][r] = run_loop(loop, &b, steps, q[loop]);
            if (loop >= FMU_Q && memcmp(q_core, q[loop], sizeof q_core) != 0) {
                fail("the FMU's q differs from the core's step");
            }
        }
        for (int loop = 0; loop < N_LOOPS; loop++) { /* reading theta: against update + angles */
            ratio[loop][r] = ns[loop][r] / ns[reads_theta(loop) ? ANGLES : BARE][r];
        }
    }
    printf("AttitudePropagator, %ld steps of %g s, median of %d repeats (thread CPU time), loops\n"
           "alternating; a loop reading theta is divided by the update + angles anchor, the\n"
           "other loops by the bare update:\n",
           steps, STEP_SIZE, repeats);
    printf("| loop | ns per step | / its anchor |\n|---|---:|---:|\n");
    for (int loop = 0; loop < N_LOOPS; loop++) {
        if (loop_given(loop, &b)) {
            printf("| %s | %.1f | %.2f |\n", LABELS[loop], ak_bench_median(ns[loop], repeats),
                   ak_bench_median(ratio[loop], repeats));
        }
    }
    return 0;
}
