/* Error-free transformations on IEEE doubles (Knuth, Dekker, Veltkamp), without fma(): the
 * elementary functions carry a double-double tail through them. Every operation is one rounded
 * IEEE double operation, so the results depend on no platform's fma or extended precision. */
#ifndef ANGULAR_KINEMATICS_ELEMENTARY_DOUBLE_DOUBLE_H
#define ANGULAR_KINEMATICS_ELEMENTARY_DOUBLE_DOUBLE_H

#include <stdint.h>
#include <string.h>

/* s + e = a + b exactly, whatever the magnitudes (Knuth's TwoSum). */
static inline void ak_two_sum(double a, double b, double *s, double *e) {
    const double sum = a + b;
    const double b_part = sum - a;
    *e = (a - (sum - b_part)) + (b - b_part);
    *s = sum;
}

/* a = hi + lo with hi of 26 significant bits, so that products of halves are exact (Veltkamp);
 * |a| < 2^995, else a * (2^27 + 1) overflows. */
static inline void ak_split(double a, double *hi, double *lo) {
    const double c = 134217729.0 * a;
    const double h = c - (c - a);
    *hi = h;
    *lo = a - h;
}

/* p + e = a b exactly (Dekker's TwoProduct), when |a|, |b| < 2^995 and e does not underflow. */
static inline void ak_two_prod(double a, double b, double *p, double *e) {
    double ah, al, bh, bl;
    ak_split(a, &ah, &al);
    ak_split(b, &bh, &bl);
    const double product = a * b;
    *e = ((ah * bh - product) + ah * bl + al * bh) + al * bl;
    *p = product;
}

/* p + e = a^2 exactly, as ak_two_prod(a, a) with one split. */
static inline void ak_two_square(double a, double *p, double *e) {
    double ah, al;
    ak_split(a, &ah, &al);
    const double product = a * a;
    *e = ((ah * ah - product) + 2.0 * ah * al) + al * al;
    *p = product;
}

/* 2^k for -1022 <= k <= 1023, from its bits (exact, no libm). */
static inline double ak_pow2(int k) {
    const uint64_t bits = (uint64_t)(k + 1023) << 52;
    double d;
    memcpy(&d, &bits, sizeof d);
    return d;
}

/* The biased exponent field of x (0 for zero and subnormals, 2047 for inf and NaN). */
static inline int ak_exponent_field(double x) {
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    return (int)((bits >> 52) & 0x7FF);
}

#endif
