/* FMI 3.0 functions for what the models do not have: types other than Float64 and Int64
 * (Enumeration), clocks, structural parameters and scheduled execution. Each refuses with
 * fmi3Error and changes nothing; a getter or setter given no value reference and no value has
 * nothing to refuse and returns fmi3OK, as its FMI 2 counterpart does. */
#include <string.h>

#include "fmi3_layer.h"

/* A getter or setter of a type no variable has: every value reference is unknown. */
static fmi3Status absent_type(fmi3Instance c, ak3_function function,
                              const fmi3ValueReference vr[], size_t nvr, const void *values,
                              size_t nValues) {
    const char *name = fmi3_name(function);
    if (!fmi3_allowed(c, function)) {
        return fmi3Error;
    }
    if ((nvr > 0 && vr == NULL) || (nValues > 0 && values == NULL)) {
        ak_log(c, AK_LOG_ERROR, AK_STATUS_ERROR, "%s: %s is NULL with %s = %zu", name,
               vr == NULL ? "valueReferences" : "values",
               vr == NULL ? "nValueReferences" : "nValues", vr == NULL ? nvr : nValues);
        return fmi3Error;
    }
    if (nvr > 0 || nValues > 0) {
        /* The type is the name's end: fmi3GetInt8, fmi3SetInt8. */
        ak_log(c, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: valueReferences[0] = %u: this FMU has no %s variables (nValueReferences = "
               "%zu, nValues = %zu)",
               name, nvr > 0 ? vr[0] : 0u, name + strlen("fmi3Get"), nvr, nValues);
        return fmi3Error;
    }
    return fmi3OK;
}

/* A function of a feature the models lack: refused in every state. */
static fmi3Status not_supported(fmi3Instance c, const char *function, const char *why) {
    if (c != NULL) {
        ak_log(c, AK_LOG_ERROR, AK_STATUS_ERROR, "%s: not supported: %s", function, why);
    }
    return fmi3Error;
}

fmi3Status fmi3GetFloat32(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                          fmi3Float32 values[], size_t nValues) {
    return absent_type(c, AK3_GET_FLOAT32, vr, nvr, values, nValues);
}

fmi3Status fmi3SetFloat32(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                          const fmi3Float32 values[], size_t nValues) {
    return absent_type(c, AK3_SET_FLOAT32, vr, nvr, values, nValues);
}

fmi3Status fmi3GetInt8(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                       fmi3Int8 values[], size_t nValues) {
    return absent_type(c, AK3_GET_INT8, vr, nvr, values, nValues);
}

fmi3Status fmi3SetInt8(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                       const fmi3Int8 values[], size_t nValues) {
    return absent_type(c, AK3_SET_INT8, vr, nvr, values, nValues);
}

fmi3Status fmi3GetUInt8(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                        fmi3UInt8 values[], size_t nValues) {
    return absent_type(c, AK3_GET_UINT8, vr, nvr, values, nValues);
}

fmi3Status fmi3SetUInt8(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                        const fmi3UInt8 values[], size_t nValues) {
    return absent_type(c, AK3_SET_UINT8, vr, nvr, values, nValues);
}

fmi3Status fmi3GetInt16(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                        fmi3Int16 values[], size_t nValues) {
    return absent_type(c, AK3_GET_INT16, vr, nvr, values, nValues);
}

fmi3Status fmi3SetInt16(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                        const fmi3Int16 values[], size_t nValues) {
    return absent_type(c, AK3_SET_INT16, vr, nvr, values, nValues);
}

fmi3Status fmi3GetUInt16(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                         fmi3UInt16 values[], size_t nValues) {
    return absent_type(c, AK3_GET_UINT16, vr, nvr, values, nValues);
}

fmi3Status fmi3SetUInt16(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                         const fmi3UInt16 values[], size_t nValues) {
    return absent_type(c, AK3_SET_UINT16, vr, nvr, values, nValues);
}

fmi3Status fmi3GetInt32(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                        fmi3Int32 values[], size_t nValues) {
    return absent_type(c, AK3_GET_INT32, vr, nvr, values, nValues);
}

fmi3Status fmi3SetInt32(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                        const fmi3Int32 values[], size_t nValues) {
    return absent_type(c, AK3_SET_INT32, vr, nvr, values, nValues);
}

fmi3Status fmi3GetUInt32(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                         fmi3UInt32 values[], size_t nValues) {
    return absent_type(c, AK3_GET_UINT32, vr, nvr, values, nValues);
}

fmi3Status fmi3SetUInt32(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                         const fmi3UInt32 values[], size_t nValues) {
    return absent_type(c, AK3_SET_UINT32, vr, nvr, values, nValues);
}

fmi3Status fmi3GetUInt64(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                         fmi3UInt64 values[], size_t nValues) {
    return absent_type(c, AK3_GET_UINT64, vr, nvr, values, nValues);
}

fmi3Status fmi3SetUInt64(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                         const fmi3UInt64 values[], size_t nValues) {
    return absent_type(c, AK3_SET_UINT64, vr, nvr, values, nValues);
}

fmi3Status fmi3GetBoolean(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                          fmi3Boolean values[], size_t nValues) {
    return absent_type(c, AK3_GET_BOOLEAN, vr, nvr, values, nValues);
}

fmi3Status fmi3SetBoolean(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                          const fmi3Boolean values[], size_t nValues) {
    return absent_type(c, AK3_SET_BOOLEAN, vr, nvr, values, nValues);
}

fmi3Status fmi3GetString(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                         fmi3String values[], size_t nValues) {
    return absent_type(c, AK3_GET_STRING, vr, nvr, values, nValues);
}

fmi3Status fmi3SetString(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                         const fmi3String values[], size_t nValues) {
    return absent_type(c, AK3_SET_STRING, vr, nvr, values, nValues);
}

fmi3Status fmi3GetBinary(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                         size_t valueSizes[], fmi3Binary values[], size_t nValues) {
    (void)valueSizes;
    return absent_type(c, AK3_GET_BINARY, vr, nvr, values, nValues);
}

fmi3Status fmi3SetBinary(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                         const size_t valueSizes[], const fmi3Binary values[], size_t nValues) {
    (void)valueSizes;
    return absent_type(c, AK3_SET_BINARY, vr, nvr, values, nValues);
}

static const char NO_CLOCKS[] = "this FMU has no Clock variables";

fmi3Status fmi3GetClock(fmi3Instance c, const fmi3ValueReference vr[], size_t n, fmi3Clock v[]) {
    (void)vr, (void)n, (void)v;
    return not_supported(c, "fmi3GetClock", NO_CLOCKS);
}

fmi3Status fmi3SetClock(fmi3Instance c, const fmi3ValueReference vr[], size_t n,
                        const fmi3Clock v[]) {
    (void)vr, (void)n, (void)v;
    return not_supported(c, "fmi3SetClock", NO_CLOCKS);
}

fmi3Status fmi3GetIntervalDecimal(fmi3Instance c, const fmi3ValueReference vr[], size_t n,
                                  fmi3Float64 v[], fmi3IntervalQualifier q[]) {
    (void)vr, (void)n, (void)v, (void)q;
    return not_supported(c, "fmi3GetIntervalDecimal", NO_CLOCKS);
}

fmi3Status fmi3GetIntervalFraction(fmi3Instance c, const fmi3ValueReference vr[], size_t n,
                                   fmi3UInt64 v[], fmi3UInt64 r[], fmi3IntervalQualifier q[]) {
    (void)vr, (void)n, (void)v, (void)r, (void)q;
    return not_supported(c, "fmi3GetIntervalFraction", NO_CLOCKS);
}

fmi3Status fmi3GetShiftDecimal(fmi3Instance c, const fmi3ValueReference vr[], size_t n,
                               fmi3Float64 v[]) {
    (void)vr, (void)n, (void)v;
    return not_supported(c, "fmi3GetShiftDecimal", NO_CLOCKS);
}

fmi3Status fmi3GetShiftFraction(fmi3Instance c, const fmi3ValueReference vr[], size_t n,
                                fmi3UInt64 v[], fmi3UInt64 r[]) {
    (void)vr, (void)n, (void)v, (void)r;
    return not_supported(c, "fmi3GetShiftFraction", NO_CLOCKS);
}

fmi3Status fmi3SetIntervalDecimal(fmi3Instance c, const fmi3ValueReference vr[], size_t n,
                                  const fmi3Float64 v[]) {
    (void)vr, (void)n, (void)v;
    return not_supported(c, "fmi3SetIntervalDecimal", NO_CLOCKS);
}

fmi3Status fmi3SetIntervalFraction(fmi3Instance c, const fmi3ValueReference vr[], size_t n,
                                   const fmi3UInt64 v[], const fmi3UInt64 r[]) {
    (void)vr, (void)n, (void)v, (void)r;
    return not_supported(c, "fmi3SetIntervalFraction", NO_CLOCKS);
}

fmi3Status fmi3SetShiftDecimal(fmi3Instance c, const fmi3ValueReference vr[], size_t n,
                               const fmi3Float64 v[]) {
    (void)vr, (void)n, (void)v;
    return not_supported(c, "fmi3SetShiftDecimal", NO_CLOCKS);
}

fmi3Status fmi3SetShiftFraction(fmi3Instance c, const fmi3ValueReference vr[], size_t n,
                                const fmi3UInt64 v[], const fmi3UInt64 r[]) {
    (void)vr, (void)n, (void)v, (void)r;
    return not_supported(c, "fmi3SetShiftFraction", NO_CLOCKS);
}

fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance c) {
    return not_supported(c, "fmi3EvaluateDiscreteStates", NO_CLOCKS);
}

fmi3Status fmi3ActivateModelPartition(fmi3Instance c, fmi3ValueReference clock, fmi3Float64 t) {
    (void)clock, (void)t;
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
