/* PassThrough: the floor of the fmpy comparison and of the C drivers' FMI 2 cycles. A
 * co-simulation FMU of 24 inputs (value references 0 to 23) and 18 outputs (24 to 41) with no
 * arithmetic: a variable below 24 shows that input, output k (value reference 24 + k) shows input
 * k. It only checks value references, so that its cost is what an importer pays for any FMU of
 * this interface. The C drivers use as many of its variables as the model they time, each get
 * and set costing the same for any value reference: AngularKinematics sets 9 (0..8) and gets 12
 * (9..20), AttitudePropagator sets 3 (0..2, omega) and gets 4 or 7 (9..15, q and theta),
 * PointKinematics sets 24 and gets 18 (24..41); modelDescription.xml describes the first (fmpy
 * loads it). Functions that a benchmark does not need return fmi2Error. */
#include <string.h>

#include "fmi2Functions.h"

enum { N_INPUTS = 24, N_OUTPUTS = 18, N_VARIABLES = N_INPUTS + N_OUTPUTS };

typedef struct {
    fmi2CallbackFunctions functions;
    double inputs[N_INPUTS];
    double time;
} passthrough;

/* The input each variable shows. A table, so that a get costs what any FMU's copy of values costs
 * (the C drivers time it beside the models' cycles, bench/bench_passthrough.h). */
static const unsigned char SOURCE[N_VARIABLES] = {
    0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20,
    21, 22, 23, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17};

const char *fmi2GetTypesPlatform(void) {
    return fmi2TypesPlatform;
}

const char *fmi2GetVersion(void) {
    return fmi2Version;
}

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t nCategories,
                               const fmi2String categories[]) {
    (void)loggingOn;
    (void)nCategories;
    (void)categories;
    return c != NULL ? fmi2OK : fmi2Error;
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation,
                              const fmi2CallbackFunctions *functions, fmi2Boolean visible,
                              fmi2Boolean loggingOn) {
    (void)instanceName;
    (void)fmuResourceLocation;
    (void)visible;
    (void)loggingOn;
    if (functions == NULL || functions->allocateMemory == NULL || functions->freeMemory == NULL ||
        fmuType != fmi2CoSimulation || fmuGUID == NULL ||
        strcmp(fmuGUID, "{5b2d7a40-3c1e-4f8a-9d6b-0e4f2a7c9b13}") != 0) {
        return NULL;
    }
    passthrough *p = functions->allocateMemory(1, sizeof(passthrough));
    if (p != NULL) {
        p->functions = *functions;
    }
    return p;
}

void fmi2FreeInstance(fmi2Component c) {
    passthrough *p = c;
    if (p != NULL) {
        p->functions.freeMemory(p);
    }
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined,
                               fmi2Real tolerance, fmi2Real startTime,
                               fmi2Boolean stopTimeDefined, fmi2Real stopTime) {
    (void)toleranceDefined;
    (void)tolerance;
    (void)stopTimeDefined;
    (void)stopTime;
    passthrough *p = c;
    if (p == NULL) {
        return fmi2Error;
    }
    p->time = startTime;
    return fmi2OK;
}

static fmi2Status ok_if_instance(fmi2Component c) {
    return c != NULL ? fmi2OK : fmi2Error;
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
    return ok_if_instance(c);
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
    return ok_if_instance(c);
}

fmi2Status fmi2Terminate(fmi2Component c) {
    return ok_if_instance(c);
}

fmi2Status fmi2Reset(fmi2Component c) {
    passthrough *p = c;
    if (p == NULL) {
        return fmi2Error;
    }
    memset(p->inputs, 0, sizeof p->inputs);
    p->time = 0.0;
    return fmi2OK;
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       fmi2Real value[]) {
    const passthrough *p = c;
    if (p == NULL) {
        return fmi2Error;
    }
    for (size_t i = 0; i < nvr; i++) { /* on an error the values are undefined (FMI 2) */
        if (vr[i] >= N_VARIABLES) {
            return fmi2Error;
        }
        value[i] = p->inputs[SOURCE[vr[i]]];
    }
    return fmi2OK;
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       const fmi2Real value[]) {
    passthrough *p = c;
    if (p == NULL) {
        return fmi2Error;
    }
    for (size_t i = 0; i < nvr; i++) {
        if (vr[i] >= N_INPUTS) {
            return fmi2Error;
        }
    }
    for (size_t i = 0; i < nvr; i++) {
        p->inputs[vr[i]] = value[i];
    }
    return fmi2OK;
}

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                      fmi2Real communicationStepSize, fmi2Boolean noSetFMUStatePriorToCurrentPoint) {
    (void)noSetFMUStatePriorToCurrentPoint;
    passthrough *p = c;
    if (p == NULL || !(communicationStepSize > 0.0)) {
        return fmi2Error;
    }
    p->time = currentCommunicationPoint + communicationStepSize;
    return fmi2OK;
}

fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real *value) {
    const passthrough *p = c;
    if (p == NULL || value == NULL || s != fmi2LastSuccessfulTime) {
        return fmi2Error;
    }
    *value = p->time;
    return fmi2OK;
}

fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean *value) {
    if (c == NULL || value == NULL || s != fmi2Terminated) {
        return fmi2Error;
    }
    *value = fmi2False;
    return fmi2OK;
}

/* ---- not needed by the benchmark: refused --------------------------------------------------- */

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          fmi2Integer value[]) {
    (void)c, (void)vr, (void)value;
    return nvr == 0 ? fmi2OK : fmi2Error;
}

fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          fmi2Boolean value[]) {
    (void)c, (void)vr, (void)value;
    return nvr == 0 ? fmi2OK : fmi2Error;
}

fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                         fmi2String value[]) {
    (void)c, (void)vr, (void)value;
    return nvr == 0 ? fmi2OK : fmi2Error;
}

fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          const fmi2Integer value[]) {
    (void)c, (void)vr, (void)value;
    return nvr == 0 ? fmi2OK : fmi2Error;
}

fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          const fmi2Boolean value[]) {
    (void)c, (void)vr, (void)value;
    return nvr == 0 ? fmi2OK : fmi2Error;
}

fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                         const fmi2String value[]) {
    (void)c, (void)vr, (void)value;
    return nvr == 0 ? fmi2OK : fmi2Error;
}

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *FMUstate) {
    (void)c, (void)FMUstate;
    return fmi2Error;
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate FMUstate) {
    (void)c, (void)FMUstate;
    return fmi2Error;
}

fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *FMUstate) {
    (void)c, (void)FMUstate;
    return fmi2Error;
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate FMUstate, size_t *size) {
    (void)c, (void)FMUstate, (void)size;
    return fmi2Error;
}

fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate FMUstate, fmi2Byte serializedState[],
                                 size_t size) {
    (void)c, (void)FMUstate, (void)serializedState, (void)size;
    return fmi2Error;
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte serializedState[], size_t size,
                                   fmi2FMUstate *FMUstate) {
    (void)c, (void)serializedState, (void)size, (void)FMUstate;
    return fmi2Error;
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference vUnknown_ref[],
                                        size_t nUnknown, const fmi2ValueReference vKnown_ref[],
                                        size_t nKnown, const fmi2Real dvKnown[],
                                        fmi2Real dvUnknown[]) {
    (void)c, (void)vUnknown_ref, (void)nUnknown, (void)vKnown_ref, (void)nKnown, (void)dvKnown,
        (void)dvUnknown;
    return fmi2Error;
}

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                       const fmi2Integer order[], const fmi2Real value[]) {
    (void)c, (void)vr, (void)nvr, (void)order, (void)value;
    return fmi2Error;
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[],
                                        size_t nvr, const fmi2Integer order[], fmi2Real value[]) {
    (void)c, (void)vr, (void)nvr, (void)order, (void)value;
    return fmi2Error;
}

fmi2Status fmi2CancelStep(fmi2Component c) {
    (void)c;
    return fmi2Error;
}

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status *value) {
    (void)c, (void)s, (void)value;
    return fmi2Discard;
}

fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer *value) {
    (void)c, (void)s, (void)value;
    return fmi2Discard;
}

fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String *value) {
    (void)c, (void)s, (void)value;
    return fmi2Discard;
}
