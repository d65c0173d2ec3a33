"""Bad input: every kind gets fmi2Error, a message naming the function, the variable and the value,
and the instance keeps its last valid values."""
import ctypes

import numpy as np
import pytest
from fmpy.fmi2 import fmi2CallbackFunctions

import reference

VALID = dict(zip(reference.INPUT_NAMES, [0.3, -0.7, 1.1, 0.5, -1.5, 2.0, 3.0, -0.25, 0.8]))
ALL = reference.INPUT_NAMES + reference.OUTPUT_NAMES


def initialized(make_instance):
    instance = make_instance()
    instance.initialize(inputs=VALID)
    return instance, instance.get(ALL)


def call_set_real(instance, vrs, values):
    vr = (ctypes.c_uint * len(vrs))(*vrs)
    array = (ctypes.c_double * len(values))(*values)
    return instance.call("fmi2SetReal", vr, len(vrs), array)


@pytest.mark.parametrize("name", reference.INPUT_NAMES)
@pytest.mark.parametrize("bad", [float("nan"), float("inf"), -float("inf")])
def test_non_finite_input_is_refused(name, bad, make_instance):
    instance, before = initialized(make_instance)
    vr = instance.vr[name]
    # The bad value last in a call that also sets a good one: the good one must not be applied either.
    status = call_set_real(instance, [instance.vr["theta[1]"], vr], [2.5, bad])
    assert status == 3
    assert instance.errors() == [
        f"fmi2SetReal: {name} = {bad:g} (vr[1] = {vr}) is not finite; no value set"]
    assert np.array_equal(instance.get(ALL), before)
    assert instance.call("fmi2DoStep", 0.0, 0.1, 1) == 0  # the instance goes on


@pytest.mark.parametrize("name", reference.OUTPUT_NAMES)
def test_output_cannot_be_set(name, make_instance):
    instance, before = initialized(make_instance)
    vr = instance.vr[name]
    assert call_set_real(instance, [vr], [1.0]) == 3
    assert instance.errors() == [
        f"fmi2SetReal: vr[0] = {vr} is {name}, an output: only inputs and parameters can be set; no value set"]
    assert np.array_equal(instance.get(ALL), before)


@pytest.mark.parametrize("function", ["fmi2SetReal", "fmi2GetReal"])
@pytest.mark.parametrize("vr", [71, 1000, 2**32 - 1])
def test_unknown_value_reference(function, vr, make_instance):
    instance, before = initialized(make_instance)
    vrs = (ctypes.c_uint * 2)(0, vr)
    values = (ctypes.c_double * 2)(7.0, 7.0)
    assert instance.call(function, vrs, 2, values) == 3
    assert instance.errors() == [
        f"{function}: vr[1] = {vr} is not a value reference of this FMU (0 to 70)"]
    if function == "fmi2GetReal":
        assert list(values) == [7.0, 7.0]  # nothing written either
    assert np.array_equal(instance.get(ALL), before)


@pytest.mark.parametrize("function", ["fmi2SetReal", "fmi2GetReal", "fmi2SetInteger", "fmi2GetInteger",
                                      "fmi2SetBoolean", "fmi2GetBoolean", "fmi2SetString",
                                      "fmi2GetString"])
@pytest.mark.parametrize("null", ["vr", "value"])
def test_null_arrays_with_nvr_above_zero(function, null, make_instance):
    instance, before = initialized(make_instance)
    vr = None if null == "vr" else (ctypes.c_uint * 1)(0)
    values = None if null == "value" else value_buffer(instance, function)
    assert instance.call(function, vr, 1, values) == 3
    assert instance.errors() == [f"{function}: {null} is NULL with nvr = 1"]
    assert np.array_equal(instance.get(ALL), before)
    assert instance.call(function, None, 0, None) == 0  # nothing to do is fine


@pytest.mark.parametrize("function,type_name", [("fmi2GetBoolean", "Boolean"), ("fmi2GetString", "String")])
def test_value_references_of_other_types_are_unknown(function, type_name, make_instance):
    instance, before = initialized(make_instance)
    vr = (ctypes.c_uint * 1)(0)
    values = value_buffer(instance, function)
    assert instance.call(function, vr, 1, values) == 3
    assert instance.errors() == [
        f"{function}: vr[0] = 0 is not a value reference of this FMU, which has no {type_name} variables"]
    assert np.array_equal(instance.get(ALL), before)


@pytest.mark.parametrize("function", ["fmi2SetInteger", "fmi2GetInteger"])
def test_real_variable_through_the_integer_functions(function, make_instance):
    instance, before = initialized(make_instance)
    vr = (ctypes.c_uint * 1)(0)
    values = value_buffer(instance, function)
    assert instance.call(function, vr, 1, values) == 3
    assert instance.errors() == [
        f"{function}: vr[0] = 0 is theta[1], of type Real, not Integer"]
    assert np.array_equal(instance.get(ALL), before)


def value_buffer(instance, function):
    """A zeroed buffer of one value, typed as the function's value argument."""
    return ctypes.cast(ctypes.create_string_buffer(64), instance.fmu._functions[function].argtypes[3])


def instantiate_raw(make_instance, name=b"raw", fmu_type=1, guid=None, callbacks=None):
    """Calls fmi2Instantiate directly, with a logger that captures the message."""
    helper = make_instance()
    fmu = helper.fmu
    guid = helper.model_description.guid.encode() if guid is None else guid
    if callbacks is None:
        callbacks = helper.callbacks
    count = len(helper.messages)
    component = fmu._functions["fmi2Instantiate"](name, fmu_type, guid, b"file:///nowhere",
                                                  ctypes.byref(callbacks), 0, 0)
    return fmu, component, helper.messages[count:]


@pytest.mark.parametrize("guid", [b"{00000000-0000-0000-0000-000000000000}", b"", None])
def test_wrong_guid(guid, make_instance):
    fmu, component, messages = instantiate_raw(make_instance, guid=guid if guid is not None else b"x")
    if guid is None:  # a NULL GUID
        fmu, component, messages = instantiate_raw(make_instance, guid=ctypes.c_char_p())
    assert component is None
    shown = "(null)" if guid is None else guid.decode()
    assert messages == [("Error", "logStatusError",
                         f'fmi2Instantiate: fmuGUID = "{shown}" does not match the GUID '
                         '"{c3391885-ba93-4824-bb36-df39703b63ee}" of this FMU\'s binary '
                         '(AngularKinematics)')]


@pytest.mark.parametrize("fmu_type", [2, -1])
def test_unknown_fmu_type_is_refused(fmu_type, make_instance):
    """Both fmi2ModelExchange (0) and fmi2CoSimulation (1) are accepted (test_model_exchange.py);
    anything else is not."""
    _, component, messages = instantiate_raw(make_instance, fmu_type=fmu_type)
    assert component is None
    assert messages == [("Error", "logStatusError",
                         f"fmi2Instantiate: fmuType = {fmu_type} is neither fmi2ModelExchange (0) "
                         "nor fmi2CoSimulation (1)")]


@pytest.mark.parametrize("name", [b"", None])
def test_missing_instance_name(name, make_instance):
    _, component, messages = instantiate_raw(make_instance, name=name)
    assert component is None
    assert messages[0][2] == "fmi2Instantiate: instanceName must be a non-empty string"


def test_missing_memory_functions(make_instance):
    helper = make_instance()
    callbacks = fmi2CallbackFunctions()
    callbacks.logger = helper.callbacks.logger
    _, component, messages = instantiate_raw(make_instance, callbacks=callbacks)
    assert component is None
    assert messages[0][2] == ("fmi2Instantiate: functions->allocateMemory and functions->freeMemory "
                              "must not be NULL")


def test_null_callbacks(make_instance):
    fmu = make_instance().fmu
    guid = fmu.guid.encode()
    assert fmu._functions["fmi2Instantiate"](b"x", 1, guid, b"", None, 0, 0) is None
