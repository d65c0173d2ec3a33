/* The master's side of the callbacks; see fmi2_test_callbacks.h. */
#include "fmi2_test_callbacks.h"

#include <stdarg.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The counters are shared by the threads of a test on purpose (a leak in any thread shows); the
 * failure countdown belongs to each thread so that threads do not disturb each other. */
static atomic_long live_allocations;
static atomic_long total_allocations;
static _Thread_local long allocations_until_failure = -1;
static _Thread_local long failures_left = 0;

static void *allocate(size_t count, size_t size) {
    if (allocations_until_failure == 0 && failures_left != 0) {
        if (failures_left > 0) {
            failures_left--;
        }
        return NULL;
    }
    if (allocations_until_failure > 0) {
        allocations_until_failure--;
    }
    void *memory = calloc(count, size);
    if (memory != NULL) {
        atomic_fetch_add(&live_allocations, 1);
        atomic_fetch_add(&total_allocations, 1);
    }
    return memory;
}

static void release(void *memory) {
    if (memory != NULL) {
        atomic_fetch_sub(&live_allocations, 1);
        free(memory);
    }
}

static bool known_category(const char *category) {
    return strcmp(category, "logStatusError") == 0 || strcmp(category, "logStatusWarning") == 0 ||
           strcmp(category, "logCalls") == 0;
}

static void copy_string(char *destination, size_t capacity, const char *source) {
    snprintf(destination, capacity, "%s", source);
}

/* Formats the message as a master does: FMI 2.0 lets it be a printf format, so the FMU must
 * have doubled every '%' it does not mean as a conversion. */
static void record(fmi2ComponentEnvironment environment, fmi2String instance_name,
                   fmi2Status status, fmi2String category, fmi2String message, ...) {
    ak_recorder *recorder = environment;
    if (instance_name == NULL || category == NULL || message == NULL ||
        (unsigned int)status > (unsigned int)fmi2Pending || !known_category(category)) {
        recorder->contract_violations++;
        return;
    }
    if (recorder->count < AK_RECORDED_MESSAGES) {
        ak_recorded_message *kept = &recorder->messages[recorder->count];
        kept->status = status;
        copy_string(kept->category, sizeof kept->category, category);
        copy_string(kept->instance_name, sizeof kept->instance_name, instance_name);
        va_list arguments;
        va_start(arguments, message);
        vsnprintf(kept->text, sizeof kept->text, message, arguments);
        va_end(arguments);
    }
    recorder->count++;
}

fmi2CallbackFunctions ak_test_callbacks(ak_recorder *recorder) {
    fmi2CallbackFunctions functions = {record, allocate, release, NULL, recorder};
    return functions;
}

void ak_recorder_clear(ak_recorder *recorder) {
    recorder->count = 0;
    recorder->contract_violations = 0;
}

long ak_test_live_allocations(void) {
    return atomic_load(&live_allocations);
}

long ak_test_total_allocations(void) {
    return atomic_load(&total_allocations);
}

void ak_test_fail_allocations(long successes, long failures) {
    allocations_until_failure = successes;
    failures_left = successes < 0 ? 0 : failures;
}
