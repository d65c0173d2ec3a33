"""The C bad-input tables (tests/c/fmi2_bad_input_table.c and each model's
fmu_src/models/<Model>/tests/bad_input_rows.c) are the one authority for every bad-input message. Their driver (build/test_fmi2_calls_<Model>) makes every call of its table, checks
status, message, unchanged instance and memory, and prints the rows as it observed them:
docs/bad_input.md must show exactly those rows (scripts/update_bad_input_table.sh writes them), and
the packaged FMU, driven through fmpy, must answer each value row the same way."""
import ctypes
import math
import re

import numpy as np

from conftest import bad_input_rows, project

STATUS_CODE = {"fmi2Discard": 2, "fmi2Error": 3}
# The states fmpy reaches here as the C driver does (docs/bad_input.md: inputs set, startTime 0,
# stopTime 10; StepComplete after a step from 0 to 1; EventMode just out of initialization).
REPLAYED_STATES = {"Instantiated", "InitializationMode", "StepComplete", "Terminated", "EventMode"}
VALUE_CALL = re.compile(r"(fmi2(?:Set|Get)(?:Real|Integer|Boolean|String))"
                        r"\(c, (NULL|\{[^}]*\}), (\d+), (NULL|v|\{[^}]*\})\)")
C_LITERALS = {"NAN": math.nan, "INFINITY": math.inf, "-INFINITY": -math.inf,
              "fmi2True": 1, "fmi2False": 0}


def table_in_document(root, model):
    text = (root / "docs" / "bad_input.md").read_text()
    start = text.index(f"<!-- bad-input table {model}: begin")
    block = text[text.index("\n", start) + 1:text.index(f"<!-- bad-input table {model}: end -->")]
    return [line for line in block.splitlines() if line.strip()]


def table_observed(model):
    return ["| State | Call | Status | Message logged |", "|---|---|---|---|"] + [
        row["line"] for row in bad_input_rows(model)]


def test_the_document_has_a_table_for_every_model_and_no_other(root):
    """Every model of codegen.project.MODELS has its C driver and table, in that order."""
    text = (root / "docs" / "bad_input.md").read_text()
    assert re.findall(r"<!-- bad-input table (\w+): begin", text) == list(project.MODELS)


def test_document_shows_the_observed_table(root, report, model):
    documented = table_in_document(root, model.name)
    observed = table_observed(model.name)
    missing = [row for row in observed if row not in documented]
    stale = [row for row in documented if row not in observed]
    assert not missing and not stale, (
        "docs/bad_input.md differs from what the FMU does; regenerate its table with "
        "scripts/update_bad_input_table.sh\nnot in the document:\n" + "\n".join(missing) +
        "\nnot what the FMU does:\n" + "\n".join(stale))
    assert documented == observed  # same order too
    rows = observed[2:]  # without header and rule
    assert len(rows) == len(set(rows))
    report(f"{len(rows)} rows of docs/bad_input.md ({model.name}) proved by the C driver")


def test_every_row_has_status_and_message_columns(model):
    for row in bad_input_rows(model.name):
        assert row["status"] in {"NULL", "fmi2Error", "fmi2Discard"}, row["line"]
        assert row["message"] is None or row["message"].startswith(
            ("fmi2", "<function>", model.name)), row["line"]


def value_rows(model):
    return [row for row in bad_input_rows(model) if row["state"] in REPLAYED_STATES
            and VALUE_CALL.fullmatch(row["call"])]


def c_array(text, ctype, count):
    """The C argument text as a ctypes array: NULL, v (a zeroed buffer) or {a, b, ...}."""
    if text == "NULL":
        return None
    if text == "v":
        return (ctype * count)()
    items = [item.strip() for item in text.strip("{}").split(",")]
    if ctype is ctypes.c_char_p:
        return (ctype * len(items))(*[item.strip('"').encode() for item in items])
    numbers = [C_LITERALS[item] if item in C_LITERALS else float(item) for item in items]
    if ctype is not ctypes.c_double:
        numbers = [int(number) for number in numbers]
    return (ctype * len(items))(*numbers)


def brought_to(state, make_model_instance, model):
    interface = "ModelExchange" if state == "EventMode" else "CoSimulation"
    instance = make_model_instance(fmi_type=interface)
    if state == "Instantiated":
        return instance
    instance.fmu.setupExperiment(startTime=0.0, stopTime=10.0)
    instance.fmu.enterInitializationMode()
    assert instance.set(model.valid_inputs) == 0
    if state == "InitializationMode":
        return instance
    instance.fmu.exitInitializationMode()
    if state != "EventMode":
        assert instance.call("fmi2DoStep", 0.0, 1.0, 1) == 0
    if state == "Terminated":
        instance.fmu.terminate()
    return instance


def replay(expected, make_model_instance, model):
    """Makes the row's call on a fresh instance; returns what differs from the row (or [])."""
    function, vr, nvr, values = VALUE_CALL.fullmatch(expected["call"]).groups()
    instance = brought_to(expected["state"], make_model_instance, model)
    names = model.inputs + model.outputs
    before = instance.get(names) if expected["state"] == "StepComplete" else None
    ctype = {"Real": ctypes.c_double, "Integer": ctypes.c_int, "Boolean": ctypes.c_int,
             "String": ctypes.c_char_p}[function[len("fmi2Set"):]]
    status = instance.call(function, c_array(vr, ctypes.c_uint, int(nvr)), int(nvr),
                           c_array(values, ctype, int(nvr)))
    logged = [message for _, _, message in instance.messages]
    differences = []
    if status != STATUS_CODE[expected["status"]]:
        differences.append(f"status {status}")
    if logged != [expected["message"]]:
        differences.append(f"logged {logged}")
    if before is not None and not np.array_equal(instance.get(names), before):
        differences.append("values changed")
    instance.free()
    return differences


def test_value_rows_through_fmpy(model, make_model_instance, report):
    """Each row of the C table that sets or gets values, replayed on the packaged FMU through
    fmpy: same status, same message, nothing changed."""
    rows = value_rows(model.name)
    assert len(rows) >= 10  # the parser still understands the table
    failed = {row["line"]: differences for row in rows
              if (differences := replay(row, make_model_instance, model))}
    assert not failed, failed
    report(f"{len(rows)} value rows of the C table ({model.name}) replayed through fmpy")
