/* ak_attitude_angles (one function per sequence, fmu_src/core/attitude.c) against the general
 * implementation it replaced (attitude_angles_reference.c), bit for bit: theta, the distance and
 * the returned bool, for all 24 sequences, through both entries (ak_attitude_angles and the
 * function of ak_attitude_angles_of). Inputs: random rotations from random unit quaternions, with
 * previous sets near either angle set (offsets of 2 pi n, up to 1e9 and beyond), far and huge
 * ones, previous == NULL, previous == theta (the same array); rotations at, near and just off
 * the singular configuration; matrices with signed zeros; ties of the unwrapping's rounding;
 * infinities and NaNs. Every output is compared bit for bit, but a NaN only as a NaN: the sign
 * and payload of a NaN that arithmetic makes are not specified by IEEE 754, and compilers swap
 * the operands of a sum, so they differ even between two builds of the same code (a NaN in R,
 * or an infinite held angle at the singular configuration, shows it). */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "attitude.h"
#include "attitude_angles_reference.h"
#include "kinematics_general.h"
#include "test_check.h"

#define RANDOM_ROTATIONS 200000 /* per sequence */

static const double PI = 3.14159265358979323846;
static const double TWO_PI = 6.28318530717958647692;

/* Deterministic pseudo-random numbers (no global state: the caller keeps the seed). */
static uint64_t next_random(uint64_t *seed) {
    *seed = *seed * 6364136223846793005ULL + 1442695040888963407ULL;
    return *seed >> 11;
}

static double uniform(uint64_t *seed) { /* [-1, 1) */
    return (double)next_random(seed) / 4503599627370496.0 - 1.0;
}

static int below(uint64_t *seed, int n) { /* 0 .. n-1 */
    return (int)(next_random(seed) % (uint64_t)n);
}

typedef struct {
    long compared;
    long singular;      /* comparisons where the singular choice was taken */
    long other_branch;  /* comparisons where theta is not the unwrapped principal set */
    long mismatches;
} tally;

static bool same_bits(double a, double b) {
    if (a != a && b != b) {
        return true;
    }
    return memcmp(&a, &b, sizeof a) == 0;
}

/* One input, both implementations (the new one through ak_attitude_angles or, every other
 * time, the function of ak_attitude_angles_of); previous_kind: 0 NULL, 1 the given set, 2 the
 * given set as the output array too. The reference's theta goes to `expected`. */
static void compare(const ak_sequence *sequence, double R[3][3], const double previous[3],
                    int previous_kind, tally *t, double expected[3]) {
    const ak_attitude_angles_function of = t->compared % 2 ? ak_attitude_angles_of(sequence) : NULL;
    double got[3], d_expected = -1.0, d_got = -2.0;
    bool r_expected, r_got;
    if (previous_kind == 2) {
        memcpy(expected, previous, 3 * sizeof *expected);
        memcpy(got, previous, sizeof got);
        r_expected = reference_attitude_angles(sequence, R, expected, expected, &d_expected);
        r_got = of != NULL ? of(R, got, got, &d_got)
                           : ak_attitude_angles(sequence, R, got, got, &d_got);
    } else {
        const double *p = previous_kind == 0 ? NULL : previous;
        r_expected = reference_attitude_angles(sequence, R, p, expected, &d_expected);
        r_got = of != NULL ? of(R, p, got, &d_got)
                           : ak_attitude_angles(sequence, R, p, got, &d_got);
    }
    bool ok = r_got == r_expected && same_bits(d_got, d_expected);
    for (int k = 0; k < 3; k++) {
        ok = ok && same_bits(got[k], expected[k]);
    }
    t->compared++;
    t->singular += r_expected;
    if (!ok) {
        t->mismatches++;
        ak_check(false,
                 "%s, previous kind %d: theta %a %a %a d %a (%d) expected %a %a %a d %a (%d)",
                 sequence->name, previous_kind, got[0], got[1], got[2], d_got, r_got,
                 expected[0], expected[1], expected[2], d_expected, r_expected);
    }
}

/* The other angle set of the principal set p (theta order, attitude_angles.h, section 1). */
static void other_set(const ak_sequence *sequence, const double p[3], double o[3]) {
    o[0] = p[0] + PI;
    o[1] = sequence->proper_euler ? -p[1] : PI - p[1];
    o[2] = p[2] + PI;
}

/* A previous set for an attitude with principal set p: near either set with offsets of 2 pi n
 * and noise of several sizes (across the 1/2 and 3 of the unwrapping), far, huge or special. */
static void make_previous(const ak_sequence *sequence, const double p[3], uint64_t *seed,
                          double previous[3]) {
    static const double TURNS[] = {0.0, 1.0, 3.0, 1e3, 1e6, 1.5e8, 1.6e8, 1e12, 1e16, 1e17};
    static const double NOISE[] = {0.0, 1e-12, 0.1, 0.45, 0.55, 2.9, 3.1, 4.0};
    static const double SPECIAL[] = {0.0, -0.0, INFINITY, -INFINITY, NAN, 1e9, -1e9, 1e300};
    double o[3];
    other_set(sequence, p, o);
    const double *base = below(seed, 2) ? o : p;
    const int kind = below(seed, 8);
    for (int k = 0; k < 3; k++) {
        const double turns = TURNS[below(seed, 10)];
        const double n = nearbyint(turns * uniform(seed));
        const double noise = NOISE[below(seed, 8)] * uniform(seed);
        switch (kind) {
        case 6: /* far: any size */
            previous[k] = uniform(seed) * pow(10.0, below(seed, 21));
            break;
        case 7: /* an angle of a special value, the others near */
            previous[k] = below(seed, 3) == 0 ? SPECIAL[below(seed, 8)] : base[k] + noise;
            break;
        default: /* near a set, some angles 2 pi n away */
            previous[k] = base[k] + TWO_PI * n + noise;
        }
    }
}

static void random_unit_quaternion(uint64_t *seed, double q[4]) {
    double n;
    do {
        n = 0.0;
        for (int k = 0; k < 4; k++) {
            q[k] = uniform(seed);
            n += q[k] * q[k];
        }
    } while (n > 1.0 || n < 1e-6);
    for (int k = 0; k < 4; k++) {
        q[k] /= sqrt(n);
    }
}

/* Random rotations: the principal set, then a previous set of each kind. */
static void random_rotations(const ak_sequence *sequence, uint64_t *seed, tally *t) {
    for (int n = 0; n < RANDOM_ROTATIONS; n++) {
        double q[4], R[3][3], p[3], previous[3];
        random_unit_quaternion(seed, q);
        ak_quat_to_matrix(q, R);
        compare(sequence, R, NULL, 0, t, p);
        make_previous(sequence, p, seed, previous);
        double theta[3];
        compare(sequence, R, previous, 1 + below(seed, 2), t, theta);
        /* theta1 pi away from the principal one, up to turns: the other set was taken. */
        if (fabs(theta[0]) < 1e6 && fabs(remainder(theta[0] - p[0], TWO_PI)) > 1.0) {
            t->other_branch++;
        }
    }
}

/* At, near and just off the singular configuration: theta2 = middle + delta, delta 0, tiny, or
 * with the distance around AK_ATTITUDE_SINGULAR_DISTANCE; R from the angles and from the
 * quaternion of the angles. */
static void singular_rotations(const ak_sequence *sequence, uint64_t *seed, tally *t) {
    const double middles[2][2] = {{PI / 2, -PI / 2}, {0.0, PI}};
    for (int n = 0; n < 20000; n++) {
        const double middle = middles[sequence->proper_euler != 0][below(seed, 2)];
        double delta;
        switch (below(seed, 4)) {
        case 0:
            delta = 0.0;
            break;
        case 1:
            delta = uniform(seed) * pow(10.0, -7.0 - 10.0 * fabs(uniform(seed)));
            break;
        default: /* the distance within a few percent of the threshold, both sides */
            delta = AK_ATTITUDE_SINGULAR_DISTANCE * (1.0 + 0.05 * uniform(seed))
                    * (below(seed, 2) ? 1.0 : -1.0);
        }
        const double angles[3] = {PI * uniform(seed), middle + delta, PI * uniform(seed)};
        double R[3][3], p[3], theta[3], previous[3];
        if (below(seed, 2)) {
            ak_general_rotation_matrix(sequence, angles, R);
        } else {
            double q[4];
            ak_general_quaternion(sequence, angles, q);
            ak_quat_to_matrix(q, R);
        }
        compare(sequence, R, NULL, 0, t, p);
        if (below(seed, 2)) {
            make_previous(sequence, p, seed, previous);
        } else { /* the generating angles, some turns away */
            for (int k = 0; k < 3; k++) {
                previous[k] = angles[k] + TWO_PI * (double)(below(seed, 5) - 2);
            }
        }
        compare(sequence, R, previous, 1 + below(seed, 2), t, theta);
    }
}

/* Matrices with exact zeros of either sign: the rotations by multiples of pi/2 and pi/4 about
 * the axes and their products, then each zero entry given a random sign. */
static void signed_zero_rotations(const ak_sequence *sequence, uint64_t *seed, tally *t) {
    const double values[] = {0.0, -0.0, 0.5, -0.5, 1.0, -1.0, 0.70710678118654752440,
                             -0.70710678118654752440};
    for (int n = 0; n < 20000; n++) {
        double q[4], norm = 0.0;
        for (int k = 0; k < 4; k++) {
            q[k] = values[below(seed, 8)];
            norm += q[k] * q[k];
        }
        if (norm == 0.0) {
            continue;
        }
        for (int k = 0; k < 4; k++) {
            q[k] /= sqrt(norm);
        }
        double R[3][3], p[3], theta[3], previous[3];
        ak_quat_to_matrix(q, R);
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 3; c++) {
                if (R[r][c] == 0.0 || fabs(R[r][c]) < 1e-300) {
                    R[r][c] = below(seed, 2) ? 0.0 : -0.0;
                }
            }
        }
        compare(sequence, R, NULL, 0, t, p);
        if (below(seed, 2)) {
            make_previous(sequence, p, seed, previous);
        } else { /* signed zeros, the principal angles exactly, or 2 pi n from them */
            for (int k = 0; k < 3; k++) {
                const int choice = below(seed, 4);
                previous[k] = choice == 0   ? 0.0
                              : choice == 1 ? -0.0
                              : choice == 2 ? p[k]
                                            : p[k] + TWO_PI * (double)(below(seed, 7) - 3);
            }
        }
        compare(sequence, R, previous, 1 + below(seed, 2), t, theta);
    }
}

/* Ties of the unwrapping's rounding: (previous - x) / 2 pi exactly n + 1/2 (rounded to even).
 * Returns how many such inputs were compared. */
static long rounding_ties(const ak_sequence *sequence, uint64_t *seed, tally *t) {
    long ties = 0;
    for (int n = 0; n < 400; n++) {
        double q[4], R[3][3], p[3], theta[3];
        if (n % 2 == 0) {
            q[0] = 1.0, q[1] = q[2] = q[3] = 0.0; /* the principal angles are zeros */
        } else {
            random_unit_quaternion(seed, q);
        }
        ak_quat_to_matrix(q, R);
        compare(sequence, R, NULL, 0, t, p);
        const int m = below(seed, 3);
        const double half = (double)(below(seed, 2000) - 1000) + 0.5;
        double previous[3] = {p[0], p[1], p[2]};
        const double centre = p[m] + TWO_PI * half;
        for (int ulps = -4; ulps <= 4; ulps++) { /* some of these divide to half exactly */
            double candidate = centre;
            for (int u = 0; u < abs(ulps); u++) {
                candidate = nextafter(candidate, ulps > 0 ? INFINITY : -INFINITY);
            }
            previous[m] = candidate;
            ties += (candidate - p[m]) / TWO_PI == half;
            compare(sequence, R, previous, 1, t, theta);
        }
    }
    return ties;
}

/* NaNs, infinities and extremes in R. */
static void special_matrices(const ak_sequence *sequence, uint64_t *seed, tally *t) {
    const double specials[] = {NAN, -NAN, INFINITY, -INFINITY, 1e308, 0x1p-1074};
    for (int n = 0; n < 2000; n++) {
        double q[4], R[3][3], p[3], theta[3], previous[3];
        random_unit_quaternion(seed, q);
        ak_quat_to_matrix(q, R);
        compare(sequence, R, NULL, 0, t, p);
        R[below(seed, 3)][below(seed, 3)] = specials[below(seed, 6)];
        if (below(seed, 2)) {
            R[below(seed, 3)][below(seed, 3)] = specials[below(seed, 6)];
        }
        make_previous(sequence, p, seed, previous);
        compare(sequence, R, NULL, 0, t, theta);
        compare(sequence, R, previous, 1 + below(seed, 2), t, theta);
    }
}

int main(void) {
    uint64_t seed = 24;
    long compared = 0, ties = 0;
    for (int s = 0; s < AK_SEQUENCE_COUNT; s++) {
        const ak_sequence *sequence = &AK_SEQUENCES[s];
        tally t = {0, 0, 0, 0};
        random_rotations(sequence, &seed, &t);
        tally near_singular = {0, 0, 0, 0};
        singular_rotations(sequence, &seed, &near_singular);
        signed_zero_rotations(sequence, &seed, &t);
        const long sequence_ties = rounding_ties(sequence, &seed, &t);
        special_matrices(sequence, &seed, &t);
        /* A copy of the table entry finds the same function. */
        const ak_sequence copy = *sequence;
        ak_check(ak_attitude_angles_of(&copy) == ak_attitude_angles_of(sequence),
                 "%s: a copy of the sequence finds its function", sequence->name);
        /* The inputs reach every branch: the other set, the singular choice both ways. */
        ak_check(t.other_branch > 1000, "%s: %ld inputs on the other branch", sequence->name,
                 t.other_branch);
        ak_check(near_singular.singular > 1000
                     && near_singular.compared - near_singular.singular > 1000,
                 "%s: %ld of %ld near-singular inputs took the singular choice", sequence->name,
                 near_singular.singular, near_singular.compared);
        ak_check(sequence_ties > 0, "%s: no exact tie of the unwrapping's rounding was reached",
                 sequence->name);
        ak_check(t.mismatches + near_singular.mismatches == 0, "%s: %ld mismatches",
                 sequence->name, t.mismatches + near_singular.mismatches);
        compared += t.compared + near_singular.compared;
        ties += sequence_ties;
    }
    printf("%ld inputs over %d sequences (%ld exact ties), %d failure(s)\n", compared,
           AK_SEQUENCE_COUNT, ties, ak_check_failures());
    return ak_check_exit_status();
}
