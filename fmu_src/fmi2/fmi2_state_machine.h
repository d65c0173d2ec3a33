/* The FMI 2.0 co-simulation and model-exchange state machines as one table: for each FMI
 * function, the mask of the states in which it may be called and the interfaces it belongs to. */
#ifndef ANGULAR_KINEMATICS_FMI2_STATE_MACHINE_H
#define ANGULAR_KINEMATICS_FMI2_STATE_MACHINE_H

#include <stdbool.h>

#include "fmi2_instance.h"
#include "fmi2_logging.h"

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

/* The interfaces a function belongs to (a mask). */
enum { AK_INTERFACE_CS = 1 << 0, AK_INTERFACE_ME = 1 << 1 };

/* For each FMI function: its name, the mask of the states it may be called in, and the
 * interfaces it belongs to (fmi2_state_machine.c). */
typedef struct {
    const char *name;
    unsigned int allowed_states;
    unsigned int interfaces;
} ak_function_rule;

extern const ak_function_rule AK_FUNCTION_RULES[AK_N_FMI2_FUNCTIONS];

/* The full check of ak_call_allowed, out of line: it diagnoses and logs a refused call and
 * traces a legal one in logCalls. */
bool ak_call_checked(const ak_instance *instance, ak_function function);

/* The check at the top of every entry point taking an instance: false for a NULL instance
 * (nothing can be logged then), a function of the other interface (a co-simulation function
 * called on a model-exchange instance or the reverse), or a state the function is not allowed
 * in; the last two are logged as errors naming the function and the interface or state. A legal
 * call is traced in logCalls. Inline, so that a legal call with the trace off costs two mask
 * tests in the caller and no call (bench/run.sh); everything else goes to ak_call_checked. */
static inline bool ak_call_allowed(const ak_instance *instance, ak_function function) {
    if (instance != NULL) {
        const ak_function_rule *rule = &AK_FUNCTION_RULES[function];
        const unsigned int interface =
            instance->fmu_type == fmi2ModelExchange ? AK_INTERFACE_ME : AK_INTERFACE_CS;
        if ((rule->allowed_states & (unsigned int)instance->state) != 0 &&
            (rule->interfaces & interface) != 0 && !ak_log_on(instance, AK_LOG_CALLS)) {
            return true;
        }
    }
    return ak_call_checked(instance, function);
}

const char *ak_state_name(ak_state state);

#endif
