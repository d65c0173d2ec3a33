/* One FMU instance: everything an instance owns lives here, nothing in globals, so any
 * number of instances can live side by side. */
#ifndef ANGULAR_KINEMATICS_FMI2_INSTANCE_H
#define ANGULAR_KINEMATICS_FMI2_INSTANCE_H

#include <stdbool.h>

#include "fmi2Functions.h"
#include "model_variables.h"

/* The FMI 2.0 co-simulation states, one bit each so that a set of them is a mask.
 * StepInProgress and StepCanceled belong to asynchronous stepping, which this FMU does not
 * offer; they appear in the masks to keep the table the standard's. */
typedef enum {
    AK_STATE_INSTANTIATED = 1 << 0,
    AK_STATE_INITIALIZATION_MODE = 1 << 1,
    AK_STATE_STEP_COMPLETE = 1 << 2,
    AK_STATE_STEP_IN_PROGRESS = 1 << 3,
    AK_STATE_STEP_FAILED = 1 << 4,
    AK_STATE_STEP_CANCELED = 1 << 5,
    AK_STATE_TERMINATED = 1 << 6
} ak_state;

/* Log categories, in the order of <LogCategories> in modelDescription.xml. */
typedef enum {
    AK_LOG_ERROR,   /* logStatusError: every call that returns fmi2Error */
    AK_LOG_WARNING, /* logStatusWarning: calls that return fmi2Warning or fmi2Discard */
    AK_LOG_CALLS,   /* logCalls: every FMI call with its arguments, and every evaluation */
    AK_N_LOG_CATEGORIES
} ak_log_category;

typedef struct {
    fmi2CallbackFunctions functions; /* a copy: the master's struct need not outlive the call */
    char *instance_name;
    bool logging_on_at_instantiation;
    bool log_enabled[AK_N_LOG_CATEGORIES];

    ak_state state;
    double time;
    bool stop_time_defined;
    double stop_time;

    /* All variable values, indexed by value reference. */
    double values[AK_N_VARIABLES];
    /* True when an input changed since the outputs were last computed. */
    bool outputs_stale;
    /* How many times the core ran; reported in the logCalls trace. */
    unsigned long evaluations;
} ak_instance;

/* Puts the instance in its just-instantiated condition (used by fmi2Instantiate and fmi2Reset). */
void ak_instance_reset(ak_instance *instance);

/* Brings the outputs up to date with the inputs, running the core only if an input changed. */
void ak_instance_update_outputs(ak_instance *instance);

#endif
