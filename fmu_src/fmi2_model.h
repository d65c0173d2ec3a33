/* What the FMI layer needs to know about a model: the model descriptor. The FMI layer
 * (fmi2_*.c) is generic; each FMU binary is compiled with exactly one model_*.c, which defines
 * AK_MODEL: its identifier, GUID, variable table (the one source of truth for value references,
 * names, causalities, units, start values and output dependencies; modelDescription.xml must
 * agree with it, and tests/test_model_description.py checks that through the model_info tool),
 * how its outputs are evaluated and which optional capabilities it has.
 *
 * Value references are laid out the same way in every model, so that the instance keeps all
 * values in one array indexed by value reference:
 *     0 .. n_inputs - 1                     Real inputs
 *     n_inputs .. first_lazy_output - 1     outputs of the main group (evaluate)
 *     first_lazy_output .. first_parameter - 1   outputs of the lazy group (evaluate_lazy)
 *     first_parameter .. n_variables - 1    parameters (variability fixed; Real or Integer)
 * Integer values are kept as doubles in the same array (every int is exact in a double). */
#ifndef ANGULAR_KINEMATICS_FMI2_MODEL_H
#define ANGULAR_KINEMATICS_FMI2_MODEL_H

#include <stdbool.h>
#include <stddef.h>

/* Upper bounds over all models, for the arrays of an instance. */
#define AK_MAX_VARIABLES 80
#define AK_MAX_INPUTS 9
#define AK_MAX_DEPENDENCIES 9

typedef enum { AK_CAUSALITY_INPUT, AK_CAUSALITY_OUTPUT, AK_CAUSALITY_PARAMETER } ak_causality;
typedef enum { AK_TYPE_REAL, AK_TYPE_INTEGER } ak_type;

typedef struct {
    unsigned int value_reference;
    const char *name;
    ak_causality causality;
    ak_type type;
    const char *declared_type; /* a <SimpleType> of modelDescription.xml */
    const char *unit;          /* "" when none */
    double start;              /* inputs and parameters */
    double min, max;           /* parameters: the values a setter accepts */
    const char *description;
    size_t n_dependencies; /* outputs only: the inputs it structurally depends on */
    unsigned int dependencies[AK_MAX_DEPENDENCIES];
} ak_variable;

/* Result of an evaluation. AK_EVAL_WARNING: outputs written and valid, the model logged why it
 * warns. AK_EVAL_FAILED: nothing written, the model logged why; the outputs keep their last
 * valid values. */
typedef enum { AK_EVAL_OK = 0, AK_EVAL_WARNING = 1, AK_EVAL_FAILED = 2 } ak_eval_status;

struct ak_instance_s;

typedef struct {
    const char *model_identifier;
    const char *guid;
    const char *state_name; /* for messages: "AngularKinematics FMU state" */
    const ak_variable *variables; /* indexed by value reference */
    int n_variables;
    int n_inputs;
    int first_lazy_output;
    int first_parameter;

    /* Computes the main output group from the inputs and parameters in instance->values. */
    ak_eval_status (*evaluate)(struct ak_instance_s *instance);
    /* Computes the lazy output group; NULL when there is none. Called only after evaluate
     * succeeded for the same inputs. */
    void (*evaluate_lazy)(struct ak_instance_s *instance);
    /* NULL when the value is acceptable for the parameter, else why not (for the message). */
    const char *(*check_parameter)(const ak_variable *variable, double value);

    /* Optional capabilities: NULL when the model does not have them (the FMI function then
     * refuses with a message naming the modelDescription.xml flag). */
    /* Exact d output / d input for the listed outputs (value references) and all inputs:
     * J[i][k] = d y(out[i]) / d u_k. */
    void (*jacobian)(struct ak_instance_s *instance, const unsigned int out[], size_t n_out,
                     double J[][AK_MAX_INPUTS]);
    /* First time derivatives of the listed outputs (checked value references of outputs), given
     * the inputs and their derivatives instance->input_derivatives. */
    void (*output_derivatives)(struct ak_instance_s *instance, const unsigned int vr[],
                               size_t nvr, double value[]);
    bool can_interpolate_inputs;
    /* True for a model whose evaluation can fail: fmi2DoStep then evaluates at the end of the
     * step and returns fmi2Discard (StepFailed) when it fails. */
    bool evaluate_in_step;
} ak_model;

/* The model this binary is built for (one model_*.c per FMU target). */
extern const ak_model AK_MODEL;

static inline const char *ak_causality_name(ak_causality causality) {
    return causality == AK_CAUSALITY_INPUT    ? "input"
           : causality == AK_CAUSALITY_OUTPUT ? "output"
                                              : "parameter";
}

#endif
