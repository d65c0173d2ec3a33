/* FMI 2.0 functions behind capability flags that modelDescription.xml sets to false: each
 * checks its instance and state like every entry point, then refuses with fmi2Error and says
 * which flag is false. */
#include "fmi2Functions.h"
#include "fmi2_instance.h"
#include "fmi2_logging.h"
#include "fmi2_state_machine.h"

static fmi2Status refuse(fmi2Component c, ak_function function, const char *flag) {
    const ak_instance *instance = c;
    if (!ak_call_allowed(instance, function)) {
        return fmi2Error;
    }
    ak_log(instance, AK_LOG_ERROR, fmi2Error,
           "%s: not supported by this FMU (%s in modelDescription.xml)",
           ak_function_name(function), flag);
    return fmi2Error;
}

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *FMUstate) {
    (void)FMUstate;
    return refuse(c, AK_FMI2_GET_FMU_STATE, "canGetAndSetFMUstate=\"false\"");
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate FMUstate) {
    (void)FMUstate;
    return refuse(c, AK_FMI2_SET_FMU_STATE, "canGetAndSetFMUstate=\"false\"");
}

fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *FMUstate) {
    (void)FMUstate;
    return refuse(c, AK_FMI2_FREE_FMU_STATE, "canGetAndSetFMUstate=\"false\"");
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate FMUstate, size_t *size) {
    (void)FMUstate;
    (void)size;
    return refuse(c, AK_FMI2_SERIALIZED_FMU_STATE_SIZE, "canSerializeFMUstate=\"false\"");
}

fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate FMUstate, fmi2Byte serializedState[],
                                 size_t size) {
    (void)FMUstate;
    (void)serializedState;
    (void)size;
    return refuse(c, AK_FMI2_SERIALIZE_FMU_STATE, "canSerializeFMUstate=\"false\"");
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte serializedState[], size_t size,
                                   fmi2FMUstate *FMUstate) {
    (void)serializedState;
    (void)size;
    (void)FMUstate;
    return refuse(c, AK_FMI2_DE_SERIALIZE_FMU_STATE, "canSerializeFMUstate=\"false\"");
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference vUnknown_ref[],
                                        size_t nUnknown, const fmi2ValueReference vKnown_ref[],
                                        size_t nKnown, const fmi2Real dvKnown[], fmi2Real dvUnknown[]) {
    (void)vUnknown_ref;
    (void)nUnknown;
    (void)vKnown_ref;
    (void)nKnown;
    (void)dvKnown;
    (void)dvUnknown;
    return refuse(c, AK_FMI2_GET_DIRECTIONAL_DERIVATIVE, "providesDirectionalDerivative=\"false\"");
}

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                       const fmi2Integer order[], const fmi2Real value[]) {
    (void)vr;
    (void)nvr;
    (void)order;
    (void)value;
    return refuse(c, AK_FMI2_SET_REAL_INPUT_DERIVATIVES, "canInterpolateInputs=\"false\"");
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                        const fmi2Integer order[], fmi2Real value[]) {
    (void)vr;
    (void)nvr;
    (void)order;
    (void)value;
    return refuse(c, AK_FMI2_GET_REAL_OUTPUT_DERIVATIVES, "maxOutputDerivativeOrder=\"0\"");
}
