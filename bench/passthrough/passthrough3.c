/* PassThrough3: the FMI 3 pass-through of the C drivers (bench_fmi3.c, bench_attitude.c), the
 * floor beside their FMI 3 cycles: float64 arrays, no arithmetic. Inputs: value references 0, 3
 * and 6, arrays of 3 (AngularKinematics' theta, theta_dot, theta_ddot; AttitudePropagator's omega
 * is the one at 0). Outputs: 9, 12, 15, 18, arrays of 3 (omega_fixed .. alpha_body), 21, an array
 * of 4 (q), and 25, an array of 3 (theta); output value k (counted from value reference 9) is
 * input value k mod 9. Like PassThrough.so it checks the instance, the value references and the
 * number of values, so that its cost is what any FMU of these interfaces pays for the calls. Only
 * the functions the drivers call are here; it has no modelDescription.xml (no importer loads it). */
#include <stdlib.h>

#include "fmi3Functions.h"

enum { N_INPUTS = 9, N_VALUES = 28 };

/* The number of values of each value reference (0: none), and the input each value shows. */
static const unsigned char SIZES[N_VALUES] = {3, 0, 0, 3, 0, 0, 3, 0, 0, 3, 0, 0, 3, 0,
                                              0, 3, 0, 0, 3, 0, 0, 4, 0, 0, 0, 3, 0, 0};
static const unsigned char SOURCE[N_VALUES] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 0, 1, 2, 3, 4,
                                               5, 6, 7, 8, 0, 1, 2, 3, 4, 5, 6, 7, 8, 0};

typedef struct {
    double inputs[N_INPUTS];
    double time;
} passthrough;

const char *fmi3GetVersion(void) {
    return fmi3Version;
}

fmi3Instance fmi3InstantiateCoSimulation(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath,
    fmi3Boolean visible, fmi3Boolean loggingOn, fmi3Boolean eventModeUsed,
    fmi3Boolean earlyReturnAllowed, const fmi3ValueReference requiredIntermediateVariables[],
    size_t nRequiredIntermediateVariables, fmi3InstanceEnvironment instanceEnvironment,
    fmi3LogMessageCallback logMessage, fmi3IntermediateUpdateCallback intermediateUpdate) {
    (void)instanceName, (void)instantiationToken, (void)resourcePath, (void)visible,
        (void)loggingOn, (void)eventModeUsed, (void)earlyReturnAllowed,
        (void)requiredIntermediateVariables, (void)instanceEnvironment, (void)logMessage,
        (void)intermediateUpdate;
    return nRequiredIntermediateVariables == 0 ? calloc(1, sizeof(passthrough)) : NULL;
}

void fmi3FreeInstance(fmi3Instance instance) {
    free(instance);
}

fmi3Status fmi3EnterInitializationMode(fmi3Instance instance, fmi3Boolean toleranceDefined,
                                       fmi3Float64 tolerance, fmi3Float64 startTime,
                                       fmi3Boolean stopTimeDefined, fmi3Float64 stopTime) {
    (void)toleranceDefined, (void)tolerance, (void)stopTimeDefined, (void)stopTime;
    passthrough *p = instance;
    if (p == NULL) {
        return fmi3Error;
    }
    p->time = startTime;
    return fmi3OK;
}

fmi3Status fmi3ExitInitializationMode(fmi3Instance instance) {
    return instance != NULL ? fmi3OK : fmi3Error;
}

fmi3Status fmi3Terminate(fmi3Instance instance) {
    return instance != NULL ? fmi3OK : fmi3Error;
}

/* Values set or got: every value reference known (an input when setting), no more values than
 * nValues, and exactly nValues in all; on an error the values are undefined (FMI 3). */
fmi3Status fmi3SetFloat64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                          const fmi3Float64 values[], size_t nValues) {
    passthrough *p = instance;
    if (p == NULL) {
        return fmi3Error;
    }
    size_t done = 0;
    for (size_t i = 0; i < nvr; i++) {
        const size_t size = vr[i] < N_INPUTS ? SIZES[vr[i]] : 0;
        if (size == 0 || done + size > nValues) {
            return fmi3Error;
        }
        for (size_t k = 0; k < size; k++) {
            p->inputs[vr[i] + k] = values[done + k];
        }
        done += size;
    }
    return done == nValues ? fmi3OK : fmi3Error;
}

fmi3Status fmi3GetFloat64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                          fmi3Float64 values[], size_t nValues) {
    const passthrough *p = instance;
    if (p == NULL) {
        return fmi3Error;
    }
    size_t done = 0;
    for (size_t i = 0; i < nvr; i++) {
        const size_t size = vr[i] < N_VALUES ? SIZES[vr[i]] : 0;
        if (size == 0 || done + size > nValues) {
            return fmi3Error;
        }
        for (size_t k = 0; k < size; k++) {
            values[done + k] = p->inputs[SOURCE[vr[i] + k]];
        }
        done += size;
    }
    return done == nValues ? fmi3OK : fmi3Error;
}

fmi3Status fmi3DoStep(fmi3Instance instance, fmi3Float64 currentCommunicationPoint,
                      fmi3Float64 communicationStepSize, fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                      fmi3Boolean *eventHandlingNeeded, fmi3Boolean *terminateSimulation,
                      fmi3Boolean *earlyReturn, fmi3Float64 *lastSuccessfulTime) {
    (void)noSetFMUStatePriorToCurrentPoint;
    passthrough *p = instance;
    if (p == NULL || !(communicationStepSize > 0.0)) {
        return fmi3Error;
    }
    p->time = currentCommunicationPoint + communicationStepSize;
    *eventHandlingNeeded = fmi3False;
    *terminateSimulation = fmi3False;
    *earlyReturn = fmi3False;
    *lastSuccessfulTime = p->time;
    return fmi3OK;
}
