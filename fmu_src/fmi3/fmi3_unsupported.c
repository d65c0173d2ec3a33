/* FMI 3.0 functions for what the models do not have: variables of types other than Float64 and
 * Enumeration (Int64), clocks and their intervals and shifts, structural parameters
 * (Configuration Mode), discrete-state evaluation of clocked partitions, and scheduled
 * execution. Each refuses with fmi3Error and a message naming the function and what is missing,
 * and changes nothing; a getter or setter given no value reference at all has nothing to refuse
 * and returns fmi3OK, as its FMI 2 counterpart does. */
#include <stddef.h>

#include "fmi3_layer.h"

/* A getter or setter of a type no variable has: every value reference is unknown. */
static fmi3Status absent_type(fmi3Instance c, ak3_function function, const char *type,
                              const fmi3ValueReference vr[], size_t nvr, const void *values,
                              size_t nValues) {
    const ak_instance *instance = c;
    if (!fmi3_allowed(instance, function)) {
        return fmi3Error;
    }
    if ((nvr > 0 && vr == NULL) || (nValues > 0 && values == NULL)) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR, "%s: %s is NULL with %s = %zu",
                fmi3_name(function), vr == NULL ? "valueReferences" : "values",
                vr == NULL ? "nValueReferences" : "nValues", vr == NULL ? nvr : nValues);
        return fmi3Error;
    }
    if (nvr > 0 || nValues > 0) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
                "%s: valueReferences[0] = %u: this FMU has no %s variables (nValueReferences = "
                "%zu, nValues = %zu)",
                fmi3_name(function), nvr > 0 ? vr[0] : 0u, type, nvr, nValues);
        return fmi3Error;
    }
    return fmi3OK;
}

/* A function of a feature the models lack: refused in every state. */
static fmi3Status not_supported(fmi3Instance c, const char *function, const char *why) {
    const ak_instance *instance = c;
    if (instance != NULL) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR, "%s: not supported: %s", function, why);
    }
    return fmi3Error;
}

fmi3Status fmi3GetFloat32(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr, fmi3Float32 values[],
                       size_t nValues) {
    return absent_type(c, AK3_GET_FLOAT32, "Float32", vr, nvr, values, nValues);
}

fmi3Status fmi3SetFloat32(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                       const fmi3Float32 values[], size_t nValues) {
    return absent_type(c, AK3_SET_FLOAT32, "Float32", vr, nvr, values, nValues);
}

fmi3Status fmi3GetInt8(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr, fmi3Int8 values[],
                       size_t nValues) {
    return absent_type(c, AK3_GET_INT8, "Int8", vr, nvr, values, nValues);
}

fmi3Status fmi3SetInt8(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                       const fmi3Int8 values[], size_t nValues) {
    return absent_type(c, AK3_SET_INT8, "Int8", vr, nvr, values, nValues);
}

fmi3Status fmi3GetUInt8(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr, fmi3UInt8 values[],
                       size_t nValues) {
    return absent_type(c, AK3_GET_UINT8, "UInt8", vr, nvr, values, nValues);
}

fmi3Status fmi3SetUInt8(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                       const fmi3UInt8 values[], size_t nValues) {
    return absent_type(c, AK3_SET_UINT8, "UInt8", vr, nvr, values, nValues);
}

fmi3Status fmi3GetInt16(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr, fmi3Int16 values[],
                       size_t nValues) {
    return absent_type(c, AK3_GET_INT16, "Int16", vr, nvr, values, nValues);
}

fmi3Status fmi3SetInt16(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                       const fmi3Int16 values[], size_t nValues) {
    return absent_type(c, AK3_SET_INT16, "Int16", vr, nvr, values, nValues);
}

fmi3Status fmi3GetUInt16(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr, fmi3UInt16 values[],
                       size_t nValues) {
    return absent_type(c, AK3_GET_UINT16, "UInt16", vr, nvr, values, nValues);
}

fmi3Status fmi3SetUInt16(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                       const fmi3UInt16 values[], size_t nValues) {
    return absent_type(c, AK3_SET_UINT16, "UInt16", vr, nvr, values, nValues);
}

fmi3Status fmi3GetInt32(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr, fmi3Int32 values[],
                       size_t nValues) {
    return absent_type(c, AK3_GET_INT32, "Int32", vr, nvr, values, nValues);
}

fmi3Status fmi3SetInt32(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                       const fmi3Int32 values[], size_t nValues) {
    return absent_type(c, AK3_SET_INT32, "Int32", vr, nvr, values, nValues);
}

fmi3Status fmi3GetUInt32(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr, fmi3UInt32 values[],
                       size_t nValues) {
    return absent_type(c, AK3_GET_UINT32, "UInt32", vr, nvr, values, nValues);
}

fmi3Status fmi3SetUInt32(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                       const fmi3UInt32 values[], size_t nValues) {
    return absent_type(c, AK3_SET_UINT32, "UInt32", vr, nvr, values, nValues);
}

fmi3Status fmi3GetUInt64(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr, fmi3UInt64 values[],
                       size_t nValues) {
    return absent_type(c, AK3_GET_UINT64, "UInt64", vr, nvr, values, nValues);
}

fmi3Status fmi3SetUInt64(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                       const fmi3UInt64 values[], size_t nValues) {
    return absent_type(c, AK3_SET_UINT64, "UInt64", vr, nvr, values, nValues);
}

fmi3Status fmi3GetBoolean(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr, fmi3Boolean values[],
                       size_t nValues) {
    return absent_type(c, AK3_GET_BOOLEAN, "Boolean", vr, nvr, values, nValues);
}

fmi3Status fmi3SetBoolean(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                       const fmi3Boolean values[], size_t nValues) {
    return absent_type(c, AK3_SET_BOOLEAN, "Boolean", vr, nvr, values, nValues);
}

fmi3Status fmi3GetString(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr, fmi3String values[],
                       size_t nValues) {
    return absent_type(c, AK3_GET_STRING, "String", vr, nvr, values, nValues);
}

fmi3Status fmi3SetString(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                       const fmi3String values[], size_t nValues) {
    return absent_type(c, AK3_SET_STRING, "String", vr, nvr, values, nValues);
}

fmi3Status fmi3GetBinary(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                         size_t valueSizes[], fmi3Binary values[], size_t nValues) {
    (void)valueSizes;
    return absent_type(c, AK3_GET_BINARY, "Binary", vr, nvr, values, nValues);
}

fmi3Status fmi3SetBinary(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                         const size_t valueSizes[], const fmi3Binary values[], size_t nValues) {
    (void)valueSizes;
    return absent_type(c, AK3_SET_BINARY, "Binary", vr, nvr, values, nValues);
}

static const char NO_CLOCKS[] = "this FMU has no Clock variables";

fmi3Status fmi3GetClock(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                        fmi3Clock values[]) {
    (void)vr, (void)nvr, (void)values;
    return not_supported(c, "fmi3GetClock", NO_CLOCKS);
}

fmi3Status fmi3SetClock(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                        const fmi3Clock values[]) {
    (void)vr, (void)nvr, (void)values;
    return not_supported(c, "fmi3SetClock", NO_CLOCKS);
}

fmi3Status fmi3GetIntervalDecimal(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                                  fmi3Float64 intervals[], fmi3IntervalQualifier qualifiers[]) {
    (void)vr, (void)nvr, (void)intervals, (void)qualifiers;
    return not_supported(c, "fmi3GetIntervalDecimal", NO_CLOCKS);
}

fmi3Status fmi3GetIntervalFraction(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                                   fmi3UInt64 counters[], fmi3UInt64 resolutions[],
                                   fmi3IntervalQualifier qualifiers[]) {
    (void)vr, (void)nvr, (void)counters, (void)resolutions, (void)qualifiers;
    return not_supported(c, "fmi3GetIntervalFraction", NO_CLOCKS);
}

fmi3Status fmi3GetShiftDecimal(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                               fmi3Float64 shifts[]) {
    (void)vr, (void)nvr, (void)shifts;
    return not_supported(c, "fmi3GetShiftDecimal", NO_CLOCKS);
}

fmi3Status fmi3GetShiftFraction(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                                fmi3UInt64 counters[], fmi3UInt64 resolutions[]) {
    (void)vr, (void)nvr, (void)counters, (void)resolutions;
    return not_supported(c, "fmi3GetShiftFraction", NO_CLOCKS);
}

fmi3Status fmi3SetIntervalDecimal(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                                  const fmi3Float64 intervals[]) {
    (void)vr, (void)nvr, (void)intervals;
    return not_supported(c, "fmi3SetIntervalDecimal", NO_CLOCKS);
}

fmi3Status fmi3SetIntervalFraction(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                                   const fmi3UInt64 counters[], const fmi3UInt64 resolutions[]) {
    (void)vr, (void)nvr, (void)counters, (void)resolutions;
    return not_supported(c, "fmi3SetIntervalFraction", NO_CLOCKS);
}

fmi3Status fmi3SetShiftDecimal(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                               const fmi3Float64 shifts[]) {
    (void)vr, (void)nvr, (void)shifts;
    return not_supported(c, "fmi3SetShiftDecimal", NO_CLOCKS);
}

fmi3Status fmi3SetShiftFraction(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                                const fmi3UInt64 counters[], const fmi3UInt64 resolutions[]) {
    (void)vr, (void)nvr, (void)counters, (void)resolutions;
    return not_supported(c, "fmi3SetShiftFraction", NO_CLOCKS);
}

fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance c) {
    return not_supported(c, "fmi3EvaluateDiscreteStates", NO_CLOCKS);
}

fmi3Status fmi3ActivateModelPartition(fmi3Instance c, fmi3ValueReference clockReference,
                                      fmi3Float64 activationTime) {
    (void)clockReference, (void)activationTime;
    return not_supported(c, "fmi3ActivateModelPartition",
                         "this FMU has no ScheduledExecution interface");
}

static const char NO_STRUCTURAL_PARAMETERS[] =
    "this FMU has no structural parameters (Configuration Mode does not apply)";

fmi3Status fmi3EnterConfigurationMode(fmi3Instance c) {
    return not_supported(c, "fmi3EnterConfigurationMode", NO_STRUCTURAL_PARAMETERS);
}

fmi3Status fmi3ExitConfigurationMode(fmi3Instance c) {
    return not_supported(c, "fmi3ExitConfigurationMode", NO_STRUCTURAL_PARAMETERS);
}

fmi3Instance fmi3InstantiateScheduledExecution(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath,
    fmi3Boolean visible, fmi3Boolean loggingOn, fmi3InstanceEnvironment instanceEnvironment,
    fmi3LogMessageCallback logMessage, fmi3ClockUpdateCallback clockUpdate,
    fmi3LockPreemptionCallback lockPreemption, fmi3UnlockPreemptionCallback unlockPreemption) {
    (void)instanceName, (void)instantiationToken, (void)resourcePath, (void)visible;
    (void)loggingOn, (void)clockUpdate, (void)lockPreemption, (void)unlockPreemption;
    fmi3_refuse_instantiation(instanceEnvironment, logMessage,
                              "fmi3InstantiateScheduledExecution: not supported: this FMU has no "
                              "ScheduledExecution interface (use fmi3InstantiateCoSimulation or "
                              "fmi3InstantiateModelExchange)");
    return NULL;
}
