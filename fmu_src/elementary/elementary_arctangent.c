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

/* arc_from_ratio for n and d doubles (nl = dl = 0), without the two zero terms: there
 * ((nh - p) - pe) + 0 - t 0 is (nh - p) - pe, the same double, which is never -0 (nh - p is exact:
 * +0 or not zero, and x - x is +0). Four operations fewer on ak_atan2's usual path. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline double arc_from_quotient(double n, double d, int q) {
    const double t = n / d;
    double p, pe;
    ak_two_prod(t, d, &p, &pe);
    return arc_kernel(t, ((n - p) - pe) / d, 1, q);
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
        const double r = arc_from_quotient(1.0, ax, 1);
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
    return arc_from_quotient(num, den, q);
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
        r = arc_from_quotient(swap ? ax : ay, swap ? ay : ax, 2 * x_negative + swap);
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

#if defined(__GNUC__) /* and clang: vectors of two doubles, each operation lane by lane */

/* Whether ak_atan2(y, x) takes its usual path (the test at its start). */
static int atan2_usual(double y, double x) {
    const int e_y = ak_exponent_field(y), e_x = ak_exponent_field(x);
    return (unsigned)(e_y - 423) <= 1200u && (unsigned)(e_x - 423) <= 1200u
        && (unsigned)(e_y - e_x + 60) <= 120u;
}

typedef double atan2_pair __attribute__((vector_size(16)));
typedef __typeof__((atan2_pair){0.0} < (atan2_pair){0.0}) atan2_mask;

/* ak_atan2's usual path for two arguments (both on it), the same operations on vectors of two
 * doubles: each IEEE operation rounds each lane as the scalar one does, so the bits are
 * ak_atan2's. Its choices (which of |y|, |x| is larger, the first interval of the kernel, the
 * sign of y) are masks, and both forms of the kernel are computed. */
__attribute__((always_inline)) static inline atan2_pair atan2_usual_pair(atan2_pair y,
                                                                        atan2_pair x) {
    const atan2_mask sign_bit_mask = (atan2_mask)((atan2_pair){-0.0, -0.0});
    const atan2_pair ay = (atan2_pair)((atan2_mask)y & ~sign_bit_mask);
    const atan2_pair ax = (atan2_pair)((atan2_mask)x & ~sign_bit_mask);
    const atan2_mask swap = ax < ay; /* then pi/2 -+ atan(ax/ay) */
    const atan2_pair num = (atan2_pair)((swap & (atan2_mask)ax) | (~swap & (atan2_mask)ay));
    const atan2_pair den = (atan2_pair)((swap & (atan2_mask)ay) | (~swap & (atan2_mask)ax));
    /* arc_from_quotient; p + pe = t den by Dekker's product (ak_two_prod). */
    const atan2_pair t = num / den;
    const atan2_pair t_c = 134217729.0 * t, d_c = 134217729.0 * den;
    const atan2_pair t_hi = t_c - (t_c - t), d_hi = d_c - (d_c - den);
    const atan2_pair t_lo = t - t_hi, d_lo = den - d_hi;
    const atan2_pair p = t * den;
    const atan2_pair pe = (((t_hi * d_hi - p) + t_hi * d_lo) + t_lo * d_hi) + t_lo * d_lo;
    const atan2_pair e = ((num - p) - pe) / den;
    /* arc_kernel with_e, both of its forms; j = 0 (t < 1/32) takes the first. */
    const atan2_pair t32 = t * 32.0;
    const int j0 = (int)t32[0], j1 = (int)t32[1];
    const int q0 = 2 * sign_bit(x[0]) + (swap[0] != 0), q1 = 2 * sign_bit(x[1]) + (swap[1] != 0);
    const atan2_pair z = t * t;
    const atan2_pair poly_0 = (t * z) * (AK_ATAN_A0 + z * (AK_ATAN_A1 + z * (AK_ATAN_A2
                            + z * AK_ATAN_A3)));
    const atan2_pair tail_0 = (e - e * z) + poly_0;
    const atan2_pair h = t - (atan2_pair){CENTRE[j0], CENTRE[j1]};
    const atan2_pair h_c = 134217729.0 * h;
    const atan2_pair h_hi = h_c - (h_c - h);
    const atan2_pair h_lo = h - h_hi;
    const double *a0 = TAYLOR[j0], *a1 = TAYLOR[j1];
    atan2_pair poly = (atan2_pair){a0[7], a1[7]} + h * (atan2_pair){a0[8], a1[8]};
    for (int k = 6; k >= 0; k--) {
        poly = (atan2_pair){a0[k], a1[k]} + h * poly;
    }
    poly = (h * h) * poly;
    const atan2_pair slope = {SLOPE_HI[j0], SLOPE_HI[j1]};
    const atan2_pair tail_j = ((slope * h_lo + (atan2_pair){SLOPE_LO[j0], SLOPE_LO[j1]} * h)
                               + poly) + e * (slope + 2.0 * (atan2_pair){a0[0], a1[0]} * h);
    const atan2_mask first = t32 < 1.0;
    const atan2_pair lead = (atan2_pair)((first & (atan2_mask)t)
                                         | (~first & (atan2_mask)(slope * h_hi)));
    const atan2_pair tail = (atan2_pair)((first & (atan2_mask)tail_0)
                                         | (~first & (atan2_mask)tail_j));
    const atan2_pair sign = {SIGN[q0], SIGN[q1]};
    const atan2_pair head = {HEAD_HI[q0][j0], HEAD_HI[q1][j1]};
    /* ak_two_sum(head, sign lead) */
    const atan2_pair b = sign * lead;
    const atan2_pair s = head + b;
    const atan2_pair b_part = s - head;
    const atan2_pair se = (head - (s - b_part)) + (b - b_part);
    const atan2_pair result = s + (se + ((atan2_pair){HEAD_LO[q0][j0], HEAD_LO[q1][j1]}
                                         + sign * tail));
    /* result > 0 (t >= 2^-61): ak_atan2's negation for y < 0 sets the sign bit */
    return (atan2_pair)((atan2_mask)result | ((atan2_mask)y & sign_bit_mask));
}

/* The third argument by ak_atan2, started first, and the other two as a pair. Three calls of
 * ak_atan2 are bound by their long chains of dependent operations (two divisions, a polynomial
 * of degree 10) and the processor's window of pending instructions, hardly by their branches
 * (mispredicted ones resolve early): with the pair's operations serving two arguments each
 * (SSE2, NEON), the three chains fit in the window together. A pair off the usual path goes to
 * ak_atan2 (one branch, taken only for those). */
void ak_atan2_three(const double y[3], const double x[3], double out[3]) {
    const double y0 = y[0], y1 = y[1], y2 = y[2], x0 = x[0], x1 = x[1], x2 = x[2];
    const double third = ak_atan2(y2, x2);
    if (!(atan2_usual(y0, x0) & atan2_usual(y1, x1))) {
        out[0] = ak_atan2(y0, x0); /* out may alias y or x */
        out[1] = ak_atan2(y1, x1);
        out[2] = third;
        return;
    }
    const atan2_pair y_pair = {y0, y1}, x_pair = {x0, x1};
    const atan2_pair pair = atan2_usual_pair(y_pair, x_pair);
    out[0] = pair[0];
    out[1] = pair[1];
    out[2] = third;
}

#else /* the same bits, one after the other */

void ak_atan2_three(const double y[3], const double x[3], double out[3]) {
    const double y0 = y[0], y1 = y[1], y2 = y[2], x0 = x[0], x1 = x[1], x2 = x[2];
    out[0] = ak_atan2(y0, x0);
    out[1] = ak_atan2(y1, x1);
    out[2] = ak_atan2(y2, x2);
}

#endif

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
