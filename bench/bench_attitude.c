/* Benchmark of AttitudePropagator (bench/run.sh): one co-simulation communication
 * point next to the bare quaternion update, in the same run.
 *
 *   bare update: the frozen copy (attitude_anchor.h) of the core's step for constant omega over
 *                the step (q := q (x) exp(omega h/2): the exponential's sin, cos and sqrt, the
 *                product, the norm correction);
 *   FMU step:    fmi2SetReal of omega[1..3], fmi2DoStep, fmi2GetReal of q[1..4] (and, in a
 *                second loop, theta[1..3] too), through the AttitudePropagator.so loaded with
 *                dlopen; with --previous, the same loops through the previous release's .so.
 * The anchors are the bare update and the update plus the angle extraction, frozen
 * in bench/attitude_anchor.c so that they do not move with the FMU's core; before timing, they
 * are checked against the core's ak_attitude_step and ak_attitude_angles (at most ANCHOR_ULPS
 * apart). Both loops cycle through a table of 256 angular velocities, alternate within each
 * repeat, and the figures are medians over the repeats (thread CPU time per iteration); the ratio
 * is the median of the per-repeat ratios. One value per iteration goes to a volatile sink. The
 * FMU's q after the run is checked against the core's step over the same inputs: a difference,
 * or a non-OK status, exits with status 1.
 *
 * With --fmi3, the same loops through the FMI 3 binary: one fmi3SetFloat64 of the array omega,
 * fmi3DoStep, one fmi3GetFloat64 of q (and theta); --previous3 the previous release's. With
 * --passthrough SO and --passthrough3 SO, the same four loops through the pass-through FMUs
 * (bench_passthrough.h: 3 inputs, 4 or 7 outputs, the same calls), what the calls cost with no
 * model behind them.
 *
 * The rows of omega (--inputs): without the option, the 256 rows the guard's counts were
 * recorded with (omega = (sin 0.1 r, 0.5 cos 0.07 r, 0.3 + 0.2 sin 0.13 r), steps of 1e-3 s);
 * random: the rate columns of bench_inputs.h's random rows (omega anywhere in [-10, 10] rad/s at
 * every step, steps of 1e-3 s); smooth: omega_body of bench_inputs.h's tumbling body (the
 * hand-written 1-2-3 formula on its smooth rows), steps of 0.01 s, so that the FMU follows the
 * body's attitude. Whatever omega does, the attitude, a state, moves a little at each step.
 *
 *     bench_attitude PATH/AttitudePropagator.so [--steps N] [--repeats R] [--previous SO]
 *                    [--fmi3 SO] [--previous3 SO] [--passthrough SO --passthrough3 SO]
 *                    [--inputs random|smooth] [--only bare|angles|q|q+theta|q3|q+theta3]
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
#include "bench_inputs.h"
#include "bench_passthrough.h"
#include "kinematics_123.h"
#include "AttitudePropagator_variables.h"
#include "attitude.h"
#include "attitude_step.h"
#include "attitude_anchor.h"
#include "fmi2FunctionTypes.h"
#include "fmi3FunctionTypes.h"

enum { TABLE_ROWS = AK_BENCH_ROWS };
static const double STEP_SIZE = 1e-3;
/* --inputs smooth steps by AK_BENCH_SMOOTH_STEP. The FMU loops take the step as an argument and
 * are inlined with it constant (AK_WITH_STEP), the anchor loops have a copy each with the anchors'
 * copy of attitude_anchor_smooth.c, so that the default loops, which the recorded counts were
 * taken with, stay instruction for instruction as they were. */
static bool smooth_steps = false;
#define AK_INLINE static inline __attribute__((always_inline))
#define AK_WITH_STEP(call_with_h) \
    (smooth_steps ? call_with_h(AK_BENCH_SMOOTH_STEP) : call_with_h(STEP_SIZE))

static double step_size(void) {
    return smooth_steps ? AK_BENCH_SMOOTH_STEP : STEP_SIZE;
}
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
        ak_attitude_step(AK_FRAME_BODY, c, step_size(), q, NULL);
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

/* The same two anchor loops for --inputs smooth: steps of AK_BENCH_SMOOTH_STEP, through the copy
 * of the anchors in attitude_anchor_smooth.c (the same frozen source, specialized for this step
 * as the default loops' copy is for theirs). */
bool ak_anchor_smooth_attitude_step(const double omega[3], double h, double q[4]);
void ak_anchor_smooth_quat_to_matrix(const double q[4], double R[3][3]);
bool ak_anchor_smooth_angles_123(double R[3][3], const double previous[3], double theta[3],
                                 double *distance);

/* The smooth copy against the core over the 256 smooth rows, step by step (at most ANCHOR_ULPS
 * apart, as check_anchors for the default copy). */
static void check_smooth_anchor(void) {
    double q_anchor[4] = {1.0, 0.0, 0.0, 0.0}, q_core[4] = {1.0, 0.0, 0.0, 0.0};
    for (int step = 0; step < TABLE_ROWS; step++) {
        const double *w = table[step];
        double c[4][3] = {{w[0], w[1], w[2]}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
        ak_anchor_smooth_attitude_step(w, AK_BENCH_SMOOTH_STEP, q_anchor);
        ak_attitude_step(AK_FRAME_BODY, c, AK_BENCH_SMOOTH_STEP, q_core, NULL);
        if (worst_apart(q_anchor, q_core, 4) > ANCHOR_ULPS) {
            fail("the smooth copy of the anchors and the core's step differ");
        }
        memcpy(q_anchor, q_core, sizeof q_core);
    }
}

static double time_bare_smooth(long n, double q_out[4]) {
    double q[4] = {1.0, 0.0, 0.0, 0.0};
    const double start = ak_bench_now_ns();
    for (long step = 0; step < n; step++) {
        ak_anchor_smooth_attitude_step(table[step & (TABLE_ROWS - 1)], AK_BENCH_SMOOTH_STEP, q);
        sink = q[step & 3];
    }
    const double elapsed = ak_bench_now_ns() - start;
    memcpy(q_out, q, sizeof q);
    return elapsed / (double)n;
}

static double time_bare_with_angles_smooth(long n) {
    double q[4] = {1.0, 0.0, 0.0, 0.0}, theta[3] = {0.0, 0.0, 0.0}, R[3][3], distance;
    const double start = ak_bench_now_ns();
    for (long step = 0; step < n; step++) {
        ak_anchor_smooth_attitude_step(table[step & (TABLE_ROWS - 1)], AK_BENCH_SMOOTH_STEP, q);
        ak_anchor_smooth_quat_to_matrix(q, R);
        ak_anchor_smooth_angles_123(R, theta, theta, &distance);
        sink = theta[step % 3];
    }
    return (ak_bench_now_ns() - start) / (double)n;
}

/* n communication points on a fresh instance, reading the first n_read of q[1..4], theta[1..3]:
 * ns per set/doStep/get. */
AK_INLINE double time_fmu_h(const fmu_api *api, long n, int n_read, double q_out[4], double h) {
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
        status |= api->do_step(c, t, h, fmi2True);
        status |= api->get_real(c, READ_VRS, (size_t)n_read, read);
        t += h;
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
AK_INLINE double time_fmu3_h(const fmu3_api *api, long n, bool with_theta, double q_out[4],
                             double h) {
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
        status |= (unsigned int)api->do_step(c, t, h, fmi3True, &event, &terminate,
                                             &early, &last);
        status |= (unsigned int)api->get_float64(c, read_vrs, n_vrs, read, n_values);
        t += h;
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

static double time_fmu(const fmu_api *api, long n, int n_read, double q_out[4]) {
#define CALL(h) time_fmu_h(api, n, n_read, q_out, h)
    return AK_WITH_STEP(CALL);
#undef CALL
}

static double time_fmu3(const fmu3_api *api, long n, bool with_theta, double q_out[4]) {
#define CALL(h) time_fmu3_h(api, n, with_theta, q_out, h)
    return AK_WITH_STEP(CALL);
#undef CALL
}

/* The loops: the anchors, then FMI 2 and FMI 3 of the current build and of the previous release,
 * each reading q, then q and theta. */
enum {
    BARE, ANGLES, FMU_Q, FMU_THETA, FMU3_Q, FMU3_THETA, PT_Q, PT_THETA, PT3_Q, PT3_THETA,
    PREV_Q, PREV_THETA, PREV3_Q, PREV3_THETA, N_LOOPS, MAX_REPEATS = 100
};
static const char *const LOOP_NAMES[N_LOOPS] = {"bare", "angles", "q", "q+theta", "q3", "q+theta3"};
static const char *const LABELS[N_LOOPS] = {
    "anchor: bare quaternion update (frozen copy of ak_attitude_step, constant omega)",
    "anchor: bare update + R + theta of body123 (frozen copy of ak_attitude_angles)",
    "FMI 2: set omega[1..3] + fmi2DoStep + get q[1..4]",
    "FMI 2: set omega[1..3] + fmi2DoStep + get q[1..4], theta[1..3]",
    "FMI 3: set omega + fmi3DoStep + get q",
    "FMI 3: set omega + fmi3DoStep + get q, theta",
    "pass-through FMU, FMI 2: set 3 + doStep + get 4",
    "pass-through FMU, FMI 2: set 3 + doStep + get 7",
    "pass-through FMU, FMI 3: set 1 array of 3 + doStep + get 1 array of 4",
    "pass-through FMU, FMI 3: set 1 array of 3 + doStep + get 2 arrays, 7 values",
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
    ak_passthrough2 pt2;
    ak_passthrough3 pt3;
} binaries;

static bool is_passthrough(int loop) {
    return loop >= PT_Q && loop <= PT3_THETA;
}

/* One run of loop `loop`: ns per step; q_out receives the final q (not for ANGLES). */
static double run_loop(int loop, const binaries *b, long steps, double q_out[4]) {
    switch (loop) {
    case BARE: return smooth_steps ? time_bare_smooth(steps, q_out) : time_bare(steps, q_out);
    case ANGLES: return smooth_steps ? time_bare_with_angles_smooth(steps) : time_bare_with_angles(steps);
    case FMU_Q: case FMU_THETA: case PREV_Q: case PREV_THETA:
        return time_fmu(&b->fmi2[loop >= PREV_Q], steps, reads_theta(loop) ? 7 : 4, q_out);
    case PT_Q: case PT_THETA:
        return ak_passthrough2_cycle(&b->pt2, &table[0][0], 3, 3, reads_theta(loop) ? 7 : 4,
                                     step_size(), steps);
    case PT3_Q: case PT3_THETA: {
        static const fmi3ValueReference omega = 0, read[2] = {21, 25}; /* PassThrough3's */
        return ak_passthrough3_cycle(&b->pt3, &table[0][0], 3, &omega, 1, 1, read,
                                     reads_theta(loop) ? 2 : 1, reads_theta(loop) ? 7 : 4,
                                     step_size(), steps);
    }
    default: return time_fmu3(&b->fmi3[loop >= PREV_Q], steps, reads_theta(loop), q_out);
    }
}

/* Whether the binaries of the loop were given. */
static bool loop_given(int loop, const binaries *b) {
    if (loop < FMU3_Q) {
        return true;
    }
    if (is_passthrough(loop)) {
        return b->pt2.library != NULL;
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
    const char *pt2 = NULL, *pt3 = NULL, *inputs = NULL;
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
        } else if (strcmp(argv[i], "--passthrough") == 0) {
            pt2 = argv[i + 1];
        } else if (strcmp(argv[i], "--passthrough3") == 0) {
            pt3 = argv[i + 1];
        } else if (strcmp(argv[i], "--inputs") == 0) {
            inputs = argv[i + 1];
        } else {
            fail("unknown option");
        }
    }
    if (steps < 1 || repeats < 1 || repeats > MAX_REPEATS) {
        fail("--steps and --repeats must be positive (repeats at most 100)");
    }
    if ((pt2 == NULL) != (pt3 == NULL) || (pt2 != NULL && fmi3 == NULL)) {
        fail("--passthrough and --passthrough3 go together, with --fmi3");
    }
    ak_bench_kind kind = AK_BENCH_RANDOM;
    if (inputs != NULL && ak_bench_parse_kind(inputs, &kind) != 0) {
        fail("--inputs random or smooth");
    }
    for (int r = 0; r < TABLE_ROWS; r++) { /* the default rows, the guard's */
        table[r][0] = sin(0.1 * r);
        table[r][1] = 0.5 * cos(0.07 * r);
        table[r][2] = 0.3 + 0.2 * sin(0.13 * r);
    }
    check_anchors(); /* on the default rows, whatever --inputs */
    if (inputs != NULL) {
        static double rows[AK_BENCH_ROWS][AK_BENCH_INPUTS];
        if (ak_bench_fill_inputs_of_kind(kind, rows) != 0) {
            fail("the input rows have equal consecutive values");
        }
        for (int r = 0; r < TABLE_ROWS; r++) {
            if (kind == AK_BENCH_SMOOTH) { /* the tumbling body's omega_body */
                double y[12];
                ak_angular_kinematics_123(rows[r], rows[r] + 3, rows[r] + 6, y, y + 3, y + 6,
                                          y + 9);
                memcpy(table[r], y + 3, sizeof table[r]);
            } else {
                memcpy(table[r], rows[r] + 3, sizeof table[r]);
            }
        }
        smooth_steps = kind == AK_BENCH_SMOOTH;
        if (smooth_steps) {
            check_smooth_anchor();
        }
    }
    const char *kind_name = inputs == NULL ? "default" : ak_bench_kind_name(kind);
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
    if (pt2 != NULL) {
        ak_passthrough2_load(pt2, &b.pt2);
        ak_passthrough3_load(pt3, &b.pt3);
    }
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
    static double floor_ratio[N_LOOPS][MAX_REPEATS];
    double q_core[4];
    core_steps(steps, q_core);
    for (int r = 0; r < repeats; r++) {
        for (int loop = 0; loop < N_LOOPS; loop++) {
            if (!loop_given(loop, &b)) {
                continue;
            }
            ns[loop][r] = run_loop(loop, &b, steps, q[loop]);
            if (loop >= FMU_Q && !is_passthrough(loop) &&
                memcmp(q_core, q[loop], sizeof q_core) != 0) {
                fail("the FMU's q differs from the core's step");
            }
        }
        for (int loop = 0; loop < N_LOOPS; loop++) { /* reading theta: against update + angles */
            const double anchor = ns[reads_theta(loop) ? ANGLES : BARE][r];
            ratio[loop][r] = ns[loop][r] / anchor;
            floor_ratio[loop][r] = (ns[loop][r] + anchor) / anchor; /* for the pass-through loops */
        }
    }
    printf("AttitudePropagator, %s inputs, %ld steps of %g s, median of %d repeats (thread CPU\n"
           "time), loops alternating; a loop reading theta is divided by the update + angles\n"
           "anchor, the other loops by the bare update:\n",
           kind_name, steps, step_size(), repeats);
    printf("| loop | ns per step | / its anchor |\n|---|---:|---:|\n");
    for (int loop = 0; loop < N_LOOPS; loop++) {
        if (loop_given(loop, &b)) {
            printf("| %s | %.1f | %.2f |\n", LABELS[loop], ak_bench_median(ns[loop], repeats),
                   ak_bench_median(ratio[loop], repeats));
        }
    }
    if (b.pt2.library != NULL) {
        static const char *const KEYS[4] = {"ap-fmi2-q", "ap-fmi2-theta", "ap-fmi3-q",
                                            "ap-fmi3-theta"};
        printf("\nBeside each FMU loop, the pass-through's same loop: its ns, and (pass-through + "
               "anchor) / anchor:\n\n| loop | / its anchor | pass-through ns | (pass-through + "
               "anchor) / anchor |\n|---|---:|---:|---:|\n");
        for (int loop = FMU_Q; loop <= FMU3_THETA; loop++) {
            const int pt = loop + (PT_Q - FMU_Q);
            const double r = ak_bench_median(ratio[loop], repeats);
            const double pt_ns = ak_bench_median(ns[pt], repeats);
            const double f = ak_bench_median(floor_ratio[pt], repeats);
            printf("| %s | %.3f | %.1f | %.3f |\n", LABELS[loop], r, pt_ns, f);
            ak_bench_record_figure(KEYS[loop - FMU_Q], kind_name, r, f, pt_ns);
        }
    }
    return 0;
}
