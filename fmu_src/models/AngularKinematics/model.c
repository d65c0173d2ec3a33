/* The AngularKinematics model: angles of any of the 24 rotation sequences and their first and
 * second derivatives in; omega and alpha in both sets of components out (main group), and R, q,
 * W_fixed, W_body and their time derivatives (lazy group, computed only when read). */
#include "AngularKinematics_variables.h"

#include <math.h>
#include <string.h>

#include "kinematics_general.h"
#include "kinematics_general_jacobian.h"
#include "kinematics_sequences.h"

_Static_assert(KIN_N_VALUE_REFERENCES <= AK_MAX_VARIABLES, "the value array holds them");
/* The kernel's Jacobian has a row for each output of 0.3.0, omega_fixed[1] .. W_body_dot[3,3],
 * whose value references are consecutive and never move. An output added since is computed from
 * these by a core function (computed_by in description.py), its row by models/model_derived.c. */
_Static_assert(KIN_VR_W_BODY_DOT + 9 == KIN_VR_OMEGA_FIXED + AK_GENERAL_N_OUTPUTS,
               "a Jacobian row for each output the kernel computes");

static unsigned int kernel_row(unsigned int vr) {
    return vr - KIN_VR_OMEGA_FIXED;
}

/* The index of the sequence parameter in AK_SEQUENCES (its range is checked when it is set). */
static int sequence_index(const ak_model_data *data) {
    return (int)data->values[KIN_VR_SEQUENCE] - 1;
}

static const ak_sequence *sequence_of(const ak_model_data *data) {
    return &AK_SEQUENCES[sequence_index(data)];
}

/* The sines of the angles, kept in data->work from evaluate for evaluate_lazy: the lazy group
 * then needs only those of the half angles. */
_Static_assert(sizeof(ak_sines) <= sizeof(((ak_model_data *)0)->work), "the work array holds them");

static ak_eval_status evaluate(ak_model_data *data) {
    double *v = data->values;
    ak_sines sines;
    ak_angle_sines(&v[KIN_VR_THETA], &sines);
    memcpy(data->work, &sines, sizeof sines);
    /* The sequence's generated kernel, called directly: what ak_general_angular_kinematics_of_sines
     * calls for it, without finding it by address. */
    AK_SEQUENCE_KINEMATICS[sequence_index(data)](&sines, &v[KIN_VR_THETA_DOT],
                                                 &v[KIN_VR_THETA_DDOT], &v[KIN_VR_OMEGA_FIXED],
                                                 &v[KIN_VR_OMEGA_BODY], &v[KIN_VR_ALPHA_FIXED],
                                                 &v[KIN_VR_ALPHA_BODY]);
    return AK_EVAL_OK;
}

/* The lazy outputs R, q, W_fixed, W_body, W_fixed_dot, W_body_dot hold consecutive value
 * references in the order of ak_rotation_outputs (checked here), so they are stored in one copy. */
_Static_assert(KIN_VR_Q == KIN_VR_R + 9 && KIN_VR_W_FIXED == KIN_VR_Q + 4 &&
                   KIN_VR_W_BODY == KIN_VR_W_FIXED + 9 && KIN_VR_W_FIXED_DOT == KIN_VR_W_BODY + 9 &&
                   KIN_VR_W_BODY_DOT == KIN_VR_W_FIXED_DOT + 9,
               "the lazy outputs follow ak_rotation_outputs");
_Static_assert(sizeof(ak_rotation_outputs) == 49 * sizeof(double), "no padding");

static void evaluate_lazy(ak_model_data *data) {
    double *v = data->values;
    ak_sines sines, half;
    memcpy(&sines, data->work, sizeof sines);
    ak_half_angle_sines(&sines, &half);
    ak_rotation_outputs out;
    ak_general_rotation_outputs(sequence_of(data), &sines, &half, &v[KIN_VR_THETA_DOT], &out);
    memcpy(&v[KIN_VR_R], &out, sizeof out);
}

/* A read of lazy outputs after an input changed: the main group by the sequence's kernel, then
 * the lazy one. Not the general kernel's one chain for all of them: its omega and alpha can differ
 * from the sequence kernel's in the sign of an exact zero, and a value must not depend on what
 * else was read. */
static ak_eval_status evaluate_all(ak_model_data *data) {
    const ak_eval_status status = evaluate(data);
    evaluate_lazy(data);
    return status;
}

static void jacobian(const ak_model_data *data, const unsigned int out[], size_t n_out,
                     double J[][AK_MAX_KNOWNS]) {
    const double *v = data->values;
    double full[AK_GENERAL_N_OUTPUTS][AK_GENERAL_N_INPUTS];
    ak_general_jacobian(sequence_of(data), &v[KIN_VR_THETA], &v[KIN_VR_THETA_DOT],
                        &v[KIN_VR_THETA_DDOT], full);
    for (size_t i = 0; i < n_out; i++) {
        for (int k = 0; k < KIN_N_INPUTS; k++) {
            J[i][k] = full[kernel_row(out[i])][k];
        }
    }
}

/* d y / dt = J (theta_dot, theta_ddot, theta_dddot) for every output: theta_dot and theta_ddot
 * are inputs, theta_dddot the first derivative of theta_ddot given by the master (zero when not
 * given). d omega / dt is alpha exactly; it comes out of the same sum. */
static void output_derivatives(ak_model_data *data, const unsigned int vr[], size_t nvr,
                               double value[]) {
    const double *v = data->values;
    double full[AK_GENERAL_N_OUTPUTS][AK_GENERAL_N_INPUTS];
    ak_general_jacobian(sequence_of(data), &v[KIN_VR_THETA], &v[KIN_VR_THETA_DOT],
                        &v[KIN_VR_THETA_DDOT], full);
    double rates[KIN_N_INPUTS];
    for (int k = 0; k < 3; k++) {
        rates[k] = v[KIN_VR_THETA_DOT + k];
        rates[3 + k] = v[KIN_VR_THETA_DDOT + k];
        rates[6 + k] = data->input_derivatives[KIN_VR_THETA_DDOT + k][0];
    }
    const bool jerk_assumed = rates[6] == 0.0 && rates[7] == 0.0 && rates[8] == 0.0;
    for (size_t i = 0; i < nvr; i++) {
        const unsigned int r = vr[i];
        if (r < KIN_VR_ALPHA_FIXED) {
            /* d omega / dt = alpha, component by component in either frame: the output itself. */
            value[i] = v[r + (KIN_VR_ALPHA_FIXED - KIN_VR_OMEGA_FIXED)];
            continue;
        }
        double sum = 0.0;
        for (int k = 0; k < KIN_N_INPUTS; k++) {
            sum += full[kernel_row(r)][k] * rates[k];
        }
        value[i] = sum;
        if (jerk_assumed && r < KIN_VR_R) {
            ak_model_log(data, AK_LOG_CALLS, AK_STATUS_OK,
                   "d(%s)/dt uses theta_dddot = 0 (no nonzero "
                   "derivative of theta_ddot was given)",
                   KIN_VARIABLES[r].name);
        }
    }
}

const ak_model AK_MODEL = {
    .model_identifier = "AngularKinematics",
    .guid = KIN_GUID,
    .variables = KIN_VARIABLES,
    .n_value_references = KIN_N_VALUE_REFERENCES,
    .n_inputs = KIN_N_INPUTS,
    .evaluate = evaluate,
    .evaluate_lazy = evaluate_lazy,
    .evaluate_all = evaluate_all,
    .jacobian = jacobian,
    .output_derivatives = output_derivatives,
    .can_interpolate_inputs = true,
    .derived = &KIN_DERIVED_OUTPUTS,
    .evaluate_in_step = false, /* the evaluation never fails: it waits for a read */
};
