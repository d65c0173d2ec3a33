/* Angles of a sequence from the attitude: the equations are stated in attitude_angles.h. */
#include "attitude_angles.h"

#include "elementary.h"

#include <math.h>
#include <stddef.h>

static const double PI = 3.14159265358979323846;
static const double TWO_PI = 6.28318530717958647692;

/* Axes of the chain (0-based, section 1), for the singular choice. */
typedef struct {
    int i, j, k;
    bool proper;
} chain_axes;

/* The angle x of R_a(x) from its row (or column) `line` != a of a matrix M that has the factor
 * R_a(x) on its right (row) or left (column); section 2. */
static double angle_from_row(int a, int line, double M[3][3]) {
    const int next = (a + 1) % 3, after = (a + 2) % 3;
    return line == next ? ak_atan2(-M[line][after], M[line][line])
                        : ak_atan2(M[line][next], M[line][line]);
}

static double angle_from_column(int a, int line, double M[3][3]) {
    const int next = (a + 1) % 3, after = (a + 2) % 3;
    return line == next ? ak_atan2(M[after][line], M[line][line])
                        : ak_atan2(-M[next][line], M[line][line]);
}

/* The elementary rotation matrix R_a(x). */
static void elementary(int a, double x, double E[3][3]) {
    const int next = (a + 1) % 3, after = (a + 2) % 3;
    double s, co;
    ak_sincos(x, &s, &co);
    for (int r = 0; r < 3; r++) {
        for (int col = 0; col < 3; col++) {
            E[r][col] = r == col ? 1.0 : 0.0;
        }
    }
    E[next][next] = co;
    E[next][after] = -s;
    E[after][next] = s;
    E[after][after] = co;
}

/* Inlined into each sequence's function (attitude_sequences.h), where the chain is constant and
 * the indices, signs and the order of theta fold away. */
#if defined(__GNUC__)
#define AK_CHAIN_INLINE __attribute__((always_inline)) inline
#else
#define AK_CHAIN_INLINE inline
#endif

/* nearbyint(x) in the rounding to nearest (ties to even) that the core assumes, without a call:
 * below 2^52, |x| + 2^52 rounds |x| to an integer and subtracting 2^52 is exact; the sign is
 * nearbyint's (-0 for x in [-1/2, 0]); from 2^52 on, x (also inf, NaN) is its own. */
static AK_CHAIN_INLINE double nearest_integer(double x) {
    const double two52 = 4503599627370496.0;
    const double a = fabs(x);
    return a < two52 ? copysign((a + two52) - two52, x) : x;
}

/* x + 2 pi n nearest to reference. Within 3 of it, n is a zero of the sign of reference - x
 * (nearbyint of a quotient below 1/2 in size), so x + (reference - x) 0 is the same bits. */
static AK_CHAIN_INLINE double unwrap(double x, double reference) {
    const double gap = reference - x;
    if (fabs(gap) < 3.0) {
        return x + gap * 0.0;
    }
    return x + TWO_PI * nearest_integer(gap / TWO_PI);
}

static double squared_distance(const double a[3], const double b[3]) {
    double sum = 0.0;
    for (int k = 0; k < 3; k++) {
        sum += (a[k] - b[k]) * (a[k] - b[k]);
    }
    return sum;
}

/* The singular choice (section 2): theta1 held at previous[0], theta3 from the rest. Rare, so
 * general over the chains and out of line. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static void singular_angles(bool space, const chain_axes *c, double R[3][3], double phi2,
                            const double previous[3], double theta[3]) {
    const int a1 = c->i, a2 = c->j, a3 = c->proper ? c->i : c->k;
    double E[3][3], M[3][3];
    const double held = previous[0];
    if (!space) { /* phi1 = theta1 held: M = R_a1(phi1)^T R = R_a2 R_a3 */
        elementary(a1, held, E);
        for (int r = 0; r < 3; r++) {
            for (int col = 0; col < 3; col++) {
                M[r][col] = E[0][r] * R[0][col] + E[1][r] * R[1][col] + E[2][r] * R[2][col];
            }
        }
        theta[2] = angle_from_row(a3, a2, M);
    } else { /* phi3 = theta1 held: M = R R_a3(phi3)^T = R_a1 R_a2 */
        elementary(a3, held, E);
        for (int r = 0; r < 3; r++) {
            for (int col = 0; col < 3; col++) {
                M[r][col] = R[r][0] * E[col][0] + R[r][1] * E[col][1] + R[r][2] * E[col][2];
            }
        }
        theta[2] = angle_from_column(a1, a2, M);
    }
    theta[0] = held;
    theta[1] = unwrap(phi2, previous[1]);
    /* theta2 at the singularity is +-pi/2 or 0/pi; the other set's theta2 (pi - x or -x) is the
     * same angle there up to 2 pi, so only theta2's unwrapping matters. */
    theta[2] = unwrap(theta[2], previous[2]);
}

/* *set = unwrap(x, reference) for a principal angle x (in [-pi, pi], or NaN), and whether it is
 * near: within 1/2 of reference, with |reference| < 1e9 so that the rounding of the unwrapping
 * stays far below the margin of section 2's choice. When |gap| < 3, *set - reference is -gap
 * (x - r = -(r - x); both exact when x = 0) and |reference| < pi + 1/2: the test is |gap| < 1/2. */
static AK_CHAIN_INLINE bool unwrap_near(double x, double reference, double *set) {
    const double gap = reference - x;
    if (fabs(gap) < 3.0) {
        *set = x + gap * 0.0;
        return fabs(gap) < 0.5;
    }
    *set = x + TWO_PI * nearest_integer(gap / TWO_PI);
    return fabs(*set - reference) < 0.5 && fabs(reference) < 1e9;
}

/* theta: the nearer to previous of the principal set (theta order) unwrapped, and the other
 * set unwrapped (section 2). Out of line: the usual step keeps the first. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static void nearer_set(bool proper, const double principal_set[3], const double unwrapped[3],
                       const double previous[3], double theta[3]) {
    const double other[3] = {
        unwrap(principal_set[0] + PI, previous[0]),
        unwrap(proper ? -principal_set[1] : PI - principal_set[1], previous[1]),
        unwrap(principal_set[2] + PI, previous[2])};
    const bool best = squared_distance(other, previous) < squared_distance(unwrapped, previous);
    for (int m = 0; m < 3; m++) {
        theta[m] = best ? other[m] : unwrapped[m];
    }
}

/* Sections 5 and 6 for the chain i, j, proper Euler or Tait-Bryan, theta in chain order
 * (body-fixed) or reversed (space-fixed). Reads `previous` and writes theta last, so that the
 * two may be the same array. */
static AK_CHAIN_INLINE bool chain_angles(int i, int j, bool proper, bool space, double R[3][3],
                                         const double previous[3], double theta[3],
                                         double *distance) {
    /* The principal chain angles (section 1): the arguments, then the three arctangents. */
    double y[3], x[3];
    const double d = ak_chain_arguments(i, j, proper, R, y, x);
    *distance = d;
    double phi[3];
    ak_atan2_three(y, x, phi); /* the bits of three ak_atan2, side by side */
    /* theta_k of chain angle m (sequences.h): reversed for space-fixed sequences. */
    const double first = space ? phi[2] : phi[0], last = space ? phi[0] : phi[2];
    if (previous == NULL) {
        theta[0] = first;
        theta[1] = phi[1];
        theta[2] = last;
        return false;
    }
    if (d < AK_ATTITUDE_SINGULAR_DISTANCE) {
        const chain_axes c = {i, j, 3 - i - j, proper};
        singular_angles(space, &c, R, phi[1], previous, theta);
        return true;
    }
    double set[3];
    /* All three, without a branch between them: nearer_set needs the whole unwrapped set. */
    const int near = (int)unwrap_near(first, previous[0], &set[0])
                     & (int)unwrap_near(phi[1], previous[1], &set[1])
                     & (int)unwrap_near(last, previous[2], &set[2]);
    if (near) {
        /* The other set is pi away in theta1 and theta3 (section 1): at squared distance above
         * 2 (pi - 1/2)^2 > 3/4, the most this one can have. */
        for (int m = 0; m < 3; m++) {
            theta[m] = set[m];
        }
        return false;
    }
    const double principal_set[3] = {first, phi[1], last};
    nearer_set(proper, principal_set, set, previous, theta);
    return false;
}

/* angles_body123 .. angles_space323 and their table ANGLES_OF_SEQUENCE, generated from the
 * sequences of codegen/project.py. */
#include "attitude_sequences.h"

ak_attitude_angles_function ak_attitude_angles_of(const ak_sequence *sequence) {
    return ANGLES_OF_SEQUENCE[sequence->kind][sequence->proper_euler != 0][sequence->axes[0] - 1]
                             [sequence->axes[1] - 1];
}

bool ak_attitude_angles(const ak_sequence *sequence, double R[3][3],
                        const double previous[3], double theta[3], double *distance) {
    return ak_attitude_angles_of(sequence)(R, previous, theta, distance);
}
