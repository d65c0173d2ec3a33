/* Derivatives of the outputs a model computes from its other outputs (ak_derived_outputs,
 * models/model.h): the model's own Jacobian and output derivatives give those of the arguments,
 * and the core tangent functions carry them through, one direction at a time (the chain rule in
 * forward mode). A call that asks for no derived output goes straight to the model. */
#include <string.h>

#include "model.h"

static bool is_derived(unsigned int vr) {
    const ak_derived_outputs *derived = AK_MODEL.derived;
    for (size_t i = 0; i < derived->n_outputs; i++) {
        if (derived->outputs[i] == vr) {
            return true;
        }
    }
    return false;
}

bool ak_model_any_derived(const unsigned int vr[], size_t n) {
    if (AK_MODEL.derived == NULL || AK_MODEL.derived->n_outputs == 0) {
        return false;
    }
    for (size_t i = 0; i < n; i++) {
        if (is_derived(vr[i])) {
            return true;
        }
    }
    return false;
}

void ak_model_jacobian(const ak_model_data *data, const unsigned int out[], size_t n_out,
                       double J[][AK_MAX_KNOWNS]) {
    if (!ak_model_any_derived(out, n_out)) {
        AK_MODEL.jacobian(data, out, n_out, J);
        return;
    }
    const ak_derived_outputs *derived = AK_MODEL.derived;
    double rows[AK_MAX_VARIABLES][AK_MAX_KNOWNS];
    AK_MODEL.jacobian(data, derived->arguments, derived->n_arguments, rows);
    /* tangents[k][vr]: the change of value vr along known k. */
    const size_t n_knowns = (size_t)(AK_MODEL.n_inputs + AK_MODEL.n_states);
    double tangents[AK_MAX_KNOWNS][AK_MAX_VARIABLES];
    for (size_t k = 0; k < n_knowns; k++) {
        memset(tangents[k], 0, sizeof tangents[k]);
        for (size_t a = 0; a < derived->n_arguments; a++) {
            tangents[k][derived->arguments[a]] = rows[a][k];
        }
        derived->tangents(data->values, tangents[k]);
    }
    for (size_t i = 0; i < n_out; i++) {
        if (!is_derived(out[i])) {
            AK_MODEL.jacobian(data, &out[i], 1, &J[i]);
            continue;
        }
        for (size_t k = 0; k < n_knowns; k++) {
            J[i][k] = tangents[k][out[i]];
        }
    }
}

void ak_model_output_derivatives(ak_model_data *data, const unsigned int vr[], size_t nvr,
                                 double value[]) {
    if (!ak_model_any_derived(vr, nvr)) {
        AK_MODEL.output_derivatives(data, vr, nvr, value);
        return;
    }
    const ak_derived_outputs *derived = AK_MODEL.derived;
    double of_arguments[AK_MAX_VARIABLES];
    AK_MODEL.output_derivatives(data, derived->arguments, derived->n_arguments, of_arguments);
    double tangents[AK_MAX_VARIABLES] = {0};
    for (size_t a = 0; a < derived->n_arguments; a++) {
        tangents[derived->arguments[a]] = of_arguments[a];
    }
    derived->tangents(data->values, tangents);
    for (size_t i = 0; i < nvr; i++) {
        if (is_derived(vr[i])) {
            value[i] = tangents[vr[i]];
        } else {
            AK_MODEL.output_derivatives(data, &vr[i], 1, &value[i]);
        }
    }
}
