/* The AttitudePropagator model: the attitude q (continuous state, unit quaternion, scalar first)
 * integrated from the angular velocity omega in the components of parameter frame; the rotation
 * matrix, the angles of parameter sequence (continuous in time), their rates, omega and alpha in
 * both frames and the singularity distance of the angles as outputs. Equations and choices:
 * core/attitude.h. No event indicators: nothing in the model is discontinuous, and the angle
 * outputs stay finite at the singular configuration, so no state event is needed. */
#include "AttitudePropagator_variables.h"

#include <math.h>

#include "attitude.h"
#include "kinematics_general.h"

_Static_assert(AP_N_VALUE_REFERENCES <= AK_MAX_VARIABLES, "the value array holds them");
_Static_assert(AP_N_INPUTS <= AK_MAX_INPUTS, "the input arrays hold them");

static const unsigned int STATE_VRS[AP_N_STATES] = {AP_VR_Q, AP_VR_Q + 1, AP_VR_Q + 2,
                                                   AP_VR_Q + 3};
static const unsigned int DERIVATIVE_VRS[AP_N_STATES] = {AP_VR_DER_Q, AP_VR_DER_Q + 1,
                                                        AP_VR_DER_Q + 2, AP_VR_DER_Q + 3};
/* The components of a unit quaternion are at most 1 in size. */
static const double NOMINALS[AP_N_STATES] = {1.0, 1.0, 1.0, 1.0};

static const ak_sequence *sequence_of(const ak_model_data *data) {
    return &AK_SEQUENCES[(int)data->values[AP_VR_SEQUENCE] - 1];
}

static ak_frame frame_of(const ak_model_data *data) {
    return (int)data->values[AP_VR_FRAME] == 2 ? AK_FRAME_BODY : AK_FRAME_FIXED;
}

/* The angular acceleration in the frame of omega: the omega_dot inputs, or when all three are
 * zero ("not given") the first input derivative of omega (co-simulation), and w2 its own
 * derivative (the order-1 derivative of omega_dot, or order 2 of omega). */
static void acceleration(const ak_model_data *data, double w1[3], double w2[3]) {
    const double *v = data->values;
    const bool given = v[AP_VR_OMEGA_DOT] != 0.0 || v[AP_VR_OMEGA_DOT + 1] != 0.0 ||
                       v[AP_VR_OMEGA_DOT + 2] != 0.0;
    for (int k = 0; k < 3; k++) {
        if (given) {
            w1[k] = v[AP_VR_OMEGA_DOT + k];
            w2[k] = data->input_derivatives[AP_VR_OMEGA_DOT + k][0];
        } else {
            w1[k] = data->input_derivatives[AP_VR_OMEGA + k][0];
            w2[k] = data->input_derivatives[AP_VR_OMEGA + k][1];
        }
    }
}

/* der(q) = q (x) (0, omega) / 2 (body) or (0, omega) (x) q / 2 (fixed); attitude.h, section 2. */
static void derivatives(ak_model_data *data) {
    double *v = data->values;
    const double w[4] = {0.0, 0.5 * v[AP_VR_OMEGA], 0.5 * v[AP_VR_OMEGA + 1],
                         0.5 * v[AP_VR_OMEGA + 2]};
    if (frame_of(data) == AK_FRAME_BODY) {
        ak_quat_multiply(&v[AP_VR_Q], w, &v[AP_VR_DER_Q]);
    } else {
        ak_quat_multiply(w, &v[AP_VR_Q], &v[AP_VR_DER_Q]);
    }
}

/* out := R in (body components to fixed, frame body) or R^T in (fixed to body, frame fixed). */
static void to_other_frame(ak_frame frame, double R[3][3], const double in[3], double out[3]) {
    for (int i = 0; i < 3; i++) {
        out[i] = frame == AK_FRAME_BODY ? R[i][0] * in[0] + R[i][1] * in[1] + R[i][2] * in[2]
                                        : R[0][i] * in[0] + R[1][i] * in[1] + R[2][i] * in[2];
    }
}

/* The main group, evaluated at every communication point (the angles' unwrapping follows the
 * path): R, theta and the distance from the states (normalized: model exchange integrators let
 * |q| drift) and the last angles (the reference of the unwrapping); der(q). */
static ak_eval_status evaluate(ak_model_data *data) {
    double *v = data->values;
    const double *q = &v[AP_VR_Q];
    const double norm = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (!(norm > 0.0) || !isfinite(norm)) {
        ak_model_log(data, AK_LOG_WARNING, AK_STATUS_DISCARD,
                     "%s: the state q = (%g, %g, %g, %g) has |q| = %g: it is not an attitude; "
                     "the outputs keep their last valid values",
                     AK_MODEL.model_identifier, q[0], q[1], q[2], q[3], norm);
        return AK_EVAL_FAILED;
    }
    const double unit[4] = {q[0] / norm, q[1] / norm, q[2] / norm, q[3] / norm};
    double R[3][3];
    ak_quat_to_matrix(unit, R);
    double theta[3], distance;
    ak_attitude_angles(sequence_of(data), R, &v[AP_VR_THETA], theta, &distance);
    for (int k = 0; k < 3; k++) {
        v[AP_VR_THETA + k] = theta[k];
    }
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
            v[AP_VR_R + 3 * i + j] = R[i][j];
        }
    }
    v[AP_VR_SINGULARITY_DISTANCE] = distance;
    derivatives(data);
    return AK_EVAL_OK;
}

/* The lazy group, computed only when one of them is read: the angle rates, omega and alpha in
 * both frames, from the main group's R and theta. */
static void evaluate_lazy(ak_model_data *data) {
    double *v = data->values;
    const ak_frame frame = frame_of(data);
    double R[3][3];
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
            R[i][j] = v[AP_VR_R + 3 * i + j];
        }
    }
    const bool singular = v[AP_VR_SINGULARITY_DISTANCE] < AK_ATTITUDE_SINGULAR_DISTANCE;
    ak_attitude_angle_rates(sequence_of(data), frame, &v[AP_VR_THETA], singular, &v[AP_VR_OMEGA],
                            &v[AP_VR_THETA_DOT]);
    double w1[3], w2[3], other[3];
    acceleration(data, w1, w2);
    double *same_omega = frame == AK_FRAME_BODY ? &v[AP_VR_OMEGA_BODY] : &v[AP_VR_OMEGA_FIXED];
    double *other_omega = frame == AK_FRAME_BODY ? &v[AP_VR_OMEGA_FIXED] : &v[AP_VR_OMEGA_BODY];
    double *same_alpha = frame == AK_FRAME_BODY ? &v[AP_VR_ALPHA_BODY] : &v[AP_VR_ALPHA_FIXED];
    double *other_alpha = frame == AK_FRAME_BODY ? &v[AP_VR_ALPHA_FIXED] : &v[AP_VR_ALPHA_BODY];
    /* Since omega x omega = 0, alpha rotates between the frames like omega. */
    to_other_frame(frame, R, &v[AP_VR_OMEGA], other);
    for (int k = 0; k < 3; k++) {
        same_omega[k] = v[AP_VR_OMEGA + k];
        other_omega[k] = other[k];
    }
    to_other_frame(frame, R, w1, other);
    for (int k = 0; k < 3; k++) {
        same_alpha[k] = w1[k];
        other_alpha[k] = other[k];
    }
}

/* q := q0 / |q0| (scaled first, so that no finite q0 overflows), and the principal angles. */
static ak_eval_status initialize(ak_model_data *data) {
    double *v = data->values;
    const double *q0 = &v[AP_VR_Q0];
    double scale = 0.0;
    for (int k = 0; k < 4; k++) {
        scale = fmax(scale, fabs(q0[k]));
    }
    if (!(scale > 0.0) || !isfinite(scale)) {
        ak_model_log(data, AK_LOG_ERROR, AK_STATUS_ERROR,
                     "%s: q0 = (%g, %g, %g, %g) is not an attitude: the initial quaternion must "
                     "be finite and not zero; q0[1] = 1 and the rest 0 is the identity",
                     AK_MODEL.model_identifier, q0[0], q0[1], q0[2], q0[3]);
        return AK_EVAL_FAILED;
    }
    double q[4], n2 = 0.0;
    for (int k = 0; k < 4; k++) {
        q[k] = q0[k] / scale;
        n2 += q[k] * q[k];
    }
    const double norm = sqrt(n2);
    for (int k = 0; k < 4; k++) {
        v[AP_VR_Q + k] = q[k] / norm;
    }
    double R[3][3], distance;
    ak_quat_to_matrix(&v[AP_VR_Q], R);
    ak_attitude_angles(sequence_of(data), R, NULL, &v[AP_VR_THETA], &distance);
    return AK_EVAL_OK;
}

/* One co-simulation step (core/attitude.h, section 4): the cubic of omega from the inputs, their
 * derivatives and the previous communication point, then the Magnus step. */
static ak_eval_status step(ak_model_data *data, double h) {
    double w1[3], w2[3], c[4][3];
    acceleration(data, w1, w2);
    double *v = data->values;
    const bool derivatives_given = w1[0] != 0.0 || w1[1] != 0.0 || w1[2] != 0.0 ||
                                   w2[0] != 0.0 || w2[1] != 0.0 || w2[2] != 0.0;
    const double hp = v[AP_VR_H_PREVIOUS];
    if (derivatives_given) {
        const bool history = hp > 0.0;
        ak_attitude_input_polynomial(&v[AP_VR_OMEGA], w1, w2,
                                     history ? &v[AP_VR_OMEGA_PREVIOUS] : NULL,
                                     history ? &v[AP_VR_OMEGA_DOT_PREVIOUS] : NULL, hp, c);
    } else { /* held inputs: omega constant over the step */
        for (int k = 0; k < 3; k++) {
            c[0][k] = v[AP_VR_OMEGA + k];
            c[1][k] = c[2][k] = c[3][k] = 0.0;
        }
    }
    if (!ak_attitude_step(frame_of(data), c, h, &v[AP_VR_Q], NULL)) {
        ak_model_log(data, AK_LOG_ERROR, AK_STATUS_ERROR,
                     "fmi2DoStep: omega = (%g, %g, %g) over communicationStepSize = %g gives a "
                     "rotation that is not finite; the state q is left as it was",
                     v[AP_VR_OMEGA], v[AP_VR_OMEGA + 1], v[AP_VR_OMEGA + 2], h);
        return AK_EVAL_FAILED;
    }
    for (int k = 0; k < 3; k++) {
        v[AP_VR_OMEGA_PREVIOUS + k] = v[AP_VR_OMEGA + k];
        v[AP_VR_OMEGA_DOT_PREVIOUS + k] = w1[k];
    }
    v[AP_VR_H_PREVIOUS] = derivatives_given ? h : 0.0;
    return AK_EVAL_OK;
}

static const char *check_parameter(const ak_variable *variable, double value) {
    switch (variable->value_reference) {
    case AP_VR_SEQUENCE:
        return value >= 1.0 && value <= AK_SEQUENCE_COUNT
                   ? NULL
                   : "is not an item of the Enumeration Sequence (1 body123 .. 24 space323)";
    case AP_VR_FRAME:
        return value == 1.0 || value == 2.0
                   ? NULL
                   : "is not an item of the Enumeration Frame (1 fixed, 2 body)";
    default: /* q0: any finite value (the setter refuses the others); its norm is checked at
              * initialization, when all four are known */
        return NULL;
    }
}

const ak_model AK_MODEL = {
    .model_identifier = "AttitudePropagator",
    .guid = AP_GUID,
    .variables = AP_VARIABLES,
    .n_value_references = AP_N_VALUE_REFERENCES,
    .n_inputs = AP_N_INPUTS,
    .evaluate = evaluate,
    .evaluate_lazy = evaluate_lazy,
    .check_parameter = check_parameter,
    .jacobian = NULL,
    .output_derivatives = NULL,
    .can_interpolate_inputs = true,
    /* The unwrapped angles depend on the path: evaluated at every communication point. */
    .evaluate_in_step = true,
    .n_states = AP_N_STATES,
    .state_vrs = STATE_VRS,
    .derivative_vrs = DERIVATIVE_VRS,
    .state_nominals = NOMINALS,
    .derivatives = derivatives,
    .step = step,
    .initialize = initialize,
};
