/* FMI 3.0 derivatives: output derivatives (maxOutputDerivativeOrder = 1) and directional and
 * adjoint derivatives (providesDirectionalDerivatives, providesAdjointDerivatives). The
 * mathematics is the model's (ak_model.jacobian, ak_model.output_derivatives); this file checks
 * arguments, expands arrays into their elements and applies seeds. As in FMI 2, the unknowns of
 * a directional or adjoint derivative are outputs or continuous-state derivatives, the knowns
 * inputs or continuous states (the model's Jacobian has a column per input, then per state). A model without one of them
 * gets the function refused with a message naming the flag its modelDescription.xml leaves
 * false. */
#include <math.h>

#include "fmi3Functions.h"
#include "fmi3_values.h"

/* The highest order fmi3GetOutputDerivatives gives: maxOutputDerivativeOrder. */
enum { MAX_OUTPUT_DERIVATIVE_ORDER = 1 };

static fmi3Status not_provided(const ak3_instance *instance, ak3_function function,
                               const char *flag) {
    ak3_log(instance, AK_LOG_ERROR, fmi3Error, "%s: not provided by %s (modelDescription.xml: %s)",
            ak3_function_name(function), AK_MODEL.model_identifier, flag);
    return fmi3Error;
}

/* The index of vr in a model's list of states (or of state derivatives), or -1. */
static int state_index(const unsigned int *vrs, unsigned int vr) {
    for (int k = 0; k < AK_MODEL.n_states; k++) {
        if (vrs[k] == vr) {
            return k;
        }
    }
    return -1;
}

/* The column of a known element (checked: of an input or a state) in the model's Jacobian. */
static size_t known_column(unsigned int vr) {
    const int state = state_index(AK_MODEL.state_vrs, vr);
    return state >= 0 ? (size_t)(AK_MODEL.n_inputs + state) : (size_t)vr;
}

/* Checks a list of value references of one causality; *total gets their number of elements.
 * also: the first elements of arrays accepted besides (the states or their derivatives), or
 * NULL. */
static bool arrays_valid(const ak3_instance *instance, ak3_function function,
                         const char *list_name, const unsigned int vr[], size_t n,
                         ak_causality causality, const unsigned int *also, size_t *total) {
    *total = 0;
    for (size_t i = 0; i < n; i++) {
        const ak3_array *array = ak3_array_of(vr[i]);
        if (array == NULL || also == NULL || state_index(also, vr[i]) < 0) {
            array = ak3_array_of_causality(instance, function, list_name, i, vr[i], causality);
        }
        if (array == NULL) {
            return false;
        }
        *total += array->n_elements;
    }
    return true;
}

static bool all_finite(const ak3_instance *instance, ak3_function function, const double seed[],
                       size_t n) {
    for (size_t j = 0; j < n; j++) {
        if (!isfinite(seed[j])) {
            ak3_log(instance, AK_LOG_ERROR, fmi3Error, "%s: seed[%zu] = %g is not finite",
                    ak3_function_name(function), j, seed[j]);
            return false;
        }
    }
    return true;
}

/* The elements (scalar value references) of the arrays vr[0 .. n - 1], in order. */
static size_t expand(const unsigned int vr[], size_t n, unsigned int elements[], size_t capacity) {
    size_t k = 0;
    for (size_t i = 0; i < n; i++) {
        for (unsigned int e = 0; e < AK3_ARRAYS[vr[i]].n_elements && k < capacity; e++) {
            elements[k++] = vr[i] + e;
        }
    }
    return k;
}

fmi3Status fmi3GetOutputDerivatives(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                                    const fmi3Int32 orders[], fmi3Float64 values[],
                                    size_t nValues) {
    ak3_instance *instance = c;
    const ak3_function self = AK3_GET_OUTPUT_DERIVATIVES;
    if (!ak3_call_allowed(instance, self)) {
        return fmi3Error;
    }
    if (AK_MODEL.output_derivatives == NULL) {
        return not_provided(instance, self, "maxOutputDerivativeOrder=\"0\"");
    }
    size_t total = 0;
    if (!ak3_given(instance, self, nvr, "nValueReferences", vr, "valueReferences") ||
        !ak3_given(instance, self, nvr, "nValueReferences", orders, "orders") ||
        !ak3_given(instance, self, nValues, "nValues", values, "values") ||
        !arrays_valid(instance, self, "valueReferences", vr, nvr, AK_CAUSALITY_OUTPUT, NULL,
                      &total)) {
        return fmi3Error;
    }
    for (size_t i = 0; i < nvr; i++) {
        if (orders[i] < 1 || orders[i] > MAX_OUTPUT_DERIVATIVE_ORDER) {
            ak3_log(instance, AK_LOG_ERROR, fmi3Error,
                    "fmi3GetOutputDerivatives: orders[%zu] = %d for %s: this FMU gives order %d "
                    "only (maxOutputDerivativeOrder)",
                    i, (int)orders[i], AK3_ARRAYS[vr[i]].name, MAX_OUTPUT_DERIVATIVE_ORDER);
            return fmi3Error;
        }
    }
    if (!ak3_count_matches(instance, self, "nValues", nValues, total, vr, nvr)) {
        return fmi3Error;
    }
    /* An output computed from others (models/model_derived.c) needs their values, lazy ones too. */
    bool derived = false;
    for (size_t i = 0; i < nvr; i++) {
        derived = derived || AK_MODEL.variables[vr[i]].group == AK_GROUP_DERIVED;
    }
    const fmi3Status status = ak3_read_status(derived ? ak3_instance_update_all_outputs(instance)
                                                      : ak3_instance_update_outputs(instance));
    if (status == fmi3Discard) {
        return status;
    }
    /* Array by array: at most 9 elements each. */
    size_t k = 0;
    for (size_t i = 0; i < nvr; i++) {
        unsigned int elements[AK_MAX_VARIABLES];
        const size_t n = expand(&vr[i], 1, elements, AK_MAX_VARIABLES);
        ak_model_output_derivatives(&instance->data, elements, n, &values[k]);
        k += n;
    }
    return status;
}

/* Checks the arguments common to both derivative functions; the element counts of unknowns
 * and knowns are then *n_rows and *n_columns. */
static bool derivative_arguments_valid(const ak3_instance *instance, ak3_function function,
                                       const unsigned int unknowns[], size_t nUnknowns,
                                       const unsigned int knowns[], size_t nKnowns,
                                       const double seed[], size_t nSeed, const double sensitivity[],
                                       size_t nSensitivity, bool adjoint, size_t *n_rows,
                                       size_t *n_columns) {
    if (!ak3_given(instance, function, nUnknowns, "nUnknowns", unknowns, "unknowns") ||
        !ak3_given(instance, function, nKnowns, "nKnowns", knowns, "knowns") ||
        !ak3_given(instance, function, nSeed, "nSeed", seed, "seed") ||
        !ak3_given(instance, function, nSensitivity, "nSensitivity", sensitivity, "sensitivity") ||
        !arrays_valid(instance, function, "unknowns", unknowns, nUnknowns, AK_CAUSALITY_OUTPUT,
                      AK_MODEL.derivative_vrs, n_rows) ||
        !arrays_valid(instance, function, "knowns", knowns, nKnowns, AK_CAUSALITY_INPUT,
                      AK_MODEL.state_vrs, n_columns)) {
        return false;
    }
    /* Directional: seed per known element, sensitivity per unknown element; adjoint: reversed. */
    const size_t seeds = adjoint ? *n_rows : *n_columns;
    const size_t sensitivities = adjoint ? *n_columns : *n_rows;
    return ak3_count_matches(instance, function, "nSeed", nSeed, seeds, adjoint ? unknowns : knowns,
                             adjoint ? nUnknowns : nKnowns) &&
           ak3_count_matches(instance, function, "nSensitivity", nSensitivity, sensitivities,
                             adjoint ? knowns : unknowns, adjoint ? nKnowns : nUnknowns) &&
           all_finite(instance, function, seed, nSeed);
}

/* sensitivity = J seed (directional) or J^T seed (adjoint), J the rows of the unknowns'
 * elements and the columns of the knowns' elements, computed one unknown array at a time. */
static fmi3Status derivative(fmi3Instance c, ak3_function self, const char *flag, bool adjoint,
                             const fmi3ValueReference unknowns[], size_t nUnknowns,
                             const fmi3ValueReference knowns[], size_t nKnowns,
                             const fmi3Float64 seed[], size_t nSeed, fmi3Float64 sensitivity[],
                             size_t nSensitivity) {
    ak3_instance *instance = c;
    if (!ak3_call_allowed(instance, self)) {
        return fmi3Error;
    }
    if (AK_MODEL.jacobian == NULL) {
        return not_provided(instance, self, flag);
    }
    size_t n_rows = 0, n_columns = 0;
    if (!derivative_arguments_valid(instance, self, unknowns, nUnknowns, knowns, nKnowns, seed,
                                    nSeed, sensitivity, nSensitivity, adjoint, &n_rows,
                                    &n_columns)) {
        return fmi3Error;
    }
    if (adjoint) {
        for (size_t j = 0; j < n_columns; j++) {
            sensitivity[j] = 0.0;
        }
    }
    size_t row = 0;
    for (size_t i = 0; i < nUnknowns; i++) {
        unsigned int rows[AK_MAX_VARIABLES];
        const size_t n = expand(&unknowns[i], 1, rows, AK_MAX_VARIABLES);
        double J[AK_MAX_VARIABLES][AK_MAX_KNOWNS]; /* columns: the inputs, then the states */
        /* An output computed from others (models/model_derived.c) needs their values, lazy ones
         * too; the others come from the inputs alone. */
        if (ak_model_any_derived(rows, n) &&
            ak3_read_status(ak3_instance_update_all_outputs(instance)) == fmi3Discard) {
            return fmi3Discard;
        }
        ak_model_jacobian(&instance->data, rows, n, J);
        for (size_t r = 0; r < n; r++, row++) {
            size_t column = 0;
            double sum = 0.0;
            for (size_t j = 0; j < nKnowns; j++) {
                for (unsigned int e = 0; e < AK3_ARRAYS[knowns[j]].n_elements; e++, column++) {
                    const double d = J[r][known_column(knowns[j] + e)];
                    if (adjoint) {
                        sensitivity[column] += d * seed[row];
                    } else {
                        sum += d * seed[column];
                    }
                }
            }
            if (!adjoint) {
                sensitivity[row] = sum;
            }
        }
    }
    return fmi3OK;
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
