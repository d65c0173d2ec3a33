"""fmi2GetReal and fmi2SetReal give the same results whatever the order of the value references:
a run of consecutive references (copied as a block) and any other order (checked one by one)."""
import ctypes
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from codegen import reference
from conftest import description_path_of

# The first value reference past AngularKinematics' last (a new variable takes it), and the Real
# ones below it, so that a run starts valid and goes past the end.
_VARIABLES = list(ET.parse(description_path_of("AngularKinematics")).getroot().iter("ScalarVariable"))
PAST = max(int(v.get("valueReference")) for v in _VARIABLES) + 1
REALS = sorted(int(v.get("valueReference")) for v in _VARIABLES if v.find("Real") is not None)

INPUTS = dict(zip(reference.INPUT_NAMES, [0.3, -1.1, 2.0, 0.7, -0.4, 1.9, 3.0, -2.5, 0.25]))


def get_raw(instance, vrs):
    """fmi2GetReal of raw value references: (status, values)."""
    array = (ctypes.c_uint * len(vrs))(*vrs)
    values = (ctypes.c_double * len(vrs))(*([-7.0] * len(vrs)))
    return instance.call("fmi2GetReal", array, len(vrs), values), list(values)


def set_raw(instance, vrs, values):
    array = (ctypes.c_uint * len(vrs))(*vrs)
    doubles = (ctypes.c_double * len(vrs))(*values)
    return instance.call("fmi2SetReal", array, len(vrs), doubles)


@pytest.fixture
def instance(make_instance):
    fmu = make_instance()
    fmu.initialize(inputs=INPUTS)
    return fmu


def test_every_order_gives_the_same_values(instance):
    all_vrs = list(range(21))
    status, in_order = get_raw(instance, all_vrs)
    assert status == 0
    for order in (all_vrs[::-1], all_vrs[9:] + all_vrs[:9], [20, 0, 9, 9, 3]):
        status, values = get_raw(instance, order)
        assert status == 0
        assert values == [in_order[vr] for vr in order]
    for start in range(21):
        for length in (1, 2, 5):
            run = list(range(start, min(start + length, 21)))
            assert get_raw(instance, run) == (0, [in_order[vr] for vr in run])


@pytest.mark.parametrize("vrs", [[REALS[-2], PAST], [REALS[-3], REALS[-2], PAST, PAST + 1],
                                 [2**32 - 1], [2**32 - 1, 0]])
def test_run_past_the_last_reference_is_refused(vrs, instance):
    status, values = get_raw(instance, vrs)
    assert status == 3
    bad = next(vr for vr in vrs if vr >= PAST)
    assert any(f"= {bad} is not a value reference" in m for m in instance.errors())
    assert values == [-7.0] * len(vrs)  # nothing written


@pytest.mark.parametrize("vrs", [list(range(9)), list(range(8, -1, -1))])
def test_set_in_any_order_then_one_bad_value_changes_nothing(vrs, instance):
    new = {reference.INPUT_NAMES[vr]: 0.5 + vr for vr in vrs}
    assert set_raw(instance, vrs, [new[reference.INPUT_NAMES[vr]] for vr in vrs]) == 0
    expected = instance.get(reference.INPUT_NAMES + reference.OUTPUT_NAMES)
    values = [1.0 + vr for vr in vrs]
    values[len(values) // 2] = float("nan")
    assert set_raw(instance, vrs, values) == 3
    assert "is not finite" in instance.errors()[-1]
    assert np.array_equal(instance.get(reference.INPUT_NAMES + reference.OUTPUT_NAMES), expected)


def test_a_run_into_the_integer_parameter_is_refused(instance):
    """vr 70 is the Enumeration parameter sequence: not readable through fmi2GetReal."""
    status, values = get_raw(instance, [68, 69, 70])
    assert status == 3
    assert instance.errors()[-1] == "fmi2GetReal: vr[2] = 70 is sequence, of type Integer, not Real"
    assert values == [-7.0] * 3
