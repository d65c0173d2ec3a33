/* The bad-input table: every kind of bad input and illegal call, the status it gets and the
 * message it logs. docs/bad_input.md shows this table; test_fmi2_calls proves each row and prints
 * the table as it observed it, and tests/test_bad_input_table.py compares that with the document. */
#ifndef ANGULAR_KINEMATICS_FMI2_BAD_INPUT_TABLE_H
#define ANGULAR_KINEMATICS_FMI2_BAD_INPUT_TABLE_H

#include <stdbool.h>
#include <stddef.h>

#include "fmi2Functions.h"
#include "fmi2_test_ops.h"

/* A bad call on an instance brought to state `in` (one of the AK_IN_ states, with AK_ME for a
 * model-exchange instance). */
/* In call and message, the driver replaces @PAST@ with the model's number of value references (the
 * first one past its last), @LAST@ with its last value reference, @STATE_BYTES@ with the size of
 * its FMU state, 92 + 8 N + 16 I, and @MODEL@ with its model identifier: a row stays true when a
 * variable is added, and serves every model. */
typedef struct {
    unsigned int in;
    const char *call; /* the call as the document shows it; c is the instance */
    ak_op_id op;
    ak_args args;
    fmi2Status status;
    const char *message; /* exactly what the master's logger receives */
    /* The driver first takes an FMU state of the instance (fmi2GetFMUstate) and passes it as
     * args.state; it frees it after the call. */
    bool with_fmu_state;
    /* Rows of the common table that hold for a model without continuous states only (the
     * driver leaves them out for a model with states, whose own table has their kind). */
    bool without_states_only;
    /* A legal call made on the instance once in state `in`, before the bad one (the call text
     * shows both, separated by "; "); with_setup false: none. */
    bool with_setup;
    ak_op_id setup_op;
    ak_args setup_args;
    /* The status `message` is logged with when it is not the status the call returns
     * (fmi2OK: it is that status). */
    fmi2Status message_status;
    /* A second message the bad call logs after `message` (NULL: only one), and its status. */
    const char *message2;
    fmi2Status status2;
} ak_bad_call;

/* What a master can hand fmi2Instantiate. */
typedef enum {
    AK_GOOD_CALLBACKS,
    AK_NULL_CALLBACKS,           /* functions == NULL */
    AK_CALLBACKS_WITHOUT_MEMORY, /* allocateMemory and freeMemory NULL */
    AK_CALLBACKS_WITHOUT_LOGGER, /* logger NULL: nothing can be said */
} ak_callbacks_choice;

/* A bad fmi2Instantiate call: it returns NULL. */
/* In ak_bad_instantiate.guid: the GUID of the model the program is built for. */
extern const char AK_THIS_GUID[];

typedef struct {
    const char *call;
    fmi2String instance_name;
    int fmu_type;
    fmi2String guid;
    ak_callbacks_choice callbacks;
    long allocations_before_failure; /* negative: memory never runs out */
    long failing_allocations;        /* then this many fail (negative: all the following) */
    /* NULL: nothing can be logged. Ends with the model's GUID and `" of this FMU's binary` when
     * guid_in_message is set (the rest is given here). */
    const char *message;
    bool guid_in_message;
} ak_bad_instantiate;

/* The rows every model has (fmi2_bad_input_table.c) and the model's own rows
 * (fmi2_bad_input_<model>.c: value references, variable names, parameters, capabilities). */
extern const ak_bad_call AK_BAD_CALLS[];
extern const size_t AK_N_BAD_CALLS;
extern const ak_bad_call AK_MODEL_BAD_CALLS[];
extern const size_t AK_N_MODEL_BAD_CALLS;
extern const ak_bad_instantiate AK_BAD_INSTANTIATES[];
extern const size_t AK_N_BAD_INSTANTIATES;

#endif
