/* One FMU instance as the runtime keeps it, whichever FMI version made it: everything an instance
 * owns lives here (nothing in globals, so any number of instances live side by side). An FMI
 * layer (fmi2/, fmi3/) embeds it as the first member of its own instance, which adds the
 * callbacks of its standard, and describes itself to the runtime once, as data (ak_layer): its
 * function table, its state names, its FMU-state format, how it logs and allocates. */
#ifndef ANGULAR_KINEMATICS_RUNTIME_INSTANCE_H
#define ANGULAR_KINEMATICS_RUNTIME_INSTANCE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "ak_compiler.h"
#include "model.h"
#include "outputs.h"
#include "state_image.h"

/* The states of the FMI 2 and FMI 3 state machines, one bit each so that a set of them is a mask.
 * StepMode is FMI 2's StepComplete; StepInProgress, StepFailed and StepCanceled are FMI 2's,
 * Configuration and Reconfiguration Mode FMI 3's. States no instance of these models ever enters
 * (asynchronous steps, structural parameters) are in the tables to keep them the standards'. */
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

/* The interface an instance was made for, one bit each (a function's table entry is a mask). */
typedef enum { AK_MODEL_EXCHANGE = 1 << 0, AK_CO_SIMULATION = 1 << 1 } ak_interface;

/* For each FMI function of a layer: its name, the states it may be called in, its interfaces. */
typedef struct {
    const char *name;
    unsigned int allowed_states;
    unsigned int interfaces;
} ak_function_rule;

typedef struct ak_instance_s ak_instance;

/* What an FMI layer tells the runtime of itself. */
typedef struct {
    /* The names of the states (ak_state), by bit index, in the standard's words. */
    const char *state_names[AK_N_STATES];
    /* Why a function of the other interface is refused, by the instance's interface
     * ([0] model exchange, [1] co-simulation): follows "<function>: ". */
    const char *other_interface[2];
    /* The names of the value-reference array, its count and the value array in messages: "vr",
     * "nvr", "value"; "valueReferences", "nValueReferences", "values". */
    const char *vr_name;
    const char *vr_count_name;
    const char *values_name;
    /* The name of the count of values: "nvr" (one value per value reference), "nValues". */
    const char *values_count_name;
    /* Added to the refusal of a set of a continuous state: where states are set. */
    const char *state_setter_note;
    /* The state an instance is in after a discarded step (FMI 2 StepFailed; FMI 3 stays in Step
     * Mode). */
    ak_state step_discarded_state;
    /* The FMU state's byte image: its format, and for each bit of the image's state field the
     * state it stands for (the image keeps the layer's numbering of earlier releases). */
    ak_state_format state_format;
    ak_state image_states[AK_N_STATES];
    /* The states an instance of each interface can be in ([0] model exchange, [1] co-simulation). */
    unsigned int possible_states[2];
    /* How many consecutive values the value reference vr names (FMI 3: an array's, at its first
     * element), 0 for none; NULL: one value per variable (FMI 2). */
    unsigned int (*elements_at)(unsigned int vr);
    /* The independent variable's value reference (at or past AK_MAX_VARIABLES), readable as a
     * Real value; NULL: none. */
    const unsigned int *time_vr;
    /* Logs why vr (vr_name[index]) names no Real value a get, or a set, can read or write. */
    void (*refuse_real)(const ak_instance *instance, const char *function, size_t index,
                        unsigned int vr, bool set);
    /* The name of the variable vr names, in messages (FMI 3: its array's); NULL: the variable's. */
    const char *(*name_of)(unsigned int vr);
    /* True when n values (count_name) are the total elements of vr[0 .. n_vr - 1], else logs;
     * NULL when the count is that of the value references (FMI 2). */
    bool (*count_matches)(const ak_instance *instance, const char *function, const char *count_name,
                          size_t n, size_t total, const unsigned int vr[], size_t n_vr);
    /* True when an error reaches the importer's logger whatever loggingOn and the categories
     * say (FMI 3.0.3, 2_2: "error logging is always enabled unless the logMessage callback
     * function pointer is NULL"); FMI 2.0.4 asks only for the enabled categories. */
    bool errors_always_logged;
    /* Sends a fully formatted message through the importer's logger (there is one). */
    void (*send)(const ak_instance *instance, ak_log_category category, ak_status status,
                 const char *message);
    /* Memory for the instance's name and FMU states: zeroed, or NULL; and its release. */
    void *(*allocate)(const ak_instance *instance, size_t size);
    void (*release)(const ak_instance *instance, void *memory);
} ak_layer;

/* What a get or set of a Real value reference involves, in increasing order of what a get must
 * bring up to date. */
typedef enum {
    AK_REAL_ABSENT = 0, /* no Real variable has this value reference */
    AK_REAL_INPUT,
    AK_REAL_PARAMETER,
    /* A continuous state that is an output: always current once initialization ended (the step
     * and the state setters write it), so a get evaluates only before that. */
    AK_REAL_STATE_OUTPUT,
    AK_REAL_MAIN_OUTPUT,
    AK_REAL_LAZY_OUTPUT,
    AK_REAL_DERIVED_OUTPUT
} ak_real_role;

/* A get or set checked and kept (values.c): importers ask the same at every communication point.
 * nvr 0: none. */
typedef struct {
    size_t nvr;
    size_t n_values;
    unsigned int vr[AK_MAX_VARIABLES];
    unsigned int roles; /* a get's: 1 << ak_real_role for each role read */
    bool one_run;       /* the values follow each other (a set: always, of inputs) */
} ak_kept_request;

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

    /* The role of each value reference, from the model's variable table: the getters and
     * setters read one byte per value instead of a variable's record. */
    unsigned char real_role[AK_MAX_VARIABLES];
    /* How many consecutive values each value reference names in the layer's calls
     * (ak_layer.elements_at); 0: none. */
    unsigned char elements[AK_MAX_VARIABLES];
    /* Values by value reference, input derivatives and the logger, as the model sees them. */
    ak_model_data data;
    /* When the outputs are computed (outputs.h); after a failed evaluation a read answers
     * Discard until an input changes. */
    ak_outputs outputs;
    /* The FMI function whose name prefixes the model's messages, while it runs one that logs
     * (output derivatives); NULL otherwise: a model never names an FMI function itself. */
    const char *calling;
    /* FMU states made by this instance and not yet freed (fmu_states.c). */
    struct ak_fmu_state_s *live_states;
    ak_kept_request kept_get, kept_set;
};

/* True when a message of this category reaches the importer (a category is never on without a
 * logger). Inline: the calls of every communication point ask it before ak_log, and pay a load
 * and a branch with the trace off. */
static inline bool ak_log_on(const ak_instance *instance, ak_log_category category) {
    return instance->log_enabled[category];
}

/* Formats a message and sends it through the layer, if the category is on or it is an error
 * the layer always logs. */
void ak_log(const ak_instance *instance, ak_log_category category, ak_status status,
            const char *format, ...) AK_PRINTF_FORMAT(4, 5);

/* Before an instance exists (instantiation refused): formats the message and hands it to
 * send(context, message), the layer's way to reach the importer's logger. */
void ak_log_without_instance(void (*send)(const void *context, const char *message),
                             const void *context, const char *format, ...) AK_PRINTF_FORMAT(3, 4);

const char *ak_state_name(const ak_instance *instance, ak_state state);

/* The full check of ak_call_allowed, out of line: logs a refused call (the other interface, a
 * state not allowed) and traces a legal one in logCalls. False for a NULL instance. */
bool ak_call_checked(const ak_instance *instance, const ak_function_rule *rule);

/* The check at the top of every entry point taking an instance: false for NULL (nothing can be
 * logged then), a function of the other interface or a state not allowed (both logged). Inline,
 * so that a legal call with the trace off costs two mask tests and no call. */
static inline bool ak_call_passes(const ak_instance *instance, const ak_function_rule *rule);
static inline bool ak_call_allowed(const ak_instance *instance, const ak_function_rule *rule) {
    return ak_call_passes(instance, rule) || ak_call_checked(instance, rule);
}

/* The test of ak_call_allowed alone: true for a legal call with the trace off, and nothing logged
 * either way (the getters' and setters' kept requests; a call it refuses is checked in full). */
static inline bool ak_call_passes(const ak_instance *instance, const ak_function_rule *rule) {
    /* A function of both interfaces (most) needs no interface test: with the table a constant,
     * the compiler drops it. */
    const bool both = rule->interfaces == (AK_MODEL_EXCHANGE | AK_CO_SIMULATION);
    return instance != NULL && (rule->allowed_states & (unsigned int)instance->state) != 0 &&
           (both || (rule->interfaces & (unsigned int)instance->interface) != 0) &&
           !ak_log_on(instance, AK_LOG_CALLS);
}

/* Logs "<function>: <pointer_name> is NULL with <count_name> = <n>"; false. */
bool ak_refuse_null(const ak_instance *instance, const char *function, size_t n,
                    const char *count_name, const char *pointer_name);
/* NULL is fine only when there is nothing to read or write. Inline: every get and set asks it. */
static inline bool ak_given(const ak_instance *instance, const char *function, size_t n,
                            const char *count_name, const void *pointer,
                            const char *pointer_name) {
    return n == 0 || pointer != NULL ||
           ak_refuse_null(instance, function, n, count_name, pointer_name);
}
/* Logs "<function>: <name> is NULL"; false. */
bool ak_refuse_null_pointer(const ak_instance *instance, const char *function, const char *name);
/* A pointer argument that must not be NULL (inline: fmi3DoStep asks it four times a step). */
static inline bool ak_not_null(const ak_instance *instance, const char *function,
                               const void *pointer, const char *name) {
    return pointer != NULL || ak_refuse_null_pointer(instance, function, name);
}
/* The call of a getter or setter allowed, and vr and values given when there is anything to
 * read or write (each refusal in the layer's words). Inline: every get and set asks it. */
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

/* Makes a new instance of an embedding layer instance whose own fields (the callbacks its
 * send, allocate and release use) are set: copies the name, puts everything at its start.
 * False when the name cannot be allocated (nothing to free then; the layer says why, naming the
 * instance, which has no name yet). */
bool ak_instance_start(ak_instance *instance, const ak_layer *layer, const char *function,
                       const char *name, ak_interface interface, bool has_logger, bool logging_on);

/* Puts the instance in its just-instantiated condition (instantiation and reset). */
void ak_instance_reset(ak_instance *instance);

/* The role of a value reference in a Real get or set (AK_REAL_ABSENT for any out of range). */
static inline ak_real_role ak_real_role_of(const ak_instance *instance, unsigned int vr) {
    return vr < AK_MAX_VARIABLES ? (ak_real_role)instance->real_role[vr] : AK_REAL_ABSENT;
}

/* Brings the output groups up to `upto` (main; main and lazy; every output) up to date with the
 * inputs, evaluating only what an input or parameter change made stale (traced in logCalls);
 * the status the outputs come from: OK, WARNING, or DISCARD after a failed evaluation (the
 * function is outside its domain; the instance stays usable). */
ak_status ak_instance_update(ak_instance *instance, ak_group upto);

/* Marks every output stale (an input, state or parameter changed). */
static inline void ak_instance_inputs_changed(ak_instance *instance) {
    ak_outputs_inputs_changed(&instance->outputs);
}

/* The index of vr in a model's list of states (or of state derivatives), or -1. */
int ak_state_index(const unsigned int *vrs, unsigned int vr);

#endif
