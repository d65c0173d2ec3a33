/* asin and acos by the arc kernel of atan and atan2 (elementary_arc_kernel.h): the elementary set
 * complete for the tests and the accuracy tool (tools/elementary/accuracy.py); no model calls
 * them. */
#include "elementary_asin_acos.h"

#include "elementary_arc_kernel.h"

/* base + sign atan(n / d) for quadrant q, n = nh + nl, d = dh + dl, 0 < n <= d, with nh and dh
 * between 2^-600 and 2^600 and n/d >= 2^-61 (no product below overflows or underflows). The
 * quotient t = nh/dh is corrected by its exact residual (Dekker's product, no fma): n/d = t + e,
 * so its rounding never reaches the result. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline double arc_from_ratio(double nh, double nl, double dh, double dl, int q) {
    const double t = nh / dh;
    double p, pe;
    ak_two_prod(t, dh, &p, &pe);
    const double e = (((nh - p) - pe) + nl - t * dl) / dh; /* nh - p is exact (Sterbenz) */
    return arc_kernel(t, e, 1, q);
}

/* sqrt(1 - a^2) = *hi + *lo for 0 <= a < 1, to about 2^-100 relative. */
static void sqrt_one_minus_square(double a, double *hi, double *lo) {
    double p, pe, d, de, dh, dl;
    ak_two_square(a, &p, &pe);
    ak_two_sum(1.0, -p, &d, &de);
    ak_two_sum(d, de - pe, &dh, &dl);
    const double s = sqrt(dh); /* IEEE sqrt: correctly rounded everywhere */
    double q, qe;
    ak_two_square(s, &q, &qe);
    *hi = s;
    *lo = (((dh - q) - qe) + dl) / (2.0 * s);
}

double ak_asin(double x) {
    const double ax = fabs(x);
    if (!(ax < 1.0)) {
        if (ax == 1.0) {
            return sign_bit(x) ? -AK_PIO2_HI : AK_PIO2_HI;
        }
        return (x - x) * INFINITY; /* NaN, invalid for |x| > 1: 0 inf */
    }
    if (ax < 0x1p-26) { /* asin x = x + x^3/6 rounds to x; keeps -0 and subnormals */
        return x;
    }
    double s_hi, s_lo;
    sqrt_one_minus_square(ax, &s_hi, &s_lo);
    /* asin x = atan(x / sqrt(1 - x^2)), as the atan of whichever ratio is at most 1 */
    const double r = ax <= s_hi ? arc_from_ratio(ax, 0.0, s_hi, s_lo, 0)
                                : arc_from_ratio(s_hi, s_lo, ax, 0.0, 1);
    return sign_bit(x) ? -r : r;
}

double ak_acos(double x) {
    const double ax = fabs(x);
    if (!(ax < 1.0)) {
        if (x == 1.0) {
            return 0.0;
        }
        if (x == -1.0) {
            return AK_PI_HI;
        }
        return (x - x) * INFINITY;
    }
    if (ax < 0x1p-57) { /* pi/2 - x rounds to pi/2 */
        return AK_PIO2_HI;
    }
    double s_hi, s_lo;
    sqrt_one_minus_square(ax, &s_hi, &s_lo);
    /* acos x = atan2(sqrt(1 - x^2), x) */
    if (ax <= s_hi) { /* pi/2 -+ atan(|x|/s) */
        return arc_from_ratio(ax, 0.0, s_hi, s_lo, sign_bit(x) ? 3 : 1);
    }
    return arc_from_ratio(s_hi, s_lo, ax, 0.0, sign_bit(x) ? 2 : 0); /* (0 or pi) +- atan(s/|x|) */
}
