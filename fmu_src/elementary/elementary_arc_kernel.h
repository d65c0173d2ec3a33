/* The kernel of atan and atan2 (elementary_atan.c, elementary_atan2.c), the atan of a ratio
 * n/d <= 1 given as its numerator and denominator, plus the base of atan2's quadrant: the
 * quotient's rounding error is recovered with Dekker's exact product (no fma), so no quotient's
 * rounding reaches the result, and atan is a table of Taylor expansions. Inline: one copy in each
 * function's usual path. */
#ifndef ANGULAR_KINEMATICS_ELEMENTARY_ARC_KERNEL_H
#define ANGULAR_KINEMATICS_ELEMENTARY_ARC_KERNEL_H

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

static inline int sign_bit(double x) {
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

/* base + sign atan(n / d) for quadrant q, n and d doubles, 0 < n <= d, between 2^-600 and 2^600,
 * n/d >= 2^-61 (no product below overflows or underflows). The quotient t = n/d is corrected by
 * its exact residual (Dekker's product, no fma): n/d = t + e, so its rounding never reaches the
 * result. ((n - p) - pe is never -0: n - p is exact, +0 or not zero, and x - x is +0.) */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline double arc_from_quotient(double n, double d, int q) {
    const double t = n / d;
    double p, pe;
    ak_two_prod(t, d, &p, &pe);
    return arc_kernel(t, ((n - p) - pe) / d, 1, q);
}

#endif
