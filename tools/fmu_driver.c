/* A minimal FMI 2.0 co-simulation master of our own, used to prove the Windows binary: built
 * natively and with mingw-w64, it loads an AngularKinematics binary (dlopen or LoadLibrary), drives
 * it through a fixed sequence of inputs, and prints every output with 17 significant digits. The
 * Linux build's printout and the Windows build's printout under wine are then compared. It drives
 * either model: both have 9 Real inputs at value references 0..8 and 12 Real outputs at 9..20
 * (AngularKinematics' omega and alpha; EulerRates' theta_dot, theta_ddot, alpha).
 *
 * The inputs are exact binary fractions computed without libm, so that both runs feed the FMU
 * bit-identical values and any difference comes from the two binaries alone.
 *
 * Usage: fmu_driver LIBRARY [STEPS [MODEL]]   MODEL: AngularKinematics (default) or EulerRates;
 * exit status 0 when every call returned fmi2OK. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2FunctionTypes.h"
#include "AngularKinematics_variables.h"
#include "EulerRates_variables.h"

#ifdef _WIN32
#include <windows.h>
#else
#include <dlfcn.h>
#endif

typedef void (*generic_function)(void);

typedef struct {
    fmi2GetVersionTYPE *get_version;
    fmi2InstantiateTYPE *instantiate;
    fmi2SetupExperimentTYPE *setup_experiment;
    fmi2EnterInitializationModeTYPE *enter_initialization_mode;
    fmi2ExitInitializationModeTYPE *exit_initialization_mode;
    fmi2SetRealTYPE *set_real;
    fmi2GetRealTYPE *get_real;
    fmi2DoStepTYPE *do_step;
    fmi2TerminateTYPE *terminate;
    fmi2FreeInstanceTYPE *free_instance;
} fmi2_api;

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
    generic_function f[10];
    const char *names[10] = {"fmi2GetVersion", "fmi2Instantiate", "fmi2SetupExperiment",
                             "fmi2EnterInitializationMode", "fmi2ExitInitializationMode",
                             "fmi2SetReal", "fmi2GetReal", "fmi2DoStep", "fmi2Terminate",
                             "fmi2FreeInstance"};
    for (int i = 0; i < 10; i++) {
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
    return 1;
}

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
 * 17th step puts theta[2] at gimbal lock (+-pi/2 rounded to a double, the same on both sides), or
 * for EulerRates, whose inverse map is undefined there, at +-1.5 (near it). */
static double input_value(int k, int j, int inverse) {
    if (j == 1 && k % 17 == 0) {
        return (k % 34 == 0 ? 1.0 : -1.0) * (inverse ? 1.5 : 1.5707963267948966);
    }
    return (double)((k * 37 + j * 101 + (k * j) % 23) % 321 - 160) / 64.0;
}

int main(int argc, char **argv) {
    if (argc < 2) {
        fprintf(stderr, "usage: %s LIBRARY [STEPS [AngularKinematics|EulerRates]]\n", argv[0]);
        return 2;
    }
    const int steps = argc > 2 ? atoi(argv[2]) : 200;
    const int inverse = argc > 3 && strcmp(argv[3], "EulerRates") == 0;
    const char *guid = inverse ? ER_GUID : AK_GUID;
    void *library = open_library(argv[1]);
    if (library == NULL) {
        fprintf(stderr, "fmu_driver: cannot load %s\n", argv[1]);
        return 1;
    }
    fmi2_api api;
    if (!load_api(library, &api)) {
        return 1;
    }
    printf("fmi2GetVersion %s\n", api.get_version());

    const fmi2CallbackFunctions callbacks = {logger, allocate, free, NULL, NULL};
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

    fmi2ValueReference inputs[AK_N_INPUTS], outputs[AK_VR_R - AK_N_INPUTS];
    for (int i = 0; i < AK_VR_R; i++) {
        if (i < AK_N_INPUTS) {
            inputs[i] = (fmi2ValueReference)i;
        } else {
            outputs[i - AK_N_INPUTS] = (fmi2ValueReference)i;
        }
    }
    for (int k = 0; k < steps && !failed; k++) {
        double u[AK_N_INPUTS], y[AK_VR_R - AK_N_INPUTS];
        for (int j = 0; j < AK_N_INPUTS; j++) {
            u[j] = input_value(k, j, inverse);
        }
        failed = api.set_real(instance, inputs, AK_N_INPUTS, u) != fmi2OK ||
                 api.get_real(instance, outputs, AK_VR_R - AK_N_INPUTS, y) != fmi2OK;
        if (failed) {
            break;
        }
        printf("%d", k);
        for (int j = 0; j < AK_VR_R - AK_N_INPUTS; j++) {
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
