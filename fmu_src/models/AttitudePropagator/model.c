/* The AttitudePropagator model: the attitude q (continuous state, unit quaternion, scalar first)
 * integrated from the angular velocity omega in the components of parameter frame; the rotation
 * matrix, the angles of parameter sequence (continuous in time), their rates, omega and alpha in
 * both frames and the singularity distance of the angles as outputs. Equations and choices:
 * core/attitude.h. No event indicators: nothing in the model is discontinuous, and the angle
 * outputs stay finite at the singular configuration, so no state event is needed. */
#include "AttitudePropagator_variables.h"

#include <float.h>
#include <math.h>

#include "attitude.h"
#include "elementary.h"
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

/* |q|, or 0 (logged) when the state q is not an attitude (a state set so in model exchange, or
 * restored from such an FMU state). */
static double attitude_norm(const ak_model_data *data) {
    const double *q = &data->values[AP_VR_Q];
    const double norm = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (!(norm > 0.0) || !isfinite(norm)) {
        ak_model_log(data, AK_LOG_WARNING, AK_STATUS_DISCARD,
                     "%s: the state q = (%g, %g, %g, %g) has |q| = %g: it is not an attitude; "
                     "the outputs keep their last valid values",
                     AK_MODEL.model_identifier, q[0], q[1], q[2], q[3], norm);
        return 0.0;
    }
    return norm;
}

/* The main group: R, theta and the distance from the states (normalized: model exchange
 * integrators let |q| drift) and the last angles computed (the reference of the unwrapping). In
 * co-simulation it waits for a read (q itself is always current): see step_angles. */
static ak_eval_status evaluate(ak_model_data *data) {
    double *v = data->values;
    const double *q = &v[AP_VR_Q];
    const double norm = attitude_norm(data);
    if (norm == 0.0) {
        return AK_EVAL_FAILED;
    }
    double R[3][3];
    if (norm == 1.0) { /* as co-simulation keeps it: q / 1 is q, without four divisions */
        ak_quat_to_matrix(q, R);
    } else {
        const double unit[4] = {q[0] / norm, q[1] / norm, q[2] / norm, q[3] / norm};
        ak_quat_to_matrix(unit, R);
    }
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
    v[AP_VR_ANGLES_AGE] = 0.0;
    v[AP_VR_ANGLES_PATH] = 0.0;
    return AK_EVAL_OK;
}

/* Lazy angles, bit-identical to angles computed at every communication point. The angles
 * unwrap to the set nearest the last one computed, so computed from an older set they could
 * differ; they do not while theta1 and theta3 moved by at most L = 1.39 rad since and theta2 by
 * at most p <= 0.75: the other candidate set is pi away from the continued one in theta1 and
 * theta3 (core/attitude.h, sections 5, 6), so at squared distance at least 2 (pi - L)^2 = 6.2
 * from the last set, above the continued one's 2 L^2 + p^2 = 4.4, and each angle unwraps to
 * the continued one's turn (L < pi): the nearest is the continued one, which the computation at
 * every point would also have reached (unwrap and the choice of set depend on the reference only
 * through that). Along a path of rotation angle p from an attitude at singularity distance D, the
 * distance stays at least D - p (it moves by at most the rotation angle), theta2 moves at a rate
 * of at most |omega| (a component of omega along a unit axis) and theta1, theta3 at most |omega|
 * / d (a row of W^-1 is a cross product of two unit axes over det W, |det W| = d): by at most
 * the integral of dp / (D - p), ln(D / (D - p)), at most ln 4 = 1.39 while p <= 0.75 D (the
 * margin of L to pi/2 - p^2 / (4 pi) = 1.53, where the squared distances meet, covers rounding),
 * and d stays above D / 4. A step's rotation angle is 4 asin(|q_new - q_old| / 2) (2-norm;
 * |q_new - q_old| = 2 sin(angle / 4)): at most pi |q_new - q_old|, and at most 2.03 of it while
 * that is at most 1/2 (asin(x) / x grows: 4 asin(1/4) / (1/2) = 2.0214), taken with the 1-norm,
 * which is larger and needs no square root (the sum that angles_path, vr 60, holds): a square
 * root and a division here (a bound up to 3 times tighter) lengthened the chain the step's branch
 * waits for, and cost more time than the angles they saved on random rows. */
static const double ANGLES_PATH_FRACTION = 0.75;
static const double PI = 3.14159265358979323846;

/* Before the state moves from v[q] to q_new: computes the angles at v[q] when a catch-up from
 * the last computed ones could differ after this step, and adds the step to the path. */
static void step_angles(ak_model_data *data, const double q_new[4]) {
    double *v = data->values;
    double moved = 0.0;
    for (int k = 0; k < 4; k++) {
        moved += fabs(q_new[k] - v[AP_VR_Q + k]);
    }
    const double rotation = (moved <= 0.5 ? 2.03 : PI) * moved; /* the bounds above */
    double path = v[AP_VR_ANGLES_PATH] + rotation;
    /* D above 5 singular distances: d stays above 1.25 of them, off the singular choice. */
    const double distance = v[AP_VR_SINGULARITY_DISTANCE];
    if (v[AP_VR_ANGLES_AGE] >= 1.0 &&
        !(path <= ANGLES_PATH_FRACTION * distance &&
          distance > 5.0 * AK_ATTITUDE_SINGULAR_DISTANCE)) {
        (void)evaluate(data); /* a unit q from the last step: cannot fail */
        path = rotation;
    }
    v[AP_VR_ANGLES_AGE] += 1.0;
    v[AP_VR_ANGLES_PATH] = path; /* at most 2 pi per step: finite */
}

/* The lazy group, computed only when one of them is read: der(q) (fmi2GetDerivatives computes
 * it itself), the angle rates, omega and alpha in both frames, from the main group's R and
 * theta. */
static void evaluate_lazy(ak_model_data *data) {
    derivatives(data);
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
    v[AP_VR_ANGLES_AGE] = 0.0;
    v[AP_VR_ANGLES_PATH] = 0.0;
    return AK_EVAL_OK;
}

/* One co-simulation step (core/attitude.h, section 4): the cubic of omega from the inputs, their
 * derivatives and the previous communication point, then the Magnus step. */
static ak_eval_status step(ak_model_data *data, double h) {
    double *v = data->values;
    const double *q_now = &v[AP_VR_Q];
    const double n2 = q_now[0] * q_now[0] + q_now[1] * q_now[1] + q_now[2] * q_now[2] +
                      q_now[3] * q_now[3];
    if (!(n2 > 0.0 && n2 <= DBL_MAX)) { /* as evaluate refuses it; logged there */
        (void)attitude_norm(data);
        return AK_EVAL_FAILED;
    }
    double w1[3], vector[3];
    double q[4] = {q_now[0], q_now[1], q_now[2], q_now[3]};
    bool derivatives_given = false, first = false;
    const bool omega_dot_given = v[AP_VR_OMEGA_DOT] != 0.0 || v[AP_VR_OMEGA_DOT + 1] != 0.0 ||
                                 v[AP_VR_OMEGA_DOT + 2] != 0.0;
    if (!omega_dot_given && !data->any_input_derivative) {
        /* Held inputs (acceleration gives w1 = w2 = 0): omega constant over the step. */
        for (int k = 0; k < 3; k++) {
            w1[k] = data->input_derivatives[AP_VR_OMEGA + k][0];
        }
        ak_attitude_step_vector_constant(frame_of(data), &v[AP_VR_OMEGA], h, vector);
    } else {
        double w2[3];
        acceleration(data, w1, w2);
        derivatives_given = w1[0] != 0.0 || w1[1] != 0.0 || w1[2] != 0.0 || w2[0] != 0.0 ||
                            w2[1] != 0.0 || w2[2] != 0.0;
        const double hp = v[AP_VR_H_PREVIOUS];
        const bool history = derivatives_given && hp > 0.0;
        if (history && v[AP_VR_FIRST_STEP_PENDING] != 0.0) {
            /* Retake the first step with the Hermite cubic over it (core/attitude.h, section 4). */
            const double none[3] = {0.0, 0.0, 0.0};
            double previous[4][3], retaken[3];
            ak_attitude_input_polynomial(&v[AP_VR_OMEGA_PREVIOUS], &v[AP_VR_OMEGA_DOT_PREVIOUS],
                                         none, &v[AP_VR_OMEGA], w1, -hp, previous);
            ak_attitude_step_vector(frame_of(data), previous, hp, retaken);
            ak_attitude_retake_step(frame_of(data), &v[AP_VR_FIRST_STEP_VECTOR], retaken, q);
        }
        if (derivatives_given) {
            double c[4][3];
            ak_attitude_input_polynomial(&v[AP_VR_OMEGA], w1, w2,
                                         history ? &v[AP_VR_OMEGA_PREVIOUS] : NULL,
                                         history ? &v[AP_VR_OMEGA_DOT_PREVIOUS] : NULL, hp, c);
            ak_attitude_step_vector(frame_of(data), c, h, vector);
        } else { /* held inputs */
            ak_attitude_step_vector_constant(frame_of(data), &v[AP_VR_OMEGA], h, vector);
        }
        first = derivatives_given && !history;
    }
    if (!ak_attitude_advance(frame_of(data), vector, q, NULL)) {
        /* Logged as the step's result: the layer discards the step (the instance stays usable). */
        ak_model_log(data, AK_LOG_WARNING, AK_STATUS_DISCARD,
                     "%s: omega = (%g, %g, %g) over the communication step size %g gives a "
                     "rotation that is not finite; the state q is left as it was",
                     AK_MODEL.model_identifier, v[AP_VR_OMEGA], v[AP_VR_OMEGA + 1],
                     v[AP_VR_OMEGA + 2], h);
        return AK_EVAL_FAILED;
    }
    step_angles(data, q);
    for (int k = 0; k < 4; k++) {
        v[AP_VR_Q + k] = q[k];
    }
    for (int k = 0; k < 3; k++) {
        v[AP_VR_OMEGA_PREVIOUS + k] = v[AP_VR_OMEGA + k];
        v[AP_VR_OMEGA_DOT_PREVIOUS + k] = w1[k];
        /* The first step with derivatives is retaken at the next (its rotation vector kept). */
        v[AP_VR_FIRST_STEP_VECTOR + k] = first ? vector[k] : 0.0;
    }
    v[AP_VR_H_PREVIOUS] = derivatives_given ? h : 0.0;
    v[AP_VR_FIRST_STEP_PENDING] = first ? 1.0 : 0.0;
    return AK_EVAL_OK;
}

/* ---- directional derivatives: columns 0..5 the inputs omega, omega_dot; 6..9 the states q ----- */

enum { COLUMN_OMEGA = AP_VR_OMEGA, COLUMN_OMEGA_DOT = AP_VR_OMEGA_DOT, COLUMN_Q = AP_N_INPUTS };

/* What every row needs: the attitude, its angles and the derivatives of R and theta with respect
 * to the states (core/attitude.h; the unit q is qn = q/|q|, dqn = (I - qn qn^T) dq / |q|). */
typedef struct {
    double qn[4];
    double R[3][3];
    double dR[4][3][3];    /* d R / d q_k */
    double theta[3];
    double dtheta[4][3];   /* d theta / d q_k */
    bool singular;
} attitude_partials;

/* theta_dot-like rates of a vector v in `frame` components at the angles theta. */
static void rates(const ak_model_data *data, ak_frame frame, const attitude_partials *a,
                  const double v[3], double out[3]) {
    ak_attitude_angle_rates(sequence_of(data), frame, a->theta, a->singular, v, out);
}

static void attitude_partials_of(const ak_model_data *data, attitude_partials *a) {
    const double *q = &data->values[AP_VR_Q];
    const double norm = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (int k = 0; k < 4; k++) {
        a->qn[k] = q[k] / norm;
    }
    ak_quat_to_matrix(a->qn, a->R);
    double distance;
    a->singular = ak_attitude_angles(sequence_of(data), a->R, &data->values[AP_VR_THETA],
                                     a->theta, &distance);
    /* R(qn) = I + (quadratic form of qn): d R / d qn_k = R(qn + e_k) - R(qn) - (R(e_k) - I). */
    double dR_unit[4][3][3];
    for (int k = 0; k < 4; k++) {
        double shifted[4] = {a->qn[0], a->qn[1], a->qn[2], a->qn[3]}, e[4] = {0, 0, 0, 0};
        double Rs[3][3], Re[3][3];
        shifted[k] += 1.0;
        e[k] = 1.0;
        ak_quat_to_matrix(shifted, Rs);
        ak_quat_to_matrix(e, Re);
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                dR_unit[k][i][j] = Rs[i][j] - a->R[i][j] - Re[i][j] + (i == j ? 1.0 : 0.0);
            }
        }
    }
    const double conj[4] = {a->qn[0], -a->qn[1], -a->qn[2], -a->qn[3]};
    for (int k = 0; k < 4; k++) {
        double dqn[4], body[4];
        for (int m = 0; m < 4; m++) {
            dqn[m] = ((m == k ? 1.0 : 0.0) - a->qn[m] * a->qn[k]) / norm;
        }
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                double sum = 0.0;
                for (int m = 0; m < 4; m++) {
                    sum += dR_unit[m][i][j] * dqn[m];
                }
                a->dR[k][i][j] = sum;
            }
        }
        /* The body rotation of dqn: dphi = 2 vec(qn* (x) dqn); d theta = W_body^-1 dphi. */
        ak_quat_multiply(conj, dqn, body);
        const double dphi[3] = {2.0 * body[1], 2.0 * body[2], 2.0 * body[3]};
        rates(data, AK_FRAME_BODY, a, dphi, a->dtheta[k]);
    }
}

/* The row of one unknown over the 10 knowns. */
static void jacobian_row(const ak_model_data *data, const attitude_partials *a, unsigned int vr,
                         double row[AK_MAX_KNOWNS]) {
    const double *v = data->values;
    const ak_frame frame = frame_of(data);
    const double *omega = &v[AP_VR_OMEGA], *omega_dot = &v[AP_VR_OMEGA_DOT];
    for (int k = 0; k < AK_MAX_KNOWNS; k++) {
        row[k] = 0.0;
    }
    if (vr >= AP_VR_Q && vr < AP_VR_Q + 4) {
        row[COLUMN_Q + (vr - AP_VR_Q)] = 1.0;
    } else if (vr >= AP_VR_DER_Q && vr < AP_VR_DER_Q + 4) {
        /* der(q) = q (x) w / 2 (body) or w (x) q / 2 (fixed), w = (0, omega): bilinear. */
        const unsigned int c = vr - AP_VR_DER_Q;
        const double w[4] = {0.0, omega[0], omega[1], omega[2]};
        for (int k = 0; k < 4; k++) {
            double e[4] = {0, 0, 0, 0}, out[4];
            e[k] = 0.5;
            if (frame == AK_FRAME_BODY) {
                ak_quat_multiply(e, w, out);
            } else {
                ak_quat_multiply(w, e, out);
            }
            row[COLUMN_Q + k] = out[c];
        }
        for (int m = 0; m < 3; m++) {
            double e[4] = {0, 0, 0, 0}, out[4];
            e[1 + m] = 0.5;
            if (frame == AK_FRAME_BODY) {
                ak_quat_multiply(&v[AP_VR_Q], e, out);
            } else {
                ak_quat_multiply(e, &v[AP_VR_Q], out);
            }
            row[COLUMN_OMEGA + m] = out[c];
        }
    } else if (vr >= AP_VR_R && vr < AP_VR_R + 9) {
        const unsigned int i = (vr - AP_VR_R) / 3, j = (vr - AP_VR_R) % 3;
        for (int k = 0; k < 4; k++) {
            row[COLUMN_Q + k] = a->dR[k][i][j];
        }
    } else if (vr >= AP_VR_THETA && vr < AP_VR_THETA + 3) {
        for (int k = 0; k < 4; k++) {
            row[COLUMN_Q + k] = a->dtheta[k][vr - AP_VR_THETA];
        }
    } else if (vr >= AP_VR_THETA_DOT && vr < AP_VR_THETA_DOT + 3) {
        /* theta_dot = W(theta)^-1 omega: d/d omega = W^-1; d/d theta_j = -W^-1 (dW/dtheta_j)
         * theta_dot, dW/dtheta_j being W_dot for the rates e_j (kinematics_general.h). */
        const unsigned int c = vr - AP_VR_THETA_DOT;
        double theta_dot[3], column[3], by_angle[3][3];
        rates(data, frame, a, omega, theta_dot);
        for (int m = 0; m < 3; m++) {
            const double e[3] = {m == 0 ? 1.0 : 0.0, m == 1 ? 1.0 : 0.0, m == 2 ? 1.0 : 0.0};
            rates(data, frame, a, e, column);
            row[COLUMN_OMEGA + m] = column[c];
            double Wf[3][3], Wb[3][3], dWf[3][3], dWb[3][3], moved[3];
            ak_general_partials(sequence_of(data), a->theta, e, Wf, Wb, dWf, dWb);
            double (*dW)[3] = frame == AK_FRAME_BODY ? dWb : dWf;
            for (int r = 0; r < 3; r++) {
                moved[r] = -(dW[r][0] * theta_dot[0] + dW[r][1] * theta_dot[1] +
                             dW[r][2] * theta_dot[2]);
            }
            rates(data, frame, a, moved, by_angle[m]);
        }
        for (int k = 0; k < 4; k++) {
            row[COLUMN_Q + k] = by_angle[0][c] * a->dtheta[k][0] + by_angle[1][c] * a->dtheta[k][1] +
                                by_angle[2][c] * a->dtheta[k][2];
        }
    } else if (vr >= AP_VR_OMEGA_FIXED && vr < AP_VR_ALPHA_BODY + 3) {
        /* omega and alpha in both frames: the input itself in its frame, R (or R^T) times it in
         * the other. */
        const unsigned int group = (vr - AP_VR_OMEGA_FIXED) / 3, c = (vr - AP_VR_OMEGA_FIXED) % 3;
        const bool is_alpha = group >= 2, in_body = group % 2 == 1;
        const int input = is_alpha ? COLUMN_OMEGA_DOT : COLUMN_OMEGA;
        const double *u = is_alpha ? omega_dot : omega;
        if (in_body == (frame == AK_FRAME_BODY)) {
            row[input + (int)c] = 1.0;
        } else {
            const bool forward = frame == AK_FRAME_BODY; /* body components to fixed: R */
            for (int m = 0; m < 3; m++) {
                row[input + m] = forward ? a->R[c][m] : a->R[m][c];
            }
            for (int k = 0; k < 4; k++) {
                double sum = 0.0;
                for (int m = 0; m < 3; m++) {
                    sum += (forward ? a->dR[k][c][m] : a->dR[k][m][c]) * u[m];
                }
                row[COLUMN_Q + k] = sum;
            }
        }
    } else if (vr == AP_VR_SINGULARITY_DISTANCE) {
        /* |cos theta2| (Tait-Bryan) or |sin theta2| (proper Euler). */
        double s2, c2;
        ak_sincos(a->theta[1], &s2, &c2);
        const double slope = sequence_of(data)->proper_euler ? (s2 >= 0.0 ? 1.0 : -1.0) * c2
                                                             : (c2 >= 0.0 ? -1.0 : 1.0) * s2;
        for (int k = 0; k < 4; k++) {
            row[COLUMN_Q + k] = slope * a->dtheta[k][1];
        }
    }
}

static void jacobian(const ak_model_data *data, const unsigned int out[], size_t n_out,
                     double J[][AK_MAX_KNOWNS]) {
    attitude_partials a;
    attitude_partials_of(data, &a);
    for (size_t i = 0; i < n_out; i++) {
        jacobian_row(data, &a, out[i], J[i]);
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
    .jacobian = jacobian,
    .output_derivatives = NULL,
    .can_interpolate_inputs = true,
    .outputs_use_input_derivatives = true, /* alpha, from omega's derivatives (acceleration) */
    .derived = &AP_DERIVED_OUTPUTS,
    /* The unwrapped angles depend on the path: the step computes them when a later read could
     * differ (step_angles); otherwise they wait for a read. */
    .evaluate_in_step = false,
    .n_states = AP_N_STATES,
    .state_vrs = STATE_VRS,
    .derivative_vrs = DERIVATIVE_VRS,
    .state_nominals = NOMINALS,
    .derivatives = derivatives,
    .step = step,
    .initialize = initialize,
};
