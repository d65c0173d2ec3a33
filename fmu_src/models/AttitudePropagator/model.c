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
    v[AP_VR_ANGLES_CHANGE_BOUND] = 0.0;
    return AK_EVAL_OK;
}

/* Lazy angles, bit-identical to angles computed at every communication point. The angles
 * unwrap to the set nearest the last one computed, so computed from an older set they could
 * differ; they do not while every angle moved by at most L = 1.3 rad since: the other candidate
 * set is pi away from the continued one in theta1 and theta3 (core/attitude.h, sections 5, 6),
 * so at squared distance at least 2 (pi - L)^2 = 6.8 from the last set, above the continued
 * one's 3 L^2 = 5.1, and each angle unwraps to the continued one's turn (L < pi): the nearest
 * is the continued one, which the computation at every point would also have reached (unwrap
 * and the choice of set depend on the reference only through that).
 * The bound follows the chain R = R_i(phi1) R_j(phi2) R_c(phi3) of the sequence (c = i for
 * proper Euler, else the third axis; a space-fixed sequence's theta is the chain reversed) along
 * each step's rotation, exp of twice the step's vector v (core/attitude.h, section 4), fixed in
 * the frame of omega. Body axis c seen in the fixed frame, u = R e_c, has azimuth phi1 about
 * fixed axis i and its angle from that axis gives phi2; its distance from the axis is the
 * singularity distance d = |e_i x u| (1 - d^2 = R[i][c]^2). So phi2 moves by at most the arc
 * of u and phi1 by at most that arc over the least d on the way, which is at least d at the
 * step's start minus the arc (d moves by at most the arc). In body components u turns about v by
 * 2 |v|, an arc of 2 |v x e_c|; and the c component of omega is phi1_dot (e_i . R_j e_c) +
 * phi3_dot, so phi3 moves by at most 2 |v_c| plus phi1's bound. In fixed components the same
 * holds with the roles of phi1 and phi3, u and R^T e_i, c and i swapped. Within 5 singular
 * distances (rounding of d included) or after a retaken step the next step computes them. */
static const double ANGLES_CHANGE_LIMIT = 1.3;

/* The axis after a, and the one after that: (a + 1) % 3 and (a + 2) % 3 without a division. */
static const int NEXT[3] = {1, 2, 0};
static const int AFTER[3] = {2, 0, 1};

/* R[i][c] of the unit quaternion q (core/attitude.c, ak_quat_to_matrix). */
static double singular_entry(int i, int c, const double q[4]) {
    if (c == i) {
        const double a = q[1 + NEXT[i]], b = q[1 + AFTER[i]];
        return 1.0 - 2.0 * (a * a + b * b);
    }
    const double sign = c == NEXT[i] ? -1.0 : 1.0;
    return 2.0 * (q[1 + i] * q[1 + c] + sign * q[0] * q[1 + (3 - i - c)]);
}

/* The step's bound on how far the angles move as the state turns from v[q] by the rotation of
 * vector (retaken: by more than it). From the distance at the step's start, so that the square
 * roots and the division run beside the quaternion update rather than after it. */
static double angles_change(const ak_model_data *data, const double vector[3], bool retaken) {
    /* The chain's first and last axes: a space-fixed sequence's chain is its axes reversed. */
    const ak_sequence *sequence = sequence_of(data);
    const bool space = sequence->kind == AK_SPACE_FIXED;
    const int i = sequence->axes[space ? 2 : 0] - 1, c = sequence->axes[space ? 0 : 2] - 1;
    const int free_axis = frame_of(data) == AK_FRAME_BODY ? c : i;
    const double a = vector[NEXT[free_axis]], b = vector[AFTER[free_axis]];
    const double arc = 2.0 * sqrt(a * a + b * b);
    const double s = singular_entry(i, c, &data->values[AP_VR_Q]);
    const double least = sqrt((1.0 - s) * (1.0 + s)) - arc; /* NaN past 1 by rounding */
    return least > 5.0 * AK_ATTITUDE_SINGULAR_DISTANCE && !retaken
               ? arc / least + 2.0 * fabs(vector[free_axis])
               : 2.0 * ANGLES_CHANGE_LIMIT;
}

/* Before the state moves: computes the angles at v[q] when a catch-up from the last computed
 * ones could differ after this step of bound change, and adds it. */
static void step_angles(ak_model_data *data, double change) {
    double *v = data->values;
    double bound = v[AP_VR_ANGLES_CHANGE_BOUND] + change;
    if (v[AP_VR_ANGLES_AGE] >= 1.0 && !(bound <= ANGLES_CHANGE_LIMIT)) {
        (void)evaluate(data); /* a unit q from the last step: cannot fail */
        bound = change;
    }
    v[AP_VR_ANGLES_AGE] += 1.0;
    /* Finite, as every value of an FMU state: past the limit, the next step computes them. */
    v[AP_VR_ANGLES_CHANGE_BOUND] = bound <= ANGLES_CHANGE_LIMIT ? bound : 2.0 * ANGLES_CHANGE_LIMIT;
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
    v[AP_VR_ANGLES_CHANGE_BOUND] = 0.0;
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
    bool derivatives_given = false, first = false, retaken = false;
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
            double previous[4][3], retaken_vector[3];
            ak_attitude_input_polynomial(&v[AP_VR_OMEGA_PREVIOUS], &v[AP_VR_OMEGA_DOT_PREVIOUS],
                                         none, &v[AP_VR_OMEGA], w1, -hp, previous);
            ak_attitude_step_vector(frame_of(data), previous, hp, retaken_vector);
            ak_attitude_retake_step(frame_of(data), &v[AP_VR_FIRST_STEP_VECTOR], retaken_vector, q);
            retaken = true;
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
    const double change = angles_change(data, vector, retaken);
    if (!ak_attitude_advance(frame_of(data), vector, q, NULL)) {
        /* Logged as the step's result: the layer discards the step (the instance stays usable). */
        ak_model_log(data, AK_LOG_WARNING, AK_STATUS_DISCARD,
                     "%s: omega = (%g, %g, %g) over the communication step size %g gives a "
                     "rotation that is not finite; the state q is left as it was",
                     AK_MODEL.model_identifier, v[AP_VR_OMEGA], v[AP_VR_OMEGA + 1],
                     v[AP_VR_OMEGA + 2], h);
        return AK_EVAL_FAILED;
    }
    step_angles(data, change);
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
