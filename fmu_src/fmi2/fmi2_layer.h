/* The FMI 2.0 layer over the runtime: the function names, the state table and the instance. */
#ifndef ANGULAR_KINEMATICS_FMI2_LAYER_H
#define ANGULAR_KINEMATICS_FMI2_LAYER_H

#include "fmi2Functions.h"
#include "runtime.h"

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
} ak_fmi2_function;

extern const ak_function_rule FMI2_RULES[AK_N_FMI2_FUNCTIONS];

/* A copy of the master's callbacks: they need not outlive fmi2Instantiate. */
typedef struct {
    ak_instance base; /* first: an fmi2Component is also an ak_instance */
    fmi2CallbackFunctions functions;
} fmi2_instance;

static inline bool fmi2_allowed(const ak_instance *instance, ak_fmi2_function function) {
    return ak_call_allowed(instance, &FMI2_RULES[function]);
}

static inline const char *fmi2_name(ak_fmi2_function function) {
    return FMI2_RULES[function].name;
}

_Static_assert((int)AK_STATUS_ERROR == (int)fmi2Error && (int)AK_STATUS_DISCARD == (int)fmi2Discard,
               "ak_status follows fmi2Status");
static inline fmi2Status fmi2_status(ak_status status) {
    return (fmi2Status)status;
}

#endif
