/* What our FMI 2 master (fmu_driver.c) knows of each model, generated from the model
 * descriptions into fmu_driver_models.c (codegen/generate.py), so that no GUID or variable table
 * is typed twice. */
#ifndef ANGULAR_KINEMATICS_FMU_DRIVER_MODELS_H
#define ANGULAR_KINEMATICS_FMU_DRIVER_MODELS_H

#include <stddef.h>

#include "model.h"

typedef struct {
    const char *name;
    const char *guid;
    const ak_variable *variables; /* indexed by value reference; name NULL: a hole */
    int n_value_references;
    int n_inputs;
    /* Input 1 is kept off the singular configuration (+-1.5 where the others take +-pi/2): an
     * output singularity_distance depends on it, and the model refuses a step there. */
    int singular_input_1;
} driven_model;

extern const driven_model DRIVEN_MODELS[];
extern const size_t N_DRIVEN_MODELS;

#endif
