/* The FMI 2.0 co-simulation and model-exchange state machines as one table: for each FMI
 * function, the mask of the states in which it may be called and the interfaces it belongs to. */
#ifndef ANGULAR_KINEMATICS_FMI2_STATE_MACHINE_H
#define ANGULAR_KINEMATICS_FMI2_STATE_MACHINE_H

#include <stdbool.h>

#include "fmi2_instance.h"

typedef enum {
    AK_FMI2_SET_DEBUG_LOGGING,
    AK_FMI2_FREE_INSTANCE,
    AK_FMI2_SETUP_EXPERIMENT,
    AK_FMI2_ENTER_INITIALIZATION_MODE,
    AK_FMI2_EXIT_INITIALIZATION_MODE,
    AK_FMI2_TERMINATE,
    AK_FMI2_RESET,
    AK_FMI2_GET_REAL,
    AK_FMI2_GET_INTEGER,
    AK_FMI2_GET_BOOLEAN,
    AK_FMI2_GET_STRING,
    AK_FMI2_SET_REAL,
    AK_FMI2_SET_INTEGER,
    AK_FMI2_SET_BOOLEAN,
    AK_FMI2_SET_STRING,
    AK_FMI2_GET_FMU_STATE,
    AK_FMI2_SET_FMU_STATE,
    AK_FMI2_FREE_FMU_STATE,
    AK_FMI2_SERIALIZED_FMU_STATE_SIZE,
    AK_FMI2_SERIALIZE_FMU_STATE,
    AK_FMI2_DE_SERIALIZE_FMU_STATE,
    AK_FMI2_GET_DIRECTIONAL_DERIVATIVE,
    AK_FMI2_SET_REAL_INPUT_DERIVATIVES,
    AK_FMI2_GET_REAL_OUTPUT_DERIVATIVES,
    AK_FMI2_DO_STEP,
    AK_FMI2_CANCEL_STEP,
    AK_FMI2_GET_STATUS,
    AK_FMI2_GET_REAL_STATUS,
    AK_FMI2_GET_INTEGER_STATUS,
    AK_FMI2_GET_BOOLEAN_STATUS,
    AK_FMI2_GET_STRING_STATUS,
    AK_FMI2_ENTER_EVENT_MODE,
    AK_FMI2_NEW_DISCRETE_STATES,
    AK_FMI2_ENTER_CONTINUOUS_TIME_MODE,
    AK_FMI2_COMPLETED_INTEGRATOR_STEP,
    AK_FMI2_SET_TIME,
    AK_FMI2_SET_CONTINUOUS_STATES,
    AK_FMI2_GET_DERIVATIVES,
    AK_FMI2_GET_EVENT_INDICATORS,
    AK_FMI2_GET_CONTINUOUS_STATES,
    AK_FMI2_GET_NOMINALS_OF_CONTINUOUS_STATES,
    AK_N_FMI2_FUNCTIONS
} ak_function;

const char *ak_function_name(ak_function function);

/* The check at the top of every entry point taking an instance: false for a NULL instance
 * (nothing can be logged then), a function of the other interface (a co-simulation function
 * called on a model-exchange instance or the reverse), or a state the function is not allowed
 * in; the last two are logged as errors naming the function and the interface or state. A legal
 * call is traced in logCalls. */
bool ak_call_allowed(const ak_instance *instance, ak_function function);

const char *ak_state_name(ak_state state);

#endif
