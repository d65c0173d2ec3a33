/* Derivatives for both FMI versions from the model's Jacobian: a column per input, then state. */
#include "runtime.h"

ak_status ak_not_provided(const ak_instance *instance, const char *function, const char *flag) {
    ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
           "%s: not provided by %s (modelDescription.xml: %s)", function,
           AK_MODEL.model_identifier, flag);
    return AK_STATUS_ERROR;
}

bool ak_derivative_variable(const ak_instance *instance, const char *function,
                            const char *list_name, size_t index, unsigned int vr,
                            ak_causality causality, const unsigned int *also) {
    if (also != NULL && ak_state_index(also, vr) >= 0) {
        return true;
    }
    const ak_variable *variable = ak_variable_of(vr);
    if (variable == NULL) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: %s[%zu] = %u is not a value reference of this FMU (0 to %d)", function,
               list_name, index, vr, AK_MODEL.n_value_references - 1);
        return false;
    }
    if (variable->causality != causality) {
        ak_log(instance, AK_LOG_ERROR, AK_STATUS_ERROR,
               "%s: %s[%zu] = %u is %s, %s %s; expected an %s", function, list_name, index, vr,
               variable->name, variable->causality == AK_CAUSALITY_PARAMETER ? "a" : "an",
               ak_causality_name(variable->causality), ak_causality_name(causality));
        return false;
    }
    return true;
}

ak_status ak_output_derivatives(ak_instance *instance, const char *function,
                                const unsigned int vr[], size_t nvr, double value[]) {
    /* An output computed from others needs their values, lazy ones too. */
    const ak_status status = ak_instance_update(
        instance, ak_model_any_derived(vr, nvr) ? AK_GROUP_LAZY : AK_GROUP_MAIN);
    if (status == AK_STATUS_DISCARD) {
        return status;
    }
    instance->calling = function;
    ak_model_output_derivatives(&instance->data, vr, nvr, value);
    instance->calling = NULL;
    return status;
}

ak_status ak_derivative(ak_instance *instance, const unsigned int unknowns[], size_t n_unknowns,
                        const unsigned int knowns[], size_t n_knowns, const double seed[],
                        double sensitivity[], bool adjoint) {
    if (ak_model_any_derived(unknowns, n_unknowns) &&
        ak_instance_update(instance, AK_GROUP_LAZY) == AK_STATUS_DISCARD) {
        return AK_STATUS_DISCARD;
    }
    double J[AK_MAX_VARIABLES][AK_MAX_KNOWNS];
    for (size_t first = 0; first < n_unknowns; first += AK_MAX_VARIABLES) {
        const size_t n =
            n_unknowns - first < AK_MAX_VARIABLES ? n_unknowns - first : AK_MAX_VARIABLES;
        ak_model_jacobian(&instance->data, &unknowns[first], n, J);
        // cppcheck-suppress knownConditionTrueFalse
        for (size_t i = 0; i < n; i++) {
            double sum = 0.0;
            for (size_t j = 0; j < n_knowns; j++) {
                const int state = ak_state_index(AK_MODEL.state_vrs, knowns[j]);
                const double d =
                    J[i][state >= 0 ? (size_t)(AK_MODEL.n_inputs + state) : (size_t)knowns[j]];
                if (adjoint) {
                    sensitivity[j] += d * seed[first + i];
                } else {
                    sum += d * seed[j];
                }
            }
            if (!adjoint) {
                sensitivity[first + i] = sum;
            }
        }
    }
    return AK_STATUS_OK;
}
