/* The angle extraction of fmu_src/core/attitude.c as it was before it became one function per
 * sequence (0.3.0 up to the commit that specialized it): general over the 24 sequences, kept
 * unchanged as the reference that tests/c/test_attitude_angles_bits.c compares with bit for bit. */
#include "attitude_angles_reference.h"

#include "attitude.h" /* AK_ATTITUDE_SINGULAR_DISTANCE */
#include "elementary.h"

#include <math.h>
#include <stddef.h>

static const double PI = 3.14159265358979323846;
static const double TWO_PI = 6.28318530717958647692;

/* Axes of the chain (0-based) and the parity e of section 5. */
typedef struct {
    int i, j, k;
    double e;
    bool proper;
} chain_axes;

static chain_axes axes_of(const ak_sequence *sequence) {
    chain_axes c;
    const bool space = sequence->kind == AK_SPACE_FIXED;
    c.i = sequence->axes[space ? 2 : 0] - 1;
    c.j = sequence->axes[1] - 1;
    c.k = 3 - c.i - c.j;
    c.e = (c.j == (c.i + 1) % 3) ? 1.0 : -1.0;
    c.proper = sequence->proper_euler != 0;
    return c;
}

/* The principal chain angles (section 5) and the distance. */
static void principal(const chain_axes *c, double R[3][3], double phi[3], double *distance) {
    const int i = c->i, j = c->j, k = c->k;
    const double e = c->e;
    if (c->proper) {
        *distance = sqrt(R[i][j] * R[i][j] + R[i][k] * R[i][k]);
        phi[1] = ak_atan2(*distance, R[i][i]);
        phi[0] = ak_atan2(R[j][i], -e * R[k][i]);
        phi[2] = ak_atan2(R[i][j], e * R[i][k]);
    } else {
        *distance = sqrt(R[i][i] * R[i][i] + R[i][j] * R[i][j]);
        phi[1] = ak_atan2(e * R[i][k], *distance);
        phi[0] = ak_atan2(-e * R[j][k], R[k][k]);
        phi[2] = ak_atan2(-e * R[i][j], R[i][i]);
    }
}

/* The angle x of R_a(x) from its row (or column) `line` != a of a matrix M that has the factor
 * R_a(x) on its right (row) or left (column); see attitude_angles.h, section 2. */
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

/* x + 2 pi n nearest to reference. Within 3 of it, n is a zero of the sign of reference - x
 * (nearbyint of a quotient below 1/2 in size), so x + (reference - x) 0 is the same bits. */
static double unwrap(double x, double reference) {
    const double gap = reference - x;
    if (fabs(gap) < 3.0) {
        return x + gap * 0.0;
    }
    return x + TWO_PI * nearbyint(gap / TWO_PI);
}

/* theta_k of chain angle m (sequences.h): reversed for space-fixed sequences. */
static int theta_index(const ak_sequence *sequence, int m) {
    return sequence->kind == AK_SPACE_FIXED ? 2 - m : m;
}

static double squared_distance(const double a[3], const double b[3]) {
    double sum = 0.0;
    for (int k = 0; k < 3; k++) {
        sum += (a[k] - b[k]) * (a[k] - b[k]);
    }
    return sum;
}

/* The singular choice (section 6): theta1 held at previous[0], theta3 from the rest. */
static void singular_angles(const ak_sequence *sequence, const chain_axes *c, double R[3][3],
                            const double phi_principal[3], const double previous[3],
                            double theta[3]) {
    const bool space = sequence->kind == AK_SPACE_FIXED;
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
    theta[1] = unwrap(phi_principal[1], previous[1]);
    /* theta2 at the singularity is +-pi/2 or 0/pi; the other set's theta2 (pi - x or -x) is the
     * same angle there up to 2 pi, so only theta2's unwrapping matters. */
    theta[2] = unwrap(theta[2], previous[2]);
}

bool reference_attitude_angles(const ak_sequence *sequence, double R[3][3],
                               const double previous[3], double theta[3], double *distance) {
    const chain_axes c = axes_of(sequence);
    double phi[3];
    principal(&c, R, phi, distance);
    if (previous != NULL && *distance < AK_ATTITUDE_SINGULAR_DISTANCE) {
        singular_angles(sequence, &c, R, phi, previous, theta);
        return true;
    }
    double sets[2][3];
    for (int m = 0; m < 3; m++) {
        sets[0][theta_index(sequence, m)] = phi[m];
    }
    if (previous == NULL) {
        for (int k = 0; k < 3; k++) {
            theta[k] = sets[0][k];
        }
        return false;
    }
    const double principal_set[3] = {sets[0][0], sets[0][1], sets[0][2]};
    bool near = true;
    for (int k = 0; k < 3; k++) {
        sets[0][k] = unwrap(sets[0][k], previous[k]);
        near = near && fabs(sets[0][k] - previous[k]) < 0.5 && fabs(previous[k]) < 1e9;
    }
    if (near) {
        /* The other set is pi away in theta1 and theta3 (section 5): at squared distance above
         * 2 (pi - 1/2)^2 > 3/4, the most this one can have; sizes below 1e9 keep the rounding
         * of the unwrapping far below that margin. */
        for (int k = 0; k < 3; k++) {
            theta[k] = sets[0][k];
        }
        return false;
    }
    const double other_middle = c.proper ? -phi[1] : PI - phi[1];
    sets[1][0] = principal_set[0] + PI;
    sets[1][1] = other_middle;
    sets[1][2] = principal_set[2] + PI;
    for (int k = 0; k < 3; k++) { /* sets[0] is unwrapped above */
        sets[1][k] = unwrap(sets[1][k], previous[k]);
    }
    const int best = squared_distance(sets[1], previous) < squared_distance(sets[0], previous);
    for (int k = 0; k < 3; k++) {
        theta[k] = sets[best][k];
    }
    return false;
}
