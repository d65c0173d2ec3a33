/* fmu_driver's cross-check mode: the master of examples/cross_check.py (simulate) as a C program,
 * call for call, so that a binary that fmpy cannot load here (a Windows DLL under wine, an
 * aarch64 library under qemu) computes the cross-check's result itself
 * (scripts/cross_check_platforms.py runs it; tests/python/test_cross_check_platforms.py proves
 * that on the x86_64-linux binary it prints fmpy's result bit for bit).
 *
 * Usage: fmu_driver LIBRARY cross-check MODEL cs|me STATES IN_VRS N_IN OUT_VRS N_OUT
 * VRS: comma-separated value references; N_IN, N_OUT: their counts. stdin: one row per
 * communication point, its time and the N_IN input values; stdout: per row the N_OUT outputs
 * (driver_rows.h: hex bits). Set up, initialize (Model Exchange: new discrete states, continuous
 * time mode), then per row: (Model Exchange: set the time), set the inputs, get the outputs,
 * then step to the next row's time (Co-Simulation: fmi2DoStep; Model Exchange with states: one
 * explicit Euler step, x + h dx element by element). Exit status 0 when no call returned more
 * than fmi2Warning (fmpy raises on those). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "driver_rows.h"
#include "fmu_driver_api.h"

enum { MAX_VALUES = 128, MAX_INPUTS = 32, MAX_STATES = 16, MAX_ROWS = 4096 };

static int failed(fmi2Status status, const char *call) {
    if (status > fmi2Warning) {
        fprintf(stderr, "fmu_driver: %s returned status %d\n", call, (int)status);
        return 1;
    }
    return 0;
}

static int euler_step(const fmi2_api *api, fmi2Component instance, size_t states, double h) {
    double x[MAX_STATES], dx[MAX_STATES];
    fmi2Boolean enter_event_mode, terminate;
    if (failed(api->get_continuous_states(instance, x, states), "fmi2GetContinuousStates") ||
        failed(api->get_derivatives(instance, dx, states), "fmi2GetDerivatives")) {
        return 1;
    }
    for (size_t k = 0; k < states; k++) {
        x[k] = x[k] + h * dx[k]; /* not fused: -ffp-contract=off on every target */
    }
    return failed(api->set_continuous_states(instance, x, states), "fmi2SetContinuousStates") ||
           failed(api->completed_integrator_step(instance, fmi2True, &enter_event_mode,
                                                 &terminate),
                  "fmi2CompletedIntegratorStep");
}

/* The rows of stdin (driver_read_rows). */
static double times[MAX_ROWS];
static double inputs[MAX_ROWS * MAX_INPUTS];

int fmu_driver_cross_check(const fmi2_api *api, const fmi2CallbackFunctions *callbacks,
                           const driven_model *model, int argc, char **argv) {
    unsigned int in_vrs[MAX_VALUES], out_vrs[MAX_VALUES];
    size_t n_in = 0, n_out = 0, states = 0;
    if (argc == 6) {
        n_in = driver_parse_list(argv[2], in_vrs, MAX_VALUES);
        n_out = driver_parse_list(argv[4], out_vrs, MAX_VALUES);
        states = (size_t)strtoul(argv[1], NULL, 10);
    }
    const int me = argc == 6 && strcmp(argv[0], "me") == 0;
    if (argc != 6 || (!me && strcmp(argv[0], "cs") != 0) || n_in == 0 || n_in > MAX_INPUTS || n_out == 0 ||
        n_in != strtoul(argv[3], NULL, 10) || n_out != strtoul(argv[5], NULL, 10) ||
        states > MAX_STATES) {
        fprintf(stderr, "usage: fmu_driver LIBRARY cross-check MODEL cs|me STATES IN_VRS N_IN "
                        "OUT_VRS N_OUT   (rows on stdin)\n");
        return 2;
    }
    const size_t rows = driver_read_rows(times, inputs, n_in, MAX_ROWS);
    if (rows == 0) {
        fprintf(stderr, "fmu_driver: no rows on stdin\n");
        return 2;
    }
    fmi2Component instance =
        api->instantiate("fmpy", me ? fmi2ModelExchange : fmi2CoSimulation, model->guid, "",
                         callbacks, fmi2False, fmi2False);
    if (instance == NULL) {
        fprintf(stderr, "fmu_driver: fmi2Instantiate failed\n");
        return 1;
    }
    /* fmpy's setupExperiment(startTime, stopTime): no tolerance, a stop time */
    int error = failed(api->setup_experiment(instance, fmi2False, 0.0, times[0], fmi2True,
                                             times[rows - 1]), "fmi2SetupExperiment") ||
                failed(api->enter_initialization_mode(instance), "fmi2EnterInitializationMode") ||
                failed(api->exit_initialization_mode(instance), "fmi2ExitInitializationMode");
    if (!error && me) {
        fmi2EventInfo event_info;
        error = failed(api->new_discrete_states(instance, &event_info), "fmi2NewDiscreteStates") ||
                failed(api->enter_continuous_time_mode(instance), "fmi2EnterContinuousTimeMode");
    }
    for (size_t row = 0; row < rows && !error; row++) {
        double outputs[MAX_VALUES];
        error = (me && failed(api->set_time(instance, times[row]), "fmi2SetTime")) ||
                failed(api->set_real(instance, in_vrs, n_in, &inputs[row * n_in]), "fmi2SetReal") ||
                failed(api->get_real(instance, out_vrs, n_out, outputs), "fmi2GetReal");
        if (error) {
            break;
        }
        driver_print_row(outputs, n_out);
        if (row + 1 < rows) {
            const double h = times[row + 1] - times[row];
            error = me ? states > 0 && euler_step(api, instance, states, h)
                       : failed(api->do_step(instance, times[row], h, fmi2True), "fmi2DoStep");
        }
    }
    if (!error) {
        error = failed(api->terminate(instance), "fmi2Terminate");
    }
    api->free_instance(instance);
    return error ? 1 : 0;
}
