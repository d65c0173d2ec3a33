/* FMI 2.0 co-simulation: the step (runtime/stepping.c) and the status functions. */
#include "fmi2_layer.h"

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                      fmi2Real communicationStepSize,
                      fmi2Boolean noSetFMUStatePriorToCurrentPoint) {
    (void)noSetFMUStatePriorToCurrentPoint; /* an FMU state is a copy: nothing to release */
    if (!fmi2_allowed(c, AK_FMI2_DO_STEP)) {
        return fmi2Error;
    }
    return fmi2_status(ak_do_step(c, fmi2_name(AK_FMI2_DO_STEP), currentCommunicationPoint,
                                  communicationStepSize));
}

fmi2Status fmi2CancelStep(fmi2Component c) {
    /* Steps are never asynchronous: no instance is in StepInProgress, the table refuses all. */
    (void)fmi2_allowed(c, AK_FMI2_CANCEL_STEP);
    return fmi2Error;
}

/* No kind is answered by fmi2GetStatus, fmi2GetIntegerStatus and fmi2GetStringStatus. */
static const fmi2StatusKind NONE = (fmi2StatusKind)-1;

/* The state check and the value pointer, then whether the kind asked is the one answered: OK
 * when the caller is to write the value. */
static fmi2Status status_asked(const ak_instance *instance, ak_fmi2_function function,
                               const void *value, fmi2StatusKind kind, fmi2StatusKind answered) {
    if (!fmi2_allowed(instance, function) ||
        !ak_not_null(instance, fmi2_name(function), value, "value")) {
        return fmi2Error;
    }
    if (kind != answered) {
        ak_log(instance, AK_LOG_WARNING, AK_STATUS_DISCARD,
               "%s: status kind %d is not available: steps are never asynchronous",
               fmi2_name(function), (int)kind);
        return fmi2Discard;
    }
    return answered == NONE ? fmi2Error : fmi2OK;
}

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status *value) {
    return status_asked(c, AK_FMI2_GET_STATUS, value, s, NONE);
}

fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real *value) {
    const fmi2Status status =
        status_asked(c, AK_FMI2_GET_REAL_STATUS, value, s, fmi2LastSuccessfulTime);
    if (status == fmi2OK) {
        *value = ((const ak_instance *)c)->time;
    }
    return status;
}

fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer *value) {
    return status_asked(c, AK_FMI2_GET_INTEGER_STATUS, value, s, NONE);
}

fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean *value) {
    const fmi2Status status = status_asked(c, AK_FMI2_GET_BOOLEAN_STATUS, value, s, fmi2Terminated);
    if (status == fmi2OK) {
        *value = fmi2False; /* the FMU never asks to end the simulation */
    }
    return status;
}

fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String *value) {
    return status_asked(c, AK_FMI2_GET_STRING_STATUS, value, s, NONE);
}
