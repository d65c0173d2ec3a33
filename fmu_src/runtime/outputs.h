/* When a model's outputs are computed: the freshness the runtime keeps per instance, and the one
 * rule that brings it up to date (runtime/outputs.c). The caller (ak_instance_update) passes
 * whether it is still before the end of initialization, and traces what ran. */
#ifndef ANGULAR_KINEMATICS_RUNTIME_OUTPUTS_H
#define ANGULAR_KINEMATICS_RUNTIME_OUTPUTS_H

#include <stdbool.h>

#include "model.h"

typedef struct {
    /* An input or parameter changed since the main group was last computed. */
    bool stale;
    /* The main group was computed since the lazy group was (computed only when read). */
    bool lazy_stale;
    /* A group was computed since the derived outputs were (computed only when read). */
    bool derived_stale;
    /* Of the evaluation the outputs come from: on AK_EVAL_FAILED they hold the values of the last
     * successful one, and a read answers as the layer says until an input changes. */
    ak_eval_status status;
    /* How many times the main group was computed; reported in the layers' logCalls trace. */
    unsigned long evaluations;
} ak_outputs;

/* What ak_outputs_update ran, as flags. */
enum {
    AK_RAN_MAIN = 1 << 0, /* evaluate, or evaluate_all (then also AK_RAN_ALL) */
    AK_RAN_ALL = 1 << 1,  /* evaluate_all: both groups in one pass */
    AK_RAN_LAZY = 1 << 2,   /* evaluate_lazy, after a main group already current */
    AK_RAN_DERIVED = 1 << 3 /* the derived outputs (AK_MODEL.derived) */
};

/* Everything stale, nothing evaluated yet. */
void ak_outputs_reset(ak_outputs *outputs);

/* An input or parameter changed: one store, so that a setter pays no more. Every evaluation of
 * the main group makes the lazy group stale. */
static inline void ak_outputs_inputs_changed(ak_outputs *outputs) {
    outputs->stale = true;
}

/* Brings the groups up to `upto` (main; main and lazy; every output) up to date with
 * data->values, running the model only for what is stale; in_initialization: the states still
 * follow the parameters (AK_MODEL.initialize runs first). Returns the status of the evaluation the outputs come from;
 * *ran the AK_RAN_ flags of what ran (0: nothing, or initialize failed). */
ak_eval_status ak_outputs_update(ak_outputs *outputs, ak_model_data *data, bool in_initialization,
                                 ak_group upto, unsigned int *ran);

#endif
