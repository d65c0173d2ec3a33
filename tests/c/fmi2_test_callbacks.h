/* Callbacks a test gives the FMU, playing the master's part: a logger that formats and keeps the
 * messages, and an allocator that counts what is live and can be told to fail. */
#ifndef ANGULAR_KINEMATICS_FMI2_TEST_CALLBACKS_H
#define ANGULAR_KINEMATICS_FMI2_TEST_CALLBACKS_H

#include <stdbool.h>
#include <stddef.h>

#include "fmi2Functions.h"

enum { AK_RECORDED_MESSAGES = 8, AK_RECORDED_MESSAGE_SIZE = 2048 };

typedef struct {
    fmi2Status status;
    char category[32];
    char instance_name[64];
    char text[AK_RECORDED_MESSAGE_SIZE];
} ak_recorded_message;

/* One per test context (per thread): the logger's componentEnvironment points to it. */
typedef struct {
    ak_recorded_message messages[AK_RECORDED_MESSAGES]; /* the first ones since the last clear */
    size_t count;                                       /* all of them, kept or not */
    size_t contract_violations; /* NULL strings, unknown status or category from the FMU */
} ak_recorder;

/* The callbacks a well-behaved master gives: recording logger, counting allocator. */
fmi2CallbackFunctions ak_test_callbacks(ak_recorder *recorder);

void ak_recorder_clear(ak_recorder *recorder);

/* Allocations made through the counting allocator and not yet freed, in all threads. */
long ak_test_live_allocations(void);
/* Allocations ever made through it, in all threads. */
long ak_test_total_allocations(void);
/* The calling thread's next `successes` allocations succeed, then `failures` fail (a negative
 * count: all the following ones), then they succeed again. ak_test_fail_allocations(-1, 0):
 * never fail. */
void ak_test_fail_allocations(long successes, long failures);

#endif
