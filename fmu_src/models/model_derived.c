/* Derivatives of the outputs a model computes from its other outputs (ak_derived_outputs,
 * models/model.h): the model's own Jacobian and output derivatives give those of the arguments,
 * and the core tangent functions carry them through, one direction at a time (the chain rule in
 * forward mode). A call that asks for no derived output goes straight to the model. */
#include <string.h>

#include "model.h"

/* vr: a checked value reference of an output or a state derivative. */
static bool is_derived(unsigned int vr) {
    return AK_MODEL.variables[vr].group == AK_GROUP_DERIVED;
}

bool ak_model_any_derived(const unsigned int vr[], size_t n) {
    for (size_t i = 0; i < n; i++) {
        if (is_derived(vr[i])) {
            return true;
        }
    }
    return false;
}

/* The positions in vr[] of the outputs that are not derived, and how many: the model computes
 * theirs in one call. */
static size_t not_derived(const unsigned int vr[], size_t n, unsigned int own[], size_t at[]) {
    size_t m = 0;
    for (size_t i = 0; i < n; i++) {
        if (!is_derived(vr[i])) {
            own[m] = vr[i];
            at[m++] = i;
        }
    }
    return m;
}

void ak_model_jacobian(const ak_model_data *data, const unsigned int out[], size_t n_out,
                       double J[][AK_MAX_KNOWNS]) {
    if (!ak_model_any_derived(out, n_out)) {
        AK_MODEL.jacobian(data, out, n_out, J);
        return;
    }
    const ak_derived_outputs *derived = AK_MODEL.derived;
    const size_t n_knowns = (size_t)(AK_MODEL.n_inputs + AK_MODEL.n_states);
    double rows[AK_MAX_VARIABLES][AK_MAX_KNOWNS];
    /* The model's own rows first (n_out <= AK_MAX_VARIABLES, as for the model's jacobian). */
    unsigned int own[AK_MAX_VARIABLES];
    size_t at[AK_MAX_VARIABLES];
    const size_t n_own = not_derived(out, n_out, own, at);
    AK_MODEL.jacobian(data, own, n_own, rows);
    for (size_t m = 0; m < n_own; m++) {
        memcpy(J[at[m]], rows[m], n_knowns * sizeof rows[m][0]);
    }
    /* Then the arguments' rows, carried through the tangents known by known:
     * tangents[k][vr] is the change of value vr along known k. */
    AK_MODEL.jacobian(data, derived->arguments, derived->n_arguments, rows);
    double tangents[AK_MAX_KNOWNS][AK_MAX_VARIABLES];
    for (size_t k = 0; k < n_knowns; k++) {
        memset(tangents[k], 0, sizeof tangents[k]);
        for (size_t a = 0; a < derived->n_arguments; a++) {
            tangents[k][derived->arguments[a]] = rows[a][k];
        }
        derived->tangents(data->values, tangents[k]);
    }
    for (size_t i = 0; i < n_out; i++) {
        if (is_derived(out[i])) {
            for (size_t k = 0; k < n_knowns; k++) {
                J[i][k] = tangents[k][out[i]];
            }
        }
    }
}

/* At most AK_MAX_VARIABLES value references (ak_model_output_derivatives cuts longer calls). */
static void output_derivatives_of_some(ak_model_data *data, const unsigned int vr[], size_t nvr,
                                       double value[]) {
    const ak_derived_outputs *derived = AK_MODEL.derived;
    double of[AK_MAX_VARIABLES];
    unsigned int own[AK_MAX_VARIABLES];
    size_t at[AK_MAX_VARIABLES];
    const size_t n_own = not_derived(vr, nvr, own, at);
    AK_MODEL.output_derivatives(data, own, n_own, of);
    for (size_t m = 0; m < n_own; m++) {
        value[at[m]] = of[m];
    }
    AK_MODEL.output_derivatives(data, derived->arguments, derived->n_arguments, of);
    double tangents[AK_MAX_VARIABLES] = {0};
    for (size_t a = 0; a < derived->n_arguments; a++) {
        tangents[derived->arguments[a]] = of[a];
    }
    derived->tangents(data->values, tangents);
    for (size_t i = 0; i < nvr; i++) {
        if (is_derived(vr[i])) {
            value[i] = tangents[vr[i]];
        }
    }
}

void ak_model_output_derivatives(ak_model_data *data, const unsigned int vr[], size_t nvr,
                                 double value[]) {
    if (!ak_model_any_derived(vr, nvr)) {
        AK_MODEL.output_derivatives(data, vr, nvr, value);
        return;
    }
    for (size_t first = 0; first < nvr; first += AK_MAX_VARIABLES) {
        const size_t n = nvr - first < AK_MAX_VARIABLES ? nvr - first : AK_MAX_VARIABLES;
        output_derivatives_of_some(data, &vr[first], n, &value[first]);
    }
}
