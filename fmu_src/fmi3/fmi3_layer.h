/* The FMI 3.0 layer over the runtime: it knows AK_MODEL and the array table, no variable. */
#ifndef ANGULAR_KINEMATICS_FMI3_LAYER_H
#define ANGULAR_KINEMATICS_FMI3_LAYER_H

#include "fmi3Functions.h"
#include "runtime.h"

/* An FMI 3 array is one variable, named by its first element's value reference; row-major. */
typedef struct {
    const char *name;       /* NULL: no variable has this value reference */
    unsigned int first_vr;
    unsigned int n_elements;
    unsigned int n_dimensions; /* 0 scalar, 1 vector, 2 matrix */
} ak3_array;

/* Generated per model: the array holding each value reference. */
extern const ak3_array AK3_ARRAYS[AK_MAX_VARIABLES];
/* Time is not in the value array: it is answered from the instance's time. */
extern const unsigned int AK3_TIME_VALUE_REFERENCE;

/* The array whose FMI 3 value reference is vr, or NULL (unknown, or not a first element). */
static inline const ak3_array *ak3_array_of(unsigned int vr) {
    if (vr >= (unsigned int)AK_MODEL.n_value_references || AK3_ARRAYS[vr].name == NULL ||
        AK3_ARRAYS[vr].first_vr != vr) {
        return NULL;
    }
    return &AK3_ARRAYS[vr];
}

typedef enum {
    AK3_SET_DEBUG_LOGGING,
    AK3_FREE_INSTANCE,
    AK3_ENTER_INITIALIZATION_MODE,
    AK3_EXIT_INITIALIZATION_MODE,
    AK3_ENTER_EVENT_MODE,
    AK3_TERMINATE,
    AK3_RESET,
    AK3_GET_FLOAT64,
    AK3_GET_INT64,
    AK3_SET_FLOAT64,
    AK3_SET_INT64,
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

extern const ak_function_rule FMI3_RULES[AK3_N_FUNCTIONS];
extern const ak_layer FMI3_LAYER;

/* The importer's logger (log_message NULL: none). */
typedef struct {
    fmi3InstanceEnvironment environment;
    fmi3LogMessageCallback log_message;
} fmi3_logger;

/* FMI 3 gives no memory callbacks: the instance is on the C heap. */
typedef struct {
    ak_instance base; /* first: an fmi3Instance is also an ak_instance */
    fmi3_logger logger;
} fmi3_instance;

static inline bool fmi3_allowed(const ak_instance *instance, ak3_function function) {
    return ak_call_allowed(instance, &FMI3_RULES[function]);
}

static inline const char *fmi3_name(ak3_function function) {
    return FMI3_RULES[function].name;
}

_Static_assert((int)AK_STATUS_ERROR == (int)fmi3Error && (int)AK_STATUS_DISCARD == (int)fmi3Discard,
               "ak_status follows fmi3Status");
static inline fmi3Status fmi3_status(ak_status status) {
    return (fmi3Status)status;
}

bool ak3_count_matches(const ak_instance *instance, const char *function, const char *count_name,
                       size_t n, size_t total, const unsigned int vr[], size_t n_vr);

#endif
