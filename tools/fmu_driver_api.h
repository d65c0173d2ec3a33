/* The FMI 2 functions tools/fmu_driver.c calls, loaded from a library or linked in. */
#ifndef ANGULAR_KINEMATICS_FMU_DRIVER_API_H
#define ANGULAR_KINEMATICS_FMU_DRIVER_API_H

#include "fmi2FunctionTypes.h"
#include "fmu_driver_models.h"

typedef struct {
    fmi2GetVersionTYPE *get_version;
    fmi2InstantiateTYPE *instantiate;
    fmi2SetupExperimentTYPE *setup_experiment;
    fmi2EnterInitializationModeTYPE *enter_initialization_mode;
    fmi2ExitInitializationModeTYPE *exit_initialization_mode;
    fmi2SetRealTYPE *set_real;
    fmi2GetRealTYPE *get_real;
    fmi2DoStepTYPE *do_step;
    fmi2TerminateTYPE *terminate;
    fmi2FreeInstanceTYPE *free_instance;
    /* Model Exchange, for the cross-check mode */
    fmi2SetTimeTYPE *set_time;
    fmi2NewDiscreteStatesTYPE *new_discrete_states;
    fmi2EnterContinuousTimeModeTYPE *enter_continuous_time_mode;
    fmi2GetContinuousStatesTYPE *get_continuous_states;
    fmi2GetDerivativesTYPE *get_derivatives;
    fmi2SetContinuousStatesTYPE *set_continuous_states;
    fmi2CompletedIntegratorStepTYPE *completed_integrator_step;
} fmi2_api;

/* The cross-check mode (tools/fmu_driver_cross_check.c): argv after "cross-check MODEL". */
int fmu_driver_cross_check(const fmi2_api *api, const fmi2CallbackFunctions *callbacks,
                           const driven_model *model, int argc, char **argv);

#endif
