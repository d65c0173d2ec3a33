/* The FMI 3 array table: FMI 3 declares each array of a model description (theta, R, ...) as one
 * variable whose value reference is that of its first element in the shared value array
 * (models/model.h), so that values[vr .. vr + n_elements - 1] are its elements, row-major.
 * The table is generated per model (models/<Model>/fmi3/<Model>_fmi3_arrays.c). */
#ifndef ANGULAR_KINEMATICS_FMI3_ARRAYS_H
#define ANGULAR_KINEMATICS_FMI3_ARRAYS_H

#include "model.h"

typedef struct {
    const char *name;       /* NULL: no variable has this value reference */
    unsigned int first_vr;  /* the FMI 3 value reference of the array */
    unsigned int n_elements;
    unsigned int n_dimensions; /* 0 scalar, 1 vector, 2 matrix */
    unsigned int rows, cols;
} ak3_array;

/* For every value reference of the model's value array: the array holding it. */
extern const ak3_array AK3_ARRAYS[AK_MAX_VARIABLES];
extern const int AK3_N_ARRAYS;
/* The independent variable time: not in the value array, answered from the instance's time. */
extern const unsigned int AK3_TIME_VALUE_REFERENCE;

/* The array whose FMI 3 value reference is vr, or NULL (unknown, or an element other than the
 * first, which FMI 3 does not address). */
static inline const ak3_array *ak3_array_of(unsigned int vr) {
    if (vr >= (unsigned int)AK_MODEL.n_value_references || AK3_ARRAYS[vr].name == NULL ||
        AK3_ARRAYS[vr].first_vr != vr) {
        return NULL;
    }
    return &AK3_ARRAYS[vr];
}

#endif
