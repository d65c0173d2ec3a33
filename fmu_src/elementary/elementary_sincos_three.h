/* ak_sincos of three angles at once (the angles of a rotation sequence), bit for bit: the same
 * operations as ak_sincos's usual paths (elementary.h), without a branch per angle. Random
 * angles make ak_sincos's branches (no reduction or not, the quadrant) mispredict; here the
 * three angles run side by side, the reduction's result or x itself and the quadrant chosen by
 * bit masks, and one branch sends the rare angles to ak_sincos. */
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

#endif
