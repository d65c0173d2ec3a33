/* FMI 3.0 derivatives and dependencies: the arguments checked, arrays expanded into elements. */
#include <math.h>

#include "fmi3_layer.h"

static const ak3_array *array_of_causality(const ak_instance *instance, const char *function,
                                           const char *list_name, size_t index, unsigned int vr,
                                           ak_causality causality) {
    const ak3_array *array = ak3_array_of(vr);
    if (array == NULL) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: %s[%zu] = %u is not a value reference of this FMU's FMI 3 variables",
               function, list_name, index, vr);
        return NULL;
    }
    const ak_causality found = AK_MODEL.variables[vr].causality;
    if (found != causality) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: %s[%zu] = %u is %s, %s %s; expected an %s", function, list_name, index, vr,
               array->name, found == AK_CAUSALITY_PARAMETER ? "a" : "an",
               ak_causality_name(found), ak_causality_name(causality));
        return NULL;
    }
    return array;
}

enum { MAX_OUTPUT_DERIVATIVE_ORDER = 1 };

/* Expands checked value references into elements; also: other arrays accepted, or NULL. */
static bool arrays_valid(const ak_instance *instance, const char *function, const char *list_name,
                         const unsigned int vr[], size_t n, ak_causality causality,
                         const unsigned int *also, unsigned int elements[], size_t *n_elements) {
    size_t total = 0;
    for (size_t i = 0; i < n; i++) {
        const ak3_array *array = ak3_array_of(vr[i]);
        if (array == NULL || also == NULL || ak_state_index(also, vr[i]) < 0) {
            array = array_of_causality(instance, function, list_name, i, vr[i], causality);
        }
        if (array == NULL) {
            return false;
        }
        total += array->n_elements;
    }
    if (total > AK_MAX_VARIABLES) { /* the same variable many times: more than the model has */
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: the %zu %s have %zu elements; at most %d in one call", function, n, list_name,
               total, AK_MAX_VARIABLES);
        return false;
    }
    *n_elements = 0;
    for (size_t i = 0; i < n; i++) {
        for (unsigned int e = 0; e < AK3_ARRAYS[vr[i]].n_elements; e++) {
            elements[(*n_elements)++] = vr[i] + e;
        }
    }
    return true;
}

fmi3Status fmi3GetOutputDerivatives(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                                    const fmi3Int32 orders[], fmi3Float64 values[],
                                    size_t nValues) {
    const char *self = fmi3_name(AK3_GET_OUTPUT_DERIVATIVES);
    if (!fmi3_allowed(c, AK3_GET_OUTPUT_DERIVATIVES)) {
        return fmi3Error;
    }
    if (AK_MODEL.output_derivatives == NULL) {
        return fmi3_status(ak_not_provided(c, self, "maxOutputDerivativeOrder=\"0\""));
    }
    unsigned int elements[AK_MAX_VARIABLES];
    size_t n = 0;
    if (!ak_given(c, self, nvr, "nValueReferences", vr, "valueReferences") ||
        !ak_given(c, self, nvr, "nValueReferences", orders, "orders") ||
        !ak_given(c, self, nValues, "nValues", values, "values") ||
        !arrays_valid(c, self, "valueReferences", vr, nvr, AK_CAUSALITY_OUTPUT, NULL,
                      elements, &n)) {
        return fmi3Error;
    }
    for (size_t i = 0; i < nvr; i++) {
        if (orders[i] < 1 || orders[i] > MAX_OUTPUT_DERIVATIVE_ORDER) {
            ak_log(c, AK_LOG_ERROR, AK_STATUS_ERROR,
                   "%s: orders[%zu] = %d for %s: this FMU gives order %d only "
                   "(maxOutputDerivativeOrder)",
                   self, i, (int)orders[i], AK3_ARRAYS[vr[i]].name, MAX_OUTPUT_DERIVATIVE_ORDER);
            return fmi3Error;
        }
    }
    if (!ak3_count_matches(c, self, "nValues", nValues, n, vr, nvr)) {
        return fmi3Error;
    }
    return fmi3_status(ak_output_derivatives(c, self, elements, n, values));
}

static fmi3Status derivative(fmi3Instance c, ak3_function function,
                             const fmi3ValueReference unknowns[], size_t nUnknowns,
                             const fmi3ValueReference knowns[], size_t nKnowns,
                             const fmi3Float64 seed[], size_t nSeed, fmi3Float64 sensitivity[],
                             size_t nSensitivity) {
    const bool adjoint = function == AK3_GET_ADJOINT_DERIVATIVE;
    const char *self = fmi3_name(function);
    if (!fmi3_allowed(c, function)) {
        return fmi3Error;
    }
    if (AK_MODEL.jacobian == NULL) {
        return fmi3_status(ak_not_provided(c, self,
                                           adjoint ? "providesAdjointDerivatives=\"false\""
                                                   : "providesDirectionalDerivatives=\"false\""));
    }
    unsigned int rows[AK_MAX_VARIABLES], columns[AK_MAX_VARIABLES];
    size_t n_rows = 0, n_columns = 0;
    if (!ak_given(c, self, nUnknowns, "nUnknowns", unknowns, "unknowns") ||
        !ak_given(c, self, nKnowns, "nKnowns", knowns, "knowns") ||
        !ak_given(c, self, nSeed, "nSeed", seed, "seed") ||
        !ak_given(c, self, nSensitivity, "nSensitivity", sensitivity, "sensitivity") ||
        !arrays_valid(c, self, "unknowns", unknowns, nUnknowns, AK_CAUSALITY_OUTPUT,
                      AK_MODEL.derivative_vrs, rows, &n_rows) ||
        !arrays_valid(c, self, "knowns", knowns, nKnowns, AK_CAUSALITY_INPUT,
                      AK_MODEL.state_vrs, columns, &n_columns)) {
        return fmi3Error;
    }
    /* Directional: seed per known element, sensitivity per unknown element; adjoint: reversed. */
    if (!ak3_count_matches(c, self, "nSeed", nSeed, adjoint ? n_rows : n_columns,
                           adjoint ? unknowns : knowns, adjoint ? nUnknowns : nKnowns) ||
        !ak3_count_matches(c, self, "nSensitivity", nSensitivity,
                           adjoint ? n_columns : n_rows, adjoint ? knowns : unknowns,
                           adjoint ? nKnowns : nUnknowns)) {
        return fmi3Error;
    }
    for (size_t j = 0; j < nSeed; j++) {
        if (!isfinite(seed[j])) {
            ak_log(c, AK_LOG_ERROR, AK_STATUS_ERROR, "%s: seed[%zu] = %g is not finite",
                   self, j, seed[j]);
            return fmi3Error;
        }
    }
    for (size_t j = 0; adjoint && j < n_columns; j++) {
        sensitivity[j] = 0.0;
    }
    const ak_status status =
        ak_derivative(c, rows, n_rows, columns, n_columns, seed, sensitivity, adjoint);
    return status == AK_STATUS_DISCARD ? fmi3Discard : fmi3OK;
}

fmi3Status fmi3GetDirectionalDerivative(fmi3Instance c, const fmi3ValueReference unknowns[],
                                        size_t nUnknowns, const fmi3ValueReference knowns[],
                                        size_t nKnowns, const fmi3Float64 seed[], size_t nSeed,
                                        fmi3Float64 sensitivity[], size_t nSensitivity) {
    return derivative(c, AK3_GET_DIRECTIONAL_DERIVATIVE, unknowns, nUnknowns, knowns, nKnowns,
                      seed, nSeed, sensitivity, nSensitivity);
}

fmi3Status fmi3GetAdjointDerivative(fmi3Instance c, const fmi3ValueReference unknowns[],
                                    size_t nUnknowns, const fmi3ValueReference knowns[],
                                    size_t nKnowns, const fmi3Float64 seed[], size_t nSeed,
                                    fmi3Float64 sensitivity[], size_t nSensitivity) {
    return derivative(c, AK3_GET_ADJOINT_DERIVATIVE, unknowns, nUnknowns, knowns, nKnowns, seed,
                      nSeed, sensitivity, nSensitivity);
}

/* The variable table lists the inputs only, so a model with states does not provide them. */
static const ak3_array *dependent_array(const ak_instance *instance, ak3_function function,
                                        const char *list_name, unsigned int vr) {
    if (!fmi3_allowed(instance, function)) {
        return NULL;
    }
    if (AK_MODEL.n_states != 0) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: not provided by %s (modelDescription.xml: providesPerElementDependencies="
               "\"false\"; <ModelStructure> gives the dependencies per array)",
               fmi3_name(function), AK_MODEL.model_identifier);
        return NULL;
    }
    return array_of_causality(instance, fmi3_name(function), list_name, 0, vr,
                              AK_CAUSALITY_OUTPUT);
}

static size_t dependency_count(const ak3_array *array) {
    size_t n = 0;
    for (unsigned int e = 0; e < array->n_elements; e++) {
        n += AK_MODEL.variables[array->first_vr + e].n_dependencies;
    }
    return n;
}

/* 1-based in the array's row-major order, 0 for a scalar. */
static size_t element_index(const ak3_array *array, unsigned int scalar_vr) {
    return array->n_dimensions == 0 ? 0 : (size_t)(scalar_vr - array->first_vr) + 1;
}

fmi3Status fmi3GetNumberOfVariableDependencies(fmi3Instance c, fmi3ValueReference valueReference,
                                               size_t *nDependencies) {
    const ak3_function self = AK3_GET_NUMBER_OF_VARIABLE_DEPENDENCIES;
    const ak3_array *array = dependent_array(c, self, "valueReference", valueReference);
    if (array == NULL || !ak_not_null(c, fmi3_name(self), nDependencies, "nDependencies")) {
        return fmi3Error;
    }
    *nDependencies = dependency_count(array);
    return fmi3OK;
}

fmi3Status fmi3GetVariableDependencies(fmi3Instance c, fmi3ValueReference dependent,
                                       size_t elementIndicesOfDependent[],
                                       fmi3ValueReference independents[],
                                       size_t elementIndicesOfIndependents[],
                                       fmi3DependencyKind dependencyKinds[],
                                       size_t nd) {
    const ak3_function self = AK3_GET_VARIABLE_DEPENDENCIES;
    const char *name = fmi3_name(self), *n = "nDependencies";
    const ak3_array *array = dependent_array(c, self, "dependent", dependent);
    if (array == NULL ||
        !ak_given(c, name, nd, n, elementIndicesOfDependent, "elementIndicesOfDependent") ||
        !ak_given(c, name, nd, n, independents, "independents") ||
        !ak_given(c, name, nd, n, elementIndicesOfIndependents, "elementIndicesOfIndependents") ||
        !ak_given(c, name, nd, n, dependencyKinds, "dependencyKinds")) {
        return fmi3Error;
    }
    if (nd != dependency_count(array)) {
        ak_log(c, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: nDependencies = %zu, but %s has %zu (fmi3GetNumberOfVariableDependencies)",
               name, nd, array->name, dependency_count(array));
        return fmi3Error;
    }
    size_t k = 0;
    for (unsigned int e = 0; e < array->n_elements; e++) {
        const ak_variable *element = &AK_MODEL.variables[array->first_vr + e];
        for (size_t d = 0; d < element->n_dependencies; d++, k++) {
            const ak3_array *input = &AK3_ARRAYS[element->dependencies[d]];
            elementIndicesOfDependent[k] = element_index(array, array->first_vr + e);
            independents[k] = input->first_vr;
            elementIndicesOfIndependents[k] = element_index(input, element->dependencies[d]);
            dependencyKinds[k] = fmi3Dependent;
        }
    }
    return fmi3OK;
}
