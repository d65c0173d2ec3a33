/* The FMI 3.0 layer: the FMI 3 entry points over the runtime (runtime/runtime.h). It knows no
 * model, only the descriptor AK_MODEL and the model's generated array table (fmi3_arrays.h); what
 * it adds to the runtime is what the standard makes its own: the signatures, fmi3Status, the
 * state table (fmi3_state_machine.c), arrays (a value reference names a whole array), the
 * importer's logger, and the functions only FMI 3 has. */
#ifndef ANGULAR_KINEMATICS_FMI3_LAYER_H
#define ANGULAR_KINEMATICS_FMI3_LAYER_H

#include <stdbool.h>

#include "fmi3Functions.h"
#include "fmi3_arrays.h"
#include "runtime.h"

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

/* The allowed states and interfaces of every FMI 3 function that takes an instance
 * (fmi3_state_machine.c); the functions of what the models do not have are refused in every
 * state (fmi3_unsupported.c). */
extern const ak_function_rule FMI3_RULES[AK3_N_FUNCTIONS];
/* What the layer tells the runtime of itself (fmi3_layer.c). */
extern const ak_layer FMI3_LAYER;

/* An FMI 3 instance: the runtime's, and the importer's logger. FMI 3 gives no memory callbacks:
 * the instance is on the C heap. */
typedef struct {
    ak_instance base; /* first: an fmi3Instance is also an ak_instance */
    fmi3InstanceEnvironment environment;
    fmi3LogMessageCallback log_message;
} fmi3_instance;

static inline bool fmi3_allowed(const ak_instance *instance, ak3_function function) {
    return ak_call_allowed(instance, &FMI3_RULES[function]);
}

static inline const char *fmi3_name(ak3_function function) {
    return FMI3_RULES[function].name;
}

/* ak_status and fmi3Status number OK, Warning, Discard and Error alike. */
_Static_assert((int)AK_STATUS_ERROR == (int)fmi3Error && (int)AK_STATUS_DISCARD == (int)fmi3Discard,
               "ak_status follows fmi3Status");
static inline fmi3Status fmi3_status(ak_status status) {
    return (fmi3Status)status;
}

/* The message of an fmi3Instantiate* function that makes no instance, to the importer's logger
 * if it gave one. */
void fmi3_refuse_instantiation(fmi3InstanceEnvironment environment,
                               fmi3LogMessageCallback log_message, const char *message);

/* The array of an FMI 3 value reference (list_name[index] = vr) of the given causality, or NULL
 * after logging why not (unknown, an inner element, another causality). */
const ak3_array *ak3_array_of_causality(const ak_instance *instance, const char *function,
                                        const char *list_name, size_t index, unsigned int vr,
                                        ak_causality causality);

/* True when n, the caller's count of values, is the number of elements of the n_vr arrays
 * (total); else logs naming the function, the count and the variables. */
bool ak3_count_matches(const ak_instance *instance, const char *function, const char *count_name,
                       size_t n, size_t total, const unsigned int vr[], size_t n_vr);

/* The layer's arrays as the runtime's values (ak_layer): how many values vr names (its array's
 * elements at its first value reference, else 0), its array's name, and why it names no Real
 * value to get or set. */
unsigned int ak3_elements_at(unsigned int vr);
const char *ak3_name_of(unsigned int vr);
void ak3_refuse_real(const ak_instance *instance, const char *function, size_t index,
                     unsigned int vr, bool set);

/* The elements (scalar value references) of the arrays vr[0 .. n - 1], in order, at most
 * capacity; how many. */
size_t ak3_expand(const unsigned int vr[], size_t n, unsigned int elements[], size_t capacity);

#endif
