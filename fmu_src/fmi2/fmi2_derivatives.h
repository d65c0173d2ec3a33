/* The co-simulation input derivatives as the FMI layer's steps and setters see them; the FMI
 * functions on derivatives themselves are in fmi2_derivatives.c. */
#ifndef ANGULAR_KINEMATICS_FMI2_DERIVATIVES_H
#define ANGULAR_KINEMATICS_FMI2_DERIVATIVES_H

#include <stdbool.h>

#include "fmi2_instance.h"

/* fmi2SetReal on an input forgets that input's derivatives: the master restated the value at
 * a new point without a slope, so the input is held from there (see docs/capabilities.md). */
void ak_forget_input_derivatives(ak_instance *instance, unsigned int input_vr);

/* Moves the inputs along their polynomials u + s du + s^2/2 d2u to the end of a step of size
 * h, and their first derivatives with them. Refuses (false, logged, nothing changed) when a
 * value would overflow. Marks the outputs stale only if an input changed. */
bool ak_advance_inputs(ak_instance *instance, double h);

#endif
