/* The pass-through FMUs beside the drivers' cycles (bench_fmu.c, bench_fmi3.c, bench_attitude.c):
 * the same set/doStep/get cycle, with the same numbers of inputs, outputs and calls, through
 * build/passthrough/PassThrough.so (FMI 2, bench/passthrough/passthrough.c) and PassThrough3.so
 * (FMI 3, passthrough3.c), which copy inputs to outputs. What an importer pays for the calls of
 * any FMU of the interface: the cycle of the model minus the pass-through's is what the model
 * adds to its arithmetic. The timed loops are never inlined, so that the drivers' own loops
 * compile as they did without them (the guard's counts). Needs _POSIX_C_SOURCE 200809L,
 * bench_inputs.h and bench_timing.h. */
#ifndef ANGULAR_KINEMATICS_BENCH_PASSTHROUGH_H
#define ANGULAR_KINEMATICS_BENCH_PASSTHROUGH_H

#include <dlfcn.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2FunctionTypes.h"
#include "fmi3FunctionTypes.h"

#define AK_PASSTHROUGH_GUID "{5b2d7a40-3c1e-4f8a-9d6b-0e4f2a7c9b13}"

typedef struct {
    void *library;
    fmi2InstantiateTYPE *instantiate;
    fmi2FreeInstanceTYPE *free_instance;
    fmi2SetRealTYPE *set_real;
    fmi2GetRealTYPE *get_real;
    fmi2DoStepTYPE *do_step;
} ak_passthrough2;

typedef struct {
    void *library;
    fmi3InstantiateCoSimulationTYPE *instantiate;
    fmi3FreeInstanceTYPE *free_instance;
    fmi3SetFloat64TYPE *set_float64;
    fmi3GetFloat64TYPE *get_float64;
    fmi3DoStepTYPE *do_step;
} ak_passthrough3;

static inline void *ak_passthrough_symbol(void *library, const char *name) {
    void *symbol = dlsym(library, name);
    if (symbol == NULL) {
        fprintf(stderr, "bench: the pass-through FMU has no %s\n", name);
        exit(1);
    }
    return symbol;
}

#define AK_PASSTHROUGH_FUNCTION(type, library, name) \
    ((type *)(uintptr_t)ak_passthrough_symbol(library, name))

static inline void *ak_passthrough_open(const char *path) {
    void *library = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (library == NULL) {
        fprintf(stderr, "bench: cannot load the pass-through FMU %s: %s\n", path, dlerror());
        exit(1);
    }
    return library;
}

static inline void ak_passthrough2_load(const char *path, ak_passthrough2 *p) {
    void *l = p->library = ak_passthrough_open(path);
    p->instantiate = AK_PASSTHROUGH_FUNCTION(fmi2InstantiateTYPE, l, "fmi2Instantiate");
    p->free_instance = AK_PASSTHROUGH_FUNCTION(fmi2FreeInstanceTYPE, l, "fmi2FreeInstance");
    p->set_real = AK_PASSTHROUGH_FUNCTION(fmi2SetRealTYPE, l, "fmi2SetReal");
    p->get_real = AK_PASSTHROUGH_FUNCTION(fmi2GetRealTYPE, l, "fmi2GetReal");
    p->do_step = AK_PASSTHROUGH_FUNCTION(fmi2DoStepTYPE, l, "fmi2DoStep");
}

static inline void ak_passthrough3_load(const char *path, ak_passthrough3 *p) {
    void *l = p->library = ak_passthrough_open(path);
    p->instantiate = AK_PASSTHROUGH_FUNCTION(fmi3InstantiateCoSimulationTYPE, l,
                                             "fmi3InstantiateCoSimulation");
    p->free_instance = AK_PASSTHROUGH_FUNCTION(fmi3FreeInstanceTYPE, l, "fmi3FreeInstance");
    p->set_float64 = AK_PASSTHROUGH_FUNCTION(fmi3SetFloat64TYPE, l, "fmi3SetFloat64");
    p->get_float64 = AK_PASSTHROUGH_FUNCTION(fmi3GetFloat64TYPE, l, "fmi3GetFloat64");
    p->do_step = AK_PASSTHROUGH_FUNCTION(fmi3DoStepTYPE, l, "fmi3DoStep");
}

static void ak_passthrough2_log(fmi2ComponentEnvironment e, fmi2String n, fmi2Status s,
                                fmi2String c, fmi2String m, ...) {
    (void)e, (void)n, (void)s, (void)c;
    fprintf(stderr, "pass-through: %s\n", m);
}

static volatile double ak_passthrough_sink;

/* n FMI 2 cycles on a fresh instance: fmi2SetReal of n_inputs inputs (value references 0..),
 * the values from rows (AK_BENCH_ROWS rows of row_length, cycled), fmi2DoStep of h, fmi2GetReal
 * of n_outputs outputs (value references 9..). ns per cycle. */
__attribute__((noinline, unused)) static double ak_passthrough2_cycle(const ak_passthrough2 *p, const double *rows,
                                           int row_length, int n_inputs, int n_outputs, double h,
                                           long n) {
    static const fmi2ValueReference vrs[21] = {0,  1,  2,  3,  4,  5,  6,  7,  8,  9,  10,
                                               11, 12, 13, 14, 15, 16, 17, 18, 19, 20};
    fmi2CallbackFunctions callbacks = {ak_passthrough2_log, calloc, free, NULL, NULL};
    fmi2Component c = p->instantiate("bench", fmi2CoSimulation, AK_PASSTHROUGH_GUID, "",
                                     &callbacks, fmi2False, fmi2False);
    if (c == NULL) {
        fprintf(stderr, "bench: the pass-through FMU did not instantiate\n");
        exit(1);
    }
    double y[12], sum = 0.0, t = 0.0;
    unsigned int statuses = 0;
    const double start = ak_bench_now_ns();
    for (long step = 0; step < n; step++) {
        const double *u = rows + (step & (AK_BENCH_ROWS - 1)) * row_length;
        statuses |= (unsigned int)p->set_real(c, vrs, (size_t)n_inputs, u);
        statuses |= (unsigned int)p->do_step(c, t, h, fmi2True);
        t += h;
        statuses |= (unsigned int)p->get_real(c, vrs + 9, (size_t)n_outputs, y);
        sum += y[step % n_outputs];
    }
    const double elapsed = ak_bench_now_ns() - start;
    ak_passthrough_sink = sum;
    p->free_instance(c);
    if (statuses != 0) {
        fprintf(stderr, "bench: a call of the FMI 2 pass-through failed\n");
        exit(1);
    }
    return elapsed / (double)n;
}

/* n FMI 3 cycles on a fresh instance: n_sets calls of fmi3SetFloat64, set k of the input arrays
 * in_vrs[k * in_per_set ...] (arrays of 3 values each, from rows as above), fmi3DoStep of h, one
 * fmi3GetFloat64 of the n_out arrays out_vrs (n_out_values values). ns per cycle. */
__attribute__((noinline, unused)) static double ak_passthrough3_cycle(const ak_passthrough3 *p, const double *rows,
                                           int row_length, const fmi3ValueReference *in_vrs,
                                           int n_sets, int in_per_set,
                                           const fmi3ValueReference *out_vrs, int n_out,
                                           int n_out_values, double h, long n) {
    fmi3Instance c = p->instantiate("bench", AK_PASSTHROUGH_GUID, NULL, fmi3False, fmi3False,
                                    fmi3False, fmi3False, NULL, 0, NULL, NULL, NULL);
    if (c == NULL) {
        fprintf(stderr, "bench: the FMI 3 pass-through did not instantiate\n");
        exit(1);
    }
    double y[12], sum = 0.0, t = 0.0, last;
    fmi3Boolean event, terminate, early;
    unsigned int statuses = 0;
    const size_t values_per_set = 3 * (size_t)in_per_set;
    const double start = ak_bench_now_ns();
    for (long step = 0; step < n; step++) {
        const double *u = rows + (step & (AK_BENCH_ROWS - 1)) * row_length;
        for (int k = 0; k < n_sets; k++) {
            statuses |= (unsigned int)p->set_float64(c, in_vrs + k * in_per_set,
                                                     (size_t)in_per_set,
                                                     u + (size_t)k * values_per_set,
                                                     values_per_set);
        }
        statuses |= (unsigned int)p->do_step(c, t, h, fmi3True, &event, &terminate, &early,
                                             &last);
        t = last;
        statuses |= (unsigned int)p->get_float64(c, out_vrs, (size_t)n_out, y,
                                                 (size_t)n_out_values);
        sum += y[step % n_out_values];
    }
    const double elapsed = ak_bench_now_ns() - start;
    ak_passthrough_sink = sum;
    p->free_instance(c);
    if (statuses != 0) {
        fprintf(stderr, "bench: a call of the FMI 3 pass-through failed\n");
        exit(1);
    }
    return elapsed / (double)n;
}

/* Appends "key kind ratio floor passthrough_ns" to the file named by AK_BENCH_FIGURES, when set:
 * the figures of bench/run.sh's goals table (ratio: the cycle to its anchor; floor: the
 * pass-through's cycle plus the anchor, to the anchor). */
static inline void ak_bench_record_figure(const char *key, const char *kind, double ratio,
                                          double floor, double passthrough_ns) {
    const char *path = getenv("AK_BENCH_FIGURES");
    if (path == NULL || path[0] == '\0') {
        return;
    }
    FILE *file = fopen(path, "a");
    if (file == NULL) {
        fprintf(stderr, "bench: cannot append to %s\n", path);
        exit(1);
    }
    fprintf(file, "%s %s %.4f %.4f %.2f\n", key, kind, ratio, floor, passthrough_ns);
    fclose(file);
}

#endif
