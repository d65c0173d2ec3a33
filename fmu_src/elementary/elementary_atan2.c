/* atan2, and three of them side by side, by the arc kernel (elementary_arc_kernel.h):
 * AttitudePropagator's angles of a rotation sequence. */
#include "elementary_arc_kernel.h"

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
