/* When a model's outputs are computed (runtime/outputs.h), for both FMI layers. */
#include "outputs.h"

void ak_outputs_reset(ak_outputs *outputs) {
    outputs->stale = true;
    outputs->lazy_stale = true;
    outputs->derived_stale = true;
    outputs->status = AK_EVAL_OK;
    outputs->evaluations = 0;
}

/* The main group, and the lazy group with it when with_lazy and the model can do both at once. */
static ak_eval_status refresh(ak_outputs *outputs, ak_model_data *data, bool in_initialization,
                              bool with_lazy, unsigned int *ran) {
    /* Until initialization ends the states follow the parameters they start from. */
    if (in_initialization && AK_MODEL.initialize != NULL &&
        AK_MODEL.initialize(data) == AK_EVAL_FAILED) {
        outputs->status = AK_EVAL_FAILED;
        outputs->stale = false;
        return AK_EVAL_FAILED;
    }
    const bool both = with_lazy && AK_MODEL.evaluate_all != NULL;
    outputs->status = both ? AK_MODEL.evaluate_all(data) : AK_MODEL.evaluate(data);
    outputs->derived_stale = true;
    outputs->stale = false;
    outputs->lazy_stale = !both || outputs->status == AK_EVAL_FAILED;
    outputs->evaluations++;
    *ran |= both ? AK_RAN_MAIN | AK_RAN_ALL : AK_RAN_MAIN;
    return outputs->status;
}

ak_eval_status ak_outputs_update(ak_outputs *outputs, ak_model_data *data, bool in_initialization,
                                 ak_group upto, unsigned int *ran) {
    const bool with_lazy = upto >= AK_GROUP_LAZY;
    *ran = 0;
    const ak_eval_status status =
        outputs->stale ? refresh(outputs, data, in_initialization, with_lazy, ran) : outputs->status;
    if (with_lazy && outputs->lazy_stale && status != AK_EVAL_FAILED && AK_MODEL.evaluate_lazy) {
        AK_MODEL.evaluate_lazy(data);
        outputs->derived_stale = true;
        outputs->lazy_stale = false;
        *ran |= AK_RAN_LAZY;
    }
    if (upto == AK_GROUP_DERIVED && outputs->derived_stale && status != AK_EVAL_FAILED) {
        ak_model_compute_derived(data);
        outputs->derived_stale = false;
        *ran |= AK_RAN_DERIVED;
    }
    return status;
}
