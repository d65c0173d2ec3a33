/* FMI 3.0 FMU state: get, set, free, serialize, deserialize (canGetAndSetFMUState,
 * canSerializeFMUState): runtime/fmu_states.c, which checks the call against the table. */
#include "fmi3_layer.h"

fmi3Status fmi3GetFMUState(fmi3Instance c, fmi3FMUState *FMUState) {
    return fmi3_status(ak_get_fmu_state(c, &FMI3_RULES[AK3_GET_FMU_STATE], FMUState));
}

fmi3Status fmi3SetFMUState(fmi3Instance c, fmi3FMUState FMUState) {
    return fmi3_status(ak_set_fmu_state(c, &FMI3_RULES[AK3_SET_FMU_STATE], FMUState));
}

fmi3Status fmi3FreeFMUState(fmi3Instance c, fmi3FMUState *FMUState) {
    return fmi3_status(ak_free_fmu_state(c, &FMI3_RULES[AK3_FREE_FMU_STATE], FMUState));
}

fmi3Status fmi3SerializedFMUStateSize(fmi3Instance c, fmi3FMUState FMUState, size_t *size) {
    return fmi3_status(
        ak_serialized_fmu_state_size(c, &FMI3_RULES[AK3_SERIALIZED_FMU_STATE_SIZE], FMUState, size));
}

fmi3Status fmi3SerializeFMUState(fmi3Instance c, fmi3FMUState FMUState, fmi3Byte serializedState[],
                                 size_t size) {
    return fmi3_status(ak_serialize_fmu_state(c, &FMI3_RULES[AK3_SERIALIZE_FMU_STATE], FMUState,
                                              serializedState, size));
}

fmi3Status fmi3DeserializeFMUState(fmi3Instance c, const fmi3Byte serializedState[], size_t size,
                                   fmi3FMUState *FMUState) {
    return fmi3_status(ak_deserialize_fmu_state(c, &FMI3_RULES[AK3_DESERIALIZE_FMU_STATE],
                                                serializedState, size, FMUState));
}
