/* sin and cos of the principal angles from the arguments of their arctangents (attitude_angles.h):
 * for QuaternionKinematics' angle rates, instead of a sine and cosine of each angle. */
#include "attitude_angles.h"

/* For the chain i, j, proper Euler or Tait-Bryan, theta in chain order (body-fixed) or reversed
 * (space-fixed); inlined into each sequence's function (attitude_sines_sequences.h). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline bool chain_sines(int i, int j, bool proper, bool space, double R[3][3],
                               double sin_theta[3], double cos_theta[3]) {
    double y[3], x[3];
    if (!(ak_chain_arguments(i, j, proper, R, y, x) >= AK_ATTITUDE_SINGULAR_DISTANCE)) {
        return false;
    }
    /* phi = atan2(y, x) has sin phi = y / |(y, x)| and cos phi = x / |(y, x)| in every
     * quadrant; |(y, x)| is about the distance for the first and last angle, about 1 for the
     * middle one, never 0 here. */
    for (int m = 0; m < 3; m++) {
        const double size = sqrt(y[m] * y[m] + x[m] * x[m]);
        const int k = space ? 2 - m : m;
        sin_theta[k] = y[m] / size;
        cos_theta[k] = x[m] / size;
    }
    return true;
}

/* sines_body123 .. sines_space323 and their table SINES_OF_SEQUENCE, generated from the
 * sequences of codegen/project.py. */
#include "attitude_sines_sequences.h"

bool ak_attitude_principal_sines(const ak_sequence *sequence, double R[3][3],
                                 double sin_theta[3], double cos_theta[3]) {
    return SINES_OF_SEQUENCE[sequence->kind][sequence->proper_euler != 0][sequence->axes[0] - 1]
                            [sequence->axes[1] - 1](R, sin_theta, cos_theta);
}
