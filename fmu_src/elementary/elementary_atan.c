/* atan by the arc kernel (elementary_arc_kernel.h): AngularKinematics' rotation angle. */
#include "elementary_arc_kernel.h"

double ak_atan(double x) {
    const double ax = fabs(x);
    if (!(ax <= 1.0)) {
        if (ax != ax) {
            return x + x;
        }
        if (ax > 0x1p54) { /* pi/2 - 1/x rounds to pi/2; also +-inf */
            return sign_bit(x) ? -AK_PIO2_HI : AK_PIO2_HI;
        }
        const double r = arc_from_quotient(1.0, ax, 1);
        return sign_bit(x) ? -r : r;
    }
    if (ax < 0x1p-27) { /* atan x = x - x^3/3 rounds to x; keeps -0 and subnormals */
        return x;
    }
    const double r = arc_kernel(ax, 0.0, 0, 0); /* t = x exactly: no correction */
    return sign_bit(x) ? -r : r;
}
