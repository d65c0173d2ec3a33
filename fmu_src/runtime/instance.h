/* One FMU instance, whichever FMI version made it: nothing in globals, so any number live side by
 * side. A layer embeds it as its instance's first member and describes itself as data. */
#ifndef ANGULAR_KINEMATICS_RUNTIME_INSTANCE_H
#define ANGULAR_KINEMATICS_RUNTIME_INSTANCE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "ak_compiler.h"
#include "model.h"

/* The states of FMI 2 and 3, one bit each so that a set is a mask; StepMode is FMI 2's
 * StepComplete. States no instance enters are here to keep the tables the standards'. */
typedef enum {
    AK_INSTANTIATED = 1 << 0,
    AK_CONFIGURATION_MODE = 1 << 1,
    AK_INITIALIZATION_MODE = 1 << 2,
    AK_EVENT_MODE = 1 << 3,
    AK_STEP_MODE = 1 << 4,
    AK_CONTINUOUS_TIME_MODE = 1 << 5,
    AK_RECONFIGURATION_MODE = 1 << 6,
    AK_TERMINATED = 1 << 7,
    AK_STEP_IN_PROGRESS = 1 << 8,
    AK_STEP_FAILED = 1 << 9,
    AK_STEP_CANCELED = 1 << 10
} ak_state;
enum { AK_N_STATES = 11 };

typedef enum { AK_MODEL_EXCHANGE = 1 << 0, AK_CO_SIMULATION = 1 << 1 } ak_interface;

typedef struct {
    const char *name;
    unsigned int allowed_states;
    unsigned int interfaces;
} ak_function_rule;

/* A layer's FMU-state format (fmu_states.c); the strings are words of its messages. */
typedef struct {
    const char *magic; /* 8 characters */
    uint32_t version;
    const char *kind;           /* "FMU state", "FMI 3 FMU state" */
    const char *token_name;     /* "GUID", "instantiationToken" */
    const char *interface_name; /* "fmuType", "interface" */
    const char *kind_argument;  /* "FMUstate" */
    const char *getter;         /* "fmi2GetFMUstate" */
    const char *deserializer;   /* "fmi2DeSerializeFMUstate" */
    const char *sizer;          /* "fmi2SerializedFMUstateSize" */
    bool input_derivatives;     /* the image holds data->input_derivatives */
} ak_state_format;

typedef struct ak_instance_s ak_instance;

typedef struct {
    const char *state_names[AK_N_STATES]; /* by bit index, in the standard's words */
    /* Why a function of the other interface is refused: [0] model exchange, [1] co-simulation. */
    const char *other_interface[2];
    const char *vr_name;
    const char *vr_count_name;
    const char *values_name;
    const char *values_count_name;
    const char *state_setter_note; /* added to the refusal of a set of a continuous state */
    ak_state step_discarded_state;
    ak_state_format state_format;
    ak_state image_states[AK_N_STATES]; /* by bit of the image's state field */
    unsigned int possible_states[2]; /* by interface, as other_interface */
    /* How many values vr names (FMI 3: an array's), 0 for none; NULL: one per variable. */
    unsigned int (*elements_at)(unsigned int vr);
    /* The independent variable's value reference, readable as a Real value; NULL: none. */
    const unsigned int *time_vr;
    void (*refuse_real)(const ak_instance *instance, const char *function, size_t index,
                        unsigned int vr, bool set);
    /* The name of vr in messages (FMI 3: its array's); NULL: the variable's. */
    const char *(*name_of)(unsigned int vr);
    /* True when n values are the total elements of vr[], else logs; NULL: one per vr (FMI 2). */
    bool (*count_matches)(const ak_instance *instance, const char *function, const char *count_name,
                          size_t n, size_t total, const unsigned int vr[], size_t n_vr);
    /* FMI 3.0.3: "error logging is always enabled unless the logMessage callback function
     * pointer is NULL"; FMI 2.0.4 logs only the enabled categories. */
    bool errors_always_logged;
    void (*send)(const ak_instance *instance, ak_log_category category, ak_status status,
                 const char *message);
    /* Zeroed memory or NULL, and its release. */
    void *(*allocate)(const ak_instance *instance, size_t size);
    void (*release)(const ak_instance *instance, void *memory);
} ak_layer;

/* A value reference's role, in increasing order of what a get must bring up to date. */
typedef enum {
    AK_REAL_ABSENT = 0, /* no Real variable has this value reference */
    AK_REAL_INPUT,
    AK_REAL_PARAMETER,
    /* Current once initialization ended (the step and the state setters write it). */
    AK_REAL_STATE_OUTPUT,
    AK_REAL_MAIN_OUTPUT,
    AK_REAL_LAZY_OUTPUT,
    AK_REAL_DERIVED_OUTPUT
} ak_real_role;

/* A get or set checked and kept: importers ask the same at every communication point. */
typedef struct {
    size_t nvr;
    size_t n_values;
    unsigned int vr[AK_MAX_VARIABLES];
    unsigned int roles; /* a get's: 1 << ak_real_role for each role read */
    bool one_run;       /* the values follow each other (a set: always, of inputs) */
} ak_kept_request;

typedef struct {
    bool stale;         /* an input or parameter changed since the main group was computed */
    bool lazy_stale;    /* the main group was computed since the lazy group was */
    bool derived_stale; /* a group was computed since the derived outputs were */
    /* On AK_EVAL_FAILED the outputs hold the last valid values, until an input changes. */
    ak_eval_status status;
    unsigned long evaluations; /* of the main group, for the logCalls trace */
} ak_outputs;

struct ak_instance_s {
    const ak_layer *layer;
    char *instance_name;
    bool has_logger;
    bool logging_on_at_instantiation;
    bool log_enabled[AK_N_LOG_CATEGORIES];

    ak_interface interface;
    ak_state state;
    double time;
    bool stop_time_defined;
    double stop_time;

    /* One byte per value reference, so that the getters and setters read no variable record. */
    unsigned char real_role[AK_MAX_VARIABLES];
    unsigned char elements[AK_MAX_VARIABLES]; /* ak_layer.elements_at */
    ak_model_data data;
    ak_outputs outputs;
    /* The FMI function prefixing the model's messages (a model never names one itself), or NULL. */
    const char *calling;
    struct ak_fmu_state_s *live_states; /* made by this instance and not yet freed */
    ak_kept_request kept_get, kept_set;
};

/* Inline: the calls of every communication point ask it before ak_log. */
static inline bool ak_log_on(const ak_instance *instance, ak_log_category category) {
    return instance->log_enabled[category];
}

/* Sends a message if its category is on or it is an error the layer always logs. */
void ak_log(const ak_instance *instance, ak_log_category category, ak_status status,
            const char *format, ...) AK_PRINTF_FORMAT(4, 5);

/* Before an instance exists (instantiation refused): the message goes to send(context, ...). */
void ak_log_without_instance(void (*send)(const void *context, const char *message),
                             const void *context, const char *format, ...) AK_PRINTF_FORMAT(3, 4);

const char *ak_state_name(const ak_instance *instance, ak_state state);

/* ak_call_allowed's full check, out of line: logs a refused call, traces a legal one. */
bool ak_call_checked(const ak_instance *instance, const ak_function_rule *rule);

/* A legal call with the trace off. Inline: two mask tests and no call; with the table a constant,
 * the compiler drops the interface test of most functions. */
static inline bool ak_call_passes(const ak_instance *instance, const ak_function_rule *rule) {
    const bool both = rule->interfaces == (AK_MODEL_EXCHANGE | AK_CO_SIMULATION);
    return instance != NULL && (rule->allowed_states & (unsigned int)instance->state) != 0 &&
           (both || (rule->interfaces & (unsigned int)instance->interface) != 0) &&
           !ak_log_on(instance, AK_LOG_CALLS);
}

/* False for NULL, a function of the other interface or a state not allowed (both logged). */
static inline bool ak_call_allowed(const ak_instance *instance, const ak_function_rule *rule) {
    return ak_call_passes(instance, rule) || ak_call_checked(instance, rule);
}

/* Logs "<function>: <pointer_name> is NULL[ with <count_name> = <n>]"; false. */
bool ak_refuse_null(const ak_instance *instance, const char *function, size_t n,
                    const char *count_name, const char *pointer_name);
/* NULL is fine only when there is nothing to read or write. */
static inline bool ak_given(const ak_instance *instance, const char *function, size_t n,
                            const char *count_name, const void *pointer,
                            const char *pointer_name) {
    return n == 0 || pointer != NULL ||
           ak_refuse_null(instance, function, n, count_name, pointer_name);
}
static inline bool ak_not_null(const ak_instance *instance, const char *function,
                               const void *pointer, const char *name) {
    return pointer != NULL || ak_refuse_null(instance, function, 0, NULL, name);
}
static AK_ALWAYS_INLINE bool ak_values_call_valid(const ak_instance *instance,
                                                  const ak_function_rule *call,
                                                  const unsigned int vr[], size_t nvr,
                                                  const void *values, size_t n_values) {
    return ak_call_allowed(instance, call) &&
           ak_given(instance, call->name, nvr, instance->layer->vr_count_name, vr,
                    instance->layer->vr_name) &&
           ak_given(instance, call->name, n_values, instance->layer->values_count_name, values,
                    instance->layer->values_name);
}

/* False when the name cannot be allocated (nothing to free then). */
bool ak_instance_start(ak_instance *instance, const ak_layer *layer, const char *function,
                       const char *name, ak_interface interface, bool has_logger, bool logging_on);

void ak_instance_reset(ak_instance *instance);

static inline ak_real_role ak_real_role_of(const ak_instance *instance, unsigned int vr) {
    return vr < AK_MAX_VARIABLES ? (ak_real_role)instance->real_role[vr] : AK_REAL_ABSENT;
}

/* Evaluates what is stale up to `upto`; DISCARD after a failed evaluation (the instance usable). */
ak_status ak_instance_update(ak_instance *instance, ak_group upto);

/* An input, state or parameter changed: one store, so that a setter pays no more. */
static inline void ak_instance_inputs_changed(ak_instance *instance) {
    instance->outputs.stale = true;
}

/* The index of vr in a model's list of states (or of state derivatives), or -1. */
int ak_state_index(const unsigned int *vrs, unsigned int vr);

#endif
