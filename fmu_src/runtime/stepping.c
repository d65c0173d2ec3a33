/* Co-simulation for both FMI versions: the inputs held, or moved along their derivatives. */
#include <math.h>
#include <string.h>

#include "runtime.h"

/* fmpy's isclose: a step that fmpy lands on the stop time within its tolerance is accepted. */
static const double TIME_RELATIVE_TOLERANCE = 1e-9;

static bool times_close(double a, double b) {
    /* Not fmax: a library call at every step. */
    const double scale = fabs(a) > fabs(b) ? fabs(a) : fabs(b);
    return fabs(a - b) <= TIME_RELATIVE_TOLERANCE * scale;
}

/* u + s du + s^2/2 d2u and its slope at s = h; false (logged, nothing changed) on overflow. */
static bool advance_inputs(ak_instance *instance, const char *function, double h) {
    double value[AK_MAX_INPUTS], slope[AK_MAX_INPUTS];
    for (int k = 0; k < AK_MODEL.n_inputs; k++) {
        const double d1 = instance->data.input_derivatives[k][0];
        const double d2 = instance->data.input_derivatives[k][1];
        value[k] = instance->data.values[k] + h * (d1 + 0.5 * h * d2);
        slope[k] = d1 + h * d2;
        if (!isfinite(value[k]) || !isfinite(slope[k])) {
            ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
                   "%s: extrapolating %s = %.17g with derivatives %g (order 1) and %g (order 2) "
                   "over communicationStepSize = %g overflows; step not taken",
                   function, AK_MODEL.variables[k].name, instance->data.values[k], d1, d2, h);
            return false;
        }
    }
    for (int k = 0; k < AK_MODEL.n_inputs; k++) {
        if (value[k] != instance->data.values[k]) {
            instance->data.values[k] = value[k];
            ak_instance_inputs_changed(instance);
        }
        instance->data.input_derivatives[k][0] = slope[k];
    }
    ak_input_derivatives_changed(instance);
    return true;
}

static bool step_arguments_valid(const ak_instance *instance, const char *function, double t,
                                 double h) {
    if (!isfinite(t) || !isfinite(h)) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: currentCommunicationPoint = %g and communicationStepSize = %g must be finite",
               function, t, h);
        return false;
    }
    if (!(h > 0.0)) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: communicationStepSize = %g must be > 0", function, h);
        return false;
    }
    if (!times_close(t, instance->time)) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: currentCommunicationPoint = %.17g does not continue from the last "
               "communication point %.17g",
               function, t, instance->time);
        return false;
    }
    const double end = t + h;
    if (instance->stop_time_defined && end > instance->stop_time &&
        !times_close(end, instance->stop_time)) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: the step from %.17g by communicationStepSize = %.17g ends at %.17g, past "
               "stopTime = %.17g",
               function, t, h, end, instance->stop_time);
        return false;
    }
    return true;
}

static ak_status step_evaluating(ak_instance *instance, const char *function, double t,
                                 double h) {
    /* Saved only when something moves before what can fail (which alone writes nothing). */
    const bool any_derivative = instance->data.any_input_derivative;
    const bool moves = (AK_MODEL.step != NULL || any_derivative) &&
                       (AK_MODEL.evaluate_in_step || any_derivative);
    double saved_values[AK_MAX_VARIABLES];
    double saved_derivatives[AK_MAX_INPUTS][AK_MAX_INPUT_DERIVATIVE_ORDER];
    const size_t n_values = sizeof(double) * (size_t)AK_MODEL.n_value_references;
    if (moves) {
        memcpy(saved_values, instance->data.values, n_values);
        memcpy(saved_derivatives, instance->data.input_derivatives, sizeof saved_derivatives);
    }
    ak_eval_status stepped = AK_EVAL_OK;
    if (AK_MODEL.step != NULL) {
        stepped = AK_MODEL.step(&instance->data, h); /* failing, it changed nothing */
        ak_instance_inputs_changed(instance);
    }
    if (stepped != AK_EVAL_FAILED && any_derivative && !advance_inputs(instance, function, h)) {
        memcpy(instance->data.values, saved_values, n_values); /* the states moved */
        return AK_STATUS_ERROR;
    }
    const ak_status status =
        stepped == AK_EVAL_FAILED   ? AK_STATUS_DISCARD
        : AK_MODEL.evaluate_in_step ? ak_instance_update(instance, AK_GROUP_MAIN)
                                    : AK_STATUS_OK;
    if (status == AK_STATUS_DISCARD) {
        if (moves) {
            memcpy(instance->data.values, saved_values, n_values);
            memcpy(instance->data.input_derivatives, saved_derivatives, sizeof saved_derivatives);
            instance->data.any_input_derivative = any_derivative;
        }
        /* A read evaluates again at the restored inputs. */
        ak_instance_inputs_changed(instance);
        instance->state = instance->layer->step_discarded_state;
        ak_log(instance, AK_LOG_WARNING, AK_STATUS_DISCARD,
               "%s: the step from %.17g to %.17g is discarded: the %s; last successful time %.17g",
               function, t, t + h,
               stepped == AK_EVAL_FAILED ? "states cannot be advanced over it"
                                         : "outputs cannot be evaluated at its end",
               instance->time);
        return AK_STATUS_DISCARD;
    }
    instance->time = t + h;
    if (ak_log_on(instance, AK_LOG_CALLS)) {
        ak_log(instance, AK_LOG_CALLS, AK_STATUS_OK, "%s: from %.17g to %.17g", function, t, t + h);
    }
    return status;
}

ak_status ak_do_step(ak_instance *instance, const char *function, double t, double h) {
    if (!step_arguments_valid(instance, function, t, h)) {
        return AK_STATUS_ERROR;
    }
    if (AK_MODEL.evaluate_in_step || AK_MODEL.step != NULL) {
        return step_evaluating(instance, function, t, h);
    }
    if (instance->data.any_input_derivative && !advance_inputs(instance, function, h)) {
        return AK_STATUS_ERROR;
    }
    if (ak_log_on(instance, AK_LOG_CALLS)) {
        ak_log(instance, AK_LOG_CALLS, AK_STATUS_OK, "%s: from %.17g to %.17g", function, t, t + h);
    }
    instance->time = t + h;
    return AK_STATUS_OK;
}

ak_status ak_set_input_derivatives(ak_instance *instance, const char *function,
                                   const unsigned int vr[], size_t nvr, const int order[],
                                   const double value[]) {
    for (size_t i = 0; i < nvr; i++) {
        if (!ak_derivative_variable(instance, function, "vr", i, vr[i], AK_CAUSALITY_INPUT,
                                    NULL)) {
            return AK_STATUS_ERROR;
        }
        if (order[i] < 1 || order[i] > AK_MAX_INPUT_DERIVATIVE_ORDER) {
            ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
                   "%s: order[%zu] = %d for %s: this FMU takes orders 1 to %d; no derivative set",
                   function, i, order[i], AK_MODEL.variables[vr[i]].name,
                   AK_MAX_INPUT_DERIVATIVE_ORDER);
            return AK_STATUS_ERROR;
        }
        if (!isfinite(value[i])) {
            ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
                   "%s: derivative of order %d of %s = %g (vr[%zu] = %u) is not finite; no "
                   "derivative set",
                   function, order[i], AK_MODEL.variables[vr[i]].name, value[i], i, vr[i]);
            return AK_STATUS_ERROR;
        }
    }
    for (size_t i = 0; i < nvr; i++) {
        ak_log(instance, AK_LOG_CALLS, AK_STATUS_OK, "%s: derivative of order %d of %s = %.17g",
               function, order[i], AK_MODEL.variables[vr[i]].name, value[i]);
        instance->data.input_derivatives[vr[i]][order[i] - 1] = value[i];
    }
    ak_input_derivatives_changed(instance);
    return AK_STATUS_OK;
}
