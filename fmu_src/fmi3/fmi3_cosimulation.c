/* FMI 3.0 co-simulation stepping over runtime/stepping.c. FMI 3 gives no input derivatives, so a
 * step holds the inputs over the step (a model that wants the inputs' rates has them as inputs
 * of its own: AttitudePropagator's omega_dot). A discarded step leaves the instance in Step Mode
 * with lastSuccessfulTime = currentCommunicationPoint. */
#include "fmi3_layer.h"

fmi3Status fmi3DoStep(fmi3Instance c, fmi3Float64 currentCommunicationPoint,
                      fmi3Float64 communicationStepSize,
                      fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                      fmi3Boolean *eventHandlingNeeded, fmi3Boolean *terminateSimulation,
                      fmi3Boolean *earlyReturn, fmi3Float64 *lastSuccessfulTime) {
    (void)noSetFMUStatePriorToCurrentPoint; /* an FMU state is a copy: nothing to release */
    ak_instance *instance = c;
    const char *self = fmi3_name(AK3_DO_STEP);
    if (!fmi3_allowed(instance, AK3_DO_STEP) ||
        !ak_not_null(instance, self, eventHandlingNeeded, "eventHandlingNeeded") ||
        !ak_not_null(instance, self, terminateSimulation, "terminateSimulation") ||
        !ak_not_null(instance, self, earlyReturn, "earlyReturn") ||
        !ak_not_null(instance, self, lastSuccessfulTime, "lastSuccessfulTime")) {
        return fmi3Error;
    }
    const ak_status status =
        ak_do_step(instance, self, currentCommunicationPoint, communicationStepSize);
    if (status != AK_STATUS_ERROR) {
        *eventHandlingNeeded = fmi3False;
        *terminateSimulation = fmi3False;
        *earlyReturn = fmi3False;
        *lastSuccessfulTime = instance->time;
    }
    return fmi3_status(status);
}
