/* The FMI 3.0 model-exchange and co-simulation state machines as one table: for each FMI 3
 * function that takes an instance, the mask of the states it may be called in and the
 * interfaces it belongs to. The functions of what the models do not have (clocks, intervals,
 * shifts, configuration mode, scheduled execution) are refused whatever the state
 * (fmi3_unsupported.c) and are not in the table. */
#ifndef ANGULAR_KINEMATICS_FMI3_STATE_MACHINE_H
#define ANGULAR_KINEMATICS_FMI3_STATE_MACHINE_H

#include <stdbool.h>

#include "fmi3_instance.h"
#include "fmi3_logging.h"

typedef enum {
    AK3_SET_DEBUG_LOGGING,
    AK3_FREE_INSTANCE,
    AK3_ENTER_INITIALIZATION_MODE,
    AK3_EXIT_INITIALIZATION_MODE,
    AK3_ENTER_EVENT_MODE,
    AK3_TERMINATE,
    AK3_RESET,
    AK3_GET_FLOAT32,
    AK3_GET_FLOAT64,
    AK3_GET_INT8,
    AK3_GET_UINT8,
    AK3_GET_INT16,
    AK3_GET_UINT16,
    AK3_GET_INT32,
    AK3_GET_UINT32,
    AK3_GET_INT64,
    AK3_GET_UINT64,
    AK3_GET_BOOLEAN,
    AK3_GET_STRING,
    AK3_GET_BINARY,
    AK3_SET_FLOAT32,
    AK3_SET_FLOAT64,
    AK3_SET_INT8,
    AK3_SET_UINT8,
    AK3_SET_INT16,
    AK3_SET_UINT16,
    AK3_SET_INT32,
    AK3_SET_UINT32,
    AK3_SET_INT64,
    AK3_SET_UINT64,
    AK3_SET_BOOLEAN,
    AK3_SET_STRING,
    AK3_SET_BINARY,
    AK3_GET_NUMBER_OF_VARIABLE_DEPENDENCIES,
    AK3_GET_VARIABLE_DEPENDENCIES,
    AK3_GET_FMU_STATE,
    AK3_SET_FMU_STATE,
    AK3_FREE_FMU_STATE,
    AK3_SERIALIZED_FMU_STATE_SIZE,
    AK3_SERIALIZE_FMU_STATE,
    AK3_DESERIALIZE_FMU_STATE,
    AK3_GET_DIRECTIONAL_DERIVATIVE,
    AK3_GET_ADJOINT_DERIVATIVE,
    AK3_UPDATE_DISCRETE_STATES,
    AK3_ENTER_CONTINUOUS_TIME_MODE,
    AK3_COMPLETED_INTEGRATOR_STEP,
    AK3_SET_TIME,
    AK3_SET_CONTINUOUS_STATES,
    AK3_GET_CONTINUOUS_STATE_DERIVATIVES,
    AK3_GET_EVENT_INDICATORS,
    AK3_GET_CONTINUOUS_STATES,
    AK3_GET_NOMINALS_OF_CONTINUOUS_STATES,
    AK3_GET_NUMBER_OF_EVENT_INDICATORS,
    AK3_GET_NUMBER_OF_CONTINUOUS_STATES,
    AK3_ENTER_STEP_MODE,
    AK3_GET_OUTPUT_DERIVATIVES,
    AK3_DO_STEP,
    AK3_N_FUNCTIONS
} ak3_function;

enum { AK3_INTERFACE_ME = 1 << 0, AK3_INTERFACE_CS = 1 << 1 };

typedef struct {
    const char *name;
    unsigned int allowed_states;
    unsigned int interfaces;
} ak3_function_rule;

extern const ak3_function_rule AK3_FUNCTION_RULES[AK3_N_FUNCTIONS];

static inline const char *ak3_function_name(ak3_function function) {
    return AK3_FUNCTION_RULES[function].name;
}

const char *ak3_state_name(ak3_state state);

/* The full check, out of line: logs a refused call, traces a legal one in logCalls. */
bool ak3_call_checked(const ak3_instance *instance, ak3_function function);

/* The check at the top of every entry point taking an instance: false for NULL (nothing can be
 * logged), a function of the other interface, or a state the function is not allowed in (both
 * logged). Inline so that a legal call with the trace off costs two mask tests. */
static inline bool ak3_call_allowed(const ak3_instance *instance, ak3_function function) {
    if (instance != NULL) {
        const ak3_function_rule *rule = &AK3_FUNCTION_RULES[function];
        const unsigned int interface =
            instance->interface == AK3_MODEL_EXCHANGE ? AK3_INTERFACE_ME : AK3_INTERFACE_CS;
        if ((rule->allowed_states & (unsigned int)instance->state) != 0 &&
            (rule->interfaces & interface) != 0 && !ak3_log_on(instance, AK_LOG_CALLS)) {
            return true;
        }
    }
    return ak3_call_checked(instance, function);
}

#endif
