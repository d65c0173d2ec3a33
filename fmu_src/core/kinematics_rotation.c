/* The orientation outputs of AngularKinematics (kinematics_general.h, sections 1, 5 and 7): the
 * rotation matrix, the quaternion and the partial angular velocity matrices of every orientation
 * output at once, and the rotation angle. R and q one at a time: kinematics_rotation_matrix.c. */
#include "kinematics_chain.h"

#include "elementary.h"

#include <math.h>

/* Every orientation output from one chain; body123_rotation_outputs makes a copy of it. */
static inline void chain_rotation_outputs(const ak_sequence *sequence, const ak_sines *sines,
                                          const ak_sines *half, const double theta_dot[3],
                                          ak_rotation_outputs *out) {
    chain ch;
    chain_of_sines(sequence, sines, &ch);
    chain_rotation_matrix(&ch, out->R);
    chain_quaternion(&ch, half, out->q);
    chain_partials(&ch, theta_dot, out->W_fixed, out->W_body, out->W_fixed_dot, out->W_body_dot);
}

/* chain_rotation_outputs for body123 with every helper inlined, so that the compiler folds the
 * constant axes: the same arithmetic in the same order, hence the same bits. */
#if defined(__GNUC__)
__attribute__((flatten))
#endif
static void body123_rotation_outputs(const ak_sines *sines, const ak_sines *half,
                                     const double theta_dot[3], ak_rotation_outputs *out) {
    chain_rotation_outputs(&AK_SEQUENCES[AK_SEQUENCE_DEFAULT], sines, half, theta_dot, out);
}

void ak_general_rotation_outputs(const ak_sequence *sequence, const ak_sines *sines,
                                 const ak_sines *half, const double theta_dot[3],
                                 ak_rotation_outputs *out) {
    if (sequence == &AK_SEQUENCES[AK_SEQUENCE_DEFAULT]) {
        body123_rotation_outputs(sines, half, theta_dot, out);
    } else {
        chain_rotation_outputs(sequence, sines, half, theta_dot, out);
    }
}

static double vector_part_norm(const double q[4]) {
    return sqrt(q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
}

void ak_rotation_angle(const double q[4], double *angle) {
    /* 2 atan2(s, q0) with s, q0 >= 0, as the atan of whichever ratio is at most 1: the project's
     * atan (elementary.h) of a ratio at most 1 costs about 60 instructions less than its atan2,
     * which would also correct the quotient's rounding (measured with callgrind, bench/run.sh's
     * "all outputs" row). */
    static const double PI = 3.14159265358979323846;
    const double s = vector_part_norm(q);
    *angle = s < q[0] ? 2.0 * ak_atan(s / q[0]) : s > 0.0 ? PI - 2.0 * ak_atan(q[0] / s) : 0.0;
}

void ak_rotation_angle_tangent(const double q[4], const double dq[4], double *d_angle) {
    const double s = vector_part_norm(q);
    if (s == 0.0) {
        *d_angle = 0.0;
        return;
    }
    const double ds = (q[1] * dq[1] + q[2] * dq[2] + q[3] * dq[3]) / s;
    *d_angle = 2.0 * (q[0] * ds - s * dq[0]) / (q[0] * q[0] + s * s);
}
