"""FMU state: get, set, free, serialize, deserialize. The serialized form is self-contained (fixed
little-endian layout, format version, GUID, CRC-32); corrupt, truncated and foreign bytes are
refused with fmi2Error and a clear message, leaving the instance as it was. What every model shares
runs for each model (the `model` fixture), what both FMI layers share for both (`layer`: FMI 2 and
FMI 3; test_fmi3_fmu_state.py has what is FMI 3's own); the byte layout and its messages are
checked on AngularKinematics."""
import ctypes
import struct
import xml.etree.ElementTree as ET
import zlib

import numpy as np
import pytest
from fmpy.fmi2 import fmi2FMUstate

from codegen import reference
from conftest import description_path_of, fmu_state_size, value_references_of
from fmi_layers import observable, set_derivatives

INPUTS = dict(zip(reference.INPUT_NAMES, [0.3, -0.7, 1.1, 0.5, -1.5, 2.0, 3.0, -0.25, 0.8]))
OTHER = dict(zip(reference.INPUT_NAMES, [-1.0, 1.5, 0.2, 4.0, 0.1, -0.3, 0.0, 9.0, -2.0]))
ALL = reference.INPUT_NAMES + reference.OUTPUT_NAMES
# AngularKinematics' layout: 92 + 8 N + 16 I bytes, N value references, I inputs (format version 2).
N_VALUES = len(value_references_of("AngularKinematics"))
N_INPUTS = len(reference.INPUT_NAMES)
SIZE = fmu_state_size("AngularKinematics")
DERIVATIVES = 88 + 8 * N_VALUES  # where the input derivatives begin
CRC = SIZE - 4
SEQUENCE = value_references_of("AngularKinematics")["sequence"]
GUID = ET.parse(description_path_of("AngularKinematics")).getroot().get("guid").encode()


def snapshot(instance):
    """Everything observable of a co-simulation instance."""
    return (instance.fmu.getRealStatus(2), tuple(instance.get(observable(instance))))


def stepping(instance, t, steps, h=0.05):
    """Steps and records the outputs after each step."""
    rows = []
    for _ in range(steps):
        assert instance.call("fmi2DoStep", t, h, 1) == 0
        t += h
        rows.append(instance.get(observable(instance)))
    return np.array(rows)


def running(make_instance, name="running", model=None):
    """An instance of AngularKinematics (or of model) stepped to t = 0.2, with inputs and three
    input derivatives set."""
    inputs = INPUTS if model is None else model.valid_inputs
    names = list(inputs)
    instance = make_instance(name)
    instance.initialize(inputs=inputs, stop_time=10.0)
    # The first, middle and last inputs (theta[1], theta_dot[2], theta_ddot[3] of AngularKinematics).
    set_derivatives(instance, {names[0]: 0.5, names[len(names) // 2]: -1.0, names[-1]: 2.0})
    stepping(instance, 0.0, 4)
    return instance


def reseal(data):
    """A byte string with its CRC-32 recomputed, to forge well-sealed but wrong contents."""
    data = bytearray(data[:SIZE - 4])
    return bytes(data) + struct.pack("<I", zlib.crc32(data))


def test_rollback_restores_time_values_and_input_derivatives(model, make_model_instance):
    instance = running(make_model_instance, model=model)
    before = snapshot(instance)
    state = instance.fmu.getFMUstate()
    future = stepping(instance, 0.2, 5)
    instance.set(dict(zip(model.inputs, OTHER.values())))  # also forgets every input derivative
    stepping(instance, 0.45, 2)
    instance.fmu.setFMUstate(state)
    assert snapshot(instance) == before
    # The input derivatives came back too: the same steps give the same outputs, bit for bit.
    assert np.array_equal(stepping(instance, 0.2, 5), future)
    instance.fmu.freeFMUstate(state)
    assert state.value is None


def test_state_restores_everything_bit_for_bit_also_in_another_instance(layer, model, new_instance,
                                                                         report):
    first = layer.started(new_instance, model, "first")
    second = new_instance(model.name, name="second", fmi_version=layer.version)  # never initialized
    state = layer.get_state(first)
    saved = layer.values(first)
    data = layer.serialized(first, state)
    assert len(data) == layer.expected_size(model)
    assert data[:8] == layer.magic
    # Move on (other inputs, a step), then back: the values and the time.
    assert layer.set_inputs(first, np.resize(list(OTHER.values()), len(model.inputs))) == 0
    assert layer.step(first, 0.25, 0.5) == (0, 0.75)
    assert layer.values(first) != saved
    assert first.call(layer.set, state) == 0
    assert layer.values(first) == saved
    # Into the fresh instance through the bytes.
    status, copy = layer.deserialized(second, data)
    assert status == 0
    assert second.call(layer.set, copy) == 0
    assert layer.values(second) == saved
    # Both go on alike, from the restored time (0.25), and serialize to the same bytes.
    t = 0.25
    for _ in range(6):
        assert layer.step(first, t, 0.05) == layer.step(second, t, 0.05) == (0, t + 0.05)
        assert layer.values(second) == layer.values(first)
        t += 0.05
    assert layer.serialized(second, layer.get_state(second)) == \
        layer.serialized(first, layer.get_state(first))
    # A state object passed back is reused; freed, it is NULL.
    assert layer.get_state(first, state) is state
    assert first.call(layer.free, ctypes.byref(state)) == 0 and not state.value
    assert second.call(layer.free, ctypes.byref(copy)) == 0 and not copy.value
    assert first.errors() == [] and second.errors() == []
    report(f"{model.name} ({layer}): serialized state {len(data)} bytes; restored bit for bit")


def test_states_not_freed_are_freed_with_the_instance(layer, model, new_instance):
    """Runs under valgrind/ASan in the abuse runs: no leak when the importer forgets states."""
    instance = layer.started(new_instance, model, "forgetful")
    states = [layer.get_state(instance) for _ in range(5)]
    assert len({state.value for state in states}) == 5 and None not in {s.value for s in states}
    instance.free()
    # The instance's memory, its states' with it, is gone; a new instance of the model works.
    again = layer.started(new_instance, model, "again")
    assert len(layer.serialized(again, layer.get_state(again))) == layer.expected_size(model)


def test_layout_is_the_documented_one(make_instance):
    instance = running(make_instance)
    data = instance.fmu.serializeFMUstate(instance.fmu.getFMUstate())
    assert data[0:8] == b"AKinFMUs"
    assert struct.unpack_from("<II", data, 8) == (2, SIZE)
    assert data[16:56] == GUID + b"\0\0"
    assert struct.unpack_from("<II", data, 56) == (1, 1 << 2)  # co-simulation, StepComplete
    assert struct.unpack_from("<ddII", data, 64) == (0.2, 10.0, 1, 0)
    assert SIZE == 92 + 8 * N_VALUES + 16 * N_INPUTS == len(data)
    values = struct.unpack_from(f"<{N_VALUES}d", data, 88)
    assert np.array_equal(values[:21], instance.get(ALL))
    assert values[SEQUENCE] == 1.0  # the parameter sequence: body123
    derivatives = np.array(struct.unpack_from(f"<{2 * N_INPUTS}d", data, DERIVATIVES)).reshape(N_INPUTS, 2)
    assert derivatives[0, 0] == 0.5 and derivatives[4, 0] == -1.0 and derivatives[8, 0] == 2.0
    assert np.count_nonzero(derivatives) == 3
    assert struct.unpack_from("<I", data, CRC)[0] == zlib.crc32(data[:CRC])  # IEEE CRC-32


def test_state_objects_are_reused_when_passed_back(model, make_model_instance):
    instance = running(make_model_instance, model=model)
    state = fmi2FMUstate()
    assert instance.call("fmi2GetFMUstate", ctypes.byref(state)) == 0
    first = state.value
    stepping(instance, 0.2, 1)
    assert instance.call("fmi2GetFMUstate", ctypes.byref(state)) == 0
    assert state.value == first  # overwritten in place, not reallocated
    data = instance.fmu.serializeFMUstate(state)
    assert struct.unpack_from("<d", data, 64)[0] == 0.25
    assert instance.fmu.deSerializeFMUstate(data, state).value == first
    assert instance.call("fmi2FreeFMUstate", ctypes.byref(state)) == 0
    assert state.value is None
    assert instance.call("fmi2FreeFMUstate", ctypes.byref(state)) == 0  # freeing NULL: nothing
    assert instance.errors() == []


def test_setting_a_state_restores_the_state_machine(model, make_model_instance):
    instance = running(make_model_instance, model=model)
    state = instance.fmu.getFMUstate()
    instance.fmu.terminate()
    assert instance.call("fmi2DoStep", 0.2, 0.1, 1) == 3
    instance.fmu.setFMUstate(state)  # back in StepComplete at t = 0.2
    assert instance.call("fmi2DoStep", 0.2, 0.1, 1) == 0


def test_model_exchange_state_round_trip(make_instance):
    # fmpy's native logger proxy delivers every message to the most recently created instance's
    # logger: the co-simulation source is made first so that the instance under test is last.
    cs = running(make_instance, "cs")
    cs_data = cs.fmu.serializeFMUstate(cs.fmu.getFMUstate())
    instance = make_instance(fmi_type="ModelExchange")
    instance.initialize(inputs=INPUTS)
    instance.fmu.enterContinuousTimeMode()
    instance.fmu.setTime(0.75)
    state = instance.fmu.getFMUstate()
    data = instance.fmu.serializeFMUstate(state)
    assert struct.unpack_from("<II", data, 56) == (0, 1 << 8)  # model exchange, ContinuousTimeMode
    instance.fmu.enterEventMode()
    instance.set(OTHER)
    instance.fmu.setFMUstate(instance.fmu.deSerializeFMUstate(data))
    assert np.array_equal(instance.get(reference.INPUT_NAMES), list(INPUTS.values()))
    assert np.allclose(instance.get(reference.OUTPUT_NAMES), reference.outputs(list(INPUTS.values())),
                       rtol=1e-14)
    assert instance.call("fmi2CompletedIntegratorStep", 1, ctypes.byref(ctypes.c_int()),
                         ctypes.byref(ctypes.c_int())) == 0  # ContinuousTimeMode again
    # A co-simulation state does not fit a model-exchange instance.
    assert try_deserialize(instance, cs_data) == 3
    assert instance.errors()[-1] == ("fmi2DeSerializeFMUstate: the FMU state is of a co-simulation "
                                     "instance (fmuType 1); this instance is for model exchange")


def try_deserialize(instance, data, state=None):
    state = fmi2FMUstate() if state is None else state
    buffer = ctypes.create_string_buffer(data, max(len(data), 1))
    return instance.call("fmi2DeSerializeFMUstate", buffer, len(data), ctypes.byref(state))


def good_bytes(make_instance, model=None):
    source = running(make_instance, "source", model)
    return source.fmu.serializeFMUstate(source.fmu.getFMUstate())


def forged(data, offset, fmt, value):
    data = bytearray(data)
    struct.pack_into(fmt, data, offset, value)
    return reseal(data)


def bad_strings(data):
    flipped = bytearray(data)
    flipped[100] ^= 0x01  # one bit of theta_dot in the payload
    return {
        "empty": (b"", "fmi2DeSerializeFMUstate: the 0 bytes are not an AngularKinematics FMU state "
                       "(too short for the header)"),
        "header only": (data[:12], "fmi2DeSerializeFMUstate: the 12 bytes are not an AngularKinematics "
                                   "FMU state (too short for the header)"),
        "truncated": (data[:-1], f"fmi2DeSerializeFMUstate: the FMU state is {SIZE - 1} bytes long and "
                                 f"declares {SIZE} bytes; format version 2 of AngularKinematics has "
                                 f"{SIZE} bytes (truncated or extended)"),
        "extended": (data + b"\0", f"fmi2DeSerializeFMUstate: the FMU state is {SIZE + 1} bytes long and "
                                   f"declares {SIZE} bytes; format version 2 of AngularKinematics has "
                                   f"{SIZE} bytes (truncated or extended)"),
        "foreign": (b"PK\x03\x04" + bytes(SIZE - 4), f"fmi2DeSerializeFMUstate: the {SIZE} bytes are not "
                                                     "an AngularKinematics FMU state (wrong magic bytes)"),
        "corrupt": (bytes(flipped), "fmi2DeSerializeFMUstate: the FMU state is corrupt: its CRC-32 is "
                                    "0x%08x, the bytes give 0x%08x" % (
                                        struct.unpack_from("<I", data, CRC)[0],
                                        zlib.crc32(bytes(flipped[:CRC])))),
        "version 1": (forged(data, 8, "<I", 1), "fmi2DeSerializeFMUstate: FMU state format version 1 "
                                                "is not supported (this binary reads version 2)"),
        "version 3": (forged(data, 8, "<I", 3), "fmi2DeSerializeFMUstate: FMU state format version 3 "
                                                "is not supported (this binary reads version 2)"),
        "other GUID": (reseal(data[:16] + b"{00000000-0000-0000-0000-000000000000}\0\0" + data[56:]),
                       'fmi2DeSerializeFMUstate: the FMU state is of an FMU with GUID '
                       '"{00000000-0000-0000-0000-000000000000}", not this one\'s (AngularKinematics) '
                       f'"{GUID.decode()}"'),
        "step in progress": (forged(data, 60, "<I", 1 << 3),
                             "fmi2DeSerializeFMUstate: the FMU state holds an impossible header "
                             "(state 0x8, time 0.2, stop time 10, stop time defined 1)"),
        "not finite": (forged(data, 88 + 8 * 4, "<d", float("inf")),
                       "fmi2DeSerializeFMUstate: the FMU state holds theta_dot[2] = inf, which is "
                       "not finite"),
        "bad sequence": (forged(data, 88 + 8 * SEQUENCE, "<d", 25.0),
                         "fmi2DeSerializeFMUstate: the FMU state holds the parameter sequence = 25, "
                         "which it cannot have"),
        "fractional sequence": (forged(data, 88 + 8 * SEQUENCE, "<d", 2.5),
                                "fmi2DeSerializeFMUstate: the FMU state holds the parameter sequence "
                                "= 2.5, which it cannot have"),
    }


@pytest.mark.parametrize("kind", ["empty", "header only", "truncated", "extended", "foreign", "corrupt",
                                  "version 1", "version 3", "other GUID", "step in progress",
                                  "not finite", "bad sequence", "fractional sequence"])
def test_bad_bytes_are_refused_and_change_nothing(kind, make_instance):
    data = good_bytes(make_instance)
    bad, message = bad_strings(data)[kind]
    instance = running(make_instance, "target")
    stepping(instance, 0.2, 1)
    before = snapshot(instance)
    # A state object passed for reuse is left as it was too.
    kept = instance.fmu.getFMUstate()
    kept_bytes = instance.fmu.serializeFMUstate(kept)
    assert try_deserialize(instance, bad, kept) == 3
    assert instance.errors() == [message]
    assert snapshot(instance) == before
    assert instance.fmu.serializeFMUstate(kept) == kept_bytes
    assert instance.call("fmi2DoStep", 0.25, 0.05, 1) == 0  # and goes on


def test_every_single_bit_flip_is_detected(model, make_model_instance):
    data = good_bytes(make_model_instance, model)
    instance = make_model_instance("target")
    refused = 0
    for byte in range(len(data)):
        for bit in range(8):
            bad = bytearray(data)
            bad[byte] ^= 1 << bit
            refused += try_deserialize(instance, bytes(bad)) == 3
    assert refused == len(data) * 8
    assert try_deserialize(instance, data) == 0


def test_null_and_stray_arguments(model, make_model_instance):
    instance = running(make_model_instance, model=model)
    size_needed = len(instance.fmu.serializeFMUstate(instance.fmu.getFMUstate()))
    stray = ctypes.c_void_p(ctypes.addressof(ctypes.create_string_buffer(512)))
    size = ctypes.c_size_t()
    assert instance.call("fmi2GetFMUstate", None) == 3
    assert instance.call("fmi2SetFMUstate", None) == 3
    assert instance.call("fmi2SetFMUstate", stray) == 3
    assert instance.call("fmi2SerializedFMUstateSize", instance.fmu.getFMUstate(), None) == 3
    small = ctypes.create_string_buffer(size_needed - 1)
    assert instance.call("fmi2SerializeFMUstate", instance.fmu.getFMUstate(), small,
                         size_needed - 1) == 3
    assert instance.call("fmi2FreeFMUstate", None) == 3
    assert instance.errors() == [
        "fmi2GetFMUstate: FMUstate is NULL",
        "fmi2SetFMUstate: FMUstate NULL is not an FMU state made by fmi2GetFMUstate or "
        "fmi2DeSerializeFMUstate of this FMU (or it was freed)",
        "fmi2SetFMUstate: FMUstate given is not an FMU state made by fmi2GetFMUstate or "
        "fmi2DeSerializeFMUstate of this FMU (or it was freed)",
        "fmi2SerializedFMUstateSize: size is NULL",
        f"fmi2SerializeFMUstate: size = {size_needed - 1} is too small; the state needs "
        f"{size_needed} bytes (fmi2SerializedFMUstateSize)",
        "fmi2FreeFMUstate: FMUstate is NULL",
    ]
    assert instance.call("fmi2SerializedFMUstateSize", instance.fmu.getFMUstate(),
                         ctypes.byref(size)) == 0
    assert size.value == size_needed


def test_many_get_free_cycles(model, make_model_instance):
    instance = running(make_model_instance, model=model)
    for _ in range(500):
        state = instance.fmu.getFMUstate()
        copy = instance.fmu.deSerializeFMUstate(instance.fmu.serializeFMUstate(state))
        instance.fmu.freeFMUstate(state)
        instance.fmu.freeFMUstate(copy)
    assert instance.errors() == []
