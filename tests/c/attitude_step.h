/* The attitude step in one call, for the tests and the benchmark: the model calls its two parts
 * (attitude.h), keeping the rotation vector to retake the first step with. */
#ifndef ANGULAR_KINEMATICS_ATTITUDE_STEP_H
#define ANGULAR_KINEMATICS_ATTITUDE_STEP_H

#include "attitude.h"

/* q := q advanced over h (attitude.h, section 4); false, q untouched, when not finite. */
static inline bool ak_attitude_step(ak_frame frame, double c[4][3], double h, double q[4],
                                    double *correction) {
    double v[3];
    ak_attitude_step_vector(frame, c, h, v);
    return ak_attitude_advance(frame, v, q, correction);
}

#endif
