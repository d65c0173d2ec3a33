/* Benchmark driver: what a co-simulation master pays per communication point, next to the bare
 * kinematics core.
 *
 * It loads the built AngularKinematics.so with dlopen, as a master does, and in the same run
 * times
 *   - the anchor every ratio is to: the hand-written 1-2-3 formula (bench_anchor.h);
 *   - the general core (a figure of its own), ak_general_angular_kinematics for body123 (the
 *     FMU's default sequence),
 *     linked from the same static library (same compiler, same flags) that the FMU is built from;
 *   - the full cycle of one communication point: fmi2SetReal of the 9 inputs, fmi2DoStep,
 *     fmi2GetReal of the 12 outputs; the same cycle getting all outputs (what fmpy's
 *     simulate_fmu records by default), and getting R[1,1] alone (one output of the lazy group);
 *   - fmi2GetReal of the 12 outputs when no input changed (the FMU must not recompute), in
 *     value-reference order and reversed; fmi2SetReal of the 9 inputs alone; fmi2DoStep alone;
 *   - fmi2SetReal of one input to a new value followed by fmi2GetReal of the 12 outputs, for
 *     each of the 9 inputs.
 * With --passthrough SO, the scaling runs time the same cycle (set 9, doStep, get 12) through the
 * pass-through FMU too (bench_passthrough.h), beside the others: what the calls cost with no model.
 * Every figure is the median over repeats of (loop CPU time / iterations); the loops compared
 * with each other run alternately within each repeat, and their ratio is the median of the
 * per-repeat ratios. Inputs come from a table of 256 different input vectors (bench_inputs.h,
 * --inputs random or smooth), cycled, so that nothing is constant across iterations; one output per iteration is added to a sum written to a
 * volatile sink, so no work can be dropped.
 *
 * The evaluations are counted, not timed: with the logCalls category on, the FMU logs
 * "kinematics evaluated (evaluation N)". After each timed loop the driver switches the trace on
 * for one probe and checks that the FMU evaluated exactly as often as the inputs changed: once
 * per cycle, once per single-input change, never for a get without change. A wrong count, a
 * non-OK status or FMU outputs that differ from the bare core's exit with status 1.
 */
#define _POSIX_C_SOURCE 200809L

#include <dlfcn.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

#include "fmi2FunctionTypes.h"
#include "AngularKinematics_variables.h"
#include "bench_inputs.h"
#include "bench_timing.h"
#include "kinematics_general.h"
#include "kinematics_general_kernel.h"
#include "kinematics_123.h"
#include "bench_anchor.h" /* after bench_inputs.h, bench_timing.h, kinematics_123.h */
#include "bench_passthrough.h"


enum { N_INPUTS = AK_BENCH_INPUTS, N_OUTPUTS = 12, TABLE_ROWS = AK_BENCH_ROWS };

static const fmi2ValueReference INPUT_VRS[N_INPUTS] = {0, 1, 2, 3, 4, 5, 6, 7, 8};
static const fmi2ValueReference OUTPUT_VRS[N_OUTPUTS] = {9,  10, 11, 12, 13, 14,
                                                         15, 16, 17, 18, 19, 20};
/* The same outputs in another order: a master need not ask in value-reference order. */
static const fmi2ValueReference OUTPUT_VRS_REVERSED[N_OUTPUTS] = {20, 19, 18, 17, 16, 15,
                                                                  14, 13, 12, 11, 10, 9};
/* Every output (what fmpy's simulate_fmu records by default), filled in by main; and one output
 * of the lazy group, R[1,1], which makes the FMU compute the whole lazy group. */
static fmi2ValueReference ALL_OUTPUT_VRS[KIN_N_OUTPUTS];
static const fmi2ValueReference ONE_LAZY_VR[1] = {KIN_VR_R};
static const double STEP_SIZE = 1e-3;

/* ---- the FMU, loaded as a master loads it ------------------------------------------------------ */

typedef struct {
    void *library;
    fmi2InstantiateTYPE *instantiate;
    fmi2FreeInstanceTYPE *free_instance;
    fmi2SetupExperimentTYPE *setup_experiment;
    fmi2EnterInitializationModeTYPE *enter_initialization_mode;
    fmi2ExitInitializationModeTYPE *exit_initialization_mode;
    fmi2TerminateTYPE *terminate;
    fmi2SetDebugLoggingTYPE *set_debug_logging;
    fmi2SetRealTYPE *set_real;
    fmi2GetRealTYPE *get_real;
    fmi2DoStepTYPE *do_step;
} fmu_api;

static bool resolve(void *library, const char *name, void *function_pointer, size_t size) {
    void *symbol = dlsym(library, name);
    if (symbol == NULL) {
        fprintf(stderr, "bench_fmu: %s not found in the FMU: %s\n", name, dlerror());
        return false;
    }
    /* ISO C has no cast from object to function pointer; POSIX guarantees the copy works. */
    memcpy(function_pointer, &symbol, size);
    return true;
}

static bool load_fmu(const char *path, fmu_api *api) {
    api->library = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (api->library == NULL) {
        fprintf(stderr, "bench_fmu: cannot load %s: %s\n", path, dlerror());
        return false;
    }
    void *l = api->library;
    return resolve(l, "fmi2Instantiate", &api->instantiate, sizeof api->instantiate) &&
           resolve(l, "fmi2FreeInstance", &api->free_instance, sizeof api->free_instance) &&
           resolve(l, "fmi2SetupExperiment", &api->setup_experiment,
                   sizeof api->setup_experiment) &&
           resolve(l, "fmi2EnterInitializationMode", &api->enter_initialization_mode,
                   sizeof api->enter_initialization_mode) &&
           resolve(l, "fmi2ExitInitializationMode", &api->exit_initialization_mode,
                   sizeof api->exit_initialization_mode) &&
           resolve(l, "fmi2Terminate", &api->terminate, sizeof api->terminate) &&
           resolve(l, "fmi2SetDebugLogging", &api->set_debug_logging,
                   sizeof api->set_debug_logging) &&
           resolve(l, "fmi2SetReal", &api->set_real, sizeof api->set_real) &&
           resolve(l, "fmi2GetReal", &api->get_real, sizeof api->get_real) &&
           resolve(l, "fmi2DoStep", &api->do_step, sizeof api->do_step);
}

/* ---- callbacks: count allocations, read the evaluation number from the trace -------------------- */

static unsigned long allocations = 0; /* the driver's own bookkeeping, not the FMU's */

static void *count_and_allocate(size_t count, size_t size) {
    allocations++;
    return calloc(count, size);
}

typedef struct {
    unsigned long last_evaluation; /* from the latest "kinematics evaluated (evaluation N)" */
    unsigned long problems;        /* messages with a status other than OK */
} log_reader;

static void read_log(fmi2ComponentEnvironment environment, fmi2String instance_name,
                     fmi2Status status, fmi2String category, fmi2String message, ...) {
    log_reader *reader = environment;
    unsigned long evaluation;
    if (sscanf(message, "kinematics evaluated (evaluation %lu)", &evaluation) == 1) {
        reader->last_evaluation = evaluation;
    }
    if (status != fmi2OK) {
        reader->problems++;
        fprintf(stderr, "bench_fmu: %s [%s]: %s\n", instance_name, category, message);
    }
}

typedef struct {
    fmu_api *api;
    fmi2Component component;
    log_reader reader;
    fmi2CallbackFunctions functions;
    double time;
} instance;

static void fail(const char *what) {
    fprintf(stderr, "bench_fmu: FAILED: %s\n", what);
    exit(1);
}

static void check_ok(fmi2Status status, const char *what) {
    if (status != fmi2OK) {
        fail(what);
    }
}

static void set_trace(instance *fmu, bool on) {
    fmi2String calls = "logCalls";
    check_ok(fmu->api->set_debug_logging(fmu->component, on ? fmi2True : fmi2False, 1, &calls),
             "fmi2SetDebugLogging");
}

/* Instantiated and initialized, trace off, inputs at their start values. */
static void start_instance(fmu_api *api, instance *fmu) {
    fmu->api = api;
    fmu->reader = (log_reader){0, 0};
    fmu->functions = (fmi2CallbackFunctions){read_log, count_and_allocate, free, NULL, &fmu->reader};
    fmu->component = api->instantiate("bench", fmi2CoSimulation, KIN_GUID, NULL, &fmu->functions,
                                      fmi2False, fmi2False);
    if (fmu->component == NULL) {
        fail("fmi2Instantiate");
    }
    set_trace(fmu, false);
    check_ok(api->setup_experiment(fmu->component, fmi2False, 0.0, 0.0, fmi2False, 0.0),
             "fmi2SetupExperiment");
    check_ok(api->enter_initialization_mode(fmu->component), "fmi2EnterInitializationMode");
    check_ok(api->exit_initialization_mode(fmu->component), "fmi2ExitInitializationMode");
    fmu->time = 0.0;
}

static void stop_instance(instance *fmu) {
    check_ok(fmu->api->terminate(fmu->component), "fmi2Terminate");
    fmu->api->free_instance(fmu->component);
    if (fmu->reader.problems != 0) {
        fail("the FMU logged a non-OK message");
    }
}

/* The number of evaluations so far, this probe's own included: it changes theta[1] and reads one
 * output with the trace on. Between two probes the FMU evaluated (after - before - 1) times. */
static unsigned long evaluations(instance *fmu) {
    static const double probe_values[2] = {0.123456789, -0.987654321};
    double theta1, output;
    const fmi2ValueReference theta1_vr = 0;
    check_ok(fmu->api->get_real(fmu->component, &theta1_vr, 1, &theta1), "probe get");
    const double new_value = theta1 == probe_values[0] ? probe_values[1] : probe_values[0];
    set_trace(fmu, true);
    check_ok(fmu->api->set_real(fmu->component, &theta1_vr, 1, &new_value), "probe set");
    check_ok(fmu->api->get_real(fmu->component, &OUTPUT_VRS[0], 1, &output), "probe get");
    set_trace(fmu, false);
    return fmu->reader.last_evaluation;
}

static unsigned long evaluations_between(unsigned long before, unsigned long after) {
    return after - before - 1;
}

/* ---- inputs ------------------------------------------------------------------------------------- */

static double input_table[TABLE_ROWS][N_INPUTS];

/* The inputs of bench/bench_inputs.h, shared with bench_fmi3.c. */
static void fill_input_table(ak_bench_kind kind) {
    if (ak_bench_fill_inputs_of_kind(kind, input_table) != 0) {
        fail("input table has equal consecutive values");
    }
}

/* ---- timing ------------------------------------------------------------------------------------- */

static volatile double sink;


/* The anchor, the hand-written 1-2-3 formula (bench_anchor.h): every ratio is to it. */
static double time_anchor(long n) {
    double sum;
    const double ns = ak_bench_time_anchor(input_table, n, &sum);
    sink = sum;
    return ns;
}

/* The general core on the inputs of steps 0..n-1, a figure of its own: ns per evaluation. */
static double time_core(long n) {
    double outputs[N_OUTPUTS];
    double sum = 0.0;
    int k = 0;
    const double start = ak_bench_now_ns();
    for (long step = 0; step < n; step++) {
        const double *u = input_table[step & (TABLE_ROWS - 1)];
        ak_general_angular_kinematics(&AK_SEQUENCES[AK_SEQUENCE_DEFAULT], u, u + 3, u + 6, outputs,
                                      outputs + 3, outputs + 6, outputs + 9);
        sum += outputs[k];
        k = k == N_OUTPUTS - 1 ? 0 : k + 1;
    }
    const double elapsed = ak_bench_now_ns() - start;
    sink = sum;
    return elapsed / (double)n;
}

/* n communication points on a fresh instance, getting the n_vrs outputs `vrs`: ns per
set/doStep/get cycle. */
static double time_cycle(fmu_api *api, const fmi2ValueReference *vrs, int n_vrs, long n) {
    instance fmu;
    start_instance(api, &fmu);
    const unsigned long evaluations_before = evaluations(&fmu);
    double outputs[KIN_N_OUTPUTS];
    double sum = 0.0, t = fmu.time;
    int k = 0;
    unsigned int statuses = fmi2OK;
    const double start = ak_bench_now_ns();
    for (long step = 0; step < n; step++) {
        const double *u = input_table[step & (TABLE_ROWS - 1)];
        statuses |= (unsigned int)api->set_real(fmu.component, INPUT_VRS, N_INPUTS, u);
        statuses |= (unsigned int)api->do_step(fmu.component, t, STEP_SIZE, fmi2True);
        t += STEP_SIZE;
        statuses |= (unsigned int)api->get_real(fmu.component, vrs, (size_t)n_vrs, outputs);
        sum += outputs[k];
        k = k >= n_vrs - 1 ? 0 : k + 1;
    }
    const double elapsed = ak_bench_now_ns() - start;
    sink = sum;
    check_ok((fmi2Status)statuses, "a call of the timed cycle");
    if (evaluations_between(evaluations_before, evaluations(&fmu)) != (unsigned long)n) {
        fail("the cycle did not evaluate exactly once per step");
    }
    stop_instance(&fmu);
    return elapsed / (double)n;
}

/* n gets of all outputs, in the order `vrs`, with no input change: ns per get. */
static double time_get_unchanged(fmu_api *api, const fmi2ValueReference *vrs, long n) {
    instance fmu;
    start_instance(api, &fmu);
    check_ok(api->set_real(fmu.component, INPUT_VRS, N_INPUTS, input_table[0]), "set");
    const unsigned long evaluations_before = evaluations(&fmu); /* leaves the outputs fresh */
    double outputs[N_OUTPUTS];
    double sum = 0.0;
    int k = 0;
    unsigned int statuses = fmi2OK;
    const double start = ak_bench_now_ns();
    for (long call = 0; call < n; call++) {
        statuses |= (unsigned int)api->get_real(fmu.component, vrs, N_OUTPUTS, outputs);
        sum += outputs[k];
        k = k == N_OUTPUTS - 1 ? 0 : k + 1;
    }
    const double elapsed = ak_bench_now_ns() - start;
    sink = sum;
    check_ok((fmi2Status)statuses, "a get of the timed loop");
    if (evaluations_between(evaluations_before, evaluations(&fmu)) != 0) {
        fail("a get without input change recomputed the outputs");
    }
    stop_instance(&fmu);
    return elapsed / (double)n;
}

/* n calls of fmi2SetReal of the 9 inputs to new values, nothing else: ns per set. */
static double time_set_only(fmu_api *api, long n) {
    instance fmu;
    start_instance(api, &fmu);
    unsigned int statuses = fmi2OK;
    const double start = ak_bench_now_ns();
    for (long call = 0; call < n; call++) {
        statuses |= (unsigned int)api->set_real(fmu.component, INPUT_VRS, N_INPUTS,
                                  input_table[call & (TABLE_ROWS - 1)]);
    }
    const double elapsed = ak_bench_now_ns() - start;
    check_ok((fmi2Status)statuses, "a set of the timed loop");
    stop_instance(&fmu);
    return elapsed / (double)n;
}

/* n calls of fmi2DoStep, nothing else: ns per step. */
static double time_step_only(fmu_api *api, long n) {
    instance fmu;
    start_instance(api, &fmu);
    unsigned int statuses = fmi2OK;
    double t = fmu.time;
    const double start = ak_bench_now_ns();
    for (long call = 0; call < n; call++) {
        statuses |= (unsigned int)api->do_step(fmu.component, t, STEP_SIZE, fmi2True);
        t += STEP_SIZE;
    }
    const double elapsed = ak_bench_now_ns() - start;
    check_ok((fmi2Status)statuses, "a step of the timed loop");
    stop_instance(&fmu);
    return elapsed / (double)n;
}

/* n times: set input `input` to a new value, then get all outputs: ns per set + get. */
static double time_single_change(fmu_api *api, int input, long n) {
    instance fmu;
    start_instance(api, &fmu);
    check_ok(api->set_real(fmu.component, INPUT_VRS, N_INPUTS, input_table[0]), "set");
    const unsigned long evaluations_before = evaluations(&fmu);
    double outputs[N_OUTPUTS];
    double sum = 0.0;
    int k = 0;
    unsigned int statuses = fmi2OK;
    const double start = ak_bench_now_ns();
    for (long call = 0; call < n; call++) {
        const double *u = input_table[(call + 1) & (TABLE_ROWS - 1)];
        statuses |= (unsigned int)api->set_real(fmu.component, &INPUT_VRS[input], 1, &u[input]);
        statuses |= (unsigned int)api->get_real(fmu.component, OUTPUT_VRS, N_OUTPUTS, outputs);
        sum += outputs[k];
        k = k == N_OUTPUTS - 1 ? 0 : k + 1;
    }
    const double elapsed = ak_bench_now_ns() - start;
    sink = sum;
    check_ok((fmi2Status)statuses, "a call of the timed loop");
    if (evaluations_between(evaluations_before, evaluations(&fmu)) != (unsigned long)n) {
        fail("a single input change did not evaluate exactly once");
    }
    stop_instance(&fmu);
    return elapsed / (double)n;
}

/* ---- checks before timing ----------------------------------------------------------------------- */

/* The FMU returns exactly what the bare core returns for the same inputs (same code, same
 * flags), and evaluates only when an input really changed. */
static void check_fmu(fmu_api *api) {
    instance fmu;
    start_instance(api, &fmu);
    for (int row = 0; row < TABLE_ROWS; row++) {
        const double *u = input_table[row];
        double expected[N_OUTPUTS], got[N_OUTPUTS];
        ak_general_angular_kinematics(&AK_SEQUENCES[AK_SEQUENCE_DEFAULT], u, u + 3, u + 6,
                                      expected, expected + 3, expected + 6, expected + 9);
        check_ok(api->set_real(fmu.component, INPUT_VRS, N_INPUTS, u), "set");
        check_ok(api->do_step(fmu.component, fmu.time, STEP_SIZE, fmi2True), "doStep");
        fmu.time += STEP_SIZE;
        check_ok(api->get_real(fmu.component, OUTPUT_VRS, N_OUTPUTS, got), "get");
        if (memcmp(expected, got, sizeof got) != 0) {
            fail("the FMU's outputs differ from the bare core's");
        }
    }
    unsigned long before = evaluations(&fmu);
    double outputs[N_OUTPUTS];
    check_ok(api->set_real(fmu.component, INPUT_VRS, N_INPUTS, input_table[0]), "set");
    check_ok(api->get_real(fmu.component, OUTPUT_VRS, N_OUTPUTS, outputs), "get");
    check_ok(api->get_real(fmu.component, OUTPUT_VRS, N_OUTPUTS, outputs), "get");
    check_ok(api->set_real(fmu.component, INPUT_VRS, N_INPUTS, input_table[0]), "set same");
    check_ok(api->get_real(fmu.component, OUTPUT_VRS, N_OUTPUTS, outputs), "get");
    if (evaluations_between(before, evaluations(&fmu)) != 1) {
        fail("gets without input change, or a set of unchanged values, recomputed");
    }
    stop_instance(&fmu);
}

/* ---- command line ------------------------------------------------------------------------------- */

enum { MAX_SIZES = 16, MAX_REPEATS = 1001 };

typedef struct {
    const char *fmu_path;
    long sizes[MAX_SIZES];
    int n_sizes;
    int repeats;
    long calls;
    const char *only; /* "core", "cycle", "all", "lazy" or "get": one loop of sizes[0] */
    const char *passthrough; /* PassThrough.so, or NULL */
    ak_bench_kind kind;
} options;

static void usage(void) {
    fprintf(stderr,
            "usage: bench_fmu FMU_SO [--steps N[,N...]] [--repeats R] [--calls N]\n"
            "                        [--only anchor|core|cycle|all|lazy|get --steps N]\n"
            "                        [--inputs random|smooth] [--passthrough PassThrough.so]\n"
            "  FMU_SO     the AngularKinematics.so of a Release build\n"
            "  --steps    step counts of the cycle-vs-core runs (default 1e3,1e4,1e5,1e6,1e7)\n"
            "  --repeats  repeats per figure, median quoted (default 5)\n"
            "  --calls    iterations of the get loops (default 1e6)\n"
            "  --only     run one loop once, print nothing (for instruction counting)\n"
            "  --inputs   the input rows of bench_inputs.h (default random)\n"
            "  --passthrough  time the pass-through FMU's cycle beside the others\n");
    exit(2);
}

static long parse_count(const char *text) {
    char *end;
    const double value = strtod(text, &end);
    if (*end != '\0' || !(value >= 1.0 && value <= 1e10)) {
        usage();
    }
    return (long)value;
}

static options parse_options(int argc, char **argv) {
    options o = {NULL, {1000, 10000, 100000, 1000000, 10000000}, 5, 5, 1000000, NULL, NULL,
                 AK_BENCH_RANDOM};
    for (int i = 1; i < argc; i++) {
        const bool has_value = i + 1 < argc;
        if (strcmp(argv[i], "--steps") == 0 && has_value) {
            o.n_sizes = 0;
            char *list = argv[++i];
            for (char *item = strtok(list, ","); item != NULL; item = strtok(NULL, ",")) {
                if (o.n_sizes == MAX_SIZES) {
                    usage();
                }
                o.sizes[o.n_sizes++] = parse_count(item);
            }
        } else if (strcmp(argv[i], "--repeats") == 0 && has_value) {
            o.repeats = (int)parse_count(argv[++i]);
        } else if (strcmp(argv[i], "--calls") == 0 && has_value) {
            o.calls = parse_count(argv[++i]);
        } else if (strcmp(argv[i], "--only") == 0 && has_value) {
            o.only = argv[++i];
        } else if (strcmp(argv[i], "--passthrough") == 0 && has_value) {
            o.passthrough = argv[++i];
        } else if (strcmp(argv[i], "--inputs") == 0 && has_value) {
            if (ak_bench_parse_kind(argv[++i], &o.kind) != 0) {
                usage();
            }
        } else if (argv[i][0] != '-' && o.fmu_path == NULL) {
            o.fmu_path = argv[i];
        } else {
            usage();
        }
    }
    if (o.fmu_path == NULL || o.n_sizes == 0 || o.repeats > MAX_REPEATS) {
        usage();
    }
    return o;
}

static long max_rss_kib(void) {
    struct rusage usage;
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss;
}

/* ---- main --------------------------------------------------------------------------------------- */

static const char *const INPUT_NAMES[N_INPUTS] = {
    "theta[1]",      "theta[2]",      "theta[3]",      "theta_dot[1]", "theta_dot[2]",
    "theta_dot[3]", "theta_ddot[1]", "theta_ddot[2]", "theta_ddot[3]"};

/* value printed with format into text, or "-" without the pass-through. */
static const char *format_or_dash(const ak_passthrough2 *pass, const char *format, double value,
                                  char text[32]) {
    if (pass == NULL) {
        return "-";
    }
    snprintf(text, 32, format, value);
    return text;
}

static void run_scaling(fmu_api *api, const options *o, const ak_passthrough2 *pass) {
    printf("Full cycles, %s inputs: fmi2SetReal of 9 inputs, fmi2DoStep, then fmi2GetReal of the\n"
           "12 omega/alpha outputs (cycle), of all %d outputs (all), or of R[1,1] alone (one lazy\n"
           "output). Each is compared with the anchor, the hand-written 1-2-3 formula\n"
           "(tests/c/kinematics_123.c, the 12 omega/alpha outputs); the general core\n"
           "(ak_general_angular_kinematics, body123) is a figure of its own; the loops run\n"
           "alternately in each repeat; ns are medians of the repeats, each ratio the median of the\n"
           "per-repeat ratios. pass-through: the cycle (set 9, doStep, get 12) of the pass-through\n"
           "FMU; floor: (pass-through + anchor) / anchor, the cycle / anchor of an FMU that added\n"
           "only the pass-through's calls to the formula:\n\n",
           ak_bench_kind_name(o->kind), (int)KIN_N_OUTPUTS);
    printf("| steps per run | repeats | anchor ns/step | general core ns | cycle ns/step | "
           "cycle / anchor | pass-through ns | floor | all ns | all / anchor | one lazy ns | "
           "one lazy / anchor | max RSS KiB | FMU allocations per run |\n");
    printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (int s = 0; s < o->n_sizes; s++) {
        const long n = o->sizes[s];
        /* Short runs are repeated more, so that every row rests on at least 1e6 steps. */
        int repeats = o->repeats;
        while (repeats < MAX_REPEATS && (long)repeats * n < 1000000) {
            repeats += 2;
        }
        double core[MAX_REPEATS], general[MAX_REPEATS], cycle[MAX_REPEATS], ratios[MAX_REPEATS];
        double all[MAX_REPEATS], all_ratios[MAX_REPEATS], lazy[MAX_REPEATS];
        double lazy_ratios[MAX_REPEATS], pt[MAX_REPEATS], floors[MAX_REPEATS];
        unsigned long allocations_per_run = 0;
        char pt_text[32], floor_text[32];
        time_anchor(n < 1000 ? n : 1000); /* warm-up */
        for (int r = 0; r < repeats; r++) {
            /* Interleaved, so that a slow moment of the shared machine hits all alike. */
            core[r] = time_anchor(n);
            general[r] = time_core(n);
            const unsigned long before = allocations;
            cycle[r] = time_cycle(api, OUTPUT_VRS, N_OUTPUTS, n);
            allocations_per_run = allocations - before;
            all[r] = time_cycle(api, ALL_OUTPUT_VRS, KIN_N_OUTPUTS, n);
            lazy[r] = time_cycle(api, ONE_LAZY_VR, 1, n);
            pt[r] = pass == NULL ? 0.0
                                 : ak_passthrough2_cycle(pass, &input_table[0][0], N_INPUTS,
                                                         N_INPUTS, N_OUTPUTS, STEP_SIZE, n);
            floors[r] = (pt[r] + core[r]) / core[r];
            ratios[r] = cycle[r] / core[r];
            all_ratios[r] = all[r] / core[r];
            lazy_ratios[r] = lazy[r] / core[r];
        }
        printf("| %ld | %d | %.1f | %.1f | %.1f | %.2f | %s | %s | %.1f | %.2f | %.1f | %.2f | %ld "
               "| %lu |\n",
               n, repeats, ak_bench_median(core, repeats), ak_bench_median(general, repeats),
               ak_bench_median(cycle, repeats), ak_bench_median(ratios, repeats),
               format_or_dash(pass, "%.1f", ak_bench_median(pt, repeats), pt_text),
               format_or_dash(pass, "%.2f", ak_bench_median(floors, repeats), floor_text),
               ak_bench_median(all, repeats), ak_bench_median(all_ratios, repeats), ak_bench_median(lazy, repeats),
               ak_bench_median(lazy_ratios, repeats), max_rss_kib(), allocations_per_run);
        fflush(stdout);
    }
}

static void print_row(const char *name, double *ns, double *ratios, int repeats) {
    printf("| %s | %.1f | %.2f |\n", name, ak_bench_median(ns, repeats), ak_bench_median(ratios, repeats));
}

static void run_calls(fmu_api *api, const options *o) {
    enum { GET, GET_REVERSED, SET, STEP, N_SINGLE_CALLS };
    const int repeats = o->repeats;
    double core[MAX_REPEATS];
    double single[N_SINGLE_CALLS][MAX_REPEATS], single_ratio[N_SINGLE_CALLS][MAX_REPEATS];
    double pair[N_INPUTS][MAX_REPEATS], pair_ratio[N_INPUTS][MAX_REPEATS];
    /* Each repeat times every loop once, so that all of them see the machine alike. */
    for (int r = 0; r < repeats; r++) {
        core[r] = time_anchor(o->calls);
        single[GET][r] = time_get_unchanged(api, OUTPUT_VRS, o->calls);
        single[GET_REVERSED][r] = time_get_unchanged(api, OUTPUT_VRS_REVERSED, o->calls);
        single[SET][r] = time_set_only(api, o->calls);
        single[STEP][r] = time_step_only(api, o->calls);
        for (int call = 0; call < N_SINGLE_CALLS; call++) {
            single_ratio[call][r] = single[call][r] / core[r];
        }
        for (int input = 0; input < N_INPUTS; input++) {
            pair[input][r] = time_single_change(api, input, o->calls);
            pair_ratio[input][r] = pair[input][r] / core[r];
        }
    }
    printf("\nSingle calls, %ld per repeat, %d repeats (median, each repeat times all loops in\n"
           "turn; / anchor is the median of the per-repeat ratios). After the get loop the FMU's\n"
           "evaluation count is checked unchanged:\n\n",
           o->calls, repeats);
    printf("| call | ns/call | / anchor |\n|---|---:|---:|\n");
    printf("| anchor: hand-written 1-2-3 formula | %.1f | 1.00 |\n", ak_bench_median(core, repeats));
    print_row("fmi2GetReal of 12 outputs, no input changed", single[GET], single_ratio[GET],
              repeats);
    print_row("same, outputs asked in reverse order", single[GET_REVERSED],
              single_ratio[GET_REVERSED], repeats);
    print_row("fmi2SetReal of 9 inputs, new values (no get)", single[SET], single_ratio[SET],
              repeats);
    print_row("fmi2DoStep alone", single[STEP], single_ratio[STEP], repeats);

    printf("\nfmi2SetReal of ONE input to a new value, then fmi2GetReal of the 12 outputs (one\n"
           "evaluation each, checked by count), same repeats:\n\n");
    printf("| input changed | set + get ns | / anchor |\n|---|---:|---:|\n");
    for (int input = 0; input < N_INPUTS; input++) {
        print_row(INPUT_NAMES[input], pair[input], pair_ratio[input], repeats);
    }
}

int main(int argc, char **argv) {
    const options o = parse_options(argc, argv);
    fmu_api api;
    if (!load_fmu(o.fmu_path, &api)) {
        return 1;
    }
    fill_input_table(o.kind);
    static ak_passthrough2 passthrough;
    if (o.passthrough != NULL) {
        ak_passthrough2_load(o.passthrough, &passthrough);
    }
    int n_outputs = 0;
    for (int vr = 0; vr < KIN_N_VALUE_REFERENCES; vr++) {
        if (KIN_VARIABLES[vr].name != NULL && KIN_VARIABLES[vr].causality == AK_CAUSALITY_OUTPUT) {
            ALL_OUTPUT_VRS[n_outputs++] = (fmi2ValueReference)vr;
        }
    }
    check_fmu(&api);

    if (o.only != NULL) {
        if (strcmp(o.only, "anchor") == 0) {
            time_anchor(o.sizes[0]);
        } else if (strcmp(o.only, "core") == 0) {
            time_core(o.sizes[0]);
        } else if (strcmp(o.only, "cycle") == 0) {
            time_cycle(&api, OUTPUT_VRS, N_OUTPUTS, o.sizes[0]);
        } else if (strcmp(o.only, "all") == 0) {
            time_cycle(&api, ALL_OUTPUT_VRS, KIN_N_OUTPUTS, o.sizes[0]);
        } else if (strcmp(o.only, "lazy") == 0) {
            time_cycle(&api, ONE_LAZY_VR, 1, o.sizes[0]);
        } else if (strcmp(o.only, "get") == 0) {
            time_get_unchanged(&api, OUTPUT_VRS, o.sizes[0]);
        } else {
            usage();
        }
        return 0;
    }
    printf("FMU outputs equal the bare core's bit for bit on %d input vectors; gets without input\n"
           "change do not recompute.\n\n",
           TABLE_ROWS);
    run_scaling(&api, &o, o.passthrough != NULL ? &passthrough : NULL);
    run_calls(&api, &o);
    dlclose(api.library);
    return 0;
}
