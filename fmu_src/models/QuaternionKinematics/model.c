/* The QuaternionKinematics model: an attitude quaternion q (any length) with its first and second
 * time derivatives in; omega and alpha in both frames, the rotation matrix, |q|, and the angles
 * of parameter sequence with their first and second derivatives out. Equations:
 * core/quaternion_kinematics.h (omega, alpha, R), core/attitude_angles.h (the principal angles)
 * and kinematics_general.h, section 6 (their rates: EulerRates' core).
 *
 * Refusals. q = 0 (or below the smallest normal double), or an output that overflows: the
 * evaluation fails with a message naming q or the output and the values, every output keeps its
 * last valid value, reads return fmi2Discard and so does fmi2DoStep. At the singular configuration
 * of the sequence, as EulerRates: theta_dot and theta_ddot are not defined; they keep their last
 * valid values, the other outputs are current, and the evaluation fails the same way; below
 * `tolerance` a warning is logged (fmi2Warning). */
#include "QuaternionKinematics_variables.h"

#include <string.h>

#include "attitude_angles.h"
#include "kinematics_general.h"
#include "quaternion_kinematics.h"

_Static_assert(QK_N_VALUE_REFERENCES <= AK_MAX_VARIABLES, "the value array holds them");
_Static_assert(QK_N_INPUTS <= AK_MAX_INPUTS, "the input arrays hold them");
/* omega, alpha, R and q_norm are stored as one ak_quaternion_outputs: their value references
 * follow it. */
_Static_assert(QK_VR_OMEGA_BODY == QK_VR_OMEGA_FIXED + 3 && QK_VR_ALPHA_FIXED == QK_VR_OMEGA_FIXED + 6 &&
                   QK_VR_ALPHA_BODY == QK_VR_OMEGA_FIXED + 9 && QK_VR_R == QK_VR_OMEGA_FIXED + 12 &&
                   QK_VR_Q_NORM == QK_VR_OMEGA_FIXED + 21,
               "the outputs follow ak_quaternion_outputs");
_Static_assert(sizeof(ak_quaternion_outputs) == 22 * sizeof(double), "no padding");

/* ak_general_euler_rates in the body frame for AK_SEQUENCES[index], the one function of the core
 * called with a constant sequence in each case: flattened, the compiler inlines it once per
 * sequence and folds the chain's axes, signs and angle order, which it otherwise reads and indexes
 * at run time (about 250 instructions of the 2450 of a cycle; the binary grows by about 100 kB).
 * The arithmetic is the same, operation for operation (no contraction: -ffp-contract=off), so are
 * the bits. Without the attribute (or without link-time optimization) it is a plain call. */
_Static_assert(AK_SEQUENCE_COUNT == 24, "a case per sequence");
#if defined(__GNUC__)
__attribute__((flatten))
#endif
static ak_rates_status body_rates(int index, const double theta[3], const double omega[3],
                                  const double omega_dot[3], double tolerance, double theta_dot[3],
                                  double theta_ddot[3], double *distance) {
    double alpha_fixed[3], alpha_body[3]; /* the rates' rotation of alpha: the core's are kept */
#define QK_RATES(k)                                                                               \
    case k:                                                                                       \
        return ak_general_euler_rates(&AK_SEQUENCES[k], AK_FRAME_BODY, theta, omega, omega_dot,    \
                                      tolerance, theta_dot, theta_ddot, alpha_fixed, alpha_body,   \
                                      distance)
    switch (index) {
        QK_RATES(0); QK_RATES(1); QK_RATES(2); QK_RATES(3); QK_RATES(4); QK_RATES(5);
        QK_RATES(6); QK_RATES(7); QK_RATES(8); QK_RATES(9); QK_RATES(10); QK_RATES(11);
        QK_RATES(12); QK_RATES(13); QK_RATES(14); QK_RATES(15); QK_RATES(16); QK_RATES(17);
        QK_RATES(18); QK_RATES(19); QK_RATES(20); QK_RATES(21); QK_RATES(22);
    default: /* 23: the parameter's range is checked by its setter */
        QK_RATES(23);
    }
#undef QK_RATES
}

static ak_eval_status evaluate(ak_model_data *data) {
    double *v = data->values;
    const double *q = &v[QK_VR_Q];
    /* The core writes the outputs straight into the value array (no copy of a fresh struct, whose
     * wide loads would wait for its narrow stores); the last valid ones are kept aside (old
     * values: no wait) and put back when one overflowed. */
    ak_quaternion_outputs kept;
    ak_quaternion_outputs *const out = (ak_quaternion_outputs *)&v[QK_VR_OMEGA_FIXED];
    memcpy(&kept, out, sizeof kept);
    const ak_quaternion_status status =
        ak_quaternion_kinematics(q, &v[QK_VR_Q_DOT], &v[QK_VR_Q_DDOT], out);
    if (status == AK_QUATERNION_NOT_ATTITUDE) {
        ak_model_log(data, AK_LOG_WARNING, AK_STATUS_DISCARD,
                     "%s: q = (%g, %g, %g, %g) is not an attitude: |q| is 0 or below the "
                     "smallest normal double; the outputs keep their last valid values",
                     AK_MODEL.model_identifier, q[0], q[1], q[2], q[3]);
        return AK_EVAL_FAILED;
    }
    if (status == AK_QUATERNION_OVERFLOW) {
        const double *o = (const double *)out;
        int k = 0;
        while (o[k] - o[k] == 0.0) {
            k++;
        }
        ak_model_log(data, AK_LOG_WARNING, AK_STATUS_DISCARD,
                     "%s: %s = %g overflows: |q| = %g, |q_dot| / |q| or |q_ddot| / |q| is too "
                     "large; the outputs keep their last valid values",
                     AK_MODEL.model_identifier, QK_VARIABLES[QK_VR_OMEGA_FIXED + k].name, o[k],
                     out->q_norm);
        memcpy(out, &kept, sizeof kept);
        return AK_EVAL_FAILED;
    }

    const int index = (int)v[QK_VR_SEQUENCE] - 1;
    const ak_sequence *sequence = &AK_SEQUENCES[index];
    double distance;
    (void)ak_attitude_angles(sequence, out->R, NULL, &v[QK_VR_THETA], &distance);
    const double tolerance = v[QK_VR_TOLERANCE];
    const ak_rates_status rates =
        body_rates(index, &v[QK_VR_THETA], out->omega_body, out->alpha_body, tolerance,
                   &v[QK_VR_THETA_DOT], &v[QK_VR_THETA_DDOT], &distance);
    v[QK_VR_SINGULARITY_DISTANCE] = distance;
    if (rates == AK_RATES_OK) {
        return AK_EVAL_OK;
    }
    const char *singular_at = sequence->proper_euler ? "0 or pi" : "+-pi/2";
    if (rates == AK_RATES_SINGULAR || rates == AK_RATES_OVERFLOW) {
        ak_model_log(data, AK_LOG_WARNING, AK_STATUS_DISCARD,
                     "%s: theta[2] = %.17g is %s the singular configuration of %s (theta[2] = "
                     "%s): singularity_distance = %g; theta_dot and theta_ddot are not defined "
                     "there and keep their last valid values",
                     AK_MODEL.model_identifier, v[QK_VR_THETA + 1],
                     rates == AK_RATES_SINGULAR ? "at" : "so close to that the rates overflow at",
                     sequence->name, singular_at, distance);
        return AK_EVAL_FAILED;
    }
    /* AK_RATES_NEAR_SINGULAR */
    ak_model_log(data, AK_LOG_WARNING, AK_STATUS_WARNING,
                 "%s: theta[2] = %.17g is near the singular configuration of %s (theta[2] = "
                 "%s): singularity_distance = %g < tolerance = %g; theta_dot[1] and "
                 "theta_dot[3] grow as 1/singularity_distance",
                 AK_MODEL.model_identifier, v[QK_VR_THETA + 1], sequence->name, singular_at,
                 distance, tolerance);
    return AK_EVAL_WARNING;
}

const ak_model AK_MODEL = {
    .model_identifier = "QuaternionKinematics",
    .guid = QK_GUID,
    .variables = QK_VARIABLES,
    .n_value_references = QK_N_VALUE_REFERENCES,
    .n_inputs = QK_N_INPUTS,
    .evaluate = evaluate,
    .evaluate_lazy = NULL,
    .jacobian = NULL,
    .output_derivatives = NULL,
    .can_interpolate_inputs = true,
    .derived = &QK_DERIVED_OUTPUTS,
    .evaluate_in_step = true, /* a refusal fails the step, as a read */
};
