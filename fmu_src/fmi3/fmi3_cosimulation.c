/* FMI 3.0 co-simulation stepping. FMI 3 gives no input derivatives, so a step holds the inputs
 * over the step. A model with continuous states (ak_model.step) advances them over the step
 * with the inputs at its start (a model that wants the inputs' rates has them as inputs of its
 * own: AttitudePropagator's omega_dot); for a model without, the map from inputs to outputs is
 * algebraic and a step only moves the time. A model whose evaluation can fail or follows the
 * path (evaluate_in_step), or has states, is evaluated at the end of the step: when the states
 * cannot be advanced or the evaluation fails the step is not taken (fmi3Discard,
 * lastSuccessfulTime = currentCommunicationPoint; time, states and outputs stay), and the
 * importer may terminate, set an FMU state or reset. */
#include <math.h>
#include <string.h>

#include "fmi3Functions.h"
#include "fmi3_instance.h"
#include "fmi3_logging.h"
#include "fmi3_state_machine.h"

/* Relative tolerance on communication times, the same as the FMI 2 layer's (fmpy's isclose). */
static const double TIME_RELATIVE_TOLERANCE = 1e-9;

static bool times_close(double a, double b) {
    const double scale = fabs(a) > fabs(b) ? fabs(a) : fabs(b);
    return fabs(a - b) <= TIME_RELATIVE_TOLERANCE * scale;
}

static bool step_arguments_valid(const ak3_instance *instance, double t, double h) {
    if (!isfinite(t) || !isfinite(h)) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error,
                "fmi3DoStep: currentCommunicationPoint = %g and communicationStepSize = %g must "
                "be finite",
                t, h);
        return false;
    }
    if (!(h > 0.0)) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error,
                "fmi3DoStep: communicationStepSize = %g must be > 0", h);
        return false;
    }
    if (!times_close(t, instance->time)) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error,
                "fmi3DoStep: currentCommunicationPoint = %.17g does not continue from the last "
                "communication point %.17g",
                t, instance->time);
        return false;
    }
    const double end = t + h;
    if (instance->stop_time_defined && end > instance->stop_time &&
        !times_close(end, instance->stop_time)) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error,
                "fmi3DoStep: the step from %.17g by communicationStepSize = %.17g ends at %.17g, "
                "past stopTime = %.17g",
                t, h, end, instance->stop_time);
        return false;
    }
    return true;
}

/* Advances the continuous states over h (a model with `step`), then evaluates the outputs at the
 * end of the step. When either fails (*step_failed: the states) every value is as it was before
 * the step, and a read evaluates again: the outputs are those of the last successful evaluation
 * until then. A model without states is only evaluated (a failure changes no value). */
static ak_eval_status advance(ak3_instance *instance, double h, bool *step_failed) {
    *step_failed = false;
    if (AK_MODEL.step == NULL) {
        return ak3_instance_update_outputs(instance);
    }
    double saved[AK_MAX_VARIABLES];
    const size_t n_values = sizeof(double) * (size_t)AK_MODEL.n_value_references;
    memcpy(saved, instance->data.values, n_values);
    ak_eval_status status = AK_MODEL.step(&instance->data, h); /* failing, it changed nothing */
    ak3_instance_inputs_changed(instance);
    *step_failed = status == AK_EVAL_FAILED;
    if (!*step_failed) {
        status = ak3_instance_update_outputs(instance);
    }
    if (status == AK_EVAL_FAILED) {
        memcpy(instance->data.values, saved, n_values);
        ak3_instance_inputs_changed(instance);
    }
    return status;
}

fmi3Status fmi3DoStep(fmi3Instance c, fmi3Float64 currentCommunicationPoint,
                      fmi3Float64 communicationStepSize,
                      fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                      fmi3Boolean *eventHandlingNeeded, fmi3Boolean *terminateSimulation,
                      fmi3Boolean *earlyReturn, fmi3Float64 *lastSuccessfulTime) {
    (void)noSetFMUStatePriorToCurrentPoint; /* an FMU state is a copy: nothing to release */
    ak3_instance *instance = c;
    if (!ak3_call_allowed(instance, AK3_DO_STEP)) {
        return fmi3Error;
    }
    if (eventHandlingNeeded == NULL || terminateSimulation == NULL || earlyReturn == NULL ||
        lastSuccessfulTime == NULL) {
        ak3_log(instance, AK_LOG_ERROR, fmi3Error, "fmi3DoStep: %s is NULL",
                eventHandlingNeeded == NULL   ? "eventHandlingNeeded"
                : terminateSimulation == NULL ? "terminateSimulation"
                : earlyReturn == NULL         ? "earlyReturn"
                                              : "lastSuccessfulTime");
        return fmi3Error;
    }
    const double t = currentCommunicationPoint, h = communicationStepSize;
    if (!step_arguments_valid(instance, t, h)) {
        return fmi3Error;
    }
    *eventHandlingNeeded = fmi3False;
    *terminateSimulation = fmi3False;
    *earlyReturn = fmi3False;
    fmi3Status status = fmi3OK;
    if (AK_MODEL.evaluate_in_step || AK_MODEL.step != NULL) {
        bool step_failed = false;
        const ak_eval_status evaluated = advance(instance, h, &step_failed);
        if (evaluated == AK_EVAL_FAILED) {
            ak3_log(instance, AK_LOG_WARNING, fmi3Discard,
                    "fmi3DoStep: the step from %.17g to %.17g is discarded: the %s; last "
                    "successful time %.17g",
                    t, t + h,
                    step_failed ? "states cannot be advanced over it"
                                : "outputs cannot be evaluated at its end",
                    instance->time);
            *lastSuccessfulTime = instance->time;
            return fmi3Discard;
        }
        status = ak3_read_status(evaluated);
    }
    instance->time = t + h;
    *lastSuccessfulTime = instance->time;
    if (ak3_log_on(instance, AK_LOG_CALLS)) {
        ak3_log(instance, AK_LOG_CALLS, fmi3OK, "fmi3DoStep: from %.17g to %.17g", t, t + h);
    }
    return status;
}

fmi3Status fmi3EnterStepMode(fmi3Instance c) {
    /* Only from Event Mode, which co-simulation instances never enter: the table refuses it. */
    ak3_instance *instance = c;
    if (!ak3_call_allowed(instance, AK3_ENTER_STEP_MODE)) {
        return fmi3Error;
    }
    instance->state = AK3_STATE_STEP_MODE;
    return fmi3OK;
}
