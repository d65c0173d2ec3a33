/* The FMI 3 functions tools/fmi3_driver.c calls, loaded from a library or linked in. */
#ifndef ANGULAR_KINEMATICS_FMI3_DRIVER_API_H
#define ANGULAR_KINEMATICS_FMI3_DRIVER_API_H

#include "fmi3FunctionTypes.h"
#include "fmi3_driver_models.h"

typedef struct {
    fmi3InstantiateCoSimulationTYPE *instantiate;
    fmi3EnterInitializationModeTYPE *enter_initialization_mode;
    fmi3ExitInitializationModeTYPE *exit_initialization_mode;
    fmi3SetInt64TYPE *set_int64;
    fmi3SetFloat64TYPE *set_float64;
    fmi3GetFloat64TYPE *get_float64;
    fmi3DoStepTYPE *do_step;
    fmi3GetDirectionalDerivativeTYPE *directional;
    fmi3GetAdjointDerivativeTYPE *adjoint;
    fmi3GetOutputDerivativesTYPE *output_derivatives;
    fmi3TerminateTYPE *terminate;
    fmi3FreeInstanceTYPE *free_instance;
    /* Model Exchange, for the cross-check mode */
    fmi3InstantiateModelExchangeTYPE *instantiate_model_exchange;
    fmi3SetTimeTYPE *set_time;
    fmi3UpdateDiscreteStatesTYPE *update_discrete_states;
    fmi3EnterContinuousTimeModeTYPE *enter_continuous_time_mode;
    fmi3GetContinuousStatesTYPE *get_continuous_states;
    fmi3GetContinuousStateDerivativesTYPE *get_continuous_state_derivatives;
    fmi3SetContinuousStatesTYPE *set_continuous_states;
    fmi3CompletedIntegratorStepTYPE *completed_integrator_step;
} fmi3_api;

/* The cross-check mode (tools/fmi3_driver_cross_check.c): argv after "MODEL cross-check". */
int fmi3_driver_cross_check(const fmi3_api *api, const driver_model *model, int argc,
                            char **argv);

#endif
