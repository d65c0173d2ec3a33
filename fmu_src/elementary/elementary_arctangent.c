/* atan, atan2, asin and acos from one kernel, the atan of a ratio n/d <= 1 given as its numerator
 * and denominator (each a double or double-double), plus the base of atan2's quadrant: the
 * quotient's rounding error is recovered with Dekker's exact product (no fma), so no quotient's
 * rounding reaches the result, and atan is a table of Taylor expansions (arc_from_ratio). */
#include "elementary.h"

#include <stdint.h>
#include <string.h>

/* The kernel's tables (elementary_coefficients.h), rows j = 0..32 by interval [j/32, (j+1)/32). */
static const double CENTRE[33] = AK_ARC_CENTRE;
static const double SLOPE_HI[33] = AK_ARC_SLOPE_HI;
static const double SLOPE_LO[33] = AK_ARC_SLOPE_LO;
static const double HEAD_HI[4][33] = AK_ARC_HEAD_HI;
static const double HEAD_LO[4][33] = AK_ARC_HEAD_LO;
static const double TAYLOR[33][9] = AK_ARC_TAYLOR;
/* Quadrant q = 2 (x < 0) + (|y| > |x|) of atan2: base + SIGN[q] atan(min/max), base 0, pi/2,
 * pi, pi/2. */
static const double SIGN[4] = {1.0, -1.0, -1.0, 1.0};

static int sign_bit(double x) {
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    return (int)(bits >> 63);
}

/* base + sign atan(t + e) for quadrant q (HEAD_HI), 0 <= t <= 1, |e| <= 2^-52 t (taken into
 * account when with_e: a constant, so the branch folds away), rounded once:
 * atan(t + e) = atan(c) + s h + a_2 h^2 + ... about the centre c of t's interval, h = t - c exact
 * (Sterbenz), s h formed exactly from a 26-bit slope; on [0, 1/32) the odd minimax polynomial.
 * Only the final addition rounds at the last bit. */
#if defined(__GNUC__)
__attribute__((always_inline)) /* atan2's and atan's usual paths: no call, constants folded */
#endif
static inline double arc_kernel(double t, double e, int with_e, int q) {
    const double sign = SIGN[q];
    const int j = (int)(t * 32.0);
    double s, se, tail;
    if (j == 0) {
        const double z = t * t;
        const double poly = (t * z) * (AK_ATAN_A0 + z * (AK_ATAN_A1 + z * (AK_ATAN_A2
                          + z * AK_ATAN_A3)));
        ak_two_sum(HEAD_HI[q][0], sign * t, &s, &se);
        tail = with_e ? (e - e * z) + poly : poly; /* atan'(t) = 1 - t^2 + ... */
    } else {
        const double h = t - CENTRE[j];
        double h_hi, h_lo;
        ak_split(h, &h_hi, &h_lo);
        const double *a = TAYLOR[j];
        const double poly = (h * h) * (a[0] + h * (a[1] + h * (a[2] + h * (a[3] + h * (a[4]
                          + h * (a[5] + h * (a[6] + h * (a[7] + h * a[8]))))))));
        ak_two_sum(HEAD_HI[q][j], sign * (SLOPE_HI[j] * h_hi), &s, &se);
        /* e times atan'(t) = s + 2 a_2 h + ..., to far below the last bit */
        tail = (SLOPE_HI[j] * h_lo + SLOPE_LO[j] * h) + poly;
        if (with_e) {
            tail = tail + e * (SLOPE_HI[j] + 2.0 * a[0] * h);
        }
    }
    return s + (se + (HEAD_LO[q][j] + sign * tail));
}

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

double ak_atan(double x) {
    const double ax = fabs(x);
    if (!(ax <= 1.0)) {
        if (ax != ax) {
            return x + x;
        }
        if (ax > 0x1p54) { /* pi/2 - 1/x rounds to pi/2; also +-inf */
            return sign_bit(x) ? -AK_PIO2_HI : AK_PIO2_HI;
        }
        const double r = arc_from_ratio(1.0, 0.0, ax, 0.0, 1);
        return sign_bit(x) ? -r : r;
    }
    if (ax < 0x1p-27) { /* atan x = x - x^3/3 rounds to x; keeps -0 and subnormals */
        return x;
    }
    const double r = arc_kernel(ax, 0.0, 0, 0); /* t = x exactly: no correction */
    return sign_bit(x) ? -r : r;
}

/* atan2 of finite nonzero |y|, |x|, in [0, pi]: the cases that the usual path of ak_atan2
 * leaves, far apart in magnitude or near the ends of the exponent range. */
static double atan2_finite(double ay, double ax, int x_negative) {
    const int swap = ay > ax; /* then atan(ay/ax) = pi/2 - atan(ax/ay) */
    const int q = 2 * x_negative + swap;
    double num = swap ? ax : ay, den = swap ? ay : ax;
    const int e_num = ak_exponent_field(num), e_den = ak_exponent_field(den);
    if (e_den - e_num > 60) {
        /* num/den < 2^-59: atan t = t - t^3/3 rounds as t; the quotient may underflow. */
        const double t = num / den;
        return q == 0 ? t : HEAD_HI[q][0] + (HEAD_LO[q][0] + SIGN[q] * t);
    }
    if (e_den > 1023 + 600 || e_num < 1023 - 600) {
        /* Scale den into [1, 2) (exact: num >= 2^-61 den stays normal) so that Dekker's product
         * neither overflows nor underflows. */
        const int scale = 1023 - e_den;
        const double first = ak_pow2(scale / 2), second = ak_pow2(scale - scale / 2);
        num = num * first * second;
        den = den * first * second;
    }
    return arc_from_ratio(num, 0.0, den, 0.0, q);
}

double ak_atan2(double y, double x) {
    const int e_y = ak_exponent_field(y), e_x = ak_exponent_field(x);
    const int x_negative = sign_bit(x);
    double r;
    if ((unsigned)(e_y - 423) <= 1200u && (unsigned)(e_x - 423) <= 1200u
        && (unsigned)(e_y - e_x + 60) <= 120u) {
        /* The usual case, without a special value or scaling: both within 2^+-600, ratio within
         * 2^+-60. */
        const double ay = fabs(y), ax = fabs(x);
        const int swap = ay > ax; /* then pi/2 -+ atan(ax/ay) */
        r = arc_from_ratio(swap ? ax : ay, 0.0, swap ? ay : ax, 0.0, 2 * x_negative + swap);
    } else if (x != x || y != y) {
        return x + y;
    } else {
        const double ay = fabs(y), ax = fabs(x);
        if (ay == 0.0) {
            r = x_negative ? AK_PI_HI : 0.0;
        } else if (ax == 0.0) {
            r = AK_PIO2_HI;
        } else if (ax > 0x1.fffffffffffffp+1023) {
            r = ay > 0x1.fffffffffffffp+1023 ? (x_negative ? AK_THREE_PIO4 : AK_PIO4_HI)
                                             : (x_negative ? AK_PI_HI : 0.0);
        } else if (ay > 0x1.fffffffffffffp+1023) {
            r = AK_PIO2_HI;
        } else {
            r = atan2_finite(ay, ax, x_negative);
        }
    }
    return sign_bit(y) ? -r : r;
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
