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
#include "kinematics_general_jacobian.h"
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

/* The principal angles of R and their rates from omega_body and alpha_body (the inverse map of
 * kinematics_general.h, section 6, in body components), fed with the sines of the angles that
 * the arguments of their arctangents give (attitude_angles.h): no sine or cosine computed; sin and
 * cos of theta next to the singularity, where those arguments may vanish. */
static ak_rates_status angles_and_rates(const ak_sequence *sequence, ak_quaternion_outputs *o,
                                        double tolerance, double theta[3], double theta_dot[3],
                                        double theta_ddot[3], double *distance) {
    (void)ak_attitude_angles(sequence, o->R, NULL, theta, distance);
    ak_sines sines;
    if (!ak_attitude_principal_sines(sequence, o->R, sines.sin, sines.cos)) {
        ak_angle_sines(theta, &sines);
    }
    double alpha_fixed[3], alpha_body[3]; /* the rates' own rotation of alpha: o's are kept */
    return ak_general_euler_rates_of_sines(sequence, AK_FRAME_BODY, theta, &sines, o->omega_body,
                                           o->alpha_body, tolerance, theta_dot, theta_ddot,
                                           alpha_fixed, alpha_body, distance);
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

    const ak_sequence *sequence = &AK_SEQUENCES[(int)v[QK_VR_SEQUENCE] - 1];
    double distance;
    const double tolerance = v[QK_VR_TOLERANCE];
    const ak_rates_status rates =
        angles_and_rates(sequence, out, tolerance, &v[QK_VR_THETA], &v[QK_VR_THETA_DOT],
                         &v[QK_VR_THETA_DDOT], &distance);
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

/* inverse := M^-1 (adjugate over determinant). */
static void invert(double M[3][3], double inverse[3][3]) {
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
            const int r1 = (j + 1) % 3, r2 = (j + 2) % 3, c1 = (i + 1) % 3, c2 = (i + 2) % 3;
            inverse[i][j] = M[r1][c1] * M[r2][c2] - M[r1][c2] * M[r2][c1];
        }
    }
    const double det = M[0][0] * inverse[0][0] + M[0][1] * inverse[1][0] + M[0][2] * inverse[2][0];
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
            inverse[i][j] /= det;
        }
    }
}

/* out := M x. */
static void times(double M[3][3], const double x[3], double out[3]) {
    for (int i = 0; i < 3; i++) {
        out[i] = M[i][0] * x[0] + M[i][1] * x[1] + M[i][2] * x[2];
    }
}

/* out := A x (rows of A from `row`, columns from `column` of the general Jacobian) */
static void block_times(double A[AK_GENERAL_N_OUTPUTS][AK_GENERAL_N_INPUTS], int row,
                        int column, const double x[3], double out[3]) {
    for (int i = 0; i < 3; i++) {
        out[i] = A[row + i][column] * x[0] + A[row + i][column + 1] * x[1] +
                 A[row + i][column + 2] * x[2];
    }
}

/* Rows of the general Jacobian (kinematics_general_jacobian.h) and its input columns. */
enum { OMEGA_BODY_ROW = 3, ALPHA_BODY_ROW = 9, THETA_COLUMN = 0, RATE_COLUMN = 3 };

/* The outputs' changes along one change of the inputs (value references 0 .. 11 in `d`): omega,
 * alpha, R, |q| from the core's tangent; the angles and their rates as the inverse of the forward
 * map (AngularKinematics' core) at the current angles: omega_body = W_body theta_dot and
 * alpha_body = W_body theta_ddot + (terms in theta, theta_dot), differentiated:
 *     W_body d theta       = 2 vec(u* dq) / |q|   (the rotation of the attitude along dq),
 *     W_body d theta_dot   = d omega_body - (d omega_body / d theta) d theta,
 *     W_body d theta_ddot  = d alpha_body - (d alpha_body / d theta) d theta
 *                                         - (d alpha_body / d theta_dot) d theta_dot. */
static void change(const ak_model_data *data, const double theta[3],
                   double full[][AK_GENERAL_N_INPUTS], double W_inverse[3][3],
                   const double d[QK_N_INPUTS], double values[]) {
    const double *v = data->values;
    ak_quaternion_outputs d_out, rotation;
    ak_quaternion_kinematics_tangent(&v[QK_VR_Q], &v[QK_VR_Q_DOT], &v[QK_VR_Q_DDOT], &d[QK_VR_Q],
                                     &d[QK_VR_Q_DOT], &d[QK_VR_Q_DDOT], &d_out);
    memcpy(&values[QK_VR_OMEGA_FIXED], &d_out, sizeof d_out);
    const double zero[4] = {0.0, 0.0, 0.0, 0.0};
    (void)ak_quaternion_kinematics(&v[QK_VR_Q], &d[QK_VR_Q], zero, &rotation);
    double *d_theta = &values[QK_VR_THETA], *d_rate = &values[QK_VR_THETA_DOT],
           *d_acceleration = &values[QK_VR_THETA_DDOT];
    double by_theta[3], by_rate[3], rest[3];
    times(W_inverse, rotation.omega_body, d_theta);
    block_times(full, OMEGA_BODY_ROW, THETA_COLUMN, d_theta, by_theta);
    for (int i = 0; i < 3; i++) {
        rest[i] = d_out.omega_body[i] - by_theta[i];
    }
    times(W_inverse, rest, d_rate);
    block_times(full, ALPHA_BODY_ROW, THETA_COLUMN, d_theta, by_theta);
    block_times(full, ALPHA_BODY_ROW, RATE_COLUMN, d_rate, by_rate);
    for (int i = 0; i < 3; i++) {
        rest[i] = d_out.alpha_body[i] - by_theta[i] - by_rate[i];
    }
    times(W_inverse, rest, d_acceleration);
    /* singularity_distance = |cos theta[2]| (Tait-Bryan) or |sin theta[2]| (proper Euler). */
    ak_sines sines;
    ak_angle_sines(theta, &sines);
    const double s = sines.sin[1], c = sines.cos[1];
    const ak_sequence *sequence = &AK_SEQUENCES[(int)v[QK_VR_SEQUENCE] - 1];
    values[QK_VR_SINGULARITY_DISTANCE] =
        sequence->proper_euler ? (s < 0.0 ? -c : c) * d_theta[1] : (c < 0.0 ? s : -s) * d_theta[1];
}

/* Column k of the Jacobian is the change of the outputs along input k. */
static void jacobian(const ak_model_data *data, const unsigned int out[], size_t n_out,
                     double J[][AK_MAX_KNOWNS]) {
    /* The angles and their rates of the current inputs, as evaluate computes them: the outputs
     * in data->values may be those of earlier inputs (the layers evaluate only for a read). */
    const double *v = data->values;
    const ak_sequence *sequence = &AK_SEQUENCES[(int)v[QK_VR_SEQUENCE] - 1];
    ak_quaternion_outputs now;
    (void)ak_quaternion_kinematics(&v[QK_VR_Q], &v[QK_VR_Q_DOT], &v[QK_VR_Q_DDOT], &now);
    double theta[3], theta_dot[3], theta_ddot[3], distance;
    (void)angles_and_rates(sequence, &now, 1.0, theta, theta_dot, theta_ddot, &distance);
    double full[AK_GENERAL_N_OUTPUTS][AK_GENERAL_N_INPUTS], W[3][3], W_inverse[3][3];
    ak_general_jacobian(sequence, theta, theta_dot, theta_ddot, full);
    for (int i = 0; i < 3; i++) { /* d omega_body / d theta_dot = W_body */
        for (int j = 0; j < 3; j++) {
            W[i][j] = full[OMEGA_BODY_ROW + i][RATE_COLUMN + j];
        }
    }
    invert(W, W_inverse);
    for (int k = 0; k < QK_N_INPUTS; k++) {
        double direction[QK_N_INPUTS] = {0.0}, values[QK_N_VALUE_REFERENCES] = {0.0};
        direction[k] = 1.0;
        change(data, theta, full, W_inverse, direction, values);
        for (size_t i = 0; i < n_out; i++) {
            J[i][k] = values[out[i]];
        }
    }
}

const ak_model AK_MODEL = {
    .model_identifier = "QuaternionKinematics",
    .guid = QK_GUID,
    .variables = QK_VARIABLES,
    .n_value_references = QK_N_VALUE_REFERENCES,
    .n_inputs = QK_N_INPUTS,
    .evaluate = evaluate,
    .evaluate_lazy = NULL,
    .jacobian = jacobian,
    .output_derivatives = NULL,
    .can_interpolate_inputs = true,
    .derived = &QK_DERIVED_OUTPUTS,
    .evaluate_in_step = true, /* a refusal fails the step, as a read */
};
