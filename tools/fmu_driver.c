/* A minimal FMI 2.0 co-simulation master of our own, used to prove the Windows binary: built
 * natively and with mingw-w64, it loads a model's binary (dlopen or LoadLibrary), drives it
 * through a fixed sequence of inputs, and prints every output with 17 significant digits. The
 * Linux build's printout and the Windows build's printout under wine are then compared. It drives
 * any model of the project: the inputs (value references 0 to n_inputs - 1, models/model.h) and
 * the outputs (every variable of causality output, in value-reference order) come from the
 * model's generated variable table, which this program is linked with (only the table: the model
 * itself is in the library it loads). A model with continuous states (AttitudePropagator)
 * integrates them in its co-simulation steps; the driver sees only inputs and outputs.
 *
 * The inputs are exact binary fractions computed without libm, so that both runs feed the FMU
 * bit-identical values and any difference comes from the two binaries alone.
 *
 * Output: "fmi2GetVersion 2.0", "outputs NAME...", then per step "k y1 y2 ...".
 *
 * Usage: fmu_driver LIBRARY [STEPS [MODEL]]   MODEL: a model of the project (default
 * AngularKinematics; the table is fmu_driver_models.c); exit status 0 when every call returned
 * fmi2OK.
 *        fmu_driver LIBRARY cross-check MODEL ...   the cross-check master instead
 * (tools/fmu_driver_cross_check.c).
 *
 * Built with AK_DRIVER_LINKED, the driver has one model's FMI functions linked in instead of
 * loading a library (LIBRARY is ignored; MODEL must be that model, or fmi2Instantiate refuses the
 * GUID): a static executable for a platform that has no dynamic loader here (the 32-bit x86 proof
 * build, docs/platforms.md). */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2FunctionTypes.h"
#include "fmu_driver_api.h"
#include "fmu_driver_models.h"

#if defined(AK_DRIVER_LINKED)
#include "fmi2Functions.h"
#elif defined(_WIN32)
#include <windows.h>
#else
#include <dlfcn.h>
#endif

typedef void (*generic_function)(void);

#ifdef AK_DRIVER_LINKED
static void *open_library(const char *path) {
    (void)path;
    static const char linked_in = 0; /* any non-NULL handle */
    return (void *)&linked_in;
}

static int load_api(void *library, fmi2_api *api) {
    (void)library;
    api->get_version = fmi2GetVersion;
    api->instantiate = fmi2Instantiate;
    api->setup_experiment = fmi2SetupExperiment;
    api->enter_initialization_mode = fmi2EnterInitializationMode;
    api->exit_initialization_mode = fmi2ExitInitializationMode;
    api->set_real = fmi2SetReal;
    api->get_real = fmi2GetReal;
    api->do_step = fmi2DoStep;
    api->terminate = fmi2Terminate;
    api->free_instance = fmi2FreeInstance;
    api->set_time = fmi2SetTime;
    api->new_discrete_states = fmi2NewDiscreteStates;
    api->enter_continuous_time_mode = fmi2EnterContinuousTimeMode;
    api->get_continuous_states = fmi2GetContinuousStates;
    api->get_derivatives = fmi2GetDerivatives;
    api->set_continuous_states = fmi2SetContinuousStates;
    api->completed_integrator_step = fmi2CompletedIntegratorStep;
    return 1;
}
#else
static generic_function load_symbol(void *library, const char *name) {
    generic_function function = NULL;
#ifdef _WIN32
    function = (generic_function)GetProcAddress((HMODULE)library, name);
#else
    void *symbol = dlsym(library, name);
    /* ISO C has no cast from object to function pointer; copying the bits is what POSIX means. */
    memcpy(&function, &symbol, sizeof function);
#endif
    if (function == NULL) {
        fprintf(stderr, "fmu_driver: the library exports no %s\n", name);
    }
    return function;
}

static void *open_library(const char *path) {
#ifdef _WIN32
    return (void *)LoadLibraryA(path);
#else
    return dlopen(path, RTLD_NOW | RTLD_LOCAL);
#endif
}

static int load_api(void *library, fmi2_api *api) {
    enum { N = 17 };
    generic_function f[N];
    const char *names[N] = {"fmi2GetVersion", "fmi2Instantiate", "fmi2SetupExperiment",
                            "fmi2EnterInitializationMode", "fmi2ExitInitializationMode",
                            "fmi2SetReal", "fmi2GetReal", "fmi2DoStep", "fmi2Terminate",
                            "fmi2FreeInstance", "fmi2SetTime", "fmi2NewDiscreteStates",
                            "fmi2EnterContinuousTimeMode", "fmi2GetContinuousStates",
                            "fmi2GetDerivatives", "fmi2SetContinuousStates",
                            "fmi2CompletedIntegratorStep"};
    for (int i = 0; i < N; i++) {
        f[i] = load_symbol(library, names[i]);
        if (f[i] == NULL) {
            return 0;
        }
    }
    api->get_version = (fmi2GetVersionTYPE *)f[0];
    api->instantiate = (fmi2InstantiateTYPE *)f[1];
    api->setup_experiment = (fmi2SetupExperimentTYPE *)f[2];
    api->enter_initialization_mode = (fmi2EnterInitializationModeTYPE *)f[3];
    api->exit_initialization_mode = (fmi2ExitInitializationModeTYPE *)f[4];
    api->set_real = (fmi2SetRealTYPE *)f[5];
    api->get_real = (fmi2GetRealTYPE *)f[6];
    api->do_step = (fmi2DoStepTYPE *)f[7];
    api->terminate = (fmi2TerminateTYPE *)f[8];
    api->free_instance = (fmi2FreeInstanceTYPE *)f[9];
    api->set_time = (fmi2SetTimeTYPE *)f[10];
    api->new_discrete_states = (fmi2NewDiscreteStatesTYPE *)f[11];
    api->enter_continuous_time_mode = (fmi2EnterContinuousTimeModeTYPE *)f[12];
    api->get_continuous_states = (fmi2GetContinuousStatesTYPE *)f[13];
    api->get_derivatives = (fmi2GetDerivativesTYPE *)f[14];
    api->set_continuous_states = (fmi2SetContinuousStatesTYPE *)f[15];
    api->completed_integrator_step = (fmi2CompletedIntegratorStepTYPE *)f[16];
    return 1;
}
#endif

static void logger(fmi2ComponentEnvironment environment, fmi2String instance, fmi2Status status,
                   fmi2String category, fmi2String message, ...) {
    (void)environment;
    va_list arguments;
    va_start(arguments, message);
    fprintf(stderr, "[%s] %s (status %d): ", category, instance, (int)status);
    vfprintf(stderr, message, arguments);
    fprintf(stderr, "\n");
    va_end(arguments);
}

static void *allocate(size_t count, size_t size) { return calloc(count, size); }

/* Input j at step k: an exact multiple of 1/64 between -2.5 and +2.5 (rad, rad/s, rad/s2); every
 * 17th step puts input 1 at +-pi/2 rounded to a double (the same on both sides): AngularKinematics'
 * theta[2] at gimbal lock; for a model whose step is refused there (singular_input_1: EulerRates'
 * inverse map), +-1.5 (near it); AttitudePropagator's omega[2], a rate like any other. */
static double input_value(int k, int j, int singular_input_1) {
    if (j == 1 && k % 17 == 0) {
        return (k % 34 == 0 ? 1.0 : -1.0) * (singular_input_1 ? 1.5 : 1.5707963267948966);
    }
    return (double)((k * 37 + j * 101 + (k * j) % 23) % 321 - 160) / 64.0;
}

int main(int argc, char **argv) {
    if (argc < 2) {
        fprintf(stderr, "usage: %s LIBRARY [STEPS [MODEL]]   MODEL: one of", argv[0]);
        for (size_t m = 0; m < N_DRIVEN_MODELS; m++) {
            fprintf(stderr, " %s", DRIVEN_MODELS[m].name);
        }
        fprintf(stderr, "\n");
        return 2;
    }
    const int cross_check = argc > 2 && strcmp(argv[2], "cross-check") == 0;
    const int steps = argc > 2 && !cross_check ? atoi(argv[2]) : 200;
    const driven_model *model = NULL;
    for (size_t m = 0; m < N_DRIVEN_MODELS; m++) {
        if (strcmp(argc > 3 ? argv[3] : "AngularKinematics", DRIVEN_MODELS[m].name) == 0) {
            model = &DRIVEN_MODELS[m];
        }
    }
    if (model == NULL) {
        fprintf(stderr, "fmu_driver: no model %s\n", argv[3]);
        return 2;
    }
    const int singular_input_1 = model->singular_input_1;
    const char *guid = model->guid;
    void *library = open_library(argv[1]);
    if (library == NULL) {
        fprintf(stderr, "fmu_driver: cannot load %s\n", argv[1]);
        return 1;
    }
    fmi2_api api;
    if (!load_api(library, &api)) {
        return 1;
    }
    const fmi2CallbackFunctions callbacks = {logger, allocate, free, NULL, NULL};
    if (cross_check) {
        return fmu_driver_cross_check(&api, &callbacks, model, argc - 4, argv + 4);
    }
    printf("fmi2GetVersion %s\n", api.get_version());

    fmi2Component instance = api.instantiate("driver", fmi2CoSimulation, guid, "", &callbacks,
                                             fmi2False, fmi2False);
    if (instance == NULL) {
        fprintf(stderr, "fmu_driver: fmi2Instantiate failed\n");
        return 1;
    }
    const double step_size = 1.0 / 64.0;
    int failed = api.setup_experiment(instance, fmi2False, 0.0, 0.0, fmi2False, 0.0) != fmi2OK ||
                 api.enter_initialization_mode(instance) != fmi2OK ||
                 api.exit_initialization_mode(instance) != fmi2OK;

    fmi2ValueReference inputs[AK_MAX_INPUTS], outputs[AK_MAX_VARIABLES];
    const size_t n_inputs = (size_t)model->n_inputs;
    size_t n_outputs = 0;
    for (int vr = 0; vr < model->n_value_references; vr++) {
        if (vr < model->n_inputs) {
            inputs[vr] = (fmi2ValueReference)vr;
        } else if (model->variables[vr].name != NULL &&
                   model->variables[vr].causality == AK_CAUSALITY_OUTPUT) {
            outputs[n_outputs++] = (fmi2ValueReference)vr;
        }
    }
    printf("outputs");
    for (size_t j = 0; j < n_outputs; j++) {
        printf(" %s", model->variables[outputs[j]].name);
    }
    printf("\n");
    for (int k = 0; k < steps && !failed; k++) {
        double u[AK_MAX_INPUTS], y[AK_MAX_VARIABLES];
        for (size_t j = 0; j < n_inputs; j++) {
            u[j] = input_value(k, (int)j, singular_input_1);
        }
        failed = api.set_real(instance, inputs, n_inputs, u) != fmi2OK ||
                 api.get_real(instance, outputs, n_outputs, y) != fmi2OK;
        if (failed) {
            break;
        }
        printf("%d", k);
        for (size_t j = 0; j < n_outputs; j++) {
            printf(" %.17g", y[j]);
        }
        printf("\n");
        failed = api.do_step(instance, k * step_size, step_size, fmi2True) != fmi2OK;
    }
    if (!failed) {
        failed = api.terminate(instance) != fmi2OK;
    }
    api.free_instance(instance);
    if (failed) {
        fprintf(stderr, "fmu_driver: an FMI call did not return fmi2OK\n");
        return 1;
    }
    return 0;
}
