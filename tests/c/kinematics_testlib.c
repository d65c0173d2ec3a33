/* Test-only shared library: the general kinematics core behind plain C-linkage functions taking
 * flat arrays, for tests through Python's ctypes (tests/test_sequences_core.py). Not in the FMU.
 * A sequence is its index in AK_SEQUENCES; an out-of-range index returns -1 and writes nothing. */
#include "kinematics_general.h"
#include "kinematics_general_kernel.h"
#include "sequences.h"

#if defined(_WIN32)
#define AKT_EXPORT __declspec(dllexport)
#else
#define AKT_EXPORT __attribute__((visibility("default")))
#endif

static const ak_sequence *sequence_at(int index) {
    return (index >= 0 && index < AK_SEQUENCE_COUNT) ? &AK_SEQUENCES[index] : 0;
}

AKT_EXPORT int akt_sequence_count(void) { return AK_SEQUENCE_COUNT; }

/* Name, axes (1..3) and kind (0 body-fixed, 1 space-fixed) of a sequence. */
AKT_EXPORT const char *akt_sequence(int index, int axes[3], int *kind, int *proper_euler) {
    const ak_sequence *seq = sequence_at(index);
    if (!seq) {
        return 0;
    }
    for (int k = 0; k < 3; k++) {
        axes[k] = seq->axes[k];
    }
    *kind = (int)seq->kind;
    *proper_euler = seq->proper_euler;
    return seq->name;
}

/* out: omega_fixed, omega_body, alpha_fixed, alpha_body (12), for each of count states of
 * 9 inputs theta, theta_dot, theta_ddot. */
AKT_EXPORT int akt_angular_kinematics(int index, int count, const double *inputs, double *out) {
    const ak_sequence *seq = sequence_at(index);
    if (!seq) {
        return -1;
    }
    for (int n = 0; n < count; n++) {
        const double *in = inputs + 9 * n;
        double *o = out + 12 * n;
        ak_general_angular_kinematics(seq, in, in + 3, in + 6, o, o + 3, o + 6, o + 9);
    }
    return 0;
}

/* The singularity distance |det W| as the FMUs get it: from the inverse map, which always
 * writes it. */
static double singularity_distance(const ak_sequence *seq, const double theta[3]) {
    const double zero[3] = {0.0, 0.0, 0.0};
    double theta_dot[3], theta_ddot[3], alpha_fixed[3], alpha_body[3], distance;
    (void)ak_general_euler_rates(seq, AK_FRAME_FIXED, theta, zero, zero, 0.0, theta_dot,
                                 theta_ddot, alpha_fixed, alpha_body, &distance);
    return distance;
}

/* out: R row-major (9), q scalar first (4), W_fixed, W_body, W_fixed_dot, W_body_dot row-major
 * (4 x 9), singularity distance (1): 50 values per state of 6 inputs theta, theta_dot. */
AKT_EXPORT int akt_rotation_terms(int index, int count, const double *inputs, double *out) {
    const ak_sequence *seq = sequence_at(index);
    if (!seq) {
        return -1;
    }
    for (int n = 0; n < count; n++) {
        const double *in = inputs + 6 * n;
        double *o = out + 50 * n;
        ak_general_rotation_matrix(seq, in, (double (*)[3])o);
        ak_general_quaternion(seq, in, o + 9);
        ak_general_partials(seq, in, in + 3, (double (*)[3])(o + 13), (double (*)[3])(o + 22),
                            (double (*)[3])(o + 31), (double (*)[3])(o + 40));
        o[49] = singularity_distance(seq, in);
    }
    return 0;
}

/* Inverse map for one state: inputs theta, omega, omega_dot (9) in the components of frame
 * (0 fixed, 1 body); out: theta_dot, theta_ddot, alpha_fixed, alpha_body (12). Returns the
 * ak_rates_status. */
AKT_EXPORT int akt_euler_rates(int index, int frame, const double *inputs, double tolerance,
                               double *out, double *distance) {
    const ak_sequence *seq = sequence_at(index);
    if (!seq || (frame != 0 && frame != 1)) {
        return -1;
    }
    return (int)ak_general_euler_rates(seq, frame ? AK_FRAME_BODY : AK_FRAME_FIXED, inputs,
                                       inputs + 3, inputs + 6, tolerance, out, out + 3, out + 6,
                                       out + 9, distance);
}
