"""Writes seed inputs for fuzz_fmi2 in its encoding (see fuzz_fmi2.c): whole simulations in both
interfaces, several instances, logging on, bad arguments, every function in StepComplete and in
EventMode, input and output derivatives, FMU states got, set, serialized and deserialized with
changed bytes, the sequence parameter, EulerRates' singular configuration. The same seeds serve
both models (fuzz_fmi2 and fuzz_fmi2_EulerRates). The fuzzer mutates these
into its corpus; scripts/fuzz.sh runs this once when the corpus folder is empty.

    python fuzz_seeds.py OUTPUT_FOLDER"""
import pathlib
import struct
import sys

# Op numbers of fmi2_test_ops.h (ak_op_id); AK_N_OPS is fmi2Instantiate.
OPS = ["SET_DEBUG_LOGGING", "SETUP_EXPERIMENT", "ENTER_INITIALIZATION_MODE", "EXIT_INITIALIZATION_MODE",
       "TERMINATE", "RESET", "GET_REAL", "GET_INTEGER", "GET_BOOLEAN", "GET_STRING", "SET_REAL",
       "SET_INTEGER", "SET_BOOLEAN", "SET_STRING", "GET_FMU_STATE", "SET_FMU_STATE", "FREE_FMU_STATE",
       "SERIALIZED_FMU_STATE_SIZE", "SERIALIZE_FMU_STATE", "DE_SERIALIZE_FMU_STATE",
       "GET_DIRECTIONAL_DERIVATIVE", "SET_REAL_INPUT_DERIVATIVES", "GET_REAL_OUTPUT_DERIVATIVES",
       "DO_STEP", "CANCEL_STEP", "GET_STATUS", "GET_REAL_STATUS", "GET_INTEGER_STATUS",
       "GET_BOOLEAN_STATUS", "GET_STRING_STATUS", "ENTER_EVENT_MODE", "NEW_DISCRETE_STATES",
       "ENTER_CONTINUOUS_TIME_MODE", "COMPLETED_INTEGRATOR_STEP", "SET_TIME", "SET_CONTINUOUS_STATES",
       "GET_DERIVATIVES", "GET_EVENT_INDICATORS", "GET_CONTINUOUS_STATES",
       "GET_NOMINALS_OF_CONTINUOUS_STATES", "FREE_INSTANCE"]
OP = {name: number for number, name in enumerate(OPS)}
INSTANTIATE = len(OPS)
CORRUPT_ROUND_TRIP = len(OPS) + 1  # serialize an FMU state, change bytes, deserialize, set
# Element types of the value arrays (values, values2), as in the op table.
TYPES = {"GET_REAL": ("real", None), "SET_REAL": ("real", None), "GET_INTEGER": ("int", None),
         "SET_INTEGER": ("int", None), "GET_BOOLEAN": ("byte", None), "SET_BOOLEAN": ("byte", None),
         "GET_STRING": ("byte", None), "SET_STRING": ("byte", None),
         "GET_DIRECTIONAL_DERIVATIVE": ("byte", "real"), "SET_REAL_INPUT_DERIVATIVES": ("real", "int"),
         "GET_REAL_OUTPUT_DERIVATIVES": ("real", "int"), "SET_CONTINUOUS_STATES": ("byte", "real"),
         "GET_DERIVATIVES": ("byte", "real"), "GET_EVENT_INDICATORS": ("byte", "real"),
         "GET_CONTINUOUS_STATES": ("byte", "real"), "GET_NOMINALS_OF_CONTINUOUS_STATES": ("byte", "real")}
# Indices into SPECIAL_REALS; TIME is "the slot's time".
ZERO, ONE, TENTH, HALF, MILLI, TEN, PI_2, NAN, INF, TWO, TIME = 0, 2, 4, 5, 6, 7, 8, 22, 24, 28, 0x7F


def raw_real(value):
    return bytes([0x80]) + struct.pack("<d", value)


def real(code_or_value):
    if isinstance(code_or_value, float):
        return raw_real(code_or_value)
    return bytes([code_or_value])


def call(op, slot=0, nulls=0, vr=(), values=(), values2=(), vr2=(), known=(), categories=(),
         data=b"", reals=(ZERO, ZERO, ZERO), flags=(0, 0, 0), kind=0, state=0):
    if op == "FREE_INSTANCE":  # takes no arguments
        return bytes([OP[op], slot])
    out = bytes([OP[op], slot, nulls, len(vr)])
    first, second = TYPES.get(op, ("byte", None))
    for v in vr:
        out += bytes([v]) if v < 0xF0 else bytes([0xF0]) + struct.pack("<I", v)
    for kind_of, given in ((first, values), (second or "byte", values2)):
        for i in range(len(vr)):
            value = given[i] if i < len(given) else 0
            if kind_of == "real":
                out += real(value)
            elif kind_of == "int":
                out += struct.pack("<i", value)
            else:
                out += bytes([value])
    out += bytes([len(vr2)]) + b"".join(bytes([v]) for v in vr2)
    out += b"".join(real(known[i] if i < len(known) else ZERO) for i in range(len(vr2)))
    out += bytes([len(categories)]) + bytes(categories)
    out += bytes([len(data)]) + data
    out += b"".join(real(r) for r in reals) + bytes(flags) + bytes([kind, state])
    return out


def instantiate(slot=0, name=0, fmu_type=1, guid=0, callbacks=0, fail_after=0, logging=0):
    """callbacks: 0 good, 1 without memory functions, 2 NULL, 3 failing allocator, 4 without logger.
    fail_after: with callbacks=3, bits 0-1 successes (0-2) then bits 2-3: fail once, twice, for good."""
    return bytes([INSTANTIATE, slot, name, fmu_type, guid, callbacks, fail_after, logging])


def corrupt_round_trip(slot=0, changes=(), length_change=255):
    """changes: (position, new byte) pairs, at most 8; length_change < 16 cuts that many bytes,
    16 to 31 appends (length_change - 16) zeros, more leaves the length."""
    out = bytes([CORRUPT_ROUND_TRIP, slot, len(changes), length_change])
    for position, value in changes:
        out += struct.pack("<H", position) + bytes([value])
    return out


def initialized(slot=0, fmu_type=1, logging=0):
    seed = instantiate(slot, fmu_type=fmu_type, logging=logging)
    seed += call("SETUP_EXPERIMENT", slot, reals=(ZERO, ZERO, TEN), flags=(0, 1, 0))
    seed += call("ENTER_INITIALIZATION_MODE", slot)
    seed += call("SET_REAL", slot, vr=range(9), values=[4, 5, 2, 3, 8, 9, 10, 11, 28])
    seed += call("EXIT_INITIALIZATION_MODE", slot)
    return seed


def model_exchange(slot=0, steps=10):
    seed = initialized(slot, fmu_type=0)
    seed += call("NEW_DISCRETE_STATES", slot) + call("ENTER_CONTINUOUS_TIME_MODE", slot)
    for k in range(steps):
        seed += call("SET_TIME", slot, reals=(0.01 * (k + 1), ZERO, ZERO))
        seed += call("SET_REAL", slot, vr=[k % 9], values=[0.1 * k])
        seed += call("SET_CONTINUOUS_STATES", slot) + call("GET_DERIVATIVES", slot)
        seed += call("GET_EVENT_INDICATORS", slot) + call("GET_REAL", slot, vr=range(22))
        seed += call("COMPLETED_INTEGRATOR_STEP", slot, flags=(1, 0, 0))
    seed += call("ENTER_EVENT_MODE", slot) + call("NEW_DISCRETE_STATES", slot)
    seed += call("GET_CONTINUOUS_STATES", slot) + call("GET_NOMINALS_OF_CONTINUOUS_STATES", slot)
    return seed + call("TERMINATE", slot) + call("GET_DERIVATIVES", slot)


def simulation(slot=0, steps=10, logging=0):
    seed = instantiate(slot, logging=logging)
    seed += call("SETUP_EXPERIMENT", slot, reals=(ZERO, ZERO, TEN), flags=(0, 1, 0))
    seed += call("ENTER_INITIALIZATION_MODE", slot)
    seed += call("SET_REAL", slot, vr=range(9), values=[4, 5, 2, 3, 8, 9, 10, 11, 28])
    seed += call("EXIT_INITIALIZATION_MODE", slot)
    for k in range(steps):
        seed += call("SET_REAL", slot, vr=[k % 9], values=[0.1 * k])
        seed += call("DO_STEP", slot, reals=(TIME, TENTH, ZERO), flags=(1, 0, 0))
        seed += call("GET_REAL", slot, vr=range(21))
    return seed


def main(folder):
    folder = pathlib.Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    seeds = {"simulation": simulation() + call("TERMINATE") + call("RESET") + call("FREE_INSTANCE")}
    seeds["logging_on"] = simulation(logging=1) + call("SET_DEBUG_LOGGING", categories=[2], flags=(0, 0, 0))
    seeds["three_instances"] = simulation(0, 3) + simulation(1, 3) + simulation(2, 3) + call("FREE_INSTANCE", 1)
    bad = simulation(steps=1)
    bad += call("SET_REAL", vr=[0, 5], values=[ONE, NAN]) + call("SET_REAL", vr=[9], values=[ONE])
    bad += call("SET_REAL", vr=[0xFFFFFFFF], values=[ONE]) + call("GET_REAL", nulls=1, vr=[9])
    bad += call("DO_STEP", reals=(ZERO, TENTH, ZERO)) + call("DO_STEP", reals=(TIME, INF, ZERO))
    bad += call("DO_STEP", reals=(TIME, TEN, ZERO)) + call("DO_STEP", reals=(TIME, 1e-300, ZERO))
    bad += call("SETUP_EXPERIMENT") + call("CANCEL_STEP") + call("RESET") + call("DO_STEP")
    seeds["bad_arguments"] = bad
    every = simulation(steps=1)
    for op in OPS:
        every += call(op, vr=[9, 0], values=[ONE, ONE], values2=[ONE, ONE], vr2=[0], known=[ONE],
                      categories=[0, 3], data=b"\x01\x02\x03\x04", reals=(TIME, TENTH, TEN), kind=2)
    seeds["every_function"] = every
    every_me = initialized(fmu_type=0)
    for op in OPS:
        every_me += call(op, vr=[9, 0], values=[ONE, ONE], values2=[ONE, ONE], vr2=[0], known=[ONE],
                         categories=[0, 3], data=b"\x01\x02\x03\x04", reals=(TENTH, TENTH, TEN), kind=2)
    seeds["every_function_model_exchange"] = every_me
    seeds["model_exchange"] = model_exchange() + call("RESET") + model_exchange(steps=3)
    derivatives = simulation(steps=1)
    derivatives += call("SET_REAL_INPUT_DERIVATIVES", vr=[0, 1, 3, 8], values=[ONE, HALF, TEN, NAN],
                        values2=[1, 2, 1, 3])
    derivatives += call("SET_REAL_INPUT_DERIVATIVES", vr=[0, 1, 3], values=[ONE, HALF, TEN], values2=[1, 2, 1])
    derivatives += call("DO_STEP", reals=(TIME, TENTH, ZERO), flags=(1, 0, 0))
    derivatives += call("GET_REAL_OUTPUT_DERIVATIVES", vr=[9, 10, 20, 21], values2=[1, 1, 1, 2])
    derivatives += call("GET_DIRECTIONAL_DERIVATIVE", vr=[9, 15, 30], vr2=[0, 4, 8], known=[ONE, HALF, TEN])
    derivatives += call("DO_STEP", reals=(TIME, TENTH, ZERO), flags=(1, 0, 0))
    seeds["derivatives"] = derivatives
    states = simulation(steps=1) + call("GET_FMU_STATE", state=0) + call("DO_STEP", reals=(TIME, TENTH, ZERO))
    states += call("SERIALIZED_FMU_STATE_SIZE", state=0) + call("SERIALIZE_FMU_STATE", state=0, data=bytes(40))
    states += call("SET_FMU_STATE", state=0) + corrupt_round_trip() + corrupt_round_trip(changes=[(0, 0)])
    states += corrupt_round_trip(changes=[(20, 0xFF), (100, 1)]) + corrupt_round_trip(length_change=3)
    states += corrupt_round_trip(length_change=20) + corrupt_round_trip(changes=[(60, 0x7F), (61, 0xF0)])
    states += call("FREE_FMU_STATE", state=0) + call("FREE_FMU_STATE", state=0)
    states += call("DE_SERIALIZE_FMU_STATE", state=1, data=b"AKFMUSTATE" + bytes(30))
    states += model_exchange(1, 2) + call("GET_FMU_STATE", 1, state=2) + corrupt_round_trip(1)
    seeds["fmu_states"] = states
    parameters = instantiate() + call("SET_INTEGER", vr=[70, 22, 23], values=[6, 7, 2])
    parameters += call("SET_REAL", vr=[24], values=[HALF]) + call("SET_INTEGER", vr=[70, 22], values=[25, 0])
    parameters += simulation(steps=2)[8:]
    parameters += call("SET_REAL", vr=[1], values=[PI_2]) + call("DO_STEP", reals=(TIME, TENTH, ZERO))
    parameters += call("GET_REAL", vr=range(22)) + call("GET_REAL_STATUS", kind=2) + call("RESET")
    seeds["parameters_and_singularity"] = parameters
    seeds["bad_instantiations"] = b"".join(
        instantiate(name=n, fmu_type=t, guid=g, callbacks=c, fail_after=f)
        for n, t, g, c, f in [(1, 1, 0, 0, 0), (2, 1, 0, 0, 0), (3, 1, 0, 0, 0), (4, 1, 0, 0, 0), (0, 0, 0, 0, 0),
                              (0, 2, 0, 0, 0), (0, 1, 1, 0, 0), (0, 1, 2, 0, 0), (0, 1, 0, 1, 0), (0, 1, 0, 2, 0),
                              (0, 1, 0, 3, 0), (0, 1, 0, 3, 1), (0, 1, 0, 3, 2), (0, 1, 0, 3, 4),
                              (0, 1, 0, 3, 8), (0, 1, 0, 3, 9), (0, 1, 1, 4, 0), (0, 1, 0, 4, 0)])
    for name, data in seeds.items():
        (folder / f"seed_{name}").write_bytes(data)
    print(f"fuzz_seeds: {len(seeds)} seeds written to {folder}")


if __name__ == "__main__":
    main(sys.argv[1])
