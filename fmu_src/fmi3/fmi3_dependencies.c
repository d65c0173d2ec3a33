/* FMI 3.0 per-element dependencies (providesPerElementDependencies): which elements of which
 * input arrays each element of an output array depends on, from the model's variable table (the
 * same dependencies that modelDescription.xml states per array). Element indices are 1-based in
 * the row-major order of the array, 0 for a scalar (FMI 3, section 2.2.10). The table lists the
 * inputs only: a model with continuous states, on which its outputs depend as well, does not
 * declare providesPerElementDependencies, and both functions refuse. */
#include "fmi3_layer.h"

static bool provided(const ak_instance *instance, ak3_function function) {
    if (AK_MODEL.n_states == 0) {
        return true;
    }
    ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
            "%s: not provided by %s (modelDescription.xml: providesPerElementDependencies="
            "\"false\"; <ModelStructure> gives the dependencies per array)",
            fmi3_name(function), AK_MODEL.model_identifier);
    return false;
}

static size_t dependency_count(const ak3_array *array) {
    size_t n = 0;
    for (unsigned int e = 0; e < array->n_elements; e++) {
        n += AK_MODEL.variables[array->first_vr + e].n_dependencies;
    }
    return n;
}

static size_t element_index(const ak3_array *array, unsigned int scalar_vr) {
    return array->n_dimensions == 0 ? 0 : (size_t)(scalar_vr - array->first_vr) + 1;
}

fmi3Status fmi3GetNumberOfVariableDependencies(fmi3Instance c, fmi3ValueReference valueReference,
                                               size_t *nDependencies) {
    ak_instance *instance = c;
    const ak3_function self = AK3_GET_NUMBER_OF_VARIABLE_DEPENDENCIES;
    const char *name = fmi3_name(self);
    if (!fmi3_allowed(instance, self) || !provided(instance, self)) {
        return fmi3Error;
    }
    const ak3_array *array = ak3_array_of_causality(instance, name, "valueReference", 0,
                                                    valueReference, AK_CAUSALITY_OUTPUT);
    if (array == NULL || !ak_not_null(instance, name, nDependencies, "nDependencies")) {
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
                                       size_t nDependencies) {
    ak_instance *instance = c;
    const ak3_function self = AK3_GET_VARIABLE_DEPENDENCIES;
    const char *name = fmi3_name(self);
    if (!fmi3_allowed(instance, self) || !provided(instance, self)) {
        return fmi3Error;
    }
    const ak3_array *array =
        ak3_array_of_causality(instance, name, "dependent", 0, dependent, AK_CAUSALITY_OUTPUT);
    if (array == NULL ||
        !ak_given(instance, name, nDependencies, "nDependencies", elementIndicesOfDependent,
                   "elementIndicesOfDependent") ||
        !ak_given(instance, name, nDependencies, "nDependencies", independents, "independents") ||
        !ak_given(instance, name, nDependencies, "nDependencies", elementIndicesOfIndependents,
                   "elementIndicesOfIndependents") ||
        !ak_given(instance, name, nDependencies, "nDependencies", dependencyKinds,
                   "dependencyKinds")) {
        return fmi3Error;
    }
    if (nDependencies != dependency_count(array)) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
                "fmi3GetVariableDependencies: nDependencies = %zu, but %s has %zu "
                "(fmi3GetNumberOfVariableDependencies)",
                nDependencies, array->name, dependency_count(array));
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
