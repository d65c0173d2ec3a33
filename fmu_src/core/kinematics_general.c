/* General angular kinematics for every rotation sequence: the formulation is stated in
 * kinematics_general.h, the chain of its section 1 in kinematics_chain.h. This file holds what
 * every model calls: the sines of the angles. */
#include "kinematics_general.h"

#include "elementary.h"
#include "elementary_sincos_three.h"

/* Angle by angle: an angle off the usual paths (tiny, huge, not finite, near a multiple of
 * pi/2). Out of line: rare, and ak_sincos is large. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static void angle_sines_each(const double theta[3], ak_sines *sines) {
    for (int k = 0; k < 3; k++) {
        ak_sincos(theta[k], &sines->sin[k], &sines->cos[k]);
    }
}

void ak_angle_sines(const double theta[3], ak_sines *sines) {
    /* The project's sincos (elementary.h), inlined: the same bits on every platform, and one
     * argument reduction for both; the three angles side by side when all take its usual path. */
    if (!ak_sincos_three_usual(theta, sines->sin, sines->cos)) {
        angle_sines_each(theta, sines);
    }
}
