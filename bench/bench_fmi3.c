/* The FMI 3 cycle beside the FMI 2 cycle, the anchor and the general core (issues 12, 24), timed
 * alternately in one run, repeat after repeat, so that all see the same machine load:
 *   - anchor: the hand-written 1-2-3 formula, ak_angular_kinematics_123 (tests/c/kinematics_123.c,
 *     the project's test reference), the physical limit of the main use; every ratio is to it;
 *   - core: ak_general_angular_kinematics (body123), a figure of its own (it moves with the code);
 *   - FMI 2 cycle: fmi2SetReal of the 9 inputs, fmi2DoStep, fmi2GetReal of the 12 outputs
 *     omega_fixed .. alpha_body (build/fmu/binaries/linux64/AngularKinematics.so);
 *   - FMI 3 cycle: three fmi3SetFloat64, one per input array (theta, theta_dot, theta_ddot),
 *     fmi3DoStep, one fmi3GetFloat64 of the four output arrays omega_fixed .. alpha_body
 *     (build/fmu3/binaries/x86_64-linux/AngularKinematics.so); and the same with one
 *     fmi3SetFloat64 of the three input arrays, the cycle of the speed goal;
 *   - with PREV2_SO and PREV3_SO: the same two cycles of the previous release's binaries;
 *   - with --passthrough SO and --passthrough3 SO: the same cycles (9 inputs, 12 outputs, the
 *     same calls) through the pass-through FMUs (bench_passthrough.h), what the calls cost with
 *     no model behind them.
 * Given EulerRates.so files, the cycles are EulerRates' (the same value references).
 * Inputs cycle through the table of bench/bench_inputs.h (that of bench_fmu.c), so every step
 * evaluates: --inputs random (the default) or smooth. CPU time of the thread;
 * medians over the repeats, the ratios are medians of the per-repeat ratios.
 *
 * Usage: bench_fmi3 FMI2_SO FMI3_SO [STEPS [REPEATS [LOOP|all [PREV2_SO PREV3_SO]]]]
 *                   [--inputs random|smooth] [--passthrough SO --passthrough3 SO]
 * (LOOP: k123, core, fmi2, fmi3, fmi3-one-set; pt2, pt3, pt3-one-set with the pass-throughs)
 * (bench/run.sh passes the build's). With a loop named, only that loop runs, once: bench/run.sh
 * and bench/guard.sh count its instructions under callgrind. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime, dlopen */

#include <dlfcn.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "AngularKinematics_variables.h" /* KIN_GUID, generated */
#include "EulerRates_variables.h"        /* ER_GUID */
#include "bench_inputs.h"
#include "bench_timing.h"
#include "fmi2FunctionTypes.h"
#include "fmi3FunctionTypes.h"
#include "kinematics_123.h"
#include "bench_anchor.h" /* after bench_inputs.h, bench_timing.h, kinematics_123.h */
#include "bench_passthrough.h"
#include "kinematics_general.h"
#include "kinematics_general_kernel.h"
#include "sequences.h"

enum { TABLE_ROWS = AK_BENCH_ROWS, MAX_REPEATS = 51 };
static double input_table[TABLE_ROWS][AK_BENCH_INPUTS];
static volatile double sink;


/* The model of the .so files: an FMU's binary is named after its model identifier. EulerRates has
 * AngularKinematics' value references for the same roles (3 input arrays at 0, 3, 6; 4 output
 * arrays at 9, 12, 15, 18), so the same loops run it (bench/guard.sh). */
static const char *guid = KIN_GUID;

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

/* The anchor (bench_anchor.h). */
static double time_k123(long n) {
    double sum;
    const double ns = ak_bench_time_anchor(input_table, n, &sum);
    sink = sum;
    return ns;
}

static void fmi2_log(fmi2ComponentEnvironment e, fmi2String n, fmi2Status s, fmi2String c,
                     fmi2String m, ...) {
    (void)e, (void)n, (void)s, (void)c;
    fprintf(stderr, "FMI 2: %s\n", m);
}

/* This loop and time_fmi3_one_set are inlined into run_loop, as they were before the
 * pass-through loops came: the recorded counts (bench/guard.sh, docs/performance.md) were taken
 * with that code. */
__attribute__((always_inline)) static inline double time_fmi2(void *library, long n) {
    fmi2CallbackFunctions callbacks = {fmi2_log, calloc, free, NULL, NULL};
    fmi2Component c = FUNCTION(fmi2InstantiateTYPE, library, "fmi2Instantiate")(
        "bench", fmi2CoSimulation, guid, "", &callbacks, fmi2False, fmi2False);
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
        "bench", guid, NULL, fmi3False, fmi3False, fmi3False, fmi3False, NULL, 0, NULL, fmi3_log, NULL);
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

/* The same cycle with the three input arrays in one fmi3SetFloat64, as the speed goal states it (a loop
 * of its own, so that time_fmi3's, which the guard's record was taken with, stays as it was). */
__attribute__((always_inline)) static inline double time_fmi3_one_set(void *library, long n) {
    fmi3Instance c = FUNCTION(fmi3InstantiateCoSimulationTYPE, library, "fmi3InstantiateCoSimulation")(
        "bench", guid, NULL, fmi3False, fmi3False, fmi3False, fmi3False, NULL, 0, NULL, fmi3_log, NULL);
    fmi3SetFloat64TYPE *set = FUNCTION(fmi3SetFloat64TYPE, library, "fmi3SetFloat64");
    fmi3GetFloat64TYPE *get = FUNCTION(fmi3GetFloat64TYPE, library, "fmi3GetFloat64");
    fmi3DoStepTYPE *step_fn = FUNCTION(fmi3DoStepTYPE, library, "fmi3DoStep");
    FUNCTION(fmi3EnterInitializationModeTYPE, library, "fmi3EnterInitializationMode")(
        c, fmi3False, 0, 0, fmi3False, 0);
    FUNCTION(fmi3ExitInitializationModeTYPE, library, "fmi3ExitInitializationMode")(c);
    const fmi3ValueReference inputs[3] = {0, 3, 6};
    const fmi3ValueReference out[4] = {9, 12, 15, 18};
    double y[12], sum = 0.0, t = 0.0, last;
    fmi3Boolean event, terminate, early;
    unsigned int statuses = 0;
    const double start = ak_bench_now_ns();
    for (long step = 0; step < n; step++) {
        const double *u = input_table[step & (TABLE_ROWS - 1)];
        statuses |= (unsigned int)set(c, inputs, 3, u, 9);
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

static ak_passthrough2 passthrough2;
static ak_passthrough3 passthrough3;
static const fmi3ValueReference PT_INPUTS[3] = {0, 3, 6}, PT_OUTPUTS[4] = {9, 12, 15, 18};

static void *load(const char *path) {
    void *library = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (library == NULL) {
        fprintf(stderr, "bench_fmi3: %s\n", dlerror());
        exit(1);
    }
    return library;
}

enum { K123, CORE, FMI2, FMI3, FMI3_ONE_SET, PT2, PT3, PT3_ONE_SET, PREV2, PREV3, N_LOOPS };
static const char *const LOOP_NAMES[N_LOOPS] = {"k123", "core", "fmi2", "fmi3", "fmi3-one-set",
                                                "pt2", "pt3", "pt3-one-set", "prev2", "prev3"};

/* One run of loop `loop` over `steps` steps: ns per step. */
static double run_loop(int loop, void *const libraries[N_LOOPS], long steps) {
    switch (loop) {
    case K123: return time_k123(steps);
    case CORE: return time_core(steps);
    case FMI2: case PREV2: return time_fmi2(libraries[loop], steps);
    case FMI3_ONE_SET: return time_fmi3_one_set(libraries[FMI3], steps);
    case PT2:
        return ak_passthrough2_cycle(&passthrough2, &input_table[0][0], AK_BENCH_INPUTS, 9, 12,
                                     1e-3, steps);
    case PT3: case PT3_ONE_SET:
        return ak_passthrough3_cycle(&passthrough3, &input_table[0][0], AK_BENCH_INPUTS, PT_INPUTS,
                                     loop == PT3 ? 3 : 1, loop == PT3 ? 1 : 3, PT_OUTPUTS, 4, 12,
                                     1e-3, steps);
    default: return time_fmi3(libraries[loop], steps);
    }
}

/* Takes the options out of argv (the positional arguments stay, in order). */
static int take_options(int argc, char **argv, ak_bench_kind *kind, const char **pt2,
                        const char **pt3) {
    int kept = 1;
    for (int i = 1; i < argc; i++) {
        if (i + 1 < argc && strcmp(argv[i], "--inputs") == 0) {
            if (ak_bench_parse_kind(argv[++i], kind) != 0) {
                fprintf(stderr, "bench_fmi3: --inputs random or smooth\n");
                exit(2);
            }
        } else if (i + 1 < argc && strcmp(argv[i], "--passthrough") == 0) {
            *pt2 = argv[++i];
        } else if (i + 1 < argc && strcmp(argv[i], "--passthrough3") == 0) {
            *pt3 = argv[++i];
        } else {
            argv[kept++] = argv[i];
        }
    }
    return kept;
}

int main(int argc, char **argv) {
    ak_bench_kind kind = AK_BENCH_RANDOM;
    const char *pt2_path = NULL, *pt3_path = NULL;
    argc = take_options(argc, argv, &kind, &pt2_path, &pt3_path);
    if (argc < 3 || argc == 7 || (pt2_path == NULL) != (pt3_path == NULL)) {
        fprintf(stderr, "usage: bench_fmi3 FMI2_SO FMI3_SO "
                        "[STEPS [REPEATS [LOOP [PREV2_SO PREV3_SO]]]] [--inputs random|smooth] "
                        "[--passthrough SO --passthrough3 SO]\n");
        return 2;
    }
    const long steps = argc > 3 ? (long)atof(argv[3]) : 1000000;
    int repeats = argc > 4 ? atoi(argv[4]) : 7;
    repeats = repeats < 1 ? 1 : repeats > MAX_REPEATS ? MAX_REPEATS : repeats;
    const int n_loops = argc > 7 ? N_LOOPS : PREV2;
    const char *model = strstr(argv[1], "EulerRates") != NULL ? "EulerRates" : "AngularKinematics";
    guid = strcmp(model, "EulerRates") == 0 ? ER_GUID : KIN_GUID;
    void *libraries[N_LOOPS] = {NULL, NULL, load(argv[1]), load(argv[2]), NULL, NULL, NULL, NULL,
                                argc > 7 ? load(argv[6]) : NULL, argc > 7 ? load(argv[7]) : NULL};
    const int pass = pt2_path != NULL;
    if (pass) {
        ak_passthrough2_load(pt2_path, &passthrough2);
        ak_passthrough3_load(pt3_path, &passthrough3);
    }
    if (ak_bench_fill_inputs_of_kind(kind, input_table) != 0) {
        fprintf(stderr, "bench_fmi3: the input table has equal consecutive values\n");
        return 1;
    }
    if (argc > 5 && strcmp(argv[5], "all") != 0) { /* one loop alone */
        for (int loop = 0; loop < PREV2; loop++) {
            if (strcmp(argv[5], LOOP_NAMES[loop]) == 0 && (loop < PT2 || pass)) {
                printf("%s: %.1f ns/step\n", argv[5], run_loop(loop, libraries, steps));
                return 0;
            }
        }
        fprintf(stderr, "bench_fmi3: unknown loop %s (k123, core, fmi2, fmi3, fmi3-one-set, "
                        "with --passthrough pt2, pt3, pt3-one-set, or all)\n", argv[5]);
        return 2;
    }
    double ns[N_LOOPS][MAX_REPEATS] = {{0.0}}, ratio[N_LOOPS][MAX_REPEATS];
    double fmi3_to_fmi2[5][MAX_REPEATS];
    double floor2[MAX_REPEATS];
    time_k123(steps / 10); /* warm-up */
    for (int r = 0; r < repeats; r++) {
        for (int loop = 0; loop < n_loops; loop++) {
            if (loop < PT2 || loop > PT3_ONE_SET || pass) {
                ns[loop][r] = run_loop(loop, libraries, steps);
            }
        }
        for (int loop = 0; loop < n_loops; loop++) {
            ratio[loop][r] = ns[loop][r] / ns[K123][r];
        }
        fmi3_to_fmi2[0][r] = ns[FMI3][r] / ns[FMI2][r];
        fmi3_to_fmi2[1][r] = n_loops > PREV2 ? ns[PREV3][r] / ns[PREV2][r] : 0.0;
        fmi3_to_fmi2[2][r] = ns[FMI3_ONE_SET][r] / ns[FMI2][r];
        if (pass) { /* the pass-through's: FMI 3 / FMI 2, and the anchor plus its FMI 2 cycle */
            fmi3_to_fmi2[3][r] = ns[PT3][r] / ns[PT2][r];
            fmi3_to_fmi2[4][r] = ns[PT3_ONE_SET][r] / ns[PT2][r];
            floor2[r] = (ns[PT2][r] + ns[K123][r]) / ns[K123][r];
        }
    }
    static const char *const LABELS[N_LOOPS] = {
        "anchor: hand-written 1-2-3 formula (tests/c/kinematics_123.c)",
        "general core, body123 (ak_general_angular_kinematics)",
        "FMI 2 cycle: fmi2SetReal of 9, fmi2DoStep, fmi2GetReal of 12",
        "FMI 3 cycle: 3 fmi3SetFloat64 of 3, fmi3DoStep, 1 fmi3GetFloat64 of 4 arrays",
        "FMI 3 cycle, one fmi3SetFloat64 of the 3 input arrays",
        "pass-through FMU, FMI 2 cycle (set 9, doStep, get 12)",
        "pass-through FMU, FMI 3 cycle (3 sets of 3, doStep, get of 4 arrays)",
        "pass-through FMU, FMI 3 cycle (one set of the 3 arrays)",
        "previous release: FMI 2 cycle", "previous release: FMI 3 cycle"};
    printf("%s body123, %s inputs, timed alternately; %ld steps per run, %d repeats, medians;\n"
           "ratios are medians of the per-repeat ratios to the anchor:\n\n", model,
           ak_bench_kind_name(kind), steps, repeats);
    printf("| loop | ns/step | / anchor |\n|---|---:|---:|\n");
    for (int loop = 0; loop < n_loops; loop++) {
        if (loop >= PT2 && loop <= PT3_ONE_SET && !pass) {
            continue;
        }
        printf("| %s | %.1f | %.3f |\n", LABELS[loop], ak_bench_median(ns[loop], repeats),
               ak_bench_median(ratio[loop], repeats));
    }
    printf("\nFMI 3 cycle / FMI 2 cycle: %.3f (one set of the 3 arrays: %.3f)",
           ak_bench_median(fmi3_to_fmi2[0], repeats), ak_bench_median(fmi3_to_fmi2[2], repeats));
    if (n_loops > PREV2) {
        printf(" (previous release: %.3f)", ak_bench_median(fmi3_to_fmi2[1], repeats));
    }
    printf("\n");
    if (pass) {
        const double pt2 = ak_bench_median(ns[PT2], repeats);
        const double pt3_one = ak_bench_median(ns[PT3_ONE_SET], repeats);
        const double floor_ratio = ak_bench_median(floor2, repeats);
        const double pt_fmi3 = ak_bench_median(fmi3_to_fmi2[4], repeats);
        printf("Beside, the pass-through FMU: FMI 2 cycle %.1f ns, (pass-through + anchor) / anchor "
               "%.3f against the FMI 2 cycle's %.3f;\npass-through FMI 3 / FMI 2 %.3f (3 sets "
               "of 3: %.3f) against the model's %.3f (%.3f).\n",
               pt2, floor_ratio, ak_bench_median(ratio[FMI2], repeats), pt_fmi3,
               ak_bench_median(fmi3_to_fmi2[3], repeats),
               ak_bench_median(fmi3_to_fmi2[2], repeats), ak_bench_median(fmi3_to_fmi2[0], repeats));
        if (strcmp(model, "AngularKinematics") == 0) {
            ak_bench_record_figure("ak-fmi2", ak_bench_kind_name(kind),
                                   ak_bench_median(ratio[FMI2], repeats), floor_ratio, pt2);
            ak_bench_record_figure("ak-fmi3", ak_bench_kind_name(kind),
                                   ak_bench_median(fmi3_to_fmi2[2], repeats), pt_fmi3, pt3_one);
        }
    }
    return 0;
}
