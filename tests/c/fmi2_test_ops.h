/* One "op" per FMI 2.0 function taking an instance: a name, the states in which the standard
 * allows it, the types of its value arrays, and an adapter that calls it with its arguments taken
 * from one generic argument record. The table-driven call tests (test_fmi2_calls.c) and the fuzz
 * harness (fuzz_fmi2.c) both drive the FMU through this table, so covering a new function takes
 * one enum value, one adapter and one table row here. */
#ifndef ANGULAR_KINEMATICS_FMI2_TEST_OPS_H
#define ANGULAR_KINEMATICS_FMI2_TEST_OPS_H

#include <stdbool.h>
#include <stddef.h>

#include "fmi2Functions.h"

/* The co-simulation and model-exchange states as the standard names them, one bit each. */
enum {
    AK_IN_INSTANTIATED = 1 << 0,
    AK_IN_INITIALIZATION_MODE = 1 << 1,
    AK_IN_STEP_COMPLETE = 1 << 2,
    AK_IN_STEP_IN_PROGRESS = 1 << 3,
    AK_IN_STEP_FAILED = 1 << 4,
    AK_IN_STEP_CANCELED = 1 << 5,
    AK_IN_TERMINATED = 1 << 6,
    AK_IN_EVENT_MODE = 1 << 7,
    AK_IN_CONTINUOUS_TIME_MODE = 1 << 8,
    AK_IN_ANY = 0x1ff,
    /* Not a state: added to a state, it means "of an instance created for model exchange" (in
     * the bad-input table and ak_test_bring_to). */
    AK_ME = 1 << 9
};

/* The interfaces a function belongs to. */
enum { AK_FOR_CS = 1 << 0, AK_FOR_ME = 1 << 1, AK_FOR_BOTH = AK_FOR_CS | AK_FOR_ME };

typedef enum {
    AK_OP_SET_DEBUG_LOGGING,
    AK_OP_SETUP_EXPERIMENT,
    AK_OP_ENTER_INITIALIZATION_MODE,
    AK_OP_EXIT_INITIALIZATION_MODE,
    AK_OP_TERMINATE,
    AK_OP_RESET,
    AK_OP_GET_REAL,
    AK_OP_GET_INTEGER,
    AK_OP_GET_BOOLEAN,
    AK_OP_GET_STRING,
    AK_OP_SET_REAL,
    AK_OP_SET_INTEGER,
    AK_OP_SET_BOOLEAN,
    AK_OP_SET_STRING,
    AK_OP_GET_FMU_STATE,
    AK_OP_SET_FMU_STATE,
    AK_OP_FREE_FMU_STATE,
    AK_OP_SERIALIZED_FMU_STATE_SIZE,
    AK_OP_SERIALIZE_FMU_STATE,
    AK_OP_DE_SERIALIZE_FMU_STATE,
    AK_OP_GET_DIRECTIONAL_DERIVATIVE,
    AK_OP_SET_REAL_INPUT_DERIVATIVES,
    AK_OP_GET_REAL_OUTPUT_DERIVATIVES,
    AK_OP_DO_STEP,
    AK_OP_CANCEL_STEP,
    AK_OP_GET_STATUS,
    AK_OP_GET_REAL_STATUS,
    AK_OP_GET_INTEGER_STATUS,
    AK_OP_GET_BOOLEAN_STATUS,
    AK_OP_GET_STRING_STATUS,
    AK_OP_ENTER_EVENT_MODE,
    AK_OP_NEW_DISCRETE_STATES,
    AK_OP_ENTER_CONTINUOUS_TIME_MODE,
    AK_OP_COMPLETED_INTEGRATOR_STEP,
    AK_OP_SET_TIME,
    AK_OP_SET_CONTINUOUS_STATES,
    AK_OP_GET_DERIVATIVES,
    AK_OP_GET_EVENT_INDICATORS,
    AK_OP_GET_CONTINUOUS_STATES,
    AK_OP_GET_NOMINALS_OF_CONTINUOUS_STATES,
    AK_OP_FREE_INSTANCE, /* last: after it the instance is gone */
    AK_N_OPS
} ak_op_id;

/* The element type of a value array, so that a caller can size it exactly. */
typedef enum {
    AK_NO_VALUES,
    AK_REAL_VALUES,
    AK_INTEGER_VALUES,
    AK_BOOLEAN_VALUES,
    AK_STRING_VALUES
} ak_value_type;

/* Every argument any op takes; each adapter documents which fields it uses. Arrays may be NULL
 * and are meant to hold exactly the count given with them. */
typedef struct {
    const fmi2ValueReference *vr; /* vr[] / vUnknown_ref[] */
    size_t nvr;                   /* nvr / nUnknown */
    const fmi2ValueReference *vr2; /* vKnown_ref[] */
    size_t nvr2;                   /* nKnown */
    void *values;        /* value[] of the getters and setters, nvr of the op's values type */
    void *values2;       /* order[] / dvUnknown[], nvr of the op's values2 type; also x[] of
                            the model-exchange functions, nvr Reals */
    fmi2Real *known;     /* dvKnown[], nvr2 Reals */
    const fmi2String *categories; /* fmi2SetDebugLogging */
    size_t n_categories;
    fmi2Byte *bytes;     /* serialized FMU state */
    size_t n_bytes;
    fmi2Real real[3];    /* tolerance, startTime, stopTime / currentCommunicationPoint, stepSize
                            / time of fmi2SetTime */
    fmi2Boolean flag[3]; /* toleranceDefined, stopTimeDefined / loggingOn / noSetFMUStatePrior... */
    int kind;            /* fmi2StatusKind */
    fmi2FMUstate state;  /* an FMU state handed to the FMU */
    void *out;           /* where a single result goes: status value, size, FMUstate */
    void *out2;          /* a second result (fmi2CompletedIntegratorStep has two) */
} ak_args;

/* Room for any single result an op writes through ak_args.out. */
typedef union {
    fmi2Status status;
    fmi2Real real;
    fmi2Integer integer;
    fmi2Boolean boolean;
    fmi2String string;
    fmi2FMUstate state;
    size_t size;
    fmi2EventInfo event_info; /* fmi2NewDiscreteStates */
} ak_result;

typedef struct {
    const char *name;
    unsigned int allowed_in; /* the standard's tables (FMI 2.0.4, sections 3.2.3 and 4.2.4),
                                restated */
    unsigned int interfaces; /* AK_FOR_CS, AK_FOR_ME or both */
    ak_value_type values_type;
    ak_value_type values2_type;
    fmi2Status (*call)(fmi2Component c, const ak_args *a);
    /* ak_args.out is an fmi2FMUstate* the master keeps (get, free, deserialize an FMU state);
     * otherwise it is an ak_result*. */
    bool out_is_fmu_state;
} ak_op;

extern const ak_op AK_OPS[AK_N_OPS];

const char *ak_status_name(fmi2Status status);

#endif
