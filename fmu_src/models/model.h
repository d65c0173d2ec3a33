/* The model descriptor: all that the runtime and the FMI layers (runtime/, fmi2/, fmi3/) know of
 * a model, and all that a model knows of an instance. Each FMU binary is compiled with exactly
 * one model folder, whose model.c defines AK_MODEL; its variable table is generated from its
 * description.py (python -m codegen).
 *
 * Values live in one array indexed by value reference. Value references are the description's
 * and never move; the rules the layers rely on (checked by the generator):
 *   - the inputs hold value references 0 .. n_inputs - 1 (all Real);
 *   - every other value reference is an output (group main or lazy), a local (the derivatives of
 *     continuous states, computed like main outputs) or a parameter (variability fixed, Real or
 *     Integer), in any order; a value reference no variable has is a hole of the table (name
 *     NULL);
 *   - continuous states (model exchange; co-simulation integrates them in `step`) live in the
 *     value array like every other value, so an FMU state carries them.
 * Integer values are kept as doubles in the same array (every int is exact in a double). */
#ifndef ANGULAR_KINEMATICS_MODEL_H
#define ANGULAR_KINEMATICS_MODEL_H

#include <stdbool.h>
#include <stddef.h>

#include "ak_compiler.h"
#include "log_categories.h"

/* Upper bounds over all models, for the arrays of an instance. */
#define AK_MAX_VARIABLES 80
#define AK_MAX_INPUTS 24
#define AK_MAX_DEPENDENCIES 13
#define AK_MAX_STATES 4
/* The knowns of a directional derivative: the inputs, then the continuous states. */
#define AK_MAX_KNOWNS (AK_MAX_INPUTS + AK_MAX_STATES)
#define AK_MAX_WORK 6

/* Highest order of input derivative a master may give: the inputs follow a polynomial of this
 * degree over a communication step. */
#define AK_MAX_INPUT_DERIVATIVE_ORDER 2

typedef enum {
    AK_CAUSALITY_INPUT,
    AK_CAUSALITY_OUTPUT,
    AK_CAUSALITY_PARAMETER,
    AK_CAUSALITY_LOCAL
} ak_causality;
typedef enum { AK_TYPE_REAL, AK_TYPE_INTEGER } ak_type;
/* Outputs of the main group are computed by evaluate whenever an input changed and an output is
 * read; those of the lazy group by evaluate_lazy, only when one of them is read; the derived ones
 * (ak_derived_outputs) from the other outputs, only when one of them is read. In increasing order
 * of what a read brings up to date. */
typedef enum { AK_GROUP_MAIN, AK_GROUP_LAZY, AK_GROUP_DERIVED } ak_group;

typedef struct {
    unsigned int value_reference;
    const char *name; /* NULL: no variable has this value reference */
    ak_causality causality;
    ak_type type;
    ak_group group;            /* outputs only */
    const char *declared_type; /* a <SimpleType> of modelDescription.xml */
    const char *unit;          /* "" when none */
    double start;              /* inputs and parameters */
    double min, max;           /* parameters: the values a setter accepts */
    const char *out_of_range;  /* parameters: why a value outside [min, max] is refused */
    const char *description;
    size_t n_dependencies; /* outputs only: the inputs it structurally depends on */
    unsigned int dependencies[AK_MAX_DEPENDENCIES];
} ak_variable;

/* The status a model reports with a message; each FMI layer maps it to its own status type. */
typedef enum { AK_STATUS_OK, AK_STATUS_WARNING, AK_STATUS_DISCARD, AK_STATUS_ERROR } ak_status;

/* What a model sees of an instance, whichever FMI layer owns it. */
typedef struct {
    double values[AK_MAX_VARIABLES]; /* indexed by value reference */
    /* input_derivatives[k][n - 1]: the n-th time derivative of input k at the current time, as
     * the master gave it; zero when not given. any_input_derivative is false when all are zero. */
    double input_derivatives[AK_MAX_INPUTS][AK_MAX_INPUT_DERIVATIVE_ORDER];
    bool any_input_derivative;
    /* The model's own: what evaluate computed and evaluate_lazy reuses (evaluate_lazy always
     * runs after an evaluate for the same inputs). The layers never read it. */
    double work[AK_MAX_WORK];
    /* The owning layer's logger: the message is fully formatted. */
    void (*log)(void *owner, ak_log_category category, ak_status status, const char *message);
    void *owner;
} ak_model_data;

/* The outputs a model computes from its other outputs by core functions that its description
 * names (`computed_by`), generated into <Model>_derived.c; their group is AK_GROUP_DERIVED. The FMI
 * layers reach them only through ak_instance_update, ak_model_jacobian and
 * ak_model_output_derivatives. */
typedef struct {
    /* The value references of the outputs they are computed from that are not derived
     * themselves: the rows the model's Jacobian gives for the derived ones' chain rule. */
    size_t n_arguments;
    const unsigned int *arguments;
    /* Writes the derived outputs into values, from the other outputs (both groups current);
     * NULL when the model has none. */
    void (*compute)(double values[]);
    /* The derived outputs' changes, tangents[vr], from the arguments' changes tangents[vr] in
     * one direction (forward mode: each core function's `_tangent` twin); NULL when the model
     * gives no derivatives. */
    void (*tangents)(const double values[], double tangents[]);
} ak_derived_outputs;

/* Result of an evaluation. AK_EVAL_WARNING: outputs written and valid, the model logged why it
 * warns. AK_EVAL_FAILED: nothing written, the model logged why; the outputs keep their last
 * valid values. */
typedef enum { AK_EVAL_OK = 0, AK_EVAL_WARNING = 1, AK_EVAL_FAILED = 2 } ak_eval_status;

typedef struct {
    const char *model_identifier;
    const char *guid;
    const ak_variable *variables; /* indexed by value reference */
    int n_value_references;       /* highest value reference + 1 */
    int n_inputs;

    /* Computes the main output group from the inputs and parameters in data->values. */
    ak_eval_status (*evaluate)(ak_model_data *data);
    /* Computes the lazy output group; NULL when there is none. Called only after evaluate
     * succeeded for the same inputs. */
    void (*evaluate_lazy)(ak_model_data *data);
    /* Both groups in one call, bit for bit what evaluate then evaluate_lazy give (a read of every
     * output, which fmpy makes by default, counts one evaluation); NULL: the layer calls the two. */
    ak_eval_status (*evaluate_all)(ak_model_data *data);

    /* Optional capabilities: NULL when the model does not have them (the FMI function then
     * refuses with a message naming the modelDescription.xml flag). */
    /* Exact derivatives of the listed unknowns (value references of outputs, or of state
     * derivatives) with respect to every known: J[i][k] = d y(out[i]) / d u_k for the inputs
     * k < n_inputs, and J[i][n_inputs + s] = d y(out[i]) / d x_s for the states. */
    void (*jacobian)(const ak_model_data *data, const unsigned int out[], size_t n_out,
                     double J[][AK_MAX_KNOWNS]);
    /* First time derivatives of the listed outputs (checked value references of outputs), given
     * the inputs and their derivatives data->input_derivatives. */
    void (*output_derivatives)(ak_model_data *data, const unsigned int vr[], size_t nvr,
                               double value[]);
    bool can_interpolate_inputs;
    /* An output is computed from data->input_derivatives (AttitudePropagator's alpha in
     * co-simulation): a change of them makes the outputs stale. */
    bool outputs_use_input_derivatives;
    /* The outputs computed from others by core functions (generated; compute NULL when none);
     * which they are is the variable table's group AK_GROUP_DERIVED. */
    const ak_derived_outputs *derived;
    /* True for a model whose evaluation can fail, or whose outputs depend on the path (the
     * unwrapped angles of AttitudePropagator): a co-simulation step then evaluates at the end
     * of the step, and is discarded when that fails. */
    bool evaluate_in_step;

    /* Continuous states: 0 / NULL for a model without. The states and their derivatives are
     * values (value references state_vrs[k], derivative_vrs[k]); state_nominals[k] the nominal
     * of state k. */
    int n_states;
    const unsigned int *state_vrs;
    const unsigned int *derivative_vrs;
    const double *state_nominals;
    /* Writes der(x) at values[derivative_vrs[k]] from the states and inputs in values. */
    void (*derivatives)(ak_model_data *data);
    /* Co-simulation: advances the states over h with the inputs and input_derivatives as given
     * (those at the step start); AK_EVAL_FAILED (logged) leaves them as they were. */
    ak_eval_status (*step)(ak_model_data *data, double h);
    /* The states from the parameters: called at instantiation and reset, before each evaluation
     * until the end of initialization, and there; AK_EVAL_FAILED
     * (logged) when the parameters give no valid start, which leaves the states as they were. */
    ak_eval_status (*initialize)(ak_model_data *data);
} ak_model;

/* The model this binary is built for (one model folder per FMU target). */
extern const ak_model AK_MODEL;

/* Formats a message and hands it to the owner's logger (models/model_log.c). */
void ak_model_log(const ak_model_data *data, ak_log_category category, ak_status status,
                  const char *format, ...) AK_PRINTF_FORMAT(4, 5);

/* The derived outputs (AK_MODEL.derived), once both groups are current. */
static inline void ak_model_compute_derived(ak_model_data *data) {
    if (AK_MODEL.derived != NULL && AK_MODEL.derived->compute != NULL) {
        AK_MODEL.derived->compute(data->values);
    }
}

/* Whether one of the value references is a derived output: its derivatives are computed from
 * the current values of its arguments, which the layer then brings up to date, lazy ones too. */
bool ak_model_any_derived(const unsigned int vr[], size_t n);

/* What the FMI layers call for AK_MODEL.jacobian and AK_MODEL.output_derivatives (same
 * contract; models/model_derived.c): the model's own for its outputs, the chain rule through
 * AK_MODEL.derived's tangents for a derived one. Call only when the model's function is not NULL;
 * at most AK_MAX_VARIABLES unknowns per ak_model_jacobian call (the rows of J). */
void ak_model_jacobian(const ak_model_data *data, const unsigned int out[], size_t n_out,
                       double J[][AK_MAX_KNOWNS]);
void ak_model_output_derivatives(ak_model_data *data, const unsigned int vr[], size_t nvr,
                                 double value[]);

/* NULL when the value is one the parameter accepts (its [min, max] of the variable table), else
 * why not, for the message. */
static inline const char *ak_parameter_refusal(const ak_variable *variable, double value) {
    return value >= variable->min && value <= variable->max ? NULL : variable->out_of_range;
}

/* The variable of a value reference, or NULL when the model has none. */
static inline const ak_variable *ak_variable_of(unsigned int vr) {
    if (vr >= (unsigned int)AK_MODEL.n_value_references || AK_MODEL.variables[vr].name == NULL) {
        return NULL;
    }
    return &AK_MODEL.variables[vr];
}

static inline const char *ak_causality_name(ak_causality causality) {
    return causality == AK_CAUSALITY_INPUT    ? "input"
           : causality == AK_CAUSALITY_OUTPUT ? "output"
           : causality == AK_CAUSALITY_LOCAL  ? "local"
                                              : "parameter";
}

#endif
