/* What both FMI layers do to a model's data at instantiation and reset (models/model.h). */
#include "model.h"

static void clear_input_derivatives(ak_model_data *data) {
    for (int k = 0; k < AK_MAX_INPUTS; k++) {
        for (int n = 0; n < AK_MAX_INPUT_DERIVATIVE_ORDER; n++) {
            data->input_derivatives[k][n] = 0.0;
        }
    }
    data->any_input_derivative = false;
}

void ak_model_data_reset(ak_model_data *data) {
    for (int vr = 0; vr < AK_MAX_VARIABLES; vr++) {
        const ak_variable *variable = ak_variable_of((unsigned int)vr);
        data->values[vr] = variable != NULL ? variable->start : 0.0;
    }
    clear_input_derivatives(data);
    if (AK_MODEL.initialize != NULL) {
        (void)AK_MODEL.initialize(data); /* the start values always give a state */
    }
}
