/* FMI 3.0 FMU state: get, set, free, serialize, deserialize (canGetAndSetFMUState,
 * canSerializeFMUState), over runtime/fmu_states.c. */
#include "fmi3_layer.h"

fmi3Status fmi3GetFMUState(fmi3Instance c, fmi3FMUState *FMUState) {
    ak_instance *instance = c;
    if (!fmi3_allowed(instance, AK3_GET_FMU_STATE)) {
        return fmi3Error;
    }
    return fmi3_status(ak_get_fmu_state(instance, fmi3_name(AK3_GET_FMU_STATE), FMUState));
}

fmi3Status fmi3SetFMUState(fmi3Instance c, fmi3FMUState FMUState) {
    ak_instance *instance = c;
    if (!fmi3_allowed(instance, AK3_SET_FMU_STATE)) {
        return fmi3Error;
    }
    return fmi3_status(ak_set_fmu_state(instance, fmi3_name(AK3_SET_FMU_STATE), FMUState));
}

fmi3Status fmi3FreeFMUState(fmi3Instance c, fmi3FMUState *FMUState) {
    ak_instance *instance = c;
    if (!fmi3_allowed(instance, AK3_FREE_FMU_STATE)) {
        return fmi3Error;
    }
    return fmi3_status(ak_free_fmu_state(instance, fmi3_name(AK3_FREE_FMU_STATE), FMUState));
}

fmi3Status fmi3SerializedFMUStateSize(fmi3Instance c, fmi3FMUState FMUState, size_t *size) {
    ak_instance *instance = c;
    if (!fmi3_allowed(instance, AK3_SERIALIZED_FMU_STATE_SIZE)) {
        return fmi3Error;
    }
    return fmi3_status(ak_serialized_fmu_state_size(
        instance, fmi3_name(AK3_SERIALIZED_FMU_STATE_SIZE), FMUState, size));
}

fmi3Status fmi3SerializeFMUState(fmi3Instance c, fmi3FMUState FMUState, fmi3Byte serializedState[],
                                 size_t size) {
    ak_instance *instance = c;
    if (!fmi3_allowed(instance, AK3_SERIALIZE_FMU_STATE)) {
        return fmi3Error;
    }
    return fmi3_status(ak_serialize_fmu_state(instance, fmi3_name(AK3_SERIALIZE_FMU_STATE),
                                              FMUState, serializedState, size));
}

fmi3Status fmi3DeserializeFMUState(fmi3Instance c, const fmi3Byte serializedState[], size_t size,
                                   fmi3FMUState *FMUState) {
    ak_instance *instance = c;
    if (!fmi3_allowed(instance, AK3_DESERIALIZE_FMU_STATE)) {
        return fmi3Error;
    }
    return fmi3_status(ak_deserialize_fmu_state(instance, fmi3_name(AK3_DESERIALIZE_FMU_STATE),
                                                serializedState, size, FMUState));
}
