/* Little-endian encoding and the CRC-32 of the serialized FMU states of both FMI layers, and
 * the bitwise comparison of their setters: FMI-independent, header only. */
#ifndef ANGULAR_KINEMATICS_AK_BYTES_H
#define ANGULAR_KINEMATICS_AK_BYTES_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "ak_compiler.h"

_Static_assert(sizeof(double) == 8, "the layouts store IEEE 754 binary64 doubles");

/* CRC-32 of IEEE 802.3 (reflected, polynomial 0xEDB88320), as zlib's crc32. */
static inline uint32_t ak_crc32(const unsigned char *bytes, size_t n) {
    uint32_t crc = 0xFFFFFFFFu;
    for (size_t i = 0; i < n; i++) {
        crc ^= bytes[i];
        for (int bit = 0; bit < 8; bit++) {
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
        }
    }
    return ~crc;
}

/* True when a and b are the same bits. A setter stores a new value only as a change when this is
 * false: +0 replacing -0 is a change (outputs may carry the sign of a zero), an equal value is
 * not (masters often set unchanged inputs). */
static inline bool ak_same_double(double a, double b) {
    uint64_t x, y;
    memcpy(&x, &a, sizeof x);
    memcpy(&y, &b, sizeof y);
    return x == y;
}

/* What ak_store_if_finite did. */
typedef enum { AK_STORE_REFUSED, AK_STORE_SAME, AK_STORE_CHANGED } ak_store_result;

/* A kept set's store: n doubles of src into dst only if every one is finite (AK_STORE_REFUSED:
 * one is NaN or infinite, nothing stored; the caller's full check names it),
 * and says whether any bit changed (same rule as ak_same_double). One pass without a branch per
 * value, then one copy: this runs at every communication point of every master. */
static AK_ALWAYS_INLINE ak_store_result ak_store_if_finite(double *dst, const double *src, size_t n) {
    const uint64_t exponent = 0x7FF0000000000000u;
    const uint64_t carry = 0x0010000000000000u; /* added to the exponent: reaches the sign bit
                                                   only from all ones (Inf or NaN) */
    uint64_t not_finite = 0, changed = 0;
    for (size_t i = 0; i < n; i++) { /* and, add, xor, or: vectorizes on every target */
        uint64_t s, d;
        memcpy(&s, &src[i], sizeof s);
        memcpy(&d, &dst[i], sizeof d);
        not_finite |= (s & exponent) + carry;
        changed |= s ^ d;
    }
    if ((not_finite >> 63) != 0) {
        return AK_STORE_REFUSED;
    }
    for (size_t i = 0; i < n; i++) { /* not memcpy: gcc may make that a slow rep movs */
        dst[i] = src[i];
    }
    return changed != 0 ? AK_STORE_CHANGED : AK_STORE_SAME;
}

static inline void ak_put_u32(unsigned char *p, uint32_t x) {
    for (int i = 0; i < 4; i++) {
        p[i] = (unsigned char)(x >> (8 * i));
    }
}

static inline uint32_t ak_get_u32(const unsigned char *p) {
    uint32_t x = 0;
    for (int i = 0; i < 4; i++) {
        x |= (uint32_t)p[i] << (8 * i);
    }
    return x;
}

static inline void ak_put_f64(unsigned char *p, double value) {
    uint64_t x;
    memcpy(&x, &value, sizeof x);
    for (int i = 0; i < 8; i++) {
        p[i] = (unsigned char)(x >> (8 * i));
    }
}

static inline double ak_get_f64(const unsigned char *p) {
    uint64_t x = 0;
    for (int i = 0; i < 8; i++) {
        x |= (uint64_t)p[i] << (8 * i);
    }
    double value;
    memcpy(&value, &x, sizeof value);
    return value;
}

#endif
