/* ak_sincos of three angles at once (the angles of a rotation sequence), bit for bit: the same
 * operations as ak_sincos's usual paths (elementary.h), without a branch per angle. Random
 * angles make ak_sincos's branches (no reduction or not, the quadrant) mispredict; here the
 * three angles run side by side, the reduction's result or x itself and the quadrant chosen by
 * bit masks, and one branch sends the rare angles to ak_sincos. With GNU C (gcc, clang) as two
 * pairs of doubles, each operation on both lanes (SSE2, NEON). */
#ifndef ANGULAR_KINEMATICS_ELEMENTARY_SINCOS_THREE_H
#define ANGULAR_KINEMATICS_ELEMENTARY_SINCOS_THREE_H

#include <stdbool.h>
#include <stdint.h>
#include <string.h>

#include "elementary.h"

static inline uint64_t ak_bits_of(double x) {
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    return bits;
}

static inline double ak_double_of(uint64_t bits) {
    double x;
    memcpy(&x, &bits, sizeof x);
    return x;
}

#if defined(__GNUC__) /* and clang: vectors of two doubles, each operation lane by lane */

typedef double ak_sincos_pair __attribute__((vector_size(16)));
typedef uint64_t ak_sincos_bits __attribute__((vector_size(16)));

/* ak_sin_kernel and ak_cos_kernel (elementary.h) for two arguments: the same operations in the
 * same order, each IEEE operation rounding each lane as the scalar one does. */
static AK_ELEMENTARY_INLINE ak_sincos_pair ak_sin_kernel_pair(ak_sincos_pair r, ak_sincos_pair rl,
                                                              ak_sincos_pair zh) {
    const ak_sincos_pair z2 = zh * zh, z4 = z2 * z2;
    const ak_sincos_pair p = ((AK_SIN_S0 + zh * AK_SIN_S1) + z2 * (AK_SIN_S2 + zh * AK_SIN_S3))
                           + z4 * ((AK_SIN_S4 + zh * AK_SIN_S5) + z2 * AK_SIN_S6);
    return r + ((r * zh) * p + rl * (1.0 - 0.5 * zh));
}

static AK_ELEMENTARY_INLINE ak_sincos_pair ak_cos_kernel_pair(ak_sincos_pair r, ak_sincos_pair rl,
                                                              ak_sincos_pair zh,
                                                              ak_sincos_pair zl) {
    const ak_sincos_pair z2 = zh * zh, z4 = z2 * z2;
    const ak_sincos_pair p = ((AK_COS_C0 + zh * AK_COS_C1) + z2 * (AK_COS_C2 + zh * AK_COS_C3))
                           + z4 * (AK_COS_C4 + zh * AK_COS_C5);
    const ak_sincos_pair hz = 0.5 * zh;
    const ak_sincos_pair w = 1.0 - hz;
    const ak_sincos_pair tail = (((1.0 - w) - hz) - 0.5 * zl) + (z2 * p - r * rl);
    return w + tail;
}

/* sin and cos of two angles by ak_sincos's usual paths (2^-27 <= |x| < pi/4, no reduction, or
 * pi/4 <= |x| < 2^20 with the short reduction, its |y| >= 2^-10), the reduction computed for
 * both and x itself or its result chosen, and the quadrant, by bit masks. Returns, per lane, all
 * ones when the angle takes one of those paths (then *s, *c are ak_sincos's bits), else 0. */
static AK_ELEMENTARY_INLINE ak_sincos_bits ak_sincos_pair_usual(ak_sincos_pair x,
                                                                ak_sincos_pair *s,
                                                                ak_sincos_pair *c) {
    const ak_sincos_bits sign_bit = {0x8000000000000000u, 0x8000000000000000u};
    const ak_sincos_pair ax = (ak_sincos_pair)((ak_sincos_bits)x & ~sign_bit);
    const double shifter = 0x1.8p52; /* adding it rounds to an integer */
    const ak_sincos_pair shifted = x * AK_TWO_OVER_PI + shifter;
    const ak_sincos_pair k = shifted - shifter;
    const ak_sincos_pair r = x - k * AK_PIO2_1;
    const ak_sincos_pair w = k * AK_PIO2_2;
    const ak_sincos_pair y = r - w;
    const ak_sincos_pair tail = ((r - y) - w) - k * AK_PIO2_3;
    const ak_sincos_pair h = y + tail;
    const ak_sincos_pair l = (y - h) + tail;
    const ak_sincos_pair ay = (ak_sincos_pair)((ak_sincos_bits)y & ~sign_bit);
    const ak_sincos_bits small = (ak_sincos_bits)(ax < 0x1.921fb54442d18p-1); /* pi/4 down */
    const ak_sincos_bits usual = (ak_sincos_bits)(ax >= 0x1p-27) & (ak_sincos_bits)(ax < 0x1p20) &
                                 (small | (ak_sincos_bits)(ay >= 0x1p-10));
    /* small: hi = x, lo = 0, n = 0 (as ak_sincos_three's scalar form, below) */
    const ak_sincos_pair hi =
        (ak_sincos_pair)(((ak_sincos_bits)x & small) | ((ak_sincos_bits)h & ~small));
    const ak_sincos_pair lo = (ak_sincos_pair)((ak_sincos_bits)l & ~small);
    const ak_sincos_bits n = (ak_sincos_bits)shifted & 3u & ~small;
    /* ak_two_square(hi) */
    const ak_sincos_pair split = 134217729.0 * hi;
    const ak_sincos_pair hi_h = split - (split - hi), hi_l = hi - hi_h;
    const ak_sincos_pair zh = hi * hi;
    const ak_sincos_pair zl = ((hi_h * hi_h - zh) + 2.0 * hi_h * hi_l) + hi_l * hi_l;
    const ak_sincos_bits sr = (ak_sincos_bits)ak_sin_kernel_pair(hi, lo, zh);
    const ak_sincos_bits cr = (ak_sincos_bits)ak_cos_kernel_pair(hi, lo, zh, zl);
    const ak_sincos_bits swap = -(n & 1u);
    /* sin flips its sign in quadrants 2, 3: -(n & 2) is 0 or all ones but the last bit (not the
     * shift (n & 2) << 62: gcc -fanalyzer takes a vector's lane count for its width); cos flips
     * in 1, 2: where sin does, unless n is odd. */
    const ak_sincos_bits flip_s = -(n & 2u) & sign_bit;
    *s = (ak_sincos_pair)(((sr & ~swap) | (cr & swap)) ^ flip_s);
    *c = (ak_sincos_pair)(((cr & ~swap) | (sr & swap)) ^ (flip_s ^ (swap & sign_bit)));
    return usual;
}

/* s[k] = sin x[k], c[k] = cos x[k], each the bits of ak_sincos, when every x[k] takes one of
 * ak_sincos's two usual paths: 2^-27 <= |x| < pi/4 (no reduction), or pi/4 <= |x| < 2^20 with
 * the short reduction (its |y| >= 2^-10). False, nothing written, otherwise. Two angles as a
 * pair and the third in a pair of its own: half the operations of three scalar chains (SSE2,
 * NEON), the same bits. */
static AK_ELEMENTARY_INLINE bool ak_sincos_three_usual(const double x[3], double s[3],
                                                       double c[3]) {
    ak_sincos_pair s01, c01, s2, c2;
    const ak_sincos_bits usual = ak_sincos_pair_usual((ak_sincos_pair){x[0], x[1]}, &s01, &c01) &
                                 ak_sincos_pair_usual((ak_sincos_pair){x[2], x[2]}, &s2, &c2);
    if ((usual[0] & usual[1]) == 0) {
        return false;
    }
    s[0] = s01[0];
    s[1] = s01[1];
    s[2] = s2[0];
    c[0] = c01[0];
    c[1] = c01[1];
    c[2] = c2[0];
    return true;
}

#else /* the same bits, three scalar chains side by side */

/* s[k] = sin x[k], c[k] = cos x[k], each the bits of ak_sincos, when every x[k] takes one of
 * ak_sincos's two usual paths: 2^-27 <= |x| < pi/4 (no reduction), or pi/4 <= |x| < 2^20 with
 * the short reduction (its |y| >= 2^-10). False, nothing written, otherwise. */
static AK_ELEMENTARY_INLINE bool ak_sincos_three_usual(const double x[3], double s[3],
                                                       double c[3]) {
    double hi[3], lo[3];
    uint64_t n[3];
    unsigned usual = 1;
    for (int i = 0; i < 3; i++) {
        const double ax = fabs(x[i]);
        /* ak_sincos's reduction, computed for every angle (unused when |x| < pi/4). */
        const double shifter = 0x1.8p52; /* adding it rounds to an integer */
        const double shifted = x[i] * AK_TWO_OVER_PI + shifter;
        const double k = shifted - shifter;
        const double r = x[i] - k * AK_PIO2_1;
        const double w = k * AK_PIO2_2;
        const double y = r - w;
        const double tail = ((r - y) - w) - k * AK_PIO2_3;
        const double h = y + tail;
        const double l = (y - h) + tail;
        const unsigned small = ax < 0x1.921fb54442d18p-1; /* pi/4 rounded down */
        usual &= (unsigned)(ax >= 0x1p-27) & (unsigned)(ax < 0x1p20) &
                 (small | (unsigned)(fabs(y) >= 0x1p-10));
        /* k mod 4 from the low bits of the shifted sum (k + 1.5 2^52, |k| < 2^51): the value of
         * (unsigned)(int)k & 3 where it is used, and no conversion of a huge k. */
        const uint64_t keep_x = -(uint64_t)small; /* all ones: hi = x, lo = 0, n = 0 */
        hi[i] = ak_double_of((ak_bits_of(x[i]) & keep_x) | (ak_bits_of(h) & ~keep_x));
        lo[i] = ak_double_of(ak_bits_of(l) & ~keep_x);
        n[i] = ak_bits_of(shifted) & 3u & ~keep_x;
    }
    if (!usual) {
        return false;
    }
    for (int i = 0; i < 3; i++) {
        double zh, zl;
        ak_two_square(hi[i], &zh, &zl);
        const uint64_t sr = ak_bits_of(ak_sin_kernel(hi[i], lo[i], zh));
        const uint64_t cr = ak_bits_of(ak_cos_kernel(hi[i], lo[i], zh, zl));
        /* Quadrant n: (s, c) = (sr, cr), (cr, -sr), (-sr, -cr), (-cr, sr); a negation is the
         * flip of the sign bit. */
        const uint64_t swap = -(n[i] & 1u);
        s[i] = ak_double_of(((sr & ~swap) | (cr & swap)) ^ ((n[i] & 2u) << 62));
        c[i] = ak_double_of(((cr & ~swap) | (sr & swap)) ^ (((n[i] + 1u) & 2u) << 62));
    }
    return true;
}

#endif /* __GNUC__ */

#endif
