/* Benchmark driver for the speed goals beyond body123 (docs/performance.md):
 *   - for each of the 24 sequences, the FMI 2 cycle (fmi2SetReal of the 9 inputs, fmi2DoStep,
 *     fmi2GetReal of the 12 omega/alpha outputs; the `sequence` parameter set before
 *     initialization) against that sequence's anchor, its closed-form formula generated once by
 *     sympy (bench/anchors_sequences.c, frozen);
 *   - the cycle reading every output (what fmpy records by default, body123) against the
 *     all-outputs anchor: the core functions the FMU runs, called inline with no FMI.
 * Before timing it checks that each anchor agrees with the FMU (relative 1e-12 of the largest
 * output) on the 256 input rows, and fails otherwise.
 * With --passthrough SO, each sequence's row has the pass-through FMU's cycle (set 9, doStep,
 * get 12; bench_passthrough.h) beside it, timed in the same alternation. --inputs random|smooth
 * chooses the rows of bench_inputs.h (default random).
 *   bench_sequences_fmu FMU_SO [--steps N] [--repeats R] [--inputs random|smooth]
 *                       [--passthrough SO]                      ns table (medians, alternating)
 *   bench_sequences_fmu FMU_SO --only anchor|cycle|all-anchor|all K --steps N
 *                                                       one loop of sequence K (1..24), no output
 *                                                       (instruction counts, bench/run.sh) */
#define _POSIX_C_SOURCE 200809L

#include <dlfcn.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2FunctionTypes.h"
#include "AngularKinematics_variables.h"
#include "anchors_sequences.h"
#include "bench_inputs.h"
#include "bench_timing.h"
#include "bench_passthrough.h"
#include "kinematics_general.h"
#include "bench_all_outputs.h"

enum { ROWS = AK_BENCH_ROWS, MAX_REPEATS = 101 };

static double input_table[ROWS][AK_BENCH_INPUTS];
static volatile double sink;
static fmi2ValueReference all_vrs[KIN_N_OUTPUTS];
static int n_all = 0;

static void fail(const char *what) {
    fprintf(stderr, "bench_sequences_fmu: FAILED: %s\n", what);
    exit(1);
}

typedef struct {
    fmi2InstantiateTYPE *instantiate;
    fmi2FreeInstanceTYPE *free_instance;
    fmi2SetupExperimentTYPE *setup;
    fmi2EnterInitializationModeTYPE *enter;
    fmi2ExitInitializationModeTYPE *exit_init;
    fmi2SetIntegerTYPE *set_integer;
    fmi2SetRealTYPE *set_real;
    fmi2GetRealTYPE *get_real;
    fmi2DoStepTYPE *do_step;
} fmu_api;

static void *symbol(void *library, const char *name) {
    void *s = dlsym(library, name);
    if (s == NULL) {
        fail(name);
    }
    return s;
}

#define FUNCTION(type, library, name) ((type *)(uintptr_t)symbol(library, name))

static fmu_api load(const char *path) {
    void *l = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (l == NULL) {
        fail(dlerror());
    }
    return (fmu_api){FUNCTION(fmi2InstantiateTYPE, l, "fmi2Instantiate"),
                     FUNCTION(fmi2FreeInstanceTYPE, l, "fmi2FreeInstance"),
                     FUNCTION(fmi2SetupExperimentTYPE, l, "fmi2SetupExperiment"),
                     FUNCTION(fmi2EnterInitializationModeTYPE, l, "fmi2EnterInitializationMode"),
                     FUNCTION(fmi2ExitInitializationModeTYPE, l, "fmi2ExitInitializationMode"),
                     FUNCTION(fmi2SetIntegerTYPE, l, "fmi2SetInteger"),
                     FUNCTION(fmi2SetRealTYPE, l, "fmi2SetReal"),
                     FUNCTION(fmi2GetRealTYPE, l, "fmi2GetReal"),
                     FUNCTION(fmi2DoStepTYPE, l, "fmi2DoStep")};
}

static void log_message(fmi2ComponentEnvironment e, fmi2String n, fmi2Status s, fmi2String c,
                        fmi2String m, ...) {
    (void)e, (void)n, (void)s, (void)c;
    fprintf(stderr, "FMU: %s\n", m);
}

static const fmi2CallbackFunctions CALLBACKS = {log_message, calloc, free, NULL, NULL};
static const fmi2ValueReference INPUTS[9] = {0, 1, 2, 3, 4, 5, 6, 7, 8};
static const fmi2ValueReference OMEGA_ALPHA[12] = {9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20};

/* Instantiated with `sequence` = k (1..24), initialized. */
static fmi2Component start(const fmu_api *api, int k) {
    fmi2Component c = api->instantiate("bench", fmi2CoSimulation, KIN_GUID, "", &CALLBACKS,
                                       fmi2False, fmi2False);
    const fmi2ValueReference sequence = KIN_VR_SEQUENCE;
    const fmi2Integer value = k;
    if (c == NULL || api->set_integer(c, &sequence, 1, &value) != fmi2OK ||
        api->setup(c, fmi2False, 0.0, 0.0, fmi2False, 0.0) != fmi2OK ||
        api->enter(c) != fmi2OK || api->exit_init(c) != fmi2OK) {
        fail("instantiation");
    }
    return c;
}

/* n cycles of sequence k reading the n_vrs outputs vrs: ns per cycle. */
static double time_cycle(const fmu_api *api, int k, const fmi2ValueReference *vrs, int n_vrs,
                         long n) {
    fmi2Component c = start(api, k);
    double y[KIN_N_OUTPUTS], sum = 0.0, t = 0.0;
    unsigned int statuses = 0;
    int j = 0;
    const double begin = ak_bench_now_ns();
    for (long step = 0; step < n; step++) {
        statuses |= (unsigned int)api->set_real(c, INPUTS, 9, input_table[step & (ROWS - 1)]);
        statuses |= (unsigned int)api->do_step(c, t, 1e-3, fmi2True);
        t += 1e-3;
        statuses |= (unsigned int)api->get_real(c, vrs, (size_t)n_vrs, y);
        sum += y[j];
        j = j >= n_vrs - 1 ? 0 : j + 1;
    }
    const double elapsed = ak_bench_now_ns() - begin;
    sink = sum;
    api->free_instance(c);
    if (statuses != 0) {
        fail("a call of the cycle");
    }
    return elapsed / (double)n;
}

/* The anchor of sequence k on the same inputs: ns per evaluation. */
static double time_anchor(int k, long n) {
    ak_anchor_kernel *anchor = AK_ANCHORS[k - 1];
    double y[12], sum = 0.0;
    int j = 0;
    const double begin = ak_bench_now_ns();
    for (long step = 0; step < n; step++) {
        const double *u = input_table[step & (ROWS - 1)];
        anchor(u, u + 3, u + 6, y);
        sum += y[j];
        j = j == 11 ? 0 : j + 1;
    }
    const double elapsed = ak_bench_now_ns() - begin;
    sink = sum;
    return elapsed / (double)n;
}

/* The all-outputs anchor: every output of body123 from the core functions the FMU calls, inline,
 * no FMI (omega, alpha, R, q, W's and their rates, the rotation angle: 62 values). */
static double time_all_anchor(long n) {
    const ak_sequence *sequence = &AK_SEQUENCES[AK_SEQUENCE_DEFAULT];
    double y[12], R[3][3], q[4], W[4][3][3], angle, sum = 0.0;
    const double begin = ak_bench_now_ns();
    for (long step = 0; step < n; step++) {
        const double *u = input_table[step & (ROWS - 1)];
        ak_sines sines, half;
        ak_angle_sines(u, &sines);
        ak_half_angle_sines(&sines, &half);
        ak_general_all_outputs(sequence, &sines, &half, u + 3, u + 6, y, y + 3, y + 6, y + 9, R,
                               q, W[0], W[1], W[2], W[3]);
        ak_rotation_angle(q, &angle);
        sum += y[step % 12] + R[step % 3][1] + q[step & 3] + W[step & 3][1][step % 3] + angle;
    }
    const double elapsed = ak_bench_now_ns() - begin;
    sink = sum;
    return elapsed / (double)n;
}

/* Each anchor agrees with the FMU of its sequence on every input row. */
static void check(const fmu_api *api) {
    for (int k = 1; k <= 24; k++) {
        fmi2Component c = start(api, k);
        double t = 0.0;
        for (int row = 0; row < ROWS; row++) {
            const double *u = input_table[row];
            double fmu[12], anchor[12], scale = 0.0;
            if (api->set_real(c, INPUTS, 9, u) != fmi2OK ||
                api->do_step(c, t, 1e-3, fmi2True) != fmi2OK ||
                api->get_real(c, OMEGA_ALPHA, 12, fmu) != fmi2OK) {
                fail("a call of the check");
            }
            t += 1e-3;
            AK_ANCHORS[k - 1](u, u + 3, u + 6, anchor);
            for (int i = 0; i < 12; i++) {
                scale = fmax(scale, fabs(fmu[i]));
            }
            for (int i = 0; i < 12; i++) {
                if (!(fabs(fmu[i] - anchor[i]) <= 1e-12 * scale)) {
                    fprintf(stderr, "sequence %d output %d: FMU %.17g, anchor %.17g\n", k, i,
                            fmu[i], anchor[i]);
                    fail("an anchor disagrees with the FMU");
                }
            }
        }
        api->free_instance(c);
    }
}

int main(int argc, char **argv) {
    if (argc < 2) {
        fprintf(stderr, "usage: bench_sequences_fmu FMU_SO [--steps N] [--repeats R] "
                        "[--only anchor|cycle|all-anchor|all K]\n");
        return 2;
    }
    long steps = 200000;
    int repeats = 5, only_k = 0;
    const char *only = NULL, *passthrough_path = NULL;
    ak_bench_kind kind = AK_BENCH_RANDOM;
    for (int i = 2; i + 1 < argc; i++) {
        if (strcmp(argv[i], "--steps") == 0) {
            steps = (long)atof(argv[++i]);
        } else if (strcmp(argv[i], "--repeats") == 0) {
            repeats = atoi(argv[++i]);
        } else if (strcmp(argv[i], "--inputs") == 0) {
            if (ak_bench_parse_kind(argv[++i], &kind) != 0) {
                fail("--inputs random or smooth");
            }
        } else if (strcmp(argv[i], "--passthrough") == 0) {
            passthrough_path = argv[++i];
        } else if (strcmp(argv[i], "--only") == 0 && i + 2 < argc) {
            only = argv[++i];
            only_k = atoi(argv[++i]);
        }
    }
    if (repeats < 1 || repeats > MAX_REPEATS || steps < 1) {
        fail("bad --steps or --repeats");
    }
    if (ak_bench_fill_inputs_of_kind(kind, input_table) != 0) {
        fail("input table");
    }
    for (int vr = 0; vr < KIN_N_VALUE_REFERENCES; vr++) {
        if (KIN_VARIABLES[vr].name != NULL && KIN_VARIABLES[vr].causality == AK_CAUSALITY_OUTPUT) {
            all_vrs[n_all++] = (fmi2ValueReference)vr;
        }
    }
    const fmu_api api = load(argv[1]);
    check(&api);
    if (only != NULL) {
        if (only_k < 1 || only_k > 24) {
            fail("--only needs a sequence 1..24");
        }
        if (strcmp(only, "anchor") == 0) {
            time_anchor(only_k, steps);
        } else if (strcmp(only, "cycle") == 0) {
            time_cycle(&api, only_k, OMEGA_ALPHA, 12, steps);
        } else if (strcmp(only, "all-anchor") == 0) {
            time_all_anchor(steps);
        } else if (strcmp(only, "all") == 0) {
            time_cycle(&api, only_k, all_vrs, n_all, steps);
        } else {
            fail("unknown --only loop");
        }
        return 0;
    }
    static ak_passthrough2 pass;
    if (passthrough_path != NULL) {
        ak_passthrough2_load(passthrough_path, &pass);
    }
    printf("Each sequence's FMI 2 cycle (set 9, doStep, get 12) against its own anchor, the\n"
           "closed-form formula of bench/anchors_sequences.c (sympy, frozen); %s inputs, %ld\n"
           "steps, %d alternating repeats, medians. pass-through: the pass-through FMU's cycle,\n"
           "floor: (pass-through + anchor) / anchor:\n\n"
           "| sequence | anchor ns | cycle ns | cycle / anchor | pass-through ns | floor |\n"
           "|---|---:|---:|---:|---:|---:|\n", ak_bench_kind_name(kind), steps, repeats);
    for (int k = 1; k <= 24; k++) {
        double a[MAX_REPEATS], cyc[MAX_REPEATS], ratio[MAX_REPEATS], pt[MAX_REPEATS];
        double floors[MAX_REPEATS];
        for (int r = 0; r < repeats; r++) {
            a[r] = time_anchor(k, steps);
            cyc[r] = time_cycle(&api, k, OMEGA_ALPHA, 12, steps);
            pt[r] = passthrough_path == NULL
                        ? 0.0
                        : ak_passthrough2_cycle(&pass, &input_table[0][0], AK_BENCH_INPUTS,
                                                AK_BENCH_INPUTS, 12, 1e-3, steps);
            ratio[r] = cyc[r] / a[r];
            floors[r] = (pt[r] + a[r]) / a[r];
        }
        if (passthrough_path != NULL) {
            printf("| %s | %.1f | %.1f | %.2f | %.1f | %.2f |\n", AK_SEQUENCES[k - 1].name,
                   ak_bench_median(a, repeats), ak_bench_median(cyc, repeats),
                   ak_bench_median(ratio, repeats), ak_bench_median(pt, repeats),
                   ak_bench_median(floors, repeats));
        } else {
            printf("| %s | %.1f | %.1f | %.2f | - | - |\n", AK_SEQUENCES[k - 1].name,
                   ak_bench_median(a, repeats), ak_bench_median(cyc, repeats),
                   ak_bench_median(ratio, repeats));
        }
    }
    double a[MAX_REPEATS], cyc[MAX_REPEATS], ratio[MAX_REPEATS];
    for (int r = 0; r < repeats; r++) {
        a[r] = time_all_anchor(steps);
        cyc[r] = time_cycle(&api, 1, all_vrs, n_all, steps);
        ratio[r] = cyc[r] / a[r];
    }
    printf("\nEvery output (%d, body123): the FMI 2 cycle reading all of them against the inline\n"
           "computation of all of them with the core's functions, no FMI (the pass-through FMU\n"
           "has 12 outputs: none beside this one):\n\n"
           "| all-outputs anchor ns | cycle ns | cycle / anchor |\n|---:|---:|---:|\n"
           "| %.1f | %.1f | %.2f |\n", n_all, ak_bench_median(a, repeats),
           ak_bench_median(cyc, repeats), ak_bench_median(ratio, repeats));
    return 0;
}
