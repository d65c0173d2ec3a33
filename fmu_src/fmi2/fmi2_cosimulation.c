/* FMI 2.0 co-simulation: the step, the input derivatives (runtime/stepping.c) and the status
 * functions, which only FMI 2 has. */
#include "fmi2_layer.h"

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                      fmi2Real communicationStepSize, fmi2Boolean noSetFMUStatePriorToCurrentPoint) {
    (void)noSetFMUStatePriorToCurrentPoint; /* an FMU state is a copy: nothing to release */
    ak_instance *instance = c;
    if (!fmi2_allowed(instance, AK_FMI2_DO_STEP)) {
        return fmi2Error;
    }
    return fmi2_status(ak_do_step(instance, fmi2_name(AK_FMI2_DO_STEP), currentCommunicationPoint,
                                  communicationStepSize));
}

fmi2Status fmi2CancelStep(fmi2Component c) {
    /* Steps are never asynchronous, so no instance is ever in StepInProgress: the table rejects
     * every call. */
    (void)fmi2_allowed(c, AK_FMI2_CANCEL_STEP);
    return fmi2Error;
}

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                       const fmi2Integer order[], const fmi2Real value[]) {
    ak_instance *instance = c;
    const char *self = fmi2_name(AK_FMI2_SET_REAL_INPUT_DERIVATIVES);
    if (!fmi2_allowed(instance, AK_FMI2_SET_REAL_INPUT_DERIVATIVES)) {
        return fmi2Error;
    }
    if (!AK_MODEL.can_interpolate_inputs) {
        return fmi2_status(ak_not_provided(instance, self, "canInterpolateInputs=\"false\""));
    }
    if (!ak_given(instance, self, nvr, "nvr", vr, "vr") ||
        !ak_given(instance, self, nvr, "nvr", order, "order") ||
        !ak_given(instance, self, nvr, "nvr", value, "value")) {
        return fmi2Error;
    }
    return fmi2_status(ak_set_input_derivatives(instance, self, vr, nvr, order, value));
}

static fmi2Status status_not_available(const ak_instance *instance, ak_fmi2_function function,
                                       int kind) {
    ak_log(instance, AK_LOG_WARNING, AK_STATUS_DISCARD,
           "%s: status kind %d is not available: steps are never asynchronous",
           fmi2_name(function), kind);
    return fmi2Discard;
}

/* The state check and the value pointer; then whether the kind is the one that is answered. */
static bool status_asked(const ak_instance *instance, ak_fmi2_function function,
                         const void *value, fmi2StatusKind kind, fmi2StatusKind answered,
                         fmi2Status *status) {
    if (!fmi2_allowed(instance, function) ||
        !ak_not_null(instance, fmi2_name(function), value, "value")) {
        *status = fmi2Error;
        return false;
    }
    if (kind != answered) {
        *status = status_not_available(instance, function, (int)kind);
        return false;
    }
    return true;
}

/* No kind is answered by fmi2GetStatus, fmi2GetIntegerStatus and fmi2GetStringStatus. */
static const fmi2StatusKind NONE = (fmi2StatusKind)-1;

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status *value) {
    fmi2Status status = fmi2Error;
    (void)status_asked(c, AK_FMI2_GET_STATUS, value, s, NONE, &status);
    return status;
}

fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real *value) {
    fmi2Status status = fmi2OK;
    if (status_asked(c, AK_FMI2_GET_REAL_STATUS, value, s, fmi2LastSuccessfulTime, &status)) {
        *value = ((const ak_instance *)c)->time;
    }
    return status;
}

fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer *value) {
    fmi2Status status = fmi2Error;
    (void)status_asked(c, AK_FMI2_GET_INTEGER_STATUS, value, s, NONE, &status);
    return status;
}

fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean *value) {
    fmi2Status status = fmi2OK;
    if (status_asked(c, AK_FMI2_GET_BOOLEAN_STATUS, value, s, fmi2Terminated, &status)) {
        *value = fmi2False; /* the FMU never asks to end the simulation */
    }
    return status;
}

fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String *value) {
    fmi2Status status = fmi2Error;
    (void)status_asked(c, AK_FMI2_GET_STRING_STATUS, value, s, NONE, &status);
    return status;
}
