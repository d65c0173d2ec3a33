"""FMI 3 FMU state, what is the FMI 3 layer's own (test_fmu_state.py has what both layers share:
a state restores everything bit for bit, also in another instance; forgotten states): damaged,
truncated, foreign (an FMI 2 state, another model's) or freed states are refused with a message,
changing nothing, and a model-exchange state does not fit a co-simulation instance. The serialized
form is 92 + 8 N bytes, N the value references of the model's FMI 2 scalars."""
import ctypes

import numpy as np
import pytest

from conftest import value_references_of
from fmi3_support import MODELS, ERROR, OK, Instance3

SIZES = {model: 92 + 8 * len(value_references_of(model)) for model in MODELS}


def first_inputs(instance):
    """The model's first two input arrays: set before the first step, then changed."""
    return instance.inputs()[:2]


def get_state(instance):
    state = ctypes.c_void_p()
    assert instance.call("fmi3GetFMUState", ctypes.byref(state)) == OK
    return state


def serialize(instance, state):
    size = ctypes.c_size_t()
    assert instance.call("fmi3SerializedFMUStateSize", state, ctypes.byref(size)) == OK
    buffer = (ctypes.c_ubyte * size.value)()
    assert instance.call("fmi3SerializeFMUState", state, buffer, size.value) == OK
    return bytes(buffer)


def deserialize(instance, data):
    state = ctypes.c_void_p()
    buffer = (ctypes.c_ubyte * max(len(data), 1)).from_buffer_copy(data or b"\0")
    status = instance.call("fmi3DeserializeFMUState", buffer, len(data), ctypes.byref(state))
    return status, state


def everything(instance):
    values = instance.get(instance.inputs() + instance.outputs())
    return np.concatenate(list(values.values())).view(np.uint64).tolist()


def started(model, sequence=11):
    instance = Instance3(model)
    zeroth, first = first_inputs(instance)
    instance.initialize(parameters={"sequence": sequence} if "sequence" in instance.vr else {},
                        inputs={zeroth: np.resize([0.4, 0.3, -0.2], instance.size[zeroth]),
                                first: np.resize([1.0, 2.0, 3.0], instance.size[first])})
    assert instance.do_step(0.0, 0.25)[0] == OK
    return instance, first


def damaged(data, model):
    flipped = bytearray(data)
    flipped[100] ^= 1
    wrong_version = bytearray(data)
    wrong_version[8] = 9
    return [
        ("one bit flipped", bytes(flipped), "CRC-32"),
        ("truncated", data[:-1], "truncated or extended"),
        ("extended", data + b"\0", "truncated or extended"),
        ("empty", b"", "too short"),
        ("another version", bytes(wrong_version), "format version 9"),
        ("another magic", b"XXXXXXXX" + data[8:], "wrong magic"),
    ]


@pytest.mark.parametrize("model", MODELS)
def test_damaged_or_foreign_states_refused_and_nothing_changed(model, new_instance):
    instance, _ = started(model)
    other_model = Instance3(next(m for m in MODELS if SIZES[m] != SIZES[model]))  # another size
    fmi2 = new_instance("AngularKinematics")
    try:
        data = serialize(instance, get_state(instance))
        saved = everything(instance)
        foreign = serialize(other_model, get_state(other_model))
        fmi2.initialize()
        fmi2_bytes = fmi2.fmu.serializeFMUstate(fmi2.fmu.getFMUstate())
        cases = damaged(data, model) + [("the other model's", foreign, "bytes long"),
                                        ("an FMI 2 state", bytes(fmi2_bytes), "wrong magic")]
        for name, bad, words in cases:
            n = len(instance.errors())
            status, state = deserialize(instance, bad)
            assert status == ERROR and not state.value, name
            assert words in instance.errors()[n], (name, instance.errors()[n])
            assert instance.errors()[n].startswith("fmi3DeserializeFMUState")
        assert everything(instance) == saved
        # A pointer that is not a live state of this instance.
        state = get_state(instance)
        assert instance.call("fmi3FreeFMUState", ctypes.byref(state)) == OK
        stale = ctypes.c_void_p(id(data))
        for function in ("fmi3SetFMUState",):
            assert instance.call(function, stale) == ERROR
            assert "not an FMU state made by" in instance.errors()[-1]
        assert instance.call("fmi3SetFMUState", None) == ERROR
        other_state = get_state(other_model)
        assert instance.call("fmi3SetFMUState", other_state) == ERROR
        assert everything(instance) == saved
    finally:
        instance.free()
        other_model.free()


def test_model_exchange_state_not_accepted_by_co_simulation():
    me = Instance3("AngularKinematics", fmi_type="ModelExchange")
    cs = Instance3("AngularKinematics")
    try:
        data = serialize(me, get_state(me))
        status, _ = deserialize(cs, data)
        assert status == ERROR and "model-exchange instance" in cs.errors()[-1]
    finally:
        me.free()
        cs.free()
