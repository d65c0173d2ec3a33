/*
 * Angles of any of the 24 rotation sequences (sequences.h) from the attitude's rotation matrix R:
 * the principal angles, and their continuity across +-pi and through the singular configuration.
 * Plain C, doubles in, doubles out, no FMI types. The half of the attitude core (attitude.h) that
 * reads angles off an attitude without propagating it.
 *
 * 1. Angles of a sequence from R
 *   Every sequence is the chain R = R_a1(phi1) R_a2(phi2) R_a3(phi3) (kinematics_general.h,
 *   section 1; theta_k = phi_k body-fixed, phi_(4-k) space-fixed). With 0-based axes i = a1,
 *   j = a2, k the remaining axis, e = +1 when (i, j, k) is cyclic, -1 otherwise:
 *     Tait-Bryan (a3 = k):  phi2 = atan2(e R[i][k], sqrt(R[i][i]^2 + R[i][j]^2))  in [-pi/2, pi/2]
 *                           phi1 = atan2(-e R[j][k], R[k][k]),  phi3 = atan2(-e R[i][j], R[i][i])
 *                           distance = |cos phi2| = sqrt(R[i][i]^2 + R[i][j]^2)
 *     proper Euler (a3 = i): phi2 = atan2(sqrt(R[i][j]^2 + R[i][k]^2), R[i][i])   in [0, pi]
 *                           phi1 = atan2(R[j][i], -e R[k][i]),  phi3 = atan2(R[i][j], e R[i][k])
 *                           distance = |sin phi2| = sqrt(R[i][j]^2 + R[i][k]^2)
 *   Every attitude has two angle sets: (phi1, phi2, phi3) and (phi1 + pi, pi - phi2, phi3 + pi)
 *   (Tait-Bryan) or (phi1 + pi, -phi2, phi3 + pi) (proper Euler).
 *
 * 2. Continuity (ak_attitude_angles with a previous angle set)
 *   Of the two angle sets, each angle is first shifted by the multiple of 2 pi that brings it
 *   nearest to the previous value ("unwrapped"); the set nearer to the previous one (sum of
 *   squared differences) is taken. So theta1 and theta3 run on across +-pi, and a trajectory that
 *   passes through the singular angle comes out on the far side with theta2 beyond +-pi/2
 *   (Tait-Bryan) or below 0 (proper Euler) instead of bouncing back with a jump of pi in theta1
 *   and theta3. Without a previous set (initialization) the principal set of section 1 is taken.
 *   At the singular configuration (distance < AK_ATTITUDE_SINGULAR_DISTANCE) only theta1 +- theta3
 *   is defined. Choice: theta1 keeps its previous value and theta3 takes the rest: for chain
 *   rotation phi_held (phi1 body-fixed, phi3 space-fixed) held, the other end is read from
 *   R_a1(phi1)^T R = R_a2(phi2) R_a3(phi3) (row a2 holds cos, sin of phi3) or
 *   R R_a3(phi3)^T = R_a1(phi1) R_a2(phi2) (column a2 holds cos, sin of phi1). Every output stays
 *   finite there. Above that distance the formulas of section 1 lose about
 *   rounding(R) / distance in theta1 and theta3 (the attitude itself is exact).
 */
#ifndef ANGULAR_KINEMATICS_ATTITUDE_ANGLES_H
#define ANGULAR_KINEMATICS_ATTITUDE_ANGLES_H

#include <math.h>
#include <stdbool.h>

#include "sequences.h"

/* Below this singularity distance theta1 is held (section 2): sqrt(DBL_EPSILON). */
#define AK_ATTITUDE_SINGULAR_DISTANCE 1.4901161193847656e-08

/* Angles of `sequence` for the attitude R (sections 1, 2). previous: the last angle set of the
 * same trajectory, or NULL for the principal set. Writes theta and the singularity distance;
 * returns true when the singular choice was taken. */
bool ak_attitude_angles(const ak_sequence *sequence, double R[3][3],
                        const double previous[3], double theta[3], double *distance);

/* ak_attitude_angles for one sequence, without the sequence: the same results. */
typedef bool (*ak_attitude_angles_function)(double R[3][3], const double previous[3],
                                            double theta[3], double *distance);

/* The function of `sequence` (an entry of AK_SEQUENCES or a copy of one), for a caller that
 * extracts the angles of one sequence many times. */
ak_attitude_angles_function ak_attitude_angles_of(const ak_sequence *sequence);

/* sin and cos of the principal angles of `sequence` for R (ak_attitude_angles with previous NULL,
 * theta order) from the arguments of their arctangents, without a sine or cosine: true when the
 * distance is at least AK_ATTITUDE_SINGULAR_DISTANCE, false (nothing written) below it, where the
 * first and last angle's arguments may vanish. */
bool ak_attitude_principal_sines(const ak_sequence *sequence, double R[3][3],
                                 double sin_theta[3], double cos_theta[3]);

/* e x for e = +-1: the same bits as the product for every x but a NaN (whose sign may differ). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline double ak_times_sign(double e, double x) {
    return e > 0.0 ? x : -x;
}

/* The arguments y, x of the arctangents of the principal chain angles (section 1) of the chain
 * i, j (0-based first and second chain axes), proper Euler or Tait-Bryan; returns the distance.
 * Inline: the angles (attitude_angles.c) and their sines (attitude_angle_sines.c) share it. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline double ak_chain_arguments(int i, int j, bool proper, double R[3][3], double y[3],
                                        double x[3]) {
    const int k = 3 - i - j;
    const double e = (j == (i + 1) % 3) ? 1.0 : -1.0;
    double d;
    if (proper) {
        d = sqrt(R[i][j] * R[i][j] + R[i][k] * R[i][k]);
        y[0] = R[j][i];
        x[0] = ak_times_sign(-e, R[k][i]);
        y[1] = d;
        x[1] = R[i][i];
        y[2] = R[i][j];
        x[2] = ak_times_sign(e, R[i][k]);
    } else {
        d = sqrt(R[i][i] * R[i][i] + R[i][j] * R[i][j]);
        y[0] = ak_times_sign(-e, R[j][k]);
        x[0] = R[k][k];
        y[1] = ak_times_sign(e, R[i][k]);
        x[1] = d;
        y[2] = ak_times_sign(-e, R[i][j]);
        x[2] = R[i][i];
    }
    return d;
}

#endif
