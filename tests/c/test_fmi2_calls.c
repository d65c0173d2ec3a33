/* Drives every exported FMI 2.0 function through legal and illegal sequences and every row of the
 * bad-input table, with a logger that keeps the messages and an allocator that counts. Checked
 * after every call: the status, the exact messages, that a rejected call left the instance bit for
 * bit unchanged and usable, and that nothing leaked. Built normally (ctest), with ASan+UBSan, and
 * run under valgrind (scripts/check_sanitizers.sh).
 *
 *   test_fmi2_calls           run everything, print a summary
 *   test_fmi2_calls --table   the same, then print the bad-input table as observed (markdown) */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

#include "fmi2Functions.h"
#include "fmi2_bad_input_table.h"
#include "fmi2_test_callbacks.h"
#include "fmi2_test_instance.h"
#include "fmi2_test_ops.h"
#include "test_check.h"

enum {
    READABLE = AK_IN_INITIALIZATION_MODE | AK_IN_STEP_COMPLETE | AK_IN_STEP_FAILED |
               AK_IN_TERMINATED | AK_IN_EVENT_MODE | AK_IN_CONTINUOUS_TIME_MODE
};

static const char *category_for(fmi2Status status) {
    return status == fmi2Error ? "logStatusError" : "logStatusWarning";
}

/* Exactly these messages (n of them: 0, 1 or 2), each with its status, text and the instance
 * name. */
static void check_messages(const ak_recorder *recorder, const char *context, size_t n,
                           const fmi2Status status[], const char *const text[],
                           const char *instance_name) {
    ak_check(recorder->contract_violations == 0, "%s: the logger got a malformed message", context);
    if (n == 0) {
        ak_check(recorder->count == 0, "%s: a message was logged where none should be", context);
        return;
    }
    if (!ak_check(recorder->count == n, "%s: not the number of messages expected", context)) {
        for (size_t i = 0; i < recorder->count && i < AK_RECORDED_MESSAGES; i++) {
            printf("     logged: %s\n", recorder->messages[i].text);
        }
        return;
    }
    for (size_t i = 0; i < n; i++) {
        const ak_recorded_message *m = &recorder->messages[i];
        if (!ak_check(strcmp(m->text, text[i]) == 0, "%s: wrong message", context)) {
            printf("     logged:   %s\n     expected: %s\n", m->text, text[i]);
        }
        ak_check(m->status == status[i],
                 "%s: message logged with another status than expected", context);
        ak_check(strcmp(m->category, category_for(status[i])) == 0,
                 "%s: message in wrong category", context);
        ak_check(strcmp(m->instance_name, instance_name) == 0,
                 "%s: message names another instance", context);
    }
}

/* Exactly one message, with this status, text and instance name; or none when text is NULL. */
static void check_logged(const ak_recorder *recorder, const char *context, fmi2Status status,
                         const char *text, const char *instance_name) {
    check_messages(recorder, context, text != NULL, &status, &text, instance_name);
}

/* A row of the common table that does not hold for this model (fmi2_bad_input_table.h). */
static bool row_applies(const ak_bad_call *bad) {
    return !(bad->without_states_only && AK_MODEL.n_states > 0);
}

/* After a rejected call the instance must go on as if the call never happened. */
static void check_still_usable(fmi2Component c, unsigned int state, const char *context) {
    if (state & READABLE) {
        ak_check(ak_test_outputs_consistent(c),
                 "%s: outputs unreadable or inconsistent after", context);
    }
    if (state == AK_IN_STEP_COMPLETE) {
        ak_check(fmi2DoStep(c, AK_TEST_STEP_COMPLETE_TIME, 0.5, fmi2True) == fmi2OK,
                 "%s: cannot step after", context);
    }
    if (state == (AK_ME | AK_IN_CONTINUOUS_TIME_MODE)) {
        fmi2Boolean enter = fmi2True, terminate = fmi2True;
        ak_check(fmi2SetTime(c, 0.5) == fmi2OK &&
                 fmi2CompletedIntegratorStep(c, fmi2True, &enter, &terminate) == fmi2OK &&
                 enter == fmi2False && terminate == fmi2False,
                 "%s: cannot integrate after", context);
    }
}

/* The text with each '|' escaped ("\\|"), so that it stays inside its cell of a markdown table. */
static void print_cell_text(const char *text) {
    for (; *text != '\0'; text++) {
        if (*text == '|') {
            putchar('\\');
        }
        putchar(*text);
    }
}

static void print_row(const char *state, const char *call, const char *status,
                      const char *message) {
    printf("| %s | `", state);
    print_cell_text(call);
    printf("` | %s | ", status);
    if (message != NULL) {
        putchar('`');
        print_cell_text(message);
        printf("` |\n");
    } else {
        printf("(nothing logged) |\n");
    }
}

/* A row's call or message with its placeholders (fmi2_bad_input_table.h) replaced by the numbers
 * of the model the program is built for. */
static void expand(const char *text, char *out, size_t size) {
    static const char *const names[] = {"@PAST@", "@LAST@", "@STATE_BYTES@", "@MODEL@"};
    char values[4][64];
    snprintf(values[0], sizeof values[0], "%d", AK_MODEL.n_value_references);
    snprintf(values[1], sizeof values[1], "%d", AK_MODEL.n_value_references - 1);
    snprintf(values[2], sizeof values[2], "%d",
             92 + 8 * AK_MODEL.n_value_references + 16 * AK_MODEL.n_inputs);
    snprintf(values[3], sizeof values[3], "%s", AK_MODEL.model_identifier);
    size_t used = 0;
    out[0] = '\0';
    while (*text != '\0' && used + 1 < size) {
        bool replaced = false;
        for (size_t k = 0; k < sizeof names / sizeof names[0] && !replaced; k++) {
            const size_t length = strlen(names[k]);
            if (strncmp(text, names[k], length) == 0) {
                const int written = snprintf(out + used, size - used, "%s", values[k]);
                used += written > 0 ? (size_t)written : 0;
                used = used < size ? used : size - 1;
                text += length;
                replaced = true;
            }
        }
        if (!replaced) {
            out[used++] = *text++;
            out[used] = '\0';
        }
    }
}

static void run_bad_call(const ak_bad_call *bad, size_t row, bool print_table) {
    char call[512];
    char expected[512], expected2[512];
    expand(bad->call, call, sizeof call);
    if (bad->message != NULL) {
        expand(bad->message, expected, sizeof expected);
    }
    if (bad->message2 != NULL) {
        expand(bad->message2, expected2, sizeof expected2);
    }
    char context[600];
    snprintf(context, sizeof context, "bad call %zu: %s", row + 1, call);
    ak_recorder recorder;
    ak_recorder_clear(&recorder);
    const fmi2CallbackFunctions functions = ak_test_callbacks(&recorder);
    fmi2Component c = ak_test_instantiate_for(bad->in, "bad-input", &functions, false);
    if (!ak_check(c != NULL && ak_test_bring_to(c, bad->in), "%s: setup failed", context)) {
        if (c != NULL) {
            fmi2FreeInstance(c);
        }
        return;
    }
    if (bad->with_setup) {
        ak_args setup = bad->setup_args;
        ak_check(AK_OPS[bad->setup_op].call(c, &setup) == fmi2OK,
                 "%s: the legal call before the bad one failed", context);
    }
    ak_args args = bad->args;
    fmi2FMUstate state = NULL;
    if (bad->with_fmu_state) {
        ak_check(fmi2GetFMUstate(c, &state) == fmi2OK, "%s: fmi2GetFMUstate failed", context);
        args.state = state;
    }
    ak_recorder_clear(&recorder);
    ak_snapshot before;
    ak_snapshot_take(&before, c);
    const fmi2Status status = AK_OPS[bad->op].call(c, &args);
    const bool status_ok = ak_check(status == bad->status, "%s: wrong status", context);
    if (!status_ok) {
        printf("     returned %s, expected %s\n", ak_status_name(status),
               ak_status_name(bad->status));
    }
    const fmi2Status statuses[2] = {bad->message_status != fmi2OK ? bad->message_status : status,
                                    bad->status2};
    const char *const texts[2] = {expected, expected2};
    check_messages(&recorder, context, bad->message == NULL ? 0 : bad->message2 == NULL ? 1 : 2,
                   statuses, texts, "bad-input");
    /* A read answered with fmi2Discard ran the evaluation (which failed): see
     * ak_snapshot_same_inputs. */
    ak_check(bad->status == fmi2Discard ? ak_snapshot_same_inputs(&before, c)
                                        : ak_snapshot_unchanged(&before, c),
             "%s: the rejected call changed the instance", context);
    const ak_recorder logged = recorder;
    /* A step answered with fmi2Discard was not taken: the instance is in StepFailed, at the
     * time it was before. */
    const bool step_discarded = bad->op == AK_OP_DO_STEP && status == fmi2Discard;
    if (step_discarded) {
        fmi2Real last = -1.0;
        ak_check(((const ak_instance *)c)->state == AK_STEP_FAILED &&
                 fmi2GetRealStatus(c, fmi2LastSuccessfulTime, &last) == fmi2OK &&
                 last == before.copy.time,
                 "%s: the discarded step did not leave the instance in StepFailed at its time", context);
    }
    check_still_usable(c, step_discarded ? AK_IN_STEP_FAILED : bad->in, context);
    if (state != NULL) {
        ak_check(fmi2FreeFMUstate(c, &state) == fmi2OK, "%s: fmi2FreeFMUstate failed", context);
    }
    fmi2FreeInstance(c);
    ak_check(ak_test_live_allocations() == 0, "%s: memory left allocated after freeing", context);
    if (print_table && status_ok) {
        /* Two messages: "`first` then `second`" in the message column. */
        char both[2 * AK_RECORDED_MESSAGE_SIZE + 16];
        if (logged.count == 2) {
            snprintf(both, sizeof both, "%s` then `%s", logged.messages[0].text,
                     logged.messages[1].text);
        }
        print_row(ak_test_state_label(bad->in), call, ak_status_name(status),
                  logged.count == 2 ? both : logged.count == 1 ? logged.messages[0].text : NULL);
    }
}

/* Returns how many rows hold for this model and were run. */
static size_t run_bad_calls(bool print_table) {
    size_t run = 0;
    for (size_t row = 0; row < AK_N_BAD_CALLS; row++) {
        if (row_applies(&AK_BAD_CALLS[row])) {
            run_bad_call(&AK_BAD_CALLS[row], row, print_table);
            run++;
        }
    }
    for (size_t row = 0; row < AK_N_MODEL_BAD_CALLS; row++) {
        run_bad_call(&AK_MODEL_BAD_CALLS[row], AK_N_BAD_CALLS + row, print_table);
        run++;
    }
    return run;
}

static void run_bad_instantiates(bool print_table) {
    for (size_t row = 0; row < AK_N_BAD_INSTANTIATES; row++) {
        const ak_bad_instantiate *bad = &AK_BAD_INSTANTIATES[row];
        char context[256];
        snprintf(context, sizeof context, "bad instantiate %zu: %s", row + 1, bad->call);
        ak_recorder recorder;
        ak_recorder_clear(&recorder);
        fmi2CallbackFunctions functions = ak_test_callbacks(&recorder);
        if (bad->callbacks == AK_CALLBACKS_WITHOUT_MEMORY) {
            functions.allocateMemory = NULL;
            functions.freeMemory = NULL;
        }
        if (bad->callbacks == AK_CALLBACKS_WITHOUT_LOGGER) {
            functions.logger = NULL;
        }
        const char *guid = bad->guid == AK_THIS_GUID ? AK_MODEL.guid : bad->guid;
        char message[512];
        if (bad->message != NULL) {
            snprintf(message, sizeof message, "%s%s", bad->message,
                     bad->guid_in_message ? AK_MODEL.guid : "");
            if (bad->guid_in_message) {
                const size_t used = strlen(message);
                snprintf(message + used, sizeof message - used, "\" of this FMU's binary (%s)",
                         AK_MODEL.model_identifier);
            }
        }
        ak_test_fail_allocations(bad->allocations_before_failure, bad->failing_allocations);
        fmi2Component c = fmi2Instantiate(
            bad->instance_name, (fmi2Type)bad->fmu_type, guid, "file:///unused",
            bad->callbacks == AK_NULL_CALLBACKS ? NULL : &functions, fmi2False, fmi2False);
        ak_test_fail_allocations(-1, 0);
        ak_check(c == NULL, "%s: an instance was created", context);
        check_logged(&recorder, context, fmi2Error, bad->message ? message : NULL,
                     bad->instance_name ? bad->instance_name : "");
        ak_check(ak_test_live_allocations() == 0, "%s: memory left allocated", context);
        if (print_table && c == NULL) {
            print_row("(none)", bad->call, "NULL",
                      recorder.count == 1 ? recorder.messages[0].text : NULL);
        }
    }
}

/* Arguments harmless to every op, with room for any single result. */
static ak_args benign_args(double time, ak_result result[2]) {
    ak_args args = {0};
    args.real[0] = time;
    args.real[1] = 0.1;
    args.real[2] = AK_TEST_STOP_TIME;
    args.flag[0] = fmi2True;
    args.kind = fmi2LastSuccessfulTime;
    args.out = &result[0];
    args.out2 = &result[1];
    return args;
}

/* Every op with c = NULL: fmi2Error (fmi2FreeInstance: nothing), no crash, nothing allocated. */
static bool run_null_instance(void) {
    const int failures_before = ak_check_failures();
    for (int op = 0; op < AK_N_OPS; op++) {
        ak_result result[2] = {{0}};
        const ak_args args = benign_args(0.0, result);
        const fmi2Status status = AK_OPS[op].call(NULL, &args);
        ak_check(status == (op == AK_OP_FREE_INSTANCE ? fmi2OK : fmi2Error),
                 "%s: %s", AK_OPS[op].name, "wrong status for c = NULL");
    }
    ak_check(ak_test_live_allocations() == 0, "%s: %s", "c = NULL", "memory allocated");
    return ak_check_failures() == failures_before;
}

/* Every op in every reachable state of both interfaces: a function of the other interface gets
 * fmi2Error and "<function>: a <interface> function, but this instance was created for ..."; where
 * the standard forbids it, fmi2Error, one message "<function>: illegal call in state <state>" and
 * nothing changed; where it allows it, no such message. */
static bool run_state_matrix(void) {
    const int failures_before = ak_check_failures();
    for (int op = 0; op < AK_N_OPS; op++) {
        for (int s = 0; s < AK_TEST_N_STATES; s++) {
            const unsigned int state = AK_TEST_STATES[s];
            if (!ak_test_state_reachable(state)) {
                continue;
            }
            char context[160];
            snprintf(context, sizeof context, "%s in state %s", AK_OPS[op].name,
                     ak_test_state_label(state));
            ak_recorder recorder;
            ak_recorder_clear(&recorder);
            const fmi2CallbackFunctions functions = ak_test_callbacks(&recorder);
            fmi2Component c = ak_test_instantiate_for(state, "matrix", &functions, false);
            if (!ak_check(c != NULL && ak_test_bring_to(c, state), "%s: setup failed", context)) {
                continue;
            }
            ak_recorder_clear(&recorder);
            const double time = ((const ak_instance *)c)->time;
            ak_result result[2] = {{0}};
            const ak_args args = benign_args(time, result);
            ak_snapshot before;
            ak_snapshot_take(&before, c);
            const fmi2Status status = AK_OPS[op].call(c, &args);
            const bool me = (state & AK_ME) != 0;
            char refusal[200];
            if ((AK_OPS[op].interfaces & (me ? AK_FOR_ME : AK_FOR_CS)) == 0) {
                snprintf(refusal, sizeof refusal,
                         "%s: a %s function, but this instance was created for %s",
                         AK_OPS[op].name, me ? "co-simulation" : "model-exchange",
                         me ? "model exchange (fmi2ModelExchange)"
                            : "co-simulation (fmi2CoSimulation)");
            } else {
                snprintf(refusal, sizeof refusal, "%s: illegal call in state %s",
                         AK_OPS[op].name, ak_test_state_name(state));
            }
            const bool allowed = (AK_OPS[op].allowed_in & state) != 0 &&
                                 (AK_OPS[op].interfaces & (me ? AK_FOR_ME : AK_FOR_CS)) != 0;
            if (!allowed) {
                ak_check(status == fmi2Error, "%s: forbidden call not refused", context);
                check_logged(&recorder, context, fmi2Error, refusal, "matrix");
                ak_check(ak_snapshot_unchanged(&before, c),
                         "%s: forbidden call changed it", context);
            } else {
                ak_check(recorder.count == 0 || strcmp(recorder.messages[0].text, refusal) != 0,
                         "%s: allowed call refused as illegal", context);
            }
            if (op != AK_OP_FREE_INSTANCE) {
                if ((op == AK_OP_GET_FMU_STATE || op == AK_OP_DE_SERIALIZE_FMU_STATE) &&
                    status == fmi2OK) {
                    fmi2FreeFMUstate(c, &result[0].state);
                }
                fmi2FreeInstance(c);
            }
            ak_check(ak_test_live_allocations() == 0, "%s: memory left allocated", context);
        }
    }
    return ak_check_failures() == failures_before;
}

/* A whole simulation, a reset from every state and a second simulation: all fmi2OK, outputs
 * always the model's, and not one message at the default logging level. */
static void run_legal_sequences(void) {
    const char *context = "legal sequence";
    ak_recorder recorder;
    ak_recorder_clear(&recorder);
    const fmi2CallbackFunctions functions = ak_test_callbacks(&recorder);
    fmi2Component c = ak_test_instantiate("legal", &functions, false);
    if (!ak_check(c != NULL, "%s: instantiation failed", context)) {
        return;
    }
    for (int s = 0; s < AK_TEST_N_STATES; s++) {
        if ((AK_TEST_STATES[s] & AK_ME) || !ak_test_state_reachable(AK_TEST_STATES[s])) {
            continue;
        }
        ak_check(ak_test_bring_to(c, AK_TEST_STATES[s]), "%s: cannot reach state", context);
        ak_check(fmi2Reset(c) == fmi2OK, "%s: reset failed", context);
        const ak_instance *instance = c;
        ak_check(instance->state == AK_INSTANTIATED && instance->time == 0.0,
                 "%s: reset did not bring back the initial condition", context);
        for (int vr = 0; vr < AK_MODEL.n_value_references; vr++) {
            const ak_variable *variable = ak_variable_of((unsigned int)vr);
            ak_check(variable == NULL || variable->causality == AK_CAUSALITY_OUTPUT
                     ? true
                     : instance->data.values[vr] == variable->start,
                     "%s: reset did not restore the start values", context);
        }
    }
    ak_recorder_clear(&recorder); /* bringing EulerRates to StepFailed logs why the step failed */
    ak_check(ak_test_bring_to(c, AK_IN_STEP_COMPLETE),
             "%s: cannot initialize after reset", context);
    double time = AK_TEST_STEP_COMPLETE_TIME;
    for (int step = 0; step < 1000; step++) {
        fmi2Real inputs[AK_TEST_MAX_INPUTS];
        for (int i = 0; i < (int)ak_test_n_inputs(); i++) {
            /* theta[2] (i = 1) stays within 1 rad of 0: away from EulerRates' singularity. */
            inputs[i] = sin(0.01 * step * (i + 1)) * (i == 1 ? 1.0 : i + 1);
        }
        if (step % 3 != 0) { /* sometimes the master does not set the inputs at all */
            ak_check(fmi2SetReal(c, AK_TEST_INPUT_VRS, ak_test_n_inputs(), inputs) == fmi2OK,
                     "%s: set", context);
        }
        ak_check(ak_test_outputs_consistent(c), "%s: outputs are not the core's", context);
        ak_check(fmi2DoStep(c, time, 0.005, fmi2False) == fmi2OK, "%s: step", context);
        time += 0.005;
    }
    fmi2Real last_time = 0.0;
    fmi2Boolean terminated = fmi2True;
    ak_check(fmi2GetRealStatus(c, fmi2LastSuccessfulTime, &last_time) == fmi2OK &&
             last_time == time,
             "%s: fmi2LastSuccessfulTime is not the end of the last step", context);
    ak_check(fmi2GetBooleanStatus(c, fmi2Terminated, &terminated) == fmi2OK &&
             terminated == fmi2False, "%s: fmi2Terminated status", context);
    /* A step too small to move the time in double precision is still a step > 0. */
    ak_check(fmi2DoStep(c, time, 5e-324, fmi2True) == fmi2OK &&
             fmi2GetRealStatus(c, fmi2LastSuccessfulTime, &last_time) == fmi2OK &&
             last_time == time, "%s: denormal step", context);
    ak_check(fmi2Terminate(c) == fmi2OK, "%s: terminate", context);
    ak_check(ak_test_outputs_consistent(c), "%s: outputs after terminate", context);
    ak_check(recorder.count == 0, "%s: messages logged at the default logging level", context);
    /* Huge but finite inputs are legal; the outputs may overflow (EulerRates: the evaluation may
     * fail, or warn), but stay the model's. */
    static const fmi2Real HUGE_VALUES[9] = {1e300, -1e300, 1e300, 1e200, 1e200,
                                            -1e200, 1e308, 5e-324, -1e-310};
    fmi2Real huge[AK_TEST_MAX_INPUTS];
    for (int i = 0; i < AK_TEST_MAX_INPUTS; i++) { /* the nine, again and again */
        huge[i] = HUGE_VALUES[i % 9];
    }
    ak_check(fmi2Reset(c) == fmi2OK &&
                 fmi2SetReal(c, AK_TEST_INPUT_VRS, ak_test_n_inputs(), huge) == fmi2OK,
             "%s: huge finite inputs refused", context);
    ak_check(fmi2EnterInitializationMode(c) == fmi2OK && ak_test_outputs_consistent(c),
             "%s: outputs for huge inputs are not the model's", context);
    fmi2FreeInstance(c);
    ak_check(ak_test_live_allocations() == 0, "%s: memory left allocated", context);
}

/* Model exchange: the whole cycle (no event indicators; the master sets time and inputs, reads the
 * model's continuous states and their derivatives, if it has any, and integrates them by explicit
 * Euler steps), all fmi2OK, outputs always the model's, no message. */
static void run_model_exchange(void) {
    const char *context = "model exchange";
    ak_recorder recorder;
    ak_recorder_clear(&recorder);
    const fmi2CallbackFunctions functions = ak_test_callbacks(&recorder);
    fmi2Component c = ak_test_instantiate_for(AK_ME, "me", &functions, false);
    const size_t nx = (size_t)AK_MODEL.n_states;
    fmi2Real x[AK_MAX_STATES] = {0}, dx[AK_MAX_STATES] = {0}, nominal[AK_MAX_STATES] = {0};
    if (!ak_check(c != NULL && fmi2GetNominalsOfContinuousStates(c, nominal, nx) == fmi2OK &&
                  ak_test_bring_to(c, AK_ME | AK_IN_EVENT_MODE), "%s: setup failed", context)) {
        return;
    }
    fmi2EventInfo info;
    memset(&info, 0xff, sizeof info);
    ak_check(fmi2NewDiscreteStates(c, &info) == fmi2OK && info.newDiscreteStatesNeeded == fmi2False &&
             info.terminateSimulation == fmi2False && info.nextEventTimeDefined == fmi2False,
             "%s: fmi2NewDiscreteStates", context);
    ak_check(fmi2EnterContinuousTimeMode(c) == fmi2OK, "%s: enter continuous-time mode", context);
    for (int step = 1; step <= 1000; step++) {
        const double time = 0.001 * step;
        fmi2Real inputs[AK_TEST_MAX_INPUTS];
        for (int i = 0; i < (int)ak_test_n_inputs(); i++) {
            inputs[i] = cos(time * (i + 1)) * (i == 1 ? 1.0 : i + 1);
        }
        fmi2Boolean enter = fmi2True, terminate = fmi2True;
        ak_check(fmi2SetTime(c, time) == fmi2OK &&
                 fmi2SetReal(c, AK_TEST_INPUT_VRS, ak_test_n_inputs(), inputs) == fmi2OK &&
                 fmi2GetContinuousStates(c, x, nx) == fmi2OK &&
                 fmi2GetDerivatives(c, dx, nx) == fmi2OK, "%s: a step of the integrator", context);
        for (size_t k = 0; k < nx; k++) {
            x[k] += 0.001 * dx[k];
        }
        ak_check(fmi2SetContinuousStates(c, x, nx) == fmi2OK &&
                 fmi2GetDerivatives(c, dx, nx) == fmi2OK &&
                 fmi2GetEventIndicators(c, NULL, 0) == fmi2OK,
                 "%s: the states of the integrator", context);
        ak_check(ak_test_outputs_consistent(c), "%s: outputs are not the model's", context);
        ak_check(fmi2CompletedIntegratorStep(c, step % 2, &enter, &terminate) == fmi2OK &&
                 enter == fmi2False && terminate == fmi2False,
                 "%s: fmi2CompletedIntegratorStep", context);
        if (step % 250 == 0) {
            ak_check(fmi2EnterEventMode(c) == fmi2OK && fmi2NewDiscreteStates(c, &info) == fmi2OK &&
                     fmi2EnterContinuousTimeMode(c) == fmi2OK, "%s: an event iteration", context);
        }
    }
    ak_check(fmi2GetContinuousStates(c, x, nx) == fmi2OK && fmi2Terminate(c) == fmi2OK &&
             ak_test_outputs_consistent(c) && fmi2GetDerivatives(c, dx, nx) == fmi2OK,
             "%s: terminate", context);
    for (size_t k = 0; k < nx; k++) {
        ak_check(nominal[k] > 0.0 && isfinite(x[k]) && isfinite(dx[k]),
                 "%s: a state, its derivative or its nominal not finite", context);
    }
    ak_check(fmi2Reset(c) == fmi2OK && ak_test_bring_to(c, AK_ME | AK_IN_CONTINUOUS_TIME_MODE),
             "%s: reset and again", context);
    ak_check(recorder.count == 0, "%s: messages logged at the default logging level", context);
    fmi2FreeInstance(c);
    ak_check(ak_test_live_allocations() == 0, "%s: memory left allocated", context);
}

/* FMU state: get, step on, set back (bit for bit the values, time and state of then), serialize
 * and deserialize, and every serialized state with one byte changed refused (fmi2Error, the
 * handle untouched), in both interfaces. */
static void run_fmu_state(unsigned int interface) {
    const char *context = interface ? "FMU state (model exchange)" : "FMU state (co-simulation)";
    ak_recorder recorder;
    ak_recorder_clear(&recorder);
    const fmi2CallbackFunctions functions = ak_test_callbacks(&recorder);
    const unsigned int state = interface | (interface ? AK_IN_EVENT_MODE : AK_IN_STEP_COMPLETE);
    fmi2Component c = ak_test_instantiate_for(state, "state", &functions, false);
    if (!ak_check(c != NULL && ak_test_bring_to(c, state), "%s: setup failed", context)) {
        return;
    }
    if (!interface) {
        const fmi2Integer order[2] = {1, 2};
        const fmi2Real derivative[2] = {0.25, -0.5};
        ak_check(fmi2SetRealInputDerivatives(c, AK_TEST_INPUT_VRS, 2, order, derivative) == fmi2OK,
                 "%s: input derivatives", context);
    }
    ak_snapshot then;
    ak_snapshot_take(&then, c);
    fmi2FMUstate saved = NULL, restored = NULL;
    ak_check(fmi2GetFMUstate(c, &saved) == fmi2OK && saved != NULL, "%s: get", context);
    const fmi2Real other[AK_TEST_MAX_INPUTS] = {-1, 0.2, 3, 4, 5, 6, 7, 8, 9};
    ak_check(fmi2SetReal(c, AK_TEST_INPUT_VRS, ak_test_n_inputs(), other) == fmi2OK,
             "%s: set inputs", context);
    if (!interface) {
        ak_check(fmi2DoStep(c, AK_TEST_STEP_COMPLETE_TIME, 0.5, fmi2True) == fmi2OK,
                 "%s: step", context);
    } else {
        ak_check(fmi2SetTime(c, 3.0) == fmi2OK && fmi2EnterContinuousTimeMode(c) == fmi2OK,
                 "%s: on", context);
    }
    ak_check(fmi2SetFMUstate(c, saved) == fmi2OK, "%s: set", context);
    const ak_instance *now = c, *was = &then.copy;
    ak_check(memcmp(now->data.values, was->data.values, sizeof now->data.values) == 0 && now->time == was->time &&
             now->state == was->state &&
             memcmp(now->data.input_derivatives, was->data.input_derivatives,
                     sizeof now->data.input_derivatives) == 0,
             "%s: the state set back is not the state got", context);
    ak_check(ak_test_outputs_consistent(c), "%s: outputs after set", context);
    size_t size = 0;
    ak_check(fmi2SerializedFMUstateSize(c, saved, &size) == fmi2OK && size > 0 && size < 4096,
             "%s: size", context);
    fmi2Byte bytes[4096];
    ak_check(fmi2SerializeFMUstate(c, saved, bytes, size) == fmi2OK, "%s: serialize", context);
    ak_check(fmi2DeSerializeFMUstate(c, bytes, size, &restored) == fmi2OK && restored != NULL &&
             fmi2SetFMUstate(c, restored) == fmi2OK && ak_test_outputs_consistent(c),
             "%s: deserialize and set", context);
    size_t refused = 0;
    for (size_t i = 0; i < size; i++) {
        bytes[i] ^= 0x5a;
        fmi2FMUstate corrupt = NULL;
        ak_recorder_clear(&recorder);
        refused += fmi2DeSerializeFMUstate(c, bytes, size, &corrupt) == fmi2Error &&
                   corrupt == NULL && recorder.count == 1;
        bytes[i] ^= 0x5a;
    }
    ak_check(refused == size, "%s: a serialized state with a changed byte was accepted", context);
    ak_recorder_clear(&recorder);
    ak_check(fmi2DeSerializeFMUstate(c, bytes, size - 1, &restored) == fmi2Error,
             "%s: a truncated state was accepted", context);
    ak_check(fmi2FreeFMUstate(c, &saved) == fmi2OK && saved == NULL &&
             fmi2FreeFMUstate(c, &restored) == fmi2OK && restored == NULL, "%s: free", context);
    fmi2FreeInstance(c);
    ak_check(ak_test_live_allocations() == 0, "%s: memory left allocated", context);
}

/* The model's parameters (sequence, and frame where the model has one), and EulerRates' singular
 * configuration: near it fmi2Warning with one
 * message naming theta[2]; at it fmi2Discard, a failed step (StepFailed) that keeps the last valid
 * time and outputs, and recovery by fmi2SetFMUstate or fmi2Reset. */
static void run_model_specific(void) {
    const char *context = AK_MODEL.model_identifier;
    ak_recorder recorder;
    ak_recorder_clear(&recorder);
    const fmi2CallbackFunctions functions = ak_test_callbacks(&recorder);
    fmi2Component c = ak_test_instantiate("model", &functions, false);
    if (!ak_check(c != NULL, "%s: instantiation failed", context)) {
        return;
    }
    fmi2ValueReference sequence_vr = 0;
    const bool has_sequence = ak_test_find_vr("sequence", &sequence_vr);
    /* Every sequence: through fmi2SetInteger, then a simulation whose outputs are the model's (a
     * model without the parameter: one simulation). */
    for (fmi2Integer sequence = 1; sequence <= (has_sequence ? 24 : 1); sequence++) {
        ak_check(fmi2Reset(c) == fmi2OK &&
                     (!has_sequence || fmi2SetInteger(c, &sequence_vr, 1, &sequence) == fmi2OK),
                 "%s: set sequence", context);
        fmi2ValueReference frame_vr = 0, tolerance_vr = 0;
        if (ak_test_find_vr("frame", &frame_vr)) { /* EulerRates, AttitudePropagator */
            const fmi2Integer frame = 1 + sequence % 2;
            ak_check(fmi2SetInteger(c, &frame_vr, 1, &frame) == fmi2OK, "%s: set frame", context);
        }
        if (ak_test_find_vr("tolerance", &tolerance_vr)) { /* EulerRates */
            const fmi2Real tolerance = 0.01;
            ak_check(fmi2SetReal(c, &tolerance_vr, 1, &tolerance) == fmi2OK,
                     "%s: set tolerance", context);
        }
        fmi2Integer got = sequence;
        ak_check(ak_test_bring_to(c, AK_IN_STEP_COMPLETE) &&
                     (!has_sequence || fmi2GetInteger(c, &sequence_vr, 1, &got) == fmi2OK) &&
                     got == sequence && ak_test_outputs_consistent(c),
                 "%s: a step with that sequence", context);
    }
    ak_check(recorder.count == 0, "%s: messages logged for the 24 sequences", context);
    if (ak_test_has_singular_theta2()) {
        const fmi2ValueReference theta2 = 1;
        ak_check(fmi2Reset(c) == fmi2OK && ak_test_bring_to(c, AK_IN_STEP_COMPLETE),
                 "%s: reset", context);
        fmi2FMUstate good = NULL;
        ak_check(fmi2GetFMUstate(c, &good) == fmi2OK, "%s: get state", context);
        ak_recorder_clear(&recorder);
        const fmi2Real near = AK_TEST_SINGULAR_THETA2 - 1e-6;
        fmi2Real value = 0.0;
        ak_check(fmi2SetReal(c, &theta2, 1, &near) == fmi2OK &&
                 fmi2GetReal(c, (const fmi2ValueReference[]){9}, 1, &value) == fmi2Warning &&
                 recorder.count == 1 && recorder.messages[0].status == fmi2Warning &&
                 strstr(recorder.messages[0].text, "theta[2]") != NULL,
                 "%s: near the singularity: fmi2Warning naming theta[2]", context);
        const fmi2Real singular = AK_TEST_SINGULAR_THETA2;
        ak_recorder_clear(&recorder);
        ak_check(fmi2SetReal(c, &theta2, 1, &singular) == fmi2OK &&
                 fmi2DoStep(c, AK_TEST_STEP_COMPLETE_TIME, 0.5, fmi2True) == fmi2Discard &&
                 recorder.count == 2 && strstr(recorder.messages[0].text, "theta[2]") != NULL &&
                 recorder.messages[0].status == fmi2Discard &&
                 strstr(recorder.messages[1].text, "fmi2DoStep: the step from 1 to 1.5 is "
                                                    "discarded") != NULL,
                 "%s: at the singularity: fmi2Discard naming theta[2]", context);
        fmi2Real last = -1.0;
        fmi2Boolean terminated = fmi2True;
        ak_check(((const ak_instance *)c)->state == AK_STEP_FAILED &&
                 fmi2GetRealStatus(c, fmi2LastSuccessfulTime, &last) == fmi2OK &&
                 last == AK_TEST_STEP_COMPLETE_TIME &&
                 fmi2GetBooleanStatus(c, fmi2Terminated, &terminated) == fmi2OK &&
                 terminated == fmi2False && ak_test_outputs_consistent(c),
                 "%s: after the failed step", context);
        ak_check(fmi2SetFMUstate(c, good) == fmi2OK &&
                 fmi2DoStep(c, AK_TEST_STEP_COMPLETE_TIME, 0.5, fmi2True) == fmi2OK &&
                 ak_test_outputs_consistent(c), "%s: recovery through fmi2SetFMUstate", context);
        ak_check(fmi2FreeFMUstate(c, &good) == fmi2OK, "%s: free state", context);
    }
    fmi2FreeInstance(c);
    ak_check(ak_test_live_allocations() == 0, "%s: memory left allocated", context);
}

/* fmi2SetDebugLogging switches categories; '%' in what the FMU logs reaches the master intact. */
static void run_logging(void) {
    const char *context = "logging";
    ak_recorder recorder;
    ak_recorder_clear(&recorder);
    const fmi2CallbackFunctions functions = ak_test_callbacks(&recorder);
    const char *name = "100% sure: %s%n%d";
    fmi2Component c = ak_test_instantiate(name, &functions, true);
    if (!ak_check(c != NULL, "%s: instantiation failed", context)) {
        return;
    }
    ak_check(recorder.count == 1 &&
             strcmp(recorder.messages[0].text,
                     "fmi2Instantiate: instance \"100% sure: %s%n%d\" created") == 0 &&
             strcmp(recorder.messages[0].instance_name, name) == 0, "%s: %s", context,
             "'%' not escaped for the master's printf");
    ak_recorder_clear(&recorder);
    char trace[128];
    snprintf(trace, sizeof trace,
        "fmi2SetReal: %s = 0.10000000000000001", AK_MODEL.variables[0].name);
    ak_check(fmi2SetReal(c, AK_TEST_INPUT_VRS, 1, (const fmi2Real[]){0.1}) == fmi2OK && recorder.count == 2 &&
             strcmp(recorder.messages[1].text, trace) == 0 &&
             strcmp(recorder.messages[1].category, "logCalls") == 0,
             "%s: logCalls trace of fmi2SetReal", context);
    ak_recorder_clear(&recorder);
    ak_check(fmi2SetDebugLogging(c, fmi2False, 0, NULL) == fmi2OK, "%s: all off", context);
    ak_recorder_clear(&recorder); /* the trace of the switch itself */
    ak_check(fmi2SetReal(c, AK_TEST_INPUT_VRS, 1, (const fmi2Real[]){NAN}) == fmi2Error &&
             recorder.count == 0, "%s: a category switched off still logs", context);
    ak_check(fmi2SetDebugLogging(c, fmi2True, 1, (const fmi2String[]){"logStatusError"}) == fmi2OK,
             "%s: errors on", context);
    ak_recorder_clear(&recorder);
    ak_check(fmi2SetReal(c, AK_TEST_INPUT_VRS, 1, (const fmi2Real[]){NAN}) == fmi2Error &&
             recorder.count == 1 && strcmp(recorder.messages[0].category, "logStatusError") == 0,
             "%s: logStatusError switched on does not log", context);
    /* Any non-zero fmi2Boolean is true. */
    ak_check(fmi2SetDebugLogging(c, 7, 1, (const fmi2String[]){"logCalls"}) == fmi2OK,
             "%s: loggingOn = 7", context);
    ak_recorder_clear(&recorder);
    ak_check(fmi2SetReal(c, AK_TEST_INPUT_VRS, 1, (const fmi2Real[]){0.2}) == fmi2OK && recorder.count == 2, "%s: loggingOn = 7 did not switch logCalls on", context);
    fmi2FreeInstance(c);
    ak_check(ak_test_live_allocations() == 0, "%s: memory left allocated", context);
}

/* A master may give no logger: bad calls are still refused, silently, and nothing breaks. */
static void run_without_logger(void) {
    const char *context = "no logger";
    ak_recorder recorder;
    ak_recorder_clear(&recorder);
    fmi2CallbackFunctions functions = ak_test_callbacks(&recorder);
    functions.logger = NULL;
    fmi2Component c = ak_test_instantiate("silent", &functions, true);
    if (!ak_check(c != NULL && ak_test_bring_to(c, AK_IN_STEP_COMPLETE),
                  "%s: setup failed", context)) {
        return;
    }
    for (size_t row = 0; row < AK_N_BAD_CALLS + AK_N_MODEL_BAD_CALLS; row++) {
        const ak_bad_call *bad = row < AK_N_BAD_CALLS ? &AK_BAD_CALLS[row]
                                                      : &AK_MODEL_BAD_CALLS[row - AK_N_BAD_CALLS];
        if (bad->in == AK_IN_STEP_COMPLETE && !bad->with_fmu_state && !bad->with_setup &&
            row_applies(bad)) {
            ak_check(AK_OPS[bad->op].call(c, &bad->args) == bad->status,
                     "%s: %s", context, bad->call);
        }
    }
    ak_check(ak_test_outputs_consistent(c) && recorder.count == 0,
             "%s: after the bad calls", context);
    fmi2FreeInstance(c);
    ak_check(ak_test_live_allocations() == 0, "%s: memory left allocated", context);
}

/* Version and platform strings, needing no instance. */
static void run_instance_free_functions(void) {
    ak_check(strcmp(fmi2GetVersion(), "2.0") == 0, "%s: %s", "fmi2GetVersion", "not 2.0");
    ak_check(strcmp(fmi2GetTypesPlatform(), "default") == 0,
             "%s: %s", "fmi2GetTypesPlatform", "not default");
}

int main(int argc, char **argv) {
    const bool print_table = argc > 1 && strcmp(argv[1], "--table") == 0;
    if (print_table) {
        printf("| State | Call | Status | Message logged |\n|---|---|---|---|\n");
    }
    int n_states = 0;
    for (int s = 0; s < AK_TEST_N_STATES; s++) {
        n_states += ak_test_state_reachable(AK_TEST_STATES[s]);
    }
    run_bad_instantiates(print_table);
    const size_t n_bad_calls = run_bad_calls(print_table);
    const bool null_ok = run_null_instance();
    const bool matrix_ok = run_state_matrix();
    if (print_table && null_ok) {
        print_row("(none)",
                  "any function but fmi2Instantiate with c = NULL (fmi2FreeInstance returns "
                  "nothing)",
                  "fmi2Error", NULL);
    }
    if (print_table && matrix_ok) {
        print_row("any", "any function in a state where FMI 2.0 forbids it", "fmi2Error",
                  "<function>: illegal call in state <state>");
    }
    run_legal_sequences();
    run_model_exchange();
    run_fmu_state(0);
    run_fmu_state(AK_ME);
    run_model_specific();
    run_logging();
    run_without_logger();
    run_instance_free_functions();
    fprintf(print_table ? stderr : stdout,
            "test_fmi2_calls (%s): %d checks, %d failures (%zu bad calls, %zu bad "
            "instantiations, %d functions x %d states)\n",
            AK_MODEL.model_identifier, ak_check_count(), ak_check_failures(), n_bad_calls,
            AK_N_BAD_INSTANTIATES, (int)AK_N_OPS, n_states);
    return ak_check_exit_status();
}
