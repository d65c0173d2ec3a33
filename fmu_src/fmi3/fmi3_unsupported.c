/* FMI 3.0 functions for what the models lack: each refuses with fmi3Error and changes nothing,
 * except a getter or setter given nothing to read or write, which returns fmi3OK as in FMI 2. */
#include <string.h>

#include "fmi3_layer.h"

/* like: fmi3GetFloat64's or fmi3SetFloat64's row, whose states every type shares. */
static fmi3Status absent_type(fmi3Instance c, ak3_function like, const char *name,
                              const fmi3ValueReference vr[], size_t nvr, const void *values,
                              size_t nValues) {
    ak_function_rule rule = FMI3_RULES[like];
    rule.name = name;
    if (!ak_call_allowed(c, &rule)) {
        return fmi3Error;
    }
    if ((nvr > 0 && vr == NULL) || (nValues > 0 && values == NULL)) {
        ak_log(c, AK_LOG_ERROR, AK_STATUS_ERROR, "%s: %s is NULL with %s = %zu", name,
               vr == NULL ? "valueReferences" : "values",
               vr == NULL ? "nValueReferences" : "nValues", vr == NULL ? nvr : nValues);
        return fmi3Error;
    }
    if (nvr > 0 || nValues > 0) {
        ak_log(c, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: valueReferences[0] = %u: this FMU has no %s variables (nValueReferences = "
               "%zu, nValues = %zu)",
               name, nvr > 0 ? vr[0] : 0u, name + strlen("fmi3Get"), nvr, nValues);
        return fmi3Error;
    }
    return fmi3OK;
}

/* The arguments after why are those the refused function ignores. */
static fmi3Status not_supported(fmi3Instance c, const char *function, const char *why, ...) {
    if (c != NULL) {
        ak_log(c, AK_LOG_ERROR, AK_STATUS_ERROR, "%s: not supported: %s", function, why);
    }
    return fmi3Error;
}

fmi3Status fmi3GetFloat32(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                          fmi3Float32 values[], size_t nValues) {
    return absent_type(c, AK3_GET_FLOAT64, "fmi3GetFloat32", vr, nvr, values, nValues);
}

fmi3Status fmi3SetFloat32(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                          const fmi3Float32 values[], size_t nValues) {
    return absent_type(c, AK3_SET_FLOAT64, "fmi3SetFloat32", vr, nvr, values, nValues);
}

fmi3Status fmi3GetInt8(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                       fmi3Int8 values[], size_t nValues) {
    return absent_type(c, AK3_GET_FLOAT64, "fmi3GetInt8", vr, nvr, values, nValues);
}

fmi3Status fmi3SetInt8(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                       const fmi3Int8 values[], size_t nValues) {
    return absent_type(c, AK3_SET_FLOAT64, "fmi3SetInt8", vr, nvr, values, nValues);
}

fmi3Status fmi3GetUInt8(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                        fmi3UInt8 values[], size_t nValues) {
    return absent_type(c, AK3_GET_FLOAT64, "fmi3GetUInt8", vr, nvr, values, nValues);
}

fmi3Status fmi3SetUInt8(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                        const fmi3UInt8 values[], size_t nValues) {
    return absent_type(c, AK3_SET_FLOAT64, "fmi3SetUInt8", vr, nvr, values, nValues);
}

fmi3Status fmi3GetInt16(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                        fmi3Int16 values[], size_t nValues) {
    return absent_type(c, AK3_GET_FLOAT64, "fmi3GetInt16", vr, nvr, values, nValues);
}

fmi3Status fmi3SetInt16(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                        const fmi3Int16 values[], size_t nValues) {
    return absent_type(c, AK3_SET_FLOAT64, "fmi3SetInt16", vr, nvr, values, nValues);
}

fmi3Status fmi3GetUInt16(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                         fmi3UInt16 values[], size_t nValues) {
    return absent_type(c, AK3_GET_FLOAT64, "fmi3GetUInt16", vr, nvr, values, nValues);
}

fmi3Status fmi3SetUInt16(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                         const fmi3UInt16 values[], size_t nValues) {
    return absent_type(c, AK3_SET_FLOAT64, "fmi3SetUInt16", vr, nvr, values, nValues);
}

fmi3Status fmi3GetInt32(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                        fmi3Int32 values[], size_t nValues) {
    return absent_type(c, AK3_GET_FLOAT64, "fmi3GetInt32", vr, nvr, values, nValues);
}

fmi3Status fmi3SetInt32(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                        const fmi3Int32 values[], size_t nValues) {
    return absent_type(c, AK3_SET_FLOAT64, "fmi3SetInt32", vr, nvr, values, nValues);
}

fmi3Status fmi3GetUInt32(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                         fmi3UInt32 values[], size_t nValues) {
    return absent_type(c, AK3_GET_FLOAT64, "fmi3GetUInt32", vr, nvr, values, nValues);
}

fmi3Status fmi3SetUInt32(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                         const fmi3UInt32 values[], size_t nValues) {
    return absent_type(c, AK3_SET_FLOAT64, "fmi3SetUInt32", vr, nvr, values, nValues);
}

fmi3Status fmi3GetUInt64(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                         fmi3UInt64 values[], size_t nValues) {
    return absent_type(c, AK3_GET_FLOAT64, "fmi3GetUInt64", vr, nvr, values, nValues);
}

fmi3Status fmi3SetUInt64(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                         const fmi3UInt64 values[], size_t nValues) {
    return absent_type(c, AK3_SET_FLOAT64, "fmi3SetUInt64", vr, nvr, values, nValues);
}

fmi3Status fmi3GetBoolean(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                          fmi3Boolean values[], size_t nValues) {
    return absent_type(c, AK3_GET_FLOAT64, "fmi3GetBoolean", vr, nvr, values, nValues);
}

fmi3Status fmi3SetBoolean(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                          const fmi3Boolean values[], size_t nValues) {
    return absent_type(c, AK3_SET_FLOAT64, "fmi3SetBoolean", vr, nvr, values, nValues);
}

fmi3Status fmi3GetString(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                         fmi3String values[], size_t nValues) {
    return absent_type(c, AK3_GET_FLOAT64, "fmi3GetString", vr, nvr, values, nValues);
}

fmi3Status fmi3SetString(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                         const fmi3String values[], size_t nValues) {
    return absent_type(c, AK3_SET_FLOAT64, "fmi3SetString", vr, nvr, values, nValues);
}

fmi3Status fmi3GetBinary(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                         size_t valueSizes[], fmi3Binary values[], size_t nValues) {
    (void)valueSizes;
    return absent_type(c, AK3_GET_FLOAT64, "fmi3GetBinary", vr, nvr, values, nValues);
}

fmi3Status fmi3SetBinary(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                         const size_t valueSizes[], const fmi3Binary values[], size_t nValues) {
    (void)valueSizes;
    return absent_type(c, AK3_SET_FLOAT64, "fmi3SetBinary", vr, nvr, values, nValues);
}

static const char NO_CLOCKS[] = "this FMU has no Clock variables";

fmi3Status fmi3GetClock(fmi3Instance c, const fmi3ValueReference vr[], size_t n, fmi3Clock v[]) {
    return not_supported(c, "fmi3GetClock", NO_CLOCKS, vr, n, v);
}

fmi3Status fmi3SetClock(fmi3Instance c, const fmi3ValueReference vr[], size_t n,
                        const fmi3Clock v[]) {
    return not_supported(c, "fmi3SetClock", NO_CLOCKS, vr, n, v);
}

fmi3Status fmi3GetIntervalDecimal(fmi3Instance c, const fmi3ValueReference vr[], size_t n,
                                  fmi3Float64 v[], fmi3IntervalQualifier q[]) {
    return not_supported(c, "fmi3GetIntervalDecimal", NO_CLOCKS, vr, n, v, q);
}

fmi3Status fmi3GetIntervalFraction(fmi3Instance c, const fmi3ValueReference vr[], size_t n,
                                   fmi3UInt64 v[], fmi3UInt64 r[], fmi3IntervalQualifier q[]) {
    return not_supported(c, "fmi3GetIntervalFraction", NO_CLOCKS, vr, n, v, r, q);
}

fmi3Status fmi3GetShiftDecimal(fmi3Instance c, const fmi3ValueReference vr[], size_t n,
                               fmi3Float64 v[]) {
    return not_supported(c, "fmi3GetShiftDecimal", NO_CLOCKS, vr, n, v);
}

fmi3Status fmi3GetShiftFraction(fmi3Instance c, const fmi3ValueReference vr[], size_t n,
                                fmi3UInt64 v[], fmi3UInt64 r[]) {
    return not_supported(c, "fmi3GetShiftFraction", NO_CLOCKS, vr, n, v, r);
}

fmi3Status fmi3SetIntervalDecimal(fmi3Instance c, const fmi3ValueReference vr[], size_t n,
                                  const fmi3Float64 v[]) {
    return not_supported(c, "fmi3SetIntervalDecimal", NO_CLOCKS, vr, n, v);
}

fmi3Status fmi3SetIntervalFraction(fmi3Instance c, const fmi3ValueReference vr[], size_t n,
                                   const fmi3UInt64 v[], const fmi3UInt64 r[]) {
    return not_supported(c, "fmi3SetIntervalFraction", NO_CLOCKS, vr, n, v, r);
}

fmi3Status fmi3SetShiftDecimal(fmi3Instance c, const fmi3ValueReference vr[], size_t n,
                               const fmi3Float64 v[]) {
    return not_supported(c, "fmi3SetShiftDecimal", NO_CLOCKS, vr, n, v);
}

fmi3Status fmi3SetShiftFraction(fmi3Instance c, const fmi3ValueReference vr[], size_t n,
                                const fmi3UInt64 v[], const fmi3UInt64 r[]) {
    return not_supported(c, "fmi3SetShiftFraction", NO_CLOCKS, vr, n, v, r);
}

fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance c) {
    return not_supported(c, "fmi3EvaluateDiscreteStates", NO_CLOCKS);
}

fmi3Status fmi3ActivateModelPartition(fmi3Instance c, fmi3ValueReference clock, fmi3Float64 t) {
    return not_supported(c, "fmi3ActivateModelPartition",
                         "this FMU has no ScheduledExecution interface", clock, t);
}

static const char NO_STRUCTURAL_PARAMETERS[] =
    "this FMU has no structural parameters (Configuration Mode does not apply)";

fmi3Status fmi3EnterConfigurationMode(fmi3Instance c) {
    return not_supported(c, "fmi3EnterConfigurationMode", NO_STRUCTURAL_PARAMETERS);
}

fmi3Status fmi3ExitConfigurationMode(fmi3Instance c) {
    return not_supported(c, "fmi3ExitConfigurationMode", NO_STRUCTURAL_PARAMETERS);
}
