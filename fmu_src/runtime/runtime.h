/* The runtime for the FMI layers, which map the ak_status. A function given the table entry
 * (`call`) checks the call first; one given its name (`function`) comes after the layer's checks.
 * A refused call changes nothing. Each file calls only those before it: instance.c < values.c <
 * derivatives.c < stepping.c, continuous.c, fmu_states.c < lifecycle.c. */
#ifndef ANGULAR_KINEMATICS_RUNTIME_H
#define ANGULAR_KINEMATICS_RUNTIME_H

#include <string.h>

#include "instance.h"

/* --- values (values.c) ------------------------------------------------------------------------- */

/* Recomputes data.any_input_derivative; the outputs go stale if they use input derivatives. */
void ak_input_derivatives_changed(ak_instance *instance);
/* Real values: vr[i] names elements[vr[i]] values (FMI 2: one; FMI 3: an array's), n_values in
 * all. A get evaluates at most once per change of inputs. */
ak_status ak_get_values(ak_instance *instance, const ak_function_rule *call,
                        const unsigned int vr[], size_t nvr, double values[], size_t n_values);
ak_status ak_set_values(ak_instance *instance, const ak_function_rule *call,
                        const unsigned int vr[], size_t nvr, const double values[],
                        size_t n_values);
const ak_variable *ak_variable_of_type(const ak_instance *instance, const char *function,
                                       unsigned int vr, size_t index, ak_type type);
/* Of a checked variable: whether a parameter may be set now, to this value (logged if not). */
bool ak_parameter_settable(const ak_instance *instance, const char *function, size_t index,
                           const ak_variable *variable, double value);
/* Stores a checked value; the outputs go stale only when a bit changed. */
void ak_store(ak_instance *instance, const char *function, unsigned int vr, double value);

/* --- derivatives (derivatives.c) --------------------------------------------------------------- */

/* The refusal of a function behind a capability flag the model does not claim. */
ak_status ak_not_provided(const ak_instance *instance, const char *function, const char *flag);
/* The first derivatives of the checked outputs vr (scalars). */
ak_status ak_output_derivatives(ak_instance *instance, const char *function,
                                const unsigned int vr[], size_t nvr, double value[]);
/* sensitivity = J seed, or += J^T seed (adjoint: zeroed by the caller); J's rows are the checked
 * unknowns (outputs or state derivatives), its columns the checked knowns (inputs or states). */
ak_status ak_derivative(ak_instance *instance, const unsigned int unknowns[], size_t n_unknowns,
                        const unsigned int knowns[], size_t n_knowns, const double seed[],
                        double sensitivity[], bool adjoint);
/* Of the given causality or (also not NULL) one of also; logs naming list_name[index] if not. */
bool ak_derivative_variable(const ak_instance *instance, const char *function,
                            const char *list_name, size_t index, unsigned int vr,
                            ak_causality causality, const unsigned int *also);

/* --- co-simulation (stepping.c) ---------------------------------------------------------------- */

/* A step from t by h (checked). A model with states or evaluate_in_step is evaluated at the end;
 * when that fails the step is not taken (DISCARD; the layer's step_discarded_state). */
ak_status ak_do_step(ak_instance *instance, const char *function, double t, double h);
/* Input derivatives (FMI 2 only): of the inputs vr[i], order[i] 1 or 2, finite. */
ak_status ak_set_input_derivatives(ak_instance *instance, const char *function,
                                   const unsigned int vr[], size_t nvr, const int order[],
                                   const double value[]);

/* --- model exchange (continuous.c) ------------------------------------------------------------- */

ak_status ak_set_time(ak_instance *instance, const ak_function_rule *call, double time);
/* Arrays of the continuous states: count_name/array_name are the layer's argument names. */
ak_status ak_set_continuous_states(ak_instance *instance, const ak_function_rule *call,
                                   const char *count_name, const char *array_name,
                                   const double x[], size_t nx);
ak_status ak_get_continuous_states(ak_instance *instance, const ak_function_rule *call,
                                   const char *count_name, const char *array_name, double x[],
                                   size_t nx);
ak_status ak_get_state_derivatives(ak_instance *instance, const ak_function_rule *call,
                                   const char *count_name, const char *array_name,
                                   double derivatives[], size_t nx);
ak_status ak_get_nominals(ak_instance *instance, const ak_function_rule *call,
                          const char *count_name, const char *array_name, double nominals[],
                          size_t nx);
/* The models have no event indicators: n must be 0. */
ak_status ak_no_event_indicators(ak_instance *instance, const ak_function_rule *call,
                                 const char *count_name, size_t n);

/* --- FMU states (fmu_states.c) ----------------------------------------------------------------- */

/* *state: a state of this instance to overwrite, or NULL for a new one. */
ak_status ak_get_fmu_state(ak_instance *instance, const ak_function_rule *call, void **state);
ak_status ak_set_fmu_state(ak_instance *instance, const ak_function_rule *call, void *state);
ak_status ak_free_fmu_state(ak_instance *instance, const ak_function_rule *call, void **state);
ak_status ak_serialized_fmu_state_size(ak_instance *instance, const ak_function_rule *call,
                                       void *state, size_t *size);
ak_status ak_serialize_fmu_state(ak_instance *instance, const ak_function_rule *call, void *state,
                                 unsigned char bytes[], size_t size);
ak_status ak_deserialize_fmu_state(ak_instance *instance, const ak_function_rule *call,
                                   const unsigned char bytes[], size_t size, void **state);
void ak_free_all_fmu_states(ak_instance *instance);

/* --- life cycle (lifecycle.c) ------------------------------------------------------------------ */

/* A move of the state machine and nothing else. */
ak_status ak_enter_state(ak_instance *instance, const ak_function_rule *call, ak_state state);
/* The instance as instantiated (fmiXReset). */
ak_status ak_reset(ak_instance *instance, const ak_function_rule *call);
/* Switches the n named categories (all when n is 0). */
ak_status ak_set_debug_logging(ak_instance *instance, const ak_function_rule *call, bool on,
                               size_t n, const char *const categories[]);
/* The experiment (checked), then the instance in state `then`. */
ak_status ak_setup_experiment(ak_instance *instance, const ak_function_rule *call,
                              bool tolerance_defined, double tolerance, double start_time,
                              bool stop_time_defined, double stop_time, ak_state then);
/* Refused parameters leave the instance in Initialization Mode, to be corrected. */
ak_status ak_exit_initialization_mode(ak_instance *instance, const ak_function_rule *call);
/* Frees what the runtime allocated for the instance; the layer then frees its own. */
void ak_instance_release(ak_instance *instance);

#endif
