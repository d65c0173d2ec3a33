"""The value references of release 0.2 are what users have saved (in SSP files, scripts, recorded
results): every variable of the published 0.2 FMUs keeps its name, value reference, causality and
type, in the modelDescription.xml files and in the C tables the binaries are built from, and a
variable added since takes a value reference that 0.2 did not use.

RELEASED is a pin, typed once from release 0.2 (commit 3285c84: modelDescription.xml and
models/EulerRates/modelDescription.xml); it must never be regenerated from the current sources."""
import xml.etree.ElementTree as ET

import pytest

from codegen import models
from conftest import c_table_of

# model: (name, value reference, causality, type as in <ScalarVariable>)
RELEASED = {
    "AngularKinematics": [
        ("theta[1]", 0, "input", "Real"), ("theta[2]", 1, "input", "Real"),
        ("theta[3]", 2, "input", "Real"), ("theta_dot[1]", 3, "input", "Real"),
        ("theta_dot[2]", 4, "input", "Real"), ("theta_dot[3]", 5, "input", "Real"),
        ("theta_ddot[1]", 6, "input", "Real"), ("theta_ddot[2]", 7, "input", "Real"),
        ("theta_ddot[3]", 8, "input", "Real"), ("omega_fixed[1]", 9, "output", "Real"),
        ("omega_fixed[2]", 10, "output", "Real"), ("omega_fixed[3]", 11, "output", "Real"),
        ("omega_body[1]", 12, "output", "Real"), ("omega_body[2]", 13, "output", "Real"),
        ("omega_body[3]", 14, "output", "Real"), ("alpha_fixed[1]", 15, "output", "Real"),
        ("alpha_fixed[2]", 16, "output", "Real"), ("alpha_fixed[3]", 17, "output", "Real"),
        ("alpha_body[1]", 18, "output", "Real"), ("alpha_body[2]", 19, "output", "Real"),
        ("alpha_body[3]", 20, "output", "Real"), ("R[1,1]", 21, "output", "Real"),
        ("R[1,2]", 22, "output", "Real"), ("R[1,3]", 23, "output", "Real"),
        ("R[2,1]", 24, "output", "Real"), ("R[2,2]", 25, "output", "Real"),
        ("R[2,3]", 26, "output", "Real"), ("R[3,1]", 27, "output", "Real"),
        ("R[3,2]", 28, "output", "Real"), ("R[3,3]", 29, "output", "Real"),
        ("q[1]", 30, "output", "Real"), ("q[2]", 31, "output", "Real"), ("q[3]", 32, "output", "Real"),
        ("q[4]", 33, "output", "Real"), ("W_fixed[1,1]", 34, "output", "Real"),
        ("W_fixed[1,2]", 35, "output", "Real"), ("W_fixed[1,3]", 36, "output", "Real"),
        ("W_fixed[2,1]", 37, "output", "Real"), ("W_fixed[2,2]", 38, "output", "Real"),
        ("W_fixed[2,3]", 39, "output", "Real"), ("W_fixed[3,1]", 40, "output", "Real"),
        ("W_fixed[3,2]", 41, "output", "Real"), ("W_fixed[3,3]", 42, "output", "Real"),
        ("W_body[1,1]", 43, "output", "Real"), ("W_body[1,2]", 44, "output", "Real"),
        ("W_body[1,3]", 45, "output", "Real"), ("W_body[2,1]", 46, "output", "Real"),
        ("W_body[2,2]", 47, "output", "Real"), ("W_body[2,3]", 48, "output", "Real"),
        ("W_body[3,1]", 49, "output", "Real"), ("W_body[3,2]", 50, "output", "Real"),
        ("W_body[3,3]", 51, "output", "Real"), ("W_fixed_dot[1,1]", 52, "output", "Real"),
        ("W_fixed_dot[1,2]", 53, "output", "Real"), ("W_fixed_dot[1,3]", 54, "output", "Real"),
        ("W_fixed_dot[2,1]", 55, "output", "Real"), ("W_fixed_dot[2,2]", 56, "output", "Real"),
        ("W_fixed_dot[2,3]", 57, "output", "Real"), ("W_fixed_dot[3,1]", 58, "output", "Real"),
        ("W_fixed_dot[3,2]", 59, "output", "Real"), ("W_fixed_dot[3,3]", 60, "output", "Real"),
        ("W_body_dot[1,1]", 61, "output", "Real"), ("W_body_dot[1,2]", 62, "output", "Real"),
        ("W_body_dot[1,3]", 63, "output", "Real"), ("W_body_dot[2,1]", 64, "output", "Real"),
        ("W_body_dot[2,2]", 65, "output", "Real"), ("W_body_dot[2,3]", 66, "output", "Real"),
        ("W_body_dot[3,1]", 67, "output", "Real"), ("W_body_dot[3,2]", 68, "output", "Real"),
        ("W_body_dot[3,3]", 69, "output", "Real"), ("sequence", 70, "parameter", "Enumeration"),
    ],
    "EulerRates": [
        ("theta[1]", 0, "input", "Real"), ("theta[2]", 1, "input", "Real"),
        ("theta[3]", 2, "input", "Real"), ("omega[1]", 3, "input", "Real"),
        ("omega[2]", 4, "input", "Real"), ("omega[3]", 5, "input", "Real"),
        ("omega_dot[1]", 6, "input", "Real"), ("omega_dot[2]", 7, "input", "Real"),
        ("omega_dot[3]", 8, "input", "Real"), ("theta_dot[1]", 9, "output", "Real"),
        ("theta_dot[2]", 10, "output", "Real"), ("theta_dot[3]", 11, "output", "Real"),
        ("theta_ddot[1]", 12, "output", "Real"), ("theta_ddot[2]", 13, "output", "Real"),
        ("theta_ddot[3]", 14, "output", "Real"), ("alpha_fixed[1]", 15, "output", "Real"),
        ("alpha_fixed[2]", 16, "output", "Real"), ("alpha_fixed[3]", 17, "output", "Real"),
        ("alpha_body[1]", 18, "output", "Real"), ("alpha_body[2]", 19, "output", "Real"),
        ("alpha_body[3]", 20, "output", "Real"), ("singularity_distance", 21, "output", "Real"),
        ("sequence", 22, "parameter", "Enumeration"), ("frame", 23, "parameter", "Enumeration"),
        ("tolerance", 24, "parameter", "Real"),
    ],
}
# The C tables store an Enumeration as an Integer (set and got through fmi2SetInteger/GetInteger).
C_TYPE = {"Enumeration": "Integer"}


def described(model):
    """(name, vr, causality, type) of each <ScalarVariable> of the model's modelDescription.xml."""
    root = ET.parse(models.load(model).model_description).getroot()
    return [(v.get("name"), int(v.get("valueReference")), v.get("causality"), v[0].tag)
            for v in root.iter("ScalarVariable")]


def in_c_table(model):
    return [(v["name"], v["valueReference"], v["causality"], v["type"])
            for v in c_table_of(model)["variables"]]


def released_in_c(model):
    return [(name, vr, causality, C_TYPE.get(kind, kind))
            for name, vr, causality, kind in RELEASED[model]]


def test_the_pin_covers_every_model_of_release_0_2():
    assert set(RELEASED) == {"AngularKinematics", "EulerRates"}
    for rows in RELEASED.values():
        assert len({vr for _, vr, _, _ in rows}) == len(rows)
        assert len({name for name, _, _, _ in rows}) == len(rows)


@pytest.mark.parametrize("model", RELEASED)
def test_model_description_keeps_every_released_variable(model):
    now = described(model)
    lost = [row for row in RELEASED[model] if row not in now]
    assert not lost, f"{model}: changed or removed since 0.2: {lost}"


@pytest.mark.parametrize("model", RELEASED)
def test_c_table_keeps_every_released_variable(model):
    now = in_c_table(model)
    lost = [row for row in released_in_c(model) if row not in now]
    assert not lost, f"{model}: the C table changed or removed since 0.2: {lost}"


@pytest.mark.parametrize("source", [described, in_c_table])
@pytest.mark.parametrize("model", RELEASED)
def test_new_variables_take_value_references_unused_in_0_2(model, source):
    released_names = {name for name, _, _, _ in RELEASED[model]}
    released_vrs = {vr for _, vr, _, _ in RELEASED[model]}
    added = [(name, vr) for name, vr, _, _ in source(model) if name not in released_names]
    reused = [(name, vr) for name, vr in added if vr in released_vrs]
    assert not reused, f"{model}: new variables on value references of 0.2: {reused}"
