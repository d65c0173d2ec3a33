/* The project's own elementary functions: the same bits on every platform. The models
 * call these instead of the platform's libm, whose sin, cos, atan and atan2 round differently on
 * glibc, mingw-w64 and macOS. Methods, accuracy and the commands that measure it:
 * docs/elementary.md. Pure IEEE double arithmetic (no fma, no x87: -ffp-contract=off, and SSE2
 * on 32-bit x86), so each function is a fixed sequence of correctly rounded operations.
 *
 * ak_sincos is inline: its usual path (|x| < 2^20, Cody-Waite reduction and two polynomial
 * kernels) is where the models spend their time. Huge arguments go to the exact Payne-Hanek
 * reduction (elementary_reduce.c); atan and atan2 are in elementary_atan.c and elementary_atan2.c,
 * asin and acos in the tests' tests/c/elementary_asin_acos.c (no model calls them). */
#ifndef ANGULAR_KINEMATICS_ELEMENTARY_H
#define ANGULAR_KINEMATICS_ELEMENTARY_H

#include "elementary_coefficients.h"
#include "elementary_double_double.h"

#include <math.h>

/* Clang contracts a * b + c into an fma by default (GCC does not in ISO C mode, -std=c11): the
 * error-free transformations need every operation rounded on its own. The build passes
 * -ffp-contract=off to every compiler; this keeps a source FMU built without it right too. */
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif

/* Special values as C99 Annex F states for sin, cos, atan, atan2. */
double ak_atan(double x);
double ak_atan2(double y, double x);
/* out[k] = ak_atan2(y[k], x[k]) for k = 0, 1, 2, bit for bit, the three side by side (the angles
 * of a rotation sequence); out may alias y or x. */
void ak_atan2_three(const double y[3], const double x[3], double out[3]);

/* x = n pi/2 + hi + lo for finite |x| >= 2^20, |hi + lo| <= pi/4, hi + lo exact to about
 * 2^-100 relative (Payne-Hanek with the bits of 2/pi); returns n mod 4. */
unsigned ak_reduce_pio2_huge(double x, double *hi, double *lo);

/* The same for |x| < 2^20 (Cody-Waite): n = round(x 2/pi) < 2^20 and each P_i of at most 33
 * bits make n P_i exact; x - n P1 is exact too (Sterbenz: x and n P1 are within a factor 2),
 * and the two TwoSums keep every rounding error, so the only error is the rounding of n P4 and
 * of the tail (about 2^-130 absolute, while |hi + lo| >= 2^-60 for every double: the nearest
 * double to a multiple of pi/2 is about 2^-61 away from it). */
static inline unsigned ak_reduce_pio2(double x, double *hi, double *lo) {
    if (!(fabs(x) < 0x1p20)) {
        return ak_reduce_pio2_huge(x, hi, lo);
    }
    const double shifter = 0x1.8p52; /* adding it rounds to an integer */
    const double n = (x * AK_TWO_OVER_PI + shifter) - shifter;
    const double t1 = x - n * AK_PIO2_1;
    double s1, e1, s2, e2;
    ak_two_sum(t1, -n * AK_PIO2_2, &s1, &e1);
    ak_two_sum(s1, -n * AK_PIO2_3, &s2, &e2);
    ak_two_sum(s2, (e1 + e2) - n * AK_PIO2_4, hi, lo);
    return (unsigned)(int)n & 3u;
}

/* sin(r + rl) and cos(r + rl) for |r| <= 0.786, |rl| <= 2^-52 |r|, z = r^2 = zh + zl exactly. */
static inline double ak_sin_kernel(double r, double rl, double zh) {
    /* Estrin's scheme: the same polynomial in a third of Horner's chain of dependent operations
     * (it only adds a small correction to r, so its own rounding hardly shows). */
    const double z2 = zh * zh, z4 = z2 * z2;
    const double p = ((AK_SIN_S0 + zh * AK_SIN_S1) + z2 * (AK_SIN_S2 + zh * AK_SIN_S3))
                   + z4 * ((AK_SIN_S4 + zh * AK_SIN_S5) + z2 * AK_SIN_S6);
    /* sin(r + rl) = sin r + rl cos r; the tail is at most a tenth of r. */
    return r + ((r * zh) * p + rl * (1.0 - 0.5 * zh));
}

static inline double ak_cos_kernel(double r, double rl, double zh, double zl) {
    const double z2 = zh * zh, z4 = z2 * z2;
    const double p = ((AK_COS_C0 + zh * AK_COS_C1) + z2 * (AK_COS_C2 + zh * AK_COS_C3))
                   + z4 * (AK_COS_C4 + zh * AK_COS_C5);
    const double hz = 0.5 * zh;
    const double w = 1.0 - hz;
    /* 1 - hz rounded to w, its error (1 - w) - hz recovered exactly (Sterbenz twice), and the
     * exact square's low part: 1 - z/2 is as good as double-double before the final sum. */
    const double tail = (((1.0 - w) - hz) - 0.5 * zl) + (z2 * p - r * rl);
    return w + tail;
}

/* Inlined wherever the compiler allows it: the models call sincos at every step. */
#if defined(__GNUC__)
#define AK_ELEMENTARY_INLINE __attribute__((always_inline)) inline
#else
#define AK_ELEMENTARY_INLINE inline
#endif

/* *s = sin x, *c = cos x, with one argument reduction. */
static AK_ELEMENTARY_INLINE void ak_sincos(double x, double *s, double *c) {
    const double ax = fabs(x);
    double hi, lo;
    unsigned n = 0;
    if (ax < 0x1.921fb54442d18p-1) { /* pi/4 rounded down: no reduction */
        if (ax < 0x1p-27) {
            /* sin x = x and cos x = 1 to the last bit; keeps the sign of -0. */
            *s = x;
            *c = 1.0;
            return;
        }
        hi = x;
        lo = 0.0;
    } else if (ax < 0x1p20) {
        /* The usual reduction (the models' angles): x - k P1 and k P2 exact as in ak_reduce_pio2,
         * one rounded subtraction whose error Fast2Sum keeps (|r| > |k P2| once |hi| >= 2^-10),
         * k P3 rounded and k P4 left out: hi + lo within 2^-74 |hi|, renormalized so that
         * |lo| <= ulp(hi)/2. A shorter chain of operations than the exact reduction, which
         * takes the rare arguments near a multiple of pi/2. */
        const double shifter = 0x1.8p52; /* adding it rounds to an integer */
        const double k = (x * AK_TWO_OVER_PI + shifter) - shifter;
        const double r = x - k * AK_PIO2_1;
        const double w = k * AK_PIO2_2;
        const double y = r - w;
        if (fabs(y) >= 0x1p-10) {
            const double tail = ((r - y) - w) - k * AK_PIO2_3;
            hi = y + tail;
            lo = (y - hi) + tail;
            n = (unsigned)(int)k & 3u;
        } else {
            n = ak_reduce_pio2(x, &hi, &lo);
        }
    } else if (ax <= 0x1.fffffffffffffp+1023) {
        n = ak_reduce_pio2_huge(x, &hi, &lo);
    } else { /* inf or NaN: NaN */
        *s = *c = x - x;
        return;
    }
    double zh, zl;
    ak_two_square(hi, &zh, &zl);
    const double sr = ak_sin_kernel(hi, lo, zh), cr = ak_cos_kernel(hi, lo, zh, zl);
    switch (n) {
    case 0: *s = sr; *c = cr; break;
    case 1: *s = cr; *c = -sr; break;
    case 2: *s = -sr; *c = -cr; break;
    default: *s = -cr; *c = sr; break;
    }
}

static inline double ak_sin(double x) {
    double s, c;
    ak_sincos(x, &s, &c);
    return s;
}

static inline double ak_cos(double x) {
    double s, c;
    ak_sincos(x, &s, &c);
    return c;
}

#endif
