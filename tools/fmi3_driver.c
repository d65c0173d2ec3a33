/* A minimal FMI 3.0 co-simulation importer of our own, to prove the binaries of other platforms:
 * built natively, for aarch64 and riscv64 (run under qemu-aarch64, qemu-riscv64) and with
 * mingw-w64 (run under wine), it loads one FMI 3 binary of AngularKinematics, EulerRates or
 * AttitudePropagator, drives it through every rotation sequence (and both frames of EulerRates
 * and AttitudePropagator) with fixed inputs, and prints every output, and for AngularKinematics
 * and AttitudePropagator the directional and adjoint derivatives (AngularKinematics also the
 * output derivatives), as the hex of their IEEE 754 bits, with the status of each call.
 * AttitudePropagator's outputs come from its states, integrated by fmi3DoStep: the printout
 * proves the integration too. Two platforms agree when their printouts are identical.
 *
 * The inputs are exact binary fractions from an integer generator, so every platform feeds the
 * FMU the same bits and any difference comes from the binaries alone.
 *
 * Usage: fmi3_driver LIBRARY MODEL [STEPS]    exit status 0 when no call returned fmi3Error.
 *        fmi3_driver LIBRARY MODEL cross-check ...   the cross-check master instead
 * (tools/fmi3_driver_cross_check.c).
 *
 * Built with AK_DRIVER_LINKED, the driver has one model's FMI functions linked in instead of
 * loading a library (LIBRARY is ignored; MODEL must be that model, or the instantiation token is
 * refused): a static executable for the 32-bit x86 proof build (docs/platforms.md). */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi3FunctionTypes.h"
#include "fmi3_driver_api.h"
#include "fmi3_driver_models.h"

#if defined(AK_DRIVER_LINKED)
#include "fmi3Functions.h"
#elif defined(_WIN32)
#include <windows.h>
#else
#include <dlfcn.h>
#endif

typedef void (*generic_function)(void);

#ifdef AK_DRIVER_LINKED
static int load_api(void *library, fmi3_api *api) {
    (void)library;
    api->instantiate = fmi3InstantiateCoSimulation;
    api->enter_initialization_mode = fmi3EnterInitializationMode;
    api->exit_initialization_mode = fmi3ExitInitializationMode;
    api->set_int64 = fmi3SetInt64;
    api->set_float64 = fmi3SetFloat64;
    api->get_float64 = fmi3GetFloat64;
    api->do_step = fmi3DoStep;
    api->directional = fmi3GetDirectionalDerivative;
    api->adjoint = fmi3GetAdjointDerivative;
    api->output_derivatives = fmi3GetOutputDerivatives;
    api->terminate = fmi3Terminate;
    api->free_instance = fmi3FreeInstance;
    api->instantiate_model_exchange = fmi3InstantiateModelExchange;
    api->set_time = fmi3SetTime;
    api->update_discrete_states = fmi3UpdateDiscreteStates;
    api->enter_continuous_time_mode = fmi3EnterContinuousTimeMode;
    api->get_continuous_states = fmi3GetContinuousStates;
    api->get_continuous_state_derivatives = fmi3GetContinuousStateDerivatives;
    api->set_continuous_states = fmi3SetContinuousStates;
    api->completed_integrator_step = fmi3CompletedIntegratorStep;
    return 1;
}
#else
static generic_function load_symbol(void *library, const char *name) {
    generic_function function = NULL;
#ifdef _WIN32
    function = (generic_function)GetProcAddress((HMODULE)library, name);
#else
    void *symbol = dlsym(library, name);
    memcpy(&function, &symbol, sizeof function); /* POSIX: object to function pointer */
#endif
    if (function == NULL) {
        fprintf(stderr, "fmi3_driver: the library exports no %s\n", name);
    }
    return function;
}

static int load_api(void *library, fmi3_api *api) {
    enum { N = 20 };
    const char *names[N] = {"fmi3InstantiateCoSimulation", "fmi3EnterInitializationMode",
                            "fmi3ExitInitializationMode", "fmi3SetInt64", "fmi3SetFloat64",
                            "fmi3GetFloat64", "fmi3DoStep", "fmi3GetDirectionalDerivative",
                            "fmi3GetAdjointDerivative", "fmi3GetOutputDerivatives",
                            "fmi3Terminate", "fmi3FreeInstance", "fmi3InstantiateModelExchange",
                            "fmi3SetTime", "fmi3UpdateDiscreteStates",
                            "fmi3EnterContinuousTimeMode", "fmi3GetContinuousStates",
                            "fmi3GetContinuousStateDerivatives", "fmi3SetContinuousStates",
                            "fmi3CompletedIntegratorStep"};
    generic_function f[N];
    for (int i = 0; i < N; i++) {
        if ((f[i] = load_symbol(library, names[i])) == NULL) {
            return 0;
        }
    }
    api->instantiate = (fmi3InstantiateCoSimulationTYPE *)f[0];
    api->enter_initialization_mode = (fmi3EnterInitializationModeTYPE *)f[1];
    api->exit_initialization_mode = (fmi3ExitInitializationModeTYPE *)f[2];
    api->set_int64 = (fmi3SetInt64TYPE *)f[3];
    api->set_float64 = (fmi3SetFloat64TYPE *)f[4];
    api->get_float64 = (fmi3GetFloat64TYPE *)f[5];
    api->do_step = (fmi3DoStepTYPE *)f[6];
    api->directional = (fmi3GetDirectionalDerivativeTYPE *)f[7];
    api->adjoint = (fmi3GetAdjointDerivativeTYPE *)f[8];
    api->output_derivatives = (fmi3GetOutputDerivativesTYPE *)f[9];
    api->terminate = (fmi3TerminateTYPE *)f[10];
    api->free_instance = (fmi3FreeInstanceTYPE *)f[11];
    api->instantiate_model_exchange = (fmi3InstantiateModelExchangeTYPE *)f[12];
    api->set_time = (fmi3SetTimeTYPE *)f[13];
    api->update_discrete_states = (fmi3UpdateDiscreteStatesTYPE *)f[14];
    api->enter_continuous_time_mode = (fmi3EnterContinuousTimeModeTYPE *)f[15];
    api->get_continuous_states = (fmi3GetContinuousStatesTYPE *)f[16];
    api->get_continuous_state_derivatives = (fmi3GetContinuousStateDerivativesTYPE *)f[17];
    api->set_continuous_states = (fmi3SetContinuousStatesTYPE *)f[18];
    api->completed_integrator_step = (fmi3CompletedIntegratorStepTYPE *)f[19];
    return 1;
}
#endif

/* The directional and adjoint derivatives are those of the first UNKNOWNS output arrays; the
 * output derivatives those of the first OUTPUT_DERIVATIVES (omega and alpha). */
enum { UNKNOWNS = 5, OUTPUT_DERIVATIVES = 4, MAX_VALUES = 64 };

static size_t elements_of_first(const driver_model *m, size_t n_arrays) {
    size_t n = 0;
    for (size_t i = 0; i < n_arrays && i < m->n_outputs; i++) {
        n += m->output_elements[i];
    }
    return n;
}

static uint64_t generator = 0x853c49e6748fea9bULL;

/* An exact binary fraction in [-3, 3): 53 random bits scaled by powers of two and shifted. */
static double next_input(void) {
    generator = generator * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(generator >> 11) * (6.0 / 9007199254740992.0) - 3.0;
}

static void print_values(const char *what, const double *v, size_t n) {
    printf("%s", what);
    for (size_t i = 0; i < n; i++) {
        uint64_t bits;
        memcpy(&bits, &v[i], sizeof bits);
        printf(" %016llx", (unsigned long long)bits);
    }
    printf("\n");
}

static int errors = 0;

static void status(const char *call, fmi3Status s) {
    printf("%s %d\n", call, (int)s);
    if (s == fmi3Error || s == fmi3Fatal) {
        errors++;
    }
}

static void run_case(const fmi3_api *api, const driver_model *m, int64_t sequence, int64_t frame,
                     int steps) {
    fmi3Instance instance = api->instantiate("driver", m->token, NULL, fmi3False, fmi3False,
                                             fmi3False, fmi3False, NULL, 0, NULL, NULL, NULL);
    if (instance == NULL) {
        printf("instantiate failed\n");
        errors++;
        return;
    }
    printf("case sequence %lld frame %lld\n", (long long)sequence, (long long)frame);
    if (m->sequence != 0) {
        status("set sequence", api->set_int64(instance, &m->sequence, 1, &sequence, 1));
    }
    if (m->frame != 0) {
        status("set frame", api->set_int64(instance, &m->frame, 1, &frame, 1));
    }
    status("enter", api->enter_initialization_mode(instance, fmi3False, 0.0, 0.0, fmi3False, 0.0));
    status("exit", api->exit_initialization_mode(instance));
    double t = 0.0;
    for (int step = 0; step < steps; step++) {
        double u[MAX_VALUES], y[MAX_VALUES];
        for (size_t k = 0; k < m->n_input_values; k++) {
            u[k] = next_input();
        }
        status("set", api->set_float64(instance, m->inputs, m->n_inputs, u, m->n_input_values));
        fmi3Boolean event, terminate, early;
        double last;
        status("step", api->do_step(instance, t, 0.125, fmi3True, &event, &terminate, &early, &last));
        t = last;
        status("get", api->get_float64(instance, m->outputs, m->n_outputs, y, m->n_output_values));
        print_values("outputs", y, m->n_output_values);
        if (m->n_knowns > 0) {
            const size_t n_unknowns = m->n_outputs < UNKNOWNS ? m->n_outputs : UNKNOWNS;
            const size_t n_rows = elements_of_first(m, UNKNOWNS);
            double seed[MAX_VALUES], sensitivity[MAX_VALUES];
            for (int k = 0; k < MAX_VALUES; k++) {
                seed[k] = (double)(k + 1) * 0.25;
            }
            status("directional",
                   api->directional(instance, m->outputs, n_unknowns, m->knowns, m->n_knowns,
                                    seed, m->n_columns, sensitivity, n_rows));
            print_values("directional", sensitivity, n_rows);
            status("adjoint", api->adjoint(instance, m->outputs, n_unknowns, m->knowns,
                                           m->n_knowns, seed, n_rows, sensitivity,
                                           m->n_columns));
            print_values("adjoint", sensitivity, m->n_columns);
        }
        if (m->output_derivatives) {
            const size_t n = elements_of_first(m, OUTPUT_DERIVATIVES);
            double sensitivity[MAX_VALUES];
            const fmi3Int32 orders[OUTPUT_DERIVATIVES] = {1, 1, 1, 1};
            status("output derivatives", api->output_derivatives(instance, m->outputs,
                                                                 OUTPUT_DERIVATIVES, orders,
                                                                 sensitivity, n));
            print_values("output derivatives", sensitivity, n);
        }
    }
    status("terminate", api->terminate(instance));
    api->free_instance(instance);
}

int main(int argc, char **argv) {
    if (argc < 3) {
        fprintf(stderr, "usage: fmi3_driver LIBRARY MODEL [STEPS]\n");
        return 2;
    }
    const driver_model *m = NULL;
    for (size_t i = 0; i < N_DRIVER_MODELS; i++) {
        if (strcmp(argv[2], DRIVER_MODELS[i].name) == 0) {
            m = &DRIVER_MODELS[i];
        }
    }
    const int cross_check = argc > 3 && strcmp(argv[3], "cross-check") == 0;
    const int steps = argc > 3 && !cross_check ? atoi(argv[3]) : 3;
#if defined(AK_DRIVER_LINKED)
    static const char linked_in = 0; /* any non-NULL handle: the functions are linked in */
    void *library = (void *)&linked_in;
#elif defined(_WIN32)
    void *library = (void *)LoadLibraryA(argv[1]);
#else
    void *library = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
#endif
    fmi3_api api;
    if (m == NULL || library == NULL || !load_api(library, &api)) {
        fprintf(stderr, "fmi3_driver: cannot load %s as model %s\n", argv[1], argv[2]);
        return 2;
    }
    if (cross_check) {
        return fmi3_driver_cross_check(&api, m, argc - 4, argv + 4);
    }
    for (int64_t sequence = 1; sequence <= (m->sequence != 0 ? 24 : 1); sequence++) {
        for (int64_t frame = 1; frame <= (m->frame != 0 ? 2 : 1); frame++) {
            run_case(&api, m, sequence, frame, steps);
        }
    }
    printf("errors %d\n", errors);
    return errors == 0 ? 0 : 1;
}
