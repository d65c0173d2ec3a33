"""Bad input, for every model: every kind gets fmi2Error and one message that names the function,
the variable and the value, and the instance keeps its last valid values. The exact wording is the
C table's (tests/c/fmi2_bad_input_table.c and fmu_src/models/<Model>/tests/bad_input_rows.c, checked
in test_bad_input_table.py); where a case here is a row of it, the message must be that row's. Non-finite inputs, outputs set and unknown value
references run for both layers (`layer`: fmi3Error and the FMI 3 function's message too);
test_fmi3_bad_input.py has the FMI 3 layer's own cases."""
import ctypes
import math

import numpy as np
import pytest
from fmpy.fmi2 import fmi2CallbackFunctions

from conftest import bad_input_rows

NON_FINITE = [math.nan, math.inf, -math.inf]


def initialized(make_model_instance, model):
    instance = make_model_instance()
    instance.initialize(inputs=model.valid_inputs)
    return instance, instance.get(model.inputs + model.outputs)


def unchanged(instance, model, before):
    return np.array_equal(instance.get(model.inputs + model.outputs), before, equal_nan=True)


def the_one_error(instance):
    errors = instance.errors()
    assert len(errors) == 1, errors
    return errors[0]


def c_number(x):
    """A value as the C table's call texts write it."""
    return {math.inf: "INFINITY", -math.inf: "-INFINITY"}.get(x, "NAN" if math.isnan(x) else f"{x:g}")


def agrees_with_c_row(model, call, message):
    """False if the C table has a row for exactly this call and logs something else; True if it
    agrees or has no such row."""
    rows = [row["message"] for row in bad_input_rows(model.name) if row["call"] == call]
    return all(expected == message for expected in rows)


def call_set_real(instance, vrs, values):
    vr = (ctypes.c_uint * len(vrs))(*vrs)
    array = (ctypes.c_double * len(values))(*values)
    return instance.call("fmi2SetReal", vr, len(vrs), array)


@pytest.mark.parametrize("bad", NON_FINITE)
def test_non_finite_input_is_refused(bad, layer, model, new_instance):
    """Each input element in turn, in a set call that also sets a good value: refused with one
    error naming the function, the element and the value; the good value is not applied either,
    nothing changes, and the instance goes on (both layers)."""
    for index in range(len(model.inputs)):
        instance = layer.started(new_instance, model, "target")
        before = layer.values(instance)
        status, name, function = layer.set_one_bad_input(instance, index, bad)
        assert status == 3
        message = the_one_error(instance)
        assert message.startswith(f"{function}: "), message
        assert name in message and f"{bad:g}" in message, message
        if layer.version == 2:
            first, vr = instance.vr[model.inputs[0]], instance.vr[name]
            assert f"{name} = {bad:g} (vr[1] = {vr})" in message and "not finite" in message, message
            assert agrees_with_c_row(model, f"fmi2SetReal(c, {{{first}, {vr}}}, 2, "
                                            f"{{2.5, {c_number(bad)}}})", message)
        assert layer.values(instance) == before
        assert layer.step(instance, 0.25, 0.1) == (0, 0.35)  # the instance goes on
        instance.free()


def test_output_cannot_be_set(layer, model, new_instance):
    """Each output in turn: refused with one error naming it as an output, nothing changes, the
    instance goes on (both layers)."""
    names = layer.output_names(layer.started(new_instance, model, "names"))
    for name in names:
        instance = layer.started(new_instance, model, "target")
        before = layer.values(instance)
        vr = instance.vr[name]
        status, _, function = layer.real_call(instance, "Set", [vr], layer.size_of(instance, name),
                                              1.0)
        assert status == 3
        message = the_one_error(instance)
        assert message.startswith(f"{function}: "), message
        assert f"[0] = {vr} is {name}, an output" in message, message
        if layer.version == 2:
            assert f"vr[0] = {vr} is {name}, an output" in message, message
            assert agrees_with_c_row(model, f"fmi2SetReal(c, {{{vr}}}, 1, {{1}})", message)
        assert layer.values(instance) == before
        assert layer.step(instance, 0.25, 0.1) == (0, 0.35)
        instance.free()


@pytest.mark.parametrize("function", ["Set", "Get"])
@pytest.mark.parametrize("beyond", [1, 1000, 2**32 - 1])
def test_unknown_value_reference(function, beyond, layer, model, new_instance):
    """A value reference past the model's last, beside a good one (FMI 2: 0, FMI 3: the first
    input array): refused with one error naming it, nothing written or changed (both layers)."""
    instance = layer.started(new_instance, model, "target")
    before = layer.values(instance)
    vr = min(model.largest_vr + beyond, 2**32 - 1)
    n_values = 2 if layer.version == 2 else layer.size_of(instance, layer.input_names(instance)[0]) + 1
    status, values, name = layer.real_call(instance, function, [0, vr], n_values)
    assert status == 3
    message = the_one_error(instance)
    assert message.startswith(f"{name}: "), message
    assert f"[1] = {vr} is not a value reference" in message, message
    if layer.version == 2:
        assert message.startswith(f"{name}: vr[1] = {vr} is not a value reference"), message
        assert f"(0 to {model.largest_vr})" in message, message
        assert agrees_with_c_row(model, f"{name}(c, {{0, {vr}}}, 2, {{7, 7}})", message)
    if function == "Get":
        assert values == [7.0] * n_values  # nothing written either
    assert layer.values(instance) == before


@pytest.mark.parametrize("function", ["fmi2SetReal", "fmi2GetReal", "fmi2SetInteger", "fmi2GetInteger",
                                      "fmi2SetBoolean", "fmi2GetBoolean", "fmi2SetString",
                                      "fmi2GetString"])
@pytest.mark.parametrize("null", ["vr", "value"])
def test_null_arrays_with_nvr_above_zero(function, null, model, make_model_instance):
    instance, before = initialized(make_model_instance, model)
    vr = None if null == "vr" else (ctypes.c_uint * 1)(0)
    values = None if null == "value" else value_buffer(instance, function)
    assert instance.call(function, vr, 1, values) == 3
    message = the_one_error(instance)
    assert message.startswith(f"{function}: {null} is NULL") and "nvr = 1" in message, message
    assert unchanged(instance, model, before)
    assert instance.call(function, None, 0, None) == 0  # nothing to do is fine


@pytest.mark.parametrize("function,type_name", [("fmi2GetBoolean", "Boolean"), ("fmi2GetString", "String")])
def test_value_references_of_other_types_are_unknown(function, type_name, model, make_model_instance):
    instance, before = initialized(make_model_instance, model)
    vr = (ctypes.c_uint * 1)(0)
    values = value_buffer(instance, function)
    assert instance.call(function, vr, 1, values) == 3
    message = the_one_error(instance)
    assert message.startswith(f"{function}: vr[0] = 0 is not a value reference"), message
    assert f"no {type_name} variables" in message, message
    assert agrees_with_c_row(model, f"{function}(c, {{0}}, 1, v)", message)
    assert unchanged(instance, model, before)


@pytest.mark.parametrize("function", ["fmi2SetInteger", "fmi2GetInteger"])
def test_real_variable_through_the_integer_functions(function, model, make_model_instance):
    instance, before = initialized(make_model_instance, model)
    vr = (ctypes.c_uint * 1)(0)
    values = value_buffer(instance, function)
    assert instance.call(function, vr, 1, values) == 3
    message = the_one_error(instance)
    assert message.startswith(f"{function}: vr[0] = 0 is {model.inputs[0]}"), message
    assert "Real, not Integer" in message, message
    assert agrees_with_c_row(model, f"{function}(c, {{0}}, 1, v)", message)
    assert unchanged(instance, model, before)


def value_buffer(instance, function):
    """A zeroed buffer of one value, typed as the function's value argument."""
    return ctypes.cast(ctypes.create_string_buffer(64), instance.fmu._functions[function].argtypes[3])


def instantiate_raw(make_model_instance, name=b"raw", fmu_type=1, guid=None, callbacks=None):
    """Calls fmi2Instantiate directly, with a logger that captures the message."""
    helper = make_model_instance()
    fmu = helper.fmu
    guid = helper.model_description.guid.encode() if guid is None else guid
    if callbacks is None:
        callbacks = helper.callbacks
    count = len(helper.messages)
    component = fmu._functions["fmi2Instantiate"](name, fmu_type, guid, b"file:///nowhere",
                                                  ctypes.byref(callbacks), 0, 0)
    return fmu, component, helper.messages[count:]


# The C rows (tests/c/fmi2_bad_input_table.c) of the same calls.
GUID_ROWS = {b"{00000000-0000-0000-0000-000000000000}":
             'fmi2Instantiate("i", fmi2CoSimulation, "{00000000-0000-0000-0000-000000000000}", ...)',
             None: 'fmi2Instantiate("i", fmi2CoSimulation, NULL, ...)'}
NAME_ROWS = {b"": 'fmi2Instantiate("", fmi2CoSimulation, GUID, ...)',
             None: "fmi2Instantiate(NULL, fmi2CoSimulation, GUID, ...)"}


@pytest.mark.parametrize("guid", [b"{00000000-0000-0000-0000-000000000000}", b"", None])
def test_wrong_guid(guid, model, make_model_instance):
    fmu, component, messages = instantiate_raw(make_model_instance,
                                               guid=guid if guid is not None else ctypes.c_char_p())
    assert component is None
    assert [(status, category) for status, category, _ in messages] == [("Error", "logStatusError")]
    message = messages[0][2]
    shown = "(null)" if guid is None else guid.decode()
    assert message.startswith(f'fmi2Instantiate: fmuGUID = "{shown}" does not match'), message
    assert model.description.guid in message and model.name in message, message
    if guid in GUID_ROWS:
        assert agrees_with_c_row(model, GUID_ROWS[guid], message)


@pytest.mark.parametrize("fmu_type", [2, 7, -1])
def test_unknown_fmu_type_is_refused(fmu_type, model, make_model_instance):
    """Both fmi2ModelExchange (0) and fmi2CoSimulation (1) are accepted (test_model_exchange.py);
    anything else is not."""
    _, component, messages = instantiate_raw(make_model_instance, fmu_type=fmu_type)
    assert component is None
    assert [(status, category) for status, category, _ in messages] == [("Error", "logStatusError")]
    message = messages[0][2]
    assert message.startswith(f"fmi2Instantiate: fmuType = {fmu_type} is neither"), message
    assert agrees_with_c_row(model, f'fmi2Instantiate("i", {fmu_type}, GUID, ...)', message)


@pytest.mark.parametrize("name", [b"", None])
def test_missing_instance_name(name, model, make_model_instance):
    _, component, messages = instantiate_raw(make_model_instance, name=name)
    assert component is None
    message = messages[0][2]
    assert message.startswith("fmi2Instantiate: instanceName"), message
    assert agrees_with_c_row(model, NAME_ROWS[name], message)


def test_missing_memory_functions(model, make_model_instance):
    helper = make_model_instance()
    callbacks = fmi2CallbackFunctions()
    callbacks.logger = helper.callbacks.logger
    _, component, messages = instantiate_raw(make_model_instance, callbacks=callbacks)
    assert component is None
    message = messages[0][2]
    assert message.startswith("fmi2Instantiate: functions->allocateMemory"), message
    assert agrees_with_c_row(
        model, 'fmi2Instantiate("i", ..., functions without allocateMemory and freeMemory, ...)',
        message)


def test_null_callbacks(make_model_instance):
    fmu = make_model_instance().fmu
    guid = fmu.guid.encode()
    assert fmu._functions["fmi2Instantiate"](b"x", 1, guid, b"", None, 0, 0) is None


def test_the_c_rows_these_tests_compare_with_exist(model):
    """Rows every model's C table has (tests/c/fmi2_bad_input_table.c): without them the
    comparisons above would compare with nothing."""
    calls = {row["call"] for row in bad_input_rows(model.name)}
    named = [*GUID_ROWS.values(), *NAME_ROWS.values(), 'fmi2Instantiate("i", 7, GUID, ...)',
             'fmi2Instantiate("i", ..., functions without allocateMemory and freeMemory, ...)',
             "fmi2GetBoolean(c, {0}, 1, v)", "fmi2GetString(c, {0}, 1, v)"]
    assert [call for call in named if call not in calls] == []
