/* Argument checks shared by the FMI 3 functions taking value references of arrays. */
#ifndef ANGULAR_KINEMATICS_FMI3_VALUES_H
#define ANGULAR_KINEMATICS_FMI3_VALUES_H

#include <stdbool.h>
#include <stddef.h>

#include "fmi3_arrays.h"
#include "fmi3_state_machine.h"

/* The array of an FMI 3 value reference (list_name[index] = vr) of the given causality, or NULL
 * after logging why not (unknown, an inner element, another causality). */
const ak3_array *ak3_array_of_causality(const ak3_instance *instance, ak3_function function,
                                        const char *list_name, size_t index, unsigned int vr,
                                        ak_causality causality);

/* True when n, the caller's count of values, is the number of elements of the n_vr arrays
 * (total); else logs naming the function, the count and the variables. */
bool ak3_count_matches(const ak3_instance *instance, ak3_function function, const char *count_name,
                       size_t n, size_t total, const unsigned int vr[], size_t n_vr);

/* NULL arrays are fine only when there is nothing to read or write. */
bool ak3_given(const ak3_instance *instance, ak3_function function, size_t n,
               const char *count_name, const void *pointer, const char *pointer_name);

#endif
