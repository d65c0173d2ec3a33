/* The general angle extraction of the attitude core before its per-sequence functions, as the
 * reference of tests/c/test_attitude_angles_bits.c: ak_attitude_angles' contract (attitude_angles.h). */
#ifndef AK_ATTITUDE_ANGLES_REFERENCE_H
#define AK_ATTITUDE_ANGLES_REFERENCE_H

#include <stdbool.h>

#include "sequences.h"

bool reference_attitude_angles(const ak_sequence *sequence, double R[3][3],
                               const double previous[3], double theta[3], double *distance);

#endif
