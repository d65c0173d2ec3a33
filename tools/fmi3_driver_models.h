/* What our FMI 3 master (fmi3_driver.c) knows of each model, generated from the model
 * descriptions into fmi3_driver_models.c (codegen/fmi3.py), so that no instantiation token or
 * value reference is typed twice. */
#ifndef ANGULAR_KINEMATICS_FMI3_DRIVER_MODELS_H
#define ANGULAR_KINEMATICS_FMI3_DRIVER_MODELS_H

#include <stddef.h>

#include "fmi3PlatformTypes.h"

enum { DRIVER_MAX_ARRAYS = 16 };

typedef struct {
    const char *name;
    const char *token;
    fmi3ValueReference inputs[DRIVER_MAX_ARRAYS]; /* the input arrays, in value-reference order */
    size_t n_inputs, n_input_values;
    fmi3ValueReference outputs[DRIVER_MAX_ARRAYS];
    size_t output_elements[DRIVER_MAX_ARRAYS];
    size_t n_outputs, n_output_values;
    fmi3ValueReference sequence, frame; /* 0: the model has none */
    /* Directional derivatives are taken with respect to the inputs and the continuous states;
     * n_knowns 0: the model provides none. */
    fmi3ValueReference knowns[DRIVER_MAX_ARRAYS];
    size_t n_knowns, n_columns;
    int output_derivatives; /* maxOutputDerivativeOrder > 0 */
} driver_model;

extern const driver_model DRIVER_MODELS[];
extern const size_t N_DRIVER_MODELS;

#endif
