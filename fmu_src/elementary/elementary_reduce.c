/* Payne-Hanek reduction of huge arguments: x = n pi/2 + r for every finite |x| >= 2^20, exact
 * to about 2^-100 relative in r, from the bits of 2/pi (elementary_coefficients.h). Integer
 * arithmetic on 32-bit words, so every platform computes the same bits. */
#include "elementary.h"

#include <stdint.h>
#include <string.h>

static const uint32_t TWO_OVER_PI[AK_TWO_OVER_PI_WORDS] = AK_TWO_OVER_PI_BITS;

enum { WINDOW = 10, PRODUCT = WINDOW + 2 };

/* Bits pos .. pos + 63 (pos >= 0) of the little-endian number held in words[0 .. PRODUCT-1]. */
static uint64_t bits_at(const uint32_t words[PRODUCT], int pos) {
    const int q = pos / 32, shift = pos % 32;
    const uint64_t w0 = q < PRODUCT ? words[q] : 0u;
    const uint64_t w1 = q + 1 < PRODUCT ? words[q + 1] : 0u;
    const uint64_t w2 = q + 2 < PRODUCT ? words[q + 2] : 0u;
    uint64_t result = (w0 | (w1 << 32)) >> shift;
    if (shift > 0) {
        result |= w2 << (64 - shift);
    }
    return result;
}

/* v < 2^53 as a double, exactly, from two 32-bit integer conversions: a 64-bit one is an x87
 * instruction on 32-bit x86. */
static double from_53_bits(uint64_t v) {
    return (double)(int32_t)(v >> 26) * 0x1p26 + (double)(int32_t)(v & 0x3FFFFFFu);
}

static int leading_zeros(uint64_t v) {
    int n = 0;
    while (!(v & 0x8000000000000000u)) {
        v <<= 1;
        n++;
    }
    return n;
}

unsigned ak_reduce_pio2_huge(double x, double *hi, double *lo) {
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    const int negative_x = (int)(bits >> 63);
    /* |x| = m 2^e with m of 53 bits (|x| >= 2^20 is normal). */
    const uint64_t m = (bits & 0x000FFFFFFFFFFFFFu) | 0x0010000000000000u;
    const int e = (int)((bits >> 52) & 0x7FF) - 1075;
    /* Words before j0 give multiples of 4 (n mod 4 is all that matters): their weight in m 2^e
     * 2/pi is at least 2^(e - 32 j0) >= 4. The ten words from j0 leave an error below 2^-200. */
    const int j0 = e >= 2 ? (e - 2) / 32 : 0;
    uint32_t product[PRODUCT] = {0};
    const uint64_t m_low = m & 0xFFFFFFFFu, m_high = m >> 32;
    uint64_t carry = 0;
    for (int i = 0; i < WINDOW; i++) {
        const uint64_t t = (uint64_t)TWO_OVER_PI[j0 + WINDOW - 1 - i] * m_low + carry;
        product[i] = (uint32_t)t;
        carry = t >> 32;
    }
    product[WINDOW] = (uint32_t)carry;
    carry = 0;
    for (int i = 0; i < WINDOW; i++) {
        const uint64_t t = (uint64_t)TWO_OVER_PI[j0 + WINDOW - 1 - i] * m_high + product[i + 1] + carry;
        product[i + 1] = (uint32_t)t;
        carry = t >> 32;
    }
    product[WINDOW + 1] = (uint32_t)carry;
    /* |x| 2/pi = product 2^(e - 32 (j0 + WINDOW)): bit `one` of product has the weight 1. */
    const int one = 32 * (j0 + WINDOW) - e;
    unsigned n = (unsigned)(bits_at(product, one) & 3u);
    uint64_t f0 = bits_at(product, one - 64), f1 = bits_at(product, one - 128),
             f2 = bits_at(product, one - 192);
    int negative_r = 0;
    if (f0 >> 63) { /* fraction >= 1/2: the next n, and r = -(1 - fraction) */
        n = (n + 1u) & 3u;
        negative_r = 1;
        /* 2^192 - f0:f1:f2 = ~f0:~f1:~f2 + 1, the carry rippling through zero words */
        const uint64_t carry2 = f2 == 0u ? 1u : 0u;
        const uint64_t carry1 = (carry2 != 0u && f1 == 0u) ? 1u : 0u;
        f2 = ~f2 + 1u;
        f1 = ~f1 + carry2;
        f0 = ~f0 + carry1;
    }
    /* The fraction f0:f1:f2 2^-192, normalized: its top 106 bits as h + l. */
    int shift = 0;
    while (f0 == 0u && shift < 128) {
        f0 = f1;
        f1 = f2;
        f2 = 0u;
        shift += 64;
    }
    if (f0 == 0u) { /* impossible (pi is irrational), kept for safety */
        *hi = *lo = 0.0;
        return n;
    }
    const int c = leading_zeros(f0);
    if (c > 0) {
        f0 = (f0 << c) | (f1 >> (64 - c));
        f1 = (f1 << c) | (f2 >> (64 - c));
    }
    shift += c;
    const double h = from_53_bits(f0 >> 11) * ak_pow2(-53 - shift);
    const double l = from_53_bits(((f0 & 0x7FFu) << 42) | (f1 >> 22)) * ak_pow2(-106 - shift);
    /* r = (h + l) pi/2 in double-double. */
    double p, pe;
    ak_two_prod(h, AK_PIO2_HI, &p, &pe);
    pe += h * AK_PIO2_LO + l * AK_PIO2_HI;
    double r_hi, r_lo;
    ak_two_sum(p, pe, &r_hi, &r_lo);
    if (negative_r != negative_x) {
        r_hi = -r_hi;
        r_lo = -r_lo;
    }
    *hi = r_hi;
    *lo = r_lo;
    return negative_x ? (4u - n) & 3u : n;
}
