/* PointKinematics' FMI 2 cycle beside its floor, timed alternately in one run, repeat after
 * repeat, so that all see the same machine load:
 *   - PointKinematics: fmi2SetReal of the 24 inputs, fmi2DoStep, fmi2GetReal of the 18 outputs
 *     (build/fmu/binaries/linux64/PointKinematics.so);
 *   - the pass-through FMU: the same calls with the same counts (build/passthrough/PassThrough.so,
 *     inputs copied to outputs): what an importer pays for the calls of any FMU of the interface;
 *   - the anchor: the hand-written formula on the same rows (bench/point_anchor.c, frozen).
 * Goal: the cycle at most 1.3 x (pass-through cycle + formula); the ratio quoted is the median of
 * the per-repeat ratios. Rows: 256 pseudo-random input vectors (components of sizes 1e-3 to 1e3,
 * either sign), cycled, consecutive rows differing in every input so that every step evaluates.
 * CPU time of the thread.
 *
 * Usage: bench_point POINT_SO PASSTHROUGH_SO [STEPS [REPEATS]]   (defaults 1e6, 5)
 *        bench_point POINT_SO PASSTHROUGH_SO STEPS 1 point|passthrough|anchor
 *          (one loop, once: for instruction counts under callgrind) */
#define _POSIX_C_SOURCE 200809L /* clock_gettime, dlopen */

#include <dlfcn.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "PointKinematics_variables.h" /* PK_GUID, generated */
#include "bench_timing.h"
#include "fmi2FunctionTypes.h"
#include "point_anchor.h"

#define PASSTHROUGH_GUID "{5b2d7a40-3c1e-4f8a-9d6b-0e4f2a7c9b13}"

enum { ROWS = 256, N_IN = 24, N_OUT = 18, MAX_REPEATS = 51 };
static double rows[ROWS][N_IN];
static volatile double sink;

typedef struct {
    const char *name;
    const char *guid;
    fmi2Component c;
    fmi2SetRealTYPE *set_real;
    fmi2GetRealTYPE *get_real;
    fmi2DoStepTYPE *do_step;
    fmi2FreeInstanceTYPE *free_instance;
    fmi2ValueReference outputs[N_OUT]; /* the value references read */
    double time;                        /* the next communication point */
} fmu;

static void fill_rows(void) {
    uint64_t x = 88172645463325252u;
    for (int row = 0; row < ROWS; row++) {
        for (int k = 0; k < N_IN; k++) {
            x ^= x << 13, x ^= x >> 7, x ^= x << 17;
            const double u = (double)(x >> 11) / 9007199254740992.0; /* [0, 1) */
            x ^= x << 13, x ^= x >> 7, x ^= x << 17;
            const double size = pow(10.0, 6.0 * ((double)(x >> 11) / 9007199254740992.0) - 3.0);
            rows[row][k] = (u < 0.5 ? -1.0 : 1.0) * size;
        }
    }
    for (int row = 0; row < ROWS; row++) { /* every input moves at every step */
        for (int k = 0; k < N_IN; k++) {
            if (rows[row][k] == rows[(row + 1) % ROWS][k]) {
                rows[row][k] *= 1.5;
            }
        }
    }
}

static void *symbol(void *library, const char *name) {
    void *s = dlsym(library, name);
    if (s == NULL) {
        fprintf(stderr, "bench_point: no %s\n", name);
        exit(1);
    }
    return s;
}

#define FUNCTION(type, library, name) ((type *)(uintptr_t)symbol(library, name))

static void log_message(fmi2ComponentEnvironment e, fmi2String n, fmi2Status s, fmi2String c,
                        fmi2String m, ...) {
    (void)e, (void)n, (void)s, (void)c;
    fprintf(stderr, "bench_point: %s\n", m);
}

static const fmi2CallbackFunctions CALLBACKS = {log_message, calloc, free, NULL, NULL};

static void load(fmu *f, const char *path, fmi2ValueReference first_output) {
    void *library = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (library == NULL) {
        fprintf(stderr, "bench_point: cannot load %s: %s\n", path, dlerror());
        exit(1);
    }
    fmi2InstantiateTYPE *instantiate = FUNCTION(fmi2InstantiateTYPE, library, "fmi2Instantiate");
    f->c = instantiate("bench", fmi2CoSimulation, f->guid, "file:///", &CALLBACKS, fmi2False,
                       fmi2False);
    f->set_real = FUNCTION(fmi2SetRealTYPE, library, "fmi2SetReal");
    f->get_real = FUNCTION(fmi2GetRealTYPE, library, "fmi2GetReal");
    f->do_step = FUNCTION(fmi2DoStepTYPE, library, "fmi2DoStep");
    f->free_instance = FUNCTION(fmi2FreeInstanceTYPE, library, "fmi2FreeInstance");
    fmi2SetupExperimentTYPE *setup = FUNCTION(fmi2SetupExperimentTYPE, library, "fmi2SetupExperiment");
    fmi2EnterInitializationModeTYPE *enter =
        FUNCTION(fmi2EnterInitializationModeTYPE, library, "fmi2EnterInitializationMode");
    fmi2ExitInitializationModeTYPE *exit_mode =
        FUNCTION(fmi2ExitInitializationModeTYPE, library, "fmi2ExitInitializationMode");
    if (f->c == NULL || setup(f->c, fmi2False, 0.0, 0.0, fmi2False, 0.0) != fmi2OK ||
        enter(f->c) != fmi2OK || exit_mode(f->c) != fmi2OK) {
        fprintf(stderr, "bench_point: %s did not start\n", f->name);
        exit(1);
    }
    for (int k = 0; k < N_OUT; k++) {
        f->outputs[k] = first_output + (fmi2ValueReference)k;
    }
}

/* n cycles: set the 24 inputs of the next row, step, get the 18 outputs. ns per cycle. */
__attribute__((noinline)) static double cycle(fmu *f, long n) {
    static const fmi2ValueReference inputs[N_IN] = {0,  1,  2,  3,  4,  5,  6,  7,  8,  9,  10, 11,
                                                    12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23};
    double y[N_OUT], sum = 0.0, t = f->time;
    unsigned int statuses = 0;
    const double start = ak_bench_now_ns();
    for (long step = 0; step < n; step++) {
        statuses |= (unsigned int)f->set_real(f->c, inputs, N_IN, rows[step & (ROWS - 1)]);
        statuses |= (unsigned int)f->do_step(f->c, t, 1e-3, fmi2True);
        t += 1e-3;
        statuses |= (unsigned int)f->get_real(f->c, f->outputs, N_OUT, y);
        sum += y[step % N_OUT];
    }
    const double elapsed = ak_bench_now_ns() - start;
    sink = sum;
    f->time = t;
    if (statuses != 0) {
        fprintf(stderr, "bench_point: a call of %s failed\n", f->name);
        exit(1);
    }
    return elapsed / (double)n;
}

/* n evaluations of the hand-written formula on the same rows. ns per evaluation. */
__attribute__((noinline)) static double anchor(long n) {
    double y[N_OUT], sum = 0.0;
    const double start = ak_bench_now_ns();
    for (long step = 0; step < n; step++) {
        ak_anchor_point(rows[step & (ROWS - 1)], y);
        sum += y[step % N_OUT];
    }
    const double elapsed = ak_bench_now_ns() - start;
    sink = sum;
    return elapsed / (double)n;
}

int main(int argc, char **argv) {
    if (argc < 3) {
        fprintf(stderr, "usage: bench_point POINT_SO PASSTHROUGH_SO [STEPS [REPEATS [LOOP]]]\n");
        return 2;
    }
    const long steps = argc > 3 ? (long)atof(argv[3]) : 1000000;
    const int repeats = argc > 4 ? atoi(argv[4]) : 5;
    const char *only = argc > 5 ? argv[5] : NULL;
    if (steps < 1 || repeats < 1 || repeats > MAX_REPEATS) {
        fprintf(stderr, "bench_point: STEPS >= 1, REPEATS in 1..%d\n", MAX_REPEATS);
        return 2;
    }
    fill_rows();
    fmu point = {.name = "PointKinematics", .guid = PK_GUID};
    fmu passthrough = {.name = "the pass-through FMU", .guid = PASSTHROUGH_GUID};
    load(&point, argv[1], PK_VR_V_P);
    load(&passthrough, argv[2], 24);
    if (only != NULL) {
        const double ns = strcmp(only, "point") == 0         ? cycle(&point, steps)
                          : strcmp(only, "passthrough") == 0 ? cycle(&passthrough, steps)
                                                             : anchor(steps);
        printf("%s: %.1f ns per cycle\n", only, ns);
        return 0;
    }
    double t_point[MAX_REPEATS], t_pass[MAX_REPEATS], t_anchor[MAX_REPEATS], ratio[MAX_REPEATS];
    (void)cycle(&point, steps / 10 + 1); /* warm the caches and the branch predictors */
    (void)cycle(&passthrough, steps / 10 + 1);
    (void)anchor(steps / 10 + 1);
    for (int r = 0; r < repeats; r++) { /* the order turns each repeat */
        for (int k = 0; k < 3; k++) {
            switch ((r + k) % 3) {
            case 0: t_point[r] = cycle(&point, steps); break;
            case 1: t_pass[r] = cycle(&passthrough, steps); break;
            default: t_anchor[r] = anchor(steps); break;
            }
        }
        ratio[r] = t_point[r] / (t_pass[r] + t_anchor[r]);
    }
    const double r_med = ak_bench_median(ratio, repeats);
    const double p = ak_bench_median(t_point, repeats), q = ak_bench_median(t_pass, repeats),
                 a = ak_bench_median(t_anchor, repeats);
    printf("PointKinematics FMI 2 cycle (set 24 inputs, doStep, get 18 outputs), %ld steps, "
           "median of %d repeats:\n", steps, repeats);
    printf("  PointKinematics %.1f ns, pass-through %.1f ns, hand-written formula %.1f ns\n", p, q, a);
    printf("  PointKinematics / (pass-through + formula): %.3f (goal 1.3: %s)\n", r_med,
           r_med <= 1.3 ? "met" : "NOT met");
    point.free_instance(point.c);
    passthrough.free_instance(passthrough.c);
    return 0;
}
