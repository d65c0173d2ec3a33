/* FMI 2.0 FMU state: get, set, free, serialize, deserialize (canGetAndSetFMUstate,
 * canSerializeFMUstate): runtime/fmu_states.c, which checks the call against the table. */
#include "fmi2_layer.h"

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *FMUstate) {
    return fmi2_status(ak_get_fmu_state(c, &FMI2_RULES[AK_FMI2_GET_FMU_STATE], FMUstate));
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate FMUstate) {
    return fmi2_status(ak_set_fmu_state(c, &FMI2_RULES[AK_FMI2_SET_FMU_STATE], FMUstate));
}

fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *FMUstate) {
    return fmi2_status(ak_free_fmu_state(c, &FMI2_RULES[AK_FMI2_FREE_FMU_STATE], FMUstate));
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate FMUstate, size_t *size) {
    return fmi2_status(ak_serialized_fmu_state_size(
        c, &FMI2_RULES[AK_FMI2_SERIALIZED_FMU_STATE_SIZE], FMUstate, size));
}

fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate FMUstate, fmi2Byte serializedState[],
                                 size_t size) {
    return fmi2_status(ak_serialize_fmu_state(c, &FMI2_RULES[AK_FMI2_SERIALIZE_FMU_STATE],
                                              FMUstate, (unsigned char *)serializedState, size));
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte serializedState[], size_t size,
                                   fmi2FMUstate *FMUstate) {
    return fmi2_status(ak_deserialize_fmu_state(c, &FMI2_RULES[AK_FMI2_DE_SERIALIZE_FMU_STATE],
                                                (const unsigned char *)serializedState, size,
                                                FMUstate));
}
