/* fmi3_driver's cross-check mode: the master of examples/cross_check3.py (simulate3) as a C
 * program, call for call, so that a binary that fmpy cannot load here (a Windows DLL under wine,
 * an aarch64 library under qemu) computes the cross-check's result itself
 * (scripts/cross_check_platforms.py runs it; tests/python/test_cross_check_platforms.py proves
 * that on the x86_64-linux binary it prints fmpy's result bit for bit).
 *
 * Usage: fmi3_driver LIBRARY MODEL cross-check cs|me STATES IN_VRS N_IN OUT_VRS N_OUT
 * VRS: comma-separated value references of whole arrays; N_IN, N_OUT: their numbers of values.
 * stdin: one row per communication point, its time and the N_IN input values; stdout: per row
 * the N_OUT output values (driver_rows.h: hex bits). Set up, initialize (Model Exchange: update
 * the discrete states, continuous time mode), then per row: (Model Exchange: set the time), set
 * the inputs, get the outputs, then step to the next row's time (Co-Simulation: fmi3DoStep;
 * Model Exchange with states: one explicit Euler step, x + h dx element by element). Exit status
 * 0 when no call returned more than fmi3Warning (fmpy raises on those). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "driver_rows.h"
#include "fmi3_driver_api.h"

enum { MAX_VALUES = 128, MAX_INPUTS = 32, MAX_STATES = 16, MAX_ROWS = 4096 };

static int failed(fmi3Status status, const char *call) {
    if (status > fmi3Warning) {
        fprintf(stderr, "fmi3_driver: %s returned status %d\n", call, (int)status);
        return 1;
    }
    return 0;
}

static void logger(fmi3InstanceEnvironment environment, fmi3Status status,
                   fmi3String category, fmi3String message) {
    (void)environment;
    fprintf(stderr, "[%s] status %d: %s\n", category, (int)status, message);
}

static int euler_step(const fmi3_api *api, fmi3Instance instance, size_t states, double h) {
    double x[MAX_STATES], dx[MAX_STATES];
    fmi3Boolean enter_event_mode, terminate;
    if (failed(api->get_continuous_states(instance, x, states), "fmi3GetContinuousStates") ||
        failed(api->get_continuous_state_derivatives(instance, dx, states),
               "fmi3GetContinuousStateDerivatives")) {
        return 1;
    }
    for (size_t k = 0; k < states; k++) {
        x[k] = x[k] + h * dx[k]; /* not fused: -ffp-contract=off on every target */
    }
    return failed(api->set_continuous_states(instance, x, states), "fmi3SetContinuousStates") ||
           failed(api->completed_integrator_step(instance, fmi3True, &enter_event_mode,
                                                 &terminate),
                  "fmi3CompletedIntegratorStep");
}

static fmi3Instance instantiate(const fmi3_api *api, const driver_model *model, int me) {
    if (me) {
        return api->instantiate_model_exchange("fmpy", model->token, "", fmi3False, fmi3False,
                                               NULL, logger);
    }
    static const fmi3ValueReference none[1] = {0};
    return api->instantiate("fmpy", model->token, "", fmi3False, fmi3False, fmi3False, fmi3False,
                            none, 0, NULL, logger, NULL);
}

static int enter_continuous_time(const fmi3_api *api, fmi3Instance instance) {
    fmi3Boolean update_needed, terminate, nominals_changed, values_changed, next_defined;
    fmi3Float64 next_time;
    return failed(api->update_discrete_states(instance, &update_needed, &terminate,
                                              &nominals_changed, &values_changed, &next_defined,
                                              &next_time),
                  "fmi3UpdateDiscreteStates") ||
           failed(api->enter_continuous_time_mode(instance), "fmi3EnterContinuousTimeMode");
}

/* The rows of stdin (driver_read_rows). */
static double times[MAX_ROWS];
static double inputs[MAX_ROWS * MAX_INPUTS];

int fmi3_driver_cross_check(const fmi3_api *api, const driver_model *model, int argc,
                            char **argv) {
    unsigned int in_vrs[MAX_VALUES], out_vrs[MAX_VALUES];
    size_t n_in_arrays = 0, n_out_arrays = 0, n_in = 0, n_out = 0, states = 0;
    if (argc == 6) {
        n_in_arrays = driver_parse_list(argv[2], in_vrs, MAX_VALUES);
        n_out_arrays = driver_parse_list(argv[4], out_vrs, MAX_VALUES);
        n_in = (size_t)strtoul(argv[3], NULL, 10);
        n_out = (size_t)strtoul(argv[5], NULL, 10);
        states = (size_t)strtoul(argv[1], NULL, 10);
    }
    const int me = argc == 6 && strcmp(argv[0], "me") == 0;
    if (argc != 6 || (!me && strcmp(argv[0], "cs") != 0) || n_in_arrays == 0 || n_in == 0 ||
        n_in > MAX_INPUTS || n_out_arrays == 0 || n_out == 0 || n_out > MAX_VALUES ||
        states > MAX_STATES) {
        fprintf(stderr, "usage: fmi3_driver LIBRARY MODEL cross-check cs|me STATES IN_VRS N_IN "
                        "OUT_VRS N_OUT   (rows on stdin)\n");
        return 2;
    }
    const size_t rows = driver_read_rows(times, inputs, n_in, MAX_ROWS);
    if (rows == 0) {
        fprintf(stderr, "fmi3_driver: no rows on stdin\n");
        return 2;
    }
    fmi3Instance instance = instantiate(api, model, me);
    if (instance == NULL) {
        fprintf(stderr, "fmi3_driver: the instantiation failed\n");
        return 1;
    }
    /* fmpy's enterInitializationMode(startTime, stopTime): no tolerance, a stop time */
    int error = failed(api->enter_initialization_mode(instance, fmi3False, 0.0, times[0],
                                                      fmi3True, times[rows - 1]),
                       "fmi3EnterInitializationMode") ||
                failed(api->exit_initialization_mode(instance), "fmi3ExitInitializationMode") ||
                (me && enter_continuous_time(api, instance));
    for (size_t row = 0; row < rows && !error; row++) {
        double outputs[MAX_VALUES];
        error = (me && failed(api->set_time(instance, times[row]), "fmi3SetTime")) ||
                failed(api->set_float64(instance, in_vrs, n_in_arrays, &inputs[row * n_in], n_in),
                       "fmi3SetFloat64") ||
                failed(api->get_float64(instance, out_vrs, n_out_arrays, outputs, n_out),
                       "fmi3GetFloat64");
        if (error) {
            break;
        }
        driver_print_row(outputs, n_out);
        if (row + 1 < rows) {
            const double h = times[row + 1] - times[row];
            fmi3Boolean event, terminate, early;
            fmi3Float64 last;
            error = me ? states > 0 && euler_step(api, instance, states, h)
                       : failed(api->do_step(instance, times[row], h, fmi3True, &event,
                                             &terminate, &early, &last),
                                "fmi3DoStep");
        }
    }
    if (!error) {
        error = failed(api->terminate(instance), "fmi3Terminate");
    }
    api->free_instance(instance);
    return error ? 1 : 0;
}
