/* FMI 3.0 derivatives: output derivatives (maxOutputDerivativeOrder = 1) and directional and
 * adjoint derivatives (providesDirectionalDerivatives, providesAdjointDerivatives), over
 * runtime/derivatives.c: this file checks the arguments and expands arrays into their elements.
 * A model without one of them gets the function refused with a message naming the flag its
 * modelDescription.xml leaves false. */
#include <math.h>

#include "fmi3_layer.h"

/* The highest order fmi3GetOutputDerivatives gives: maxOutputDerivativeOrder. */
enum { MAX_OUTPUT_DERIVATIVE_ORDER = 1 };

/* Checks a list of value references of one causality and expands it into its elements (at most
 * AK_MAX_VARIABLES), *n_elements of them. also: the first elements of arrays accepted besides
 * (the states or their derivatives), or NULL. */
static bool arrays_valid(const ak_instance *instance, const char *function, const char *list_name,
                         const unsigned int vr[], size_t n, ak_causality causality,
                         const unsigned int *also, unsigned int elements[], size_t *n_elements) {
    size_t total = 0;
    for (size_t i = 0; i < n; i++) {
        const ak3_array *array = ak3_array_of(vr[i]);
        if (array == NULL || also == NULL || ak_state_index(also, vr[i]) < 0) {
            array = ak3_array_of_causality(instance, function, list_name, i, vr[i], causality);
        }
        if (array == NULL) {
            return false;
        }
        total += array->n_elements;
    }
    *n_elements = ak3_expand(vr, n, elements, AK_MAX_VARIABLES);
    if (total > AK_MAX_VARIABLES) { /* the same variable many times: more than the model has */
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: the %zu %s have %zu elements; at most %d in one call", function, n, list_name,
               total, AK_MAX_VARIABLES);
        return false;
    }
    return true;
}

fmi3Status fmi3GetOutputDerivatives(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                                    const fmi3Int32 orders[], fmi3Float64 values[],
                                    size_t nValues) {
    ak_instance *instance = c;
    const char *self = fmi3_name(AK3_GET_OUTPUT_DERIVATIVES);
    if (!fmi3_allowed(instance, AK3_GET_OUTPUT_DERIVATIVES)) {
        return fmi3Error;
    }
    if (AK_MODEL.output_derivatives == NULL) {
        return fmi3_status(ak_not_provided(instance, self, "maxOutputDerivativeOrder=\"0\""));
    }
    unsigned int elements[AK_MAX_VARIABLES];
    size_t n = 0;
    if (!ak_given(instance, self, nvr, "nValueReferences", vr, "valueReferences") ||
        !ak_given(instance, self, nvr, "nValueReferences", orders, "orders") ||
        !ak_given(instance, self, nValues, "nValues", values, "values") ||
        !arrays_valid(instance, self, "valueReferences", vr, nvr, AK_CAUSALITY_OUTPUT, NULL,
                      elements, &n)) {
        return fmi3Error;
    }
    for (size_t i = 0; i < nvr; i++) {
        if (orders[i] < 1 || orders[i] > MAX_OUTPUT_DERIVATIVE_ORDER) {
            ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
                   "%s: orders[%zu] = %d for %s: this FMU gives order %d only "
                   "(maxOutputDerivativeOrder)",
                   self, i, (int)orders[i], AK3_ARRAYS[vr[i]].name, MAX_OUTPUT_DERIVATIVE_ORDER);
            return fmi3Error;
        }
    }
    if (!ak3_count_matches(instance, self, "nValues", nValues, n, vr, nvr)) {
        return fmi3Error;
    }
    return fmi3_status(ak_output_derivatives(instance, self, elements, n, values));
}

/* sensitivity = J seed (directional) or J^T seed (adjoint), J the rows of the unknowns'
 * elements and the columns of the knowns' elements. */
static fmi3Status derivative(fmi3Instance c, ak3_function function, const char *flag, bool adjoint,
                             const fmi3ValueReference unknowns[], size_t nUnknowns,
                             const fmi3ValueReference knowns[], size_t nKnowns,
                             const fmi3Float64 seed[], size_t nSeed, fmi3Float64 sensitivity[],
                             size_t nSensitivity) {
    ak_instance *instance = c;
    const char *self = fmi3_name(function);
    if (!fmi3_allowed(instance, function)) {
        return fmi3Error;
    }
    if (AK_MODEL.jacobian == NULL) {
        return fmi3_status(ak_not_provided(instance, self, flag));
    }
    unsigned int rows[AK_MAX_VARIABLES], columns[AK_MAX_VARIABLES];
    size_t n_rows = 0, n_columns = 0;
    if (!ak_given(instance, self, nUnknowns, "nUnknowns", unknowns, "unknowns") ||
        !ak_given(instance, self, nKnowns, "nKnowns", knowns, "knowns") ||
        !ak_given(instance, self, nSeed, "nSeed", seed, "seed") ||
        !ak_given(instance, self, nSensitivity, "nSensitivity", sensitivity, "sensitivity") ||
        !arrays_valid(instance, self, "unknowns", unknowns, nUnknowns, AK_CAUSALITY_OUTPUT,
                      AK_MODEL.derivative_vrs, rows, &n_rows) ||
        !arrays_valid(instance, self, "knowns", knowns, nKnowns, AK_CAUSALITY_INPUT,
                      AK_MODEL.state_vrs, columns, &n_columns)) {
        return fmi3Error;
    }
    /* Directional: seed per known element, sensitivity per unknown element; adjoint: reversed. */
    if (!ak3_count_matches(instance, self, "nSeed", nSeed, adjoint ? n_rows : n_columns,
                           adjoint ? unknowns : knowns, adjoint ? nUnknowns : nKnowns) ||
        !ak3_count_matches(instance, self, "nSensitivity", nSensitivity,
                           adjoint ? n_columns : n_rows, adjoint ? knowns : unknowns,
                           adjoint ? nKnowns : nUnknowns)) {
        return fmi3Error;
    }
    for (size_t j = 0; j < nSeed; j++) {
        if (!isfinite(seed[j])) {
            ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR, "%s: seed[%zu] = %g is not finite",
                   self, j, seed[j]);
            return fmi3Error;
        }
    }
    for (size_t j = 0; adjoint && j < n_columns; j++) {
        sensitivity[j] = 0.0;
    }
    const ak_status status =
        ak_derivative(instance, rows, n_rows, columns, n_columns, seed, sensitivity, adjoint);
    return status == AK_STATUS_DISCARD ? fmi3Discard : fmi3OK;
}

fmi3Status fmi3GetDirectionalDerivative(fmi3Instance c, const fmi3ValueReference unknowns[],
                                        size_t nUnknowns, const fmi3ValueReference knowns[],
                                        size_t nKnowns, const fmi3Float64 seed[], size_t nSeed,
                                        fmi3Float64 sensitivity[], size_t nSensitivity) {
    return derivative(c, AK3_GET_DIRECTIONAL_DERIVATIVE,
                      "providesDirectionalDerivatives=\"false\"", false, unknowns, nUnknowns,
                      knowns, nKnowns, seed, nSeed, sensitivity, nSensitivity);
}

fmi3Status fmi3GetAdjointDerivative(fmi3Instance c, const fmi3ValueReference unknowns[],
                                    size_t nUnknowns, const fmi3ValueReference knowns[],
                                    size_t nKnowns, const fmi3Float64 seed[], size_t nSeed,
                                    fmi3Float64 sensitivity[], size_t nSensitivity) {
    return derivative(c, AK3_GET_ADJOINT_DERIVATIVE, "providesAdjointDerivatives=\"false\"", true,
                      unknowns, nUnknowns, knowns, nKnowns, seed, nSeed, sensitivity,
                      nSensitivity);
}
