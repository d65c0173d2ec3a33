"""The co-simulation engines people use, from PyPI: libcosim (libcosimpy) and Ecos (ecospy) run every
FMU of dist/ in Co-Simulation with inputs driven at every step (examples/engines.py), and every
output must equal fmpy's run of the same scenario within TOLERANCE (0: bit for bit, both masters
set the inputs, step and read as fmpy's does); the engine table of docs/cosimulation.md must be
what python -m codegen writes there (codegen/engine_table.py). Installed by scripts/setup.sh
(requirements.txt) and scripts/setup_importers.sh (Debian's libtbb12 for Ecos); outside CI a missing engine skips, in CI
(CI=true) it fails."""
import importlib
import os
import pathlib

import numpy as np
import pytest

from codegen import engine_table, project
from examples import engines

ROOT = pathlib.Path(__file__).resolve().parents[2]

pytestmark = pytest.mark.external  # PyPI engines with native libraries (Ecos: Debian's libtbb12)
TOLERANCE = {"libcosim": 0.0, "Ecos": 0.0}  # largest |difference| from fmpy allowed
# What each engine says to an FMI 3.0 FMU: libcosim 0.0.6 refuses the FMI version; Ecos 0.7.2 loads
# it but has no fmu::theta[1]: it gives each array one scalar property (fmu::theta).
EXPECTED_FMI3 = {"libcosim": "not supported: Unsupported feature: Unsupported FMI version for FMU",
                 "Ecos": "not supported: No real property fmu::"}
FMI2 = [(model, fmu) for model, version, fmu in engine_table.fmus() if version == "2.0"]
FMI3 = [(model, fmu) for model, version, fmu in engine_table.fmus() if version == "3.0"]


def require(engine):
    try:
        importlib.import_module(engine_table.MODULES[engine])
    except (ImportError, OSError) as error:  # OSError: Ecos's libecosc.so without libtbb.so.12
        message = f"{engine} missing ({error}): run bash scripts/setup.sh and scripts/setup_importers.sh"
        if os.environ.get("CI") == "true":
            pytest.fail(message)
        pytest.skip(message)


def test_every_model_is_covered():
    assert {model for model, _ in FMI2} == set(project.MODELS)
    assert {model for model, _ in FMI3} == {model for model, _ in FMI2}


def test_the_scenario_drives_the_inputs():
    """Every input changes at every step, and fmpy's outputs follow them step by step."""
    _, _, inputs = engines.scenario(ROOT / "dist" / "AngularKinematics.fmu")
    assert inputs.shape == (engines.STEPS, 9) and np.all(np.diff(inputs, axis=0) != 0)
    _, outputs = engine_table.fmpy_run("AngularKinematics")
    assert np.all(np.any(np.diff(outputs, axis=0) != 0, axis=1))


@pytest.mark.parametrize("engine", list(engines.RUNNERS))
@pytest.mark.parametrize("model,fmu", FMI2, ids=[model for model, _ in FMI2])
def test_fmi2_engine_equals_fmpy(engine, model, fmu, report):
    require(engine)
    values, differing, largest = engine_table.compare(engine, model, fmu)
    report(f"{engine} {model}: {values} values, {differing} differ in any bit, largest {largest:.2g}")
    assert largest <= TOLERANCE[engine]


@pytest.mark.parametrize("engine", list(engines.RUNNERS))
@pytest.mark.parametrize("model,fmu", FMI3, ids=[model for model, _ in FMI3])
def test_fmi3_in_the_engines(engine, model, fmu, report):
    """What each engine does with the FMI 3.0 FMUs: the table says it (here it is checked)."""
    require(engine)
    cell = engine_table.cell(engine_table.compare, engine, model, fmu)
    report(f"{engine} {model} FMI 3.0: {cell}")
    assert cell.startswith(EXPECTED_FMI3[engine])


def test_a_wrong_output_is_caught(monkeypatch):
    """The comparison can fail: fmpy's reference with one value moved by one ulp."""
    require("libcosim")
    names, outputs = engine_table.fmpy_run("EulerRates")
    planted = outputs.copy()
    planted[50, 0] = np.nextafter(planted[50, 0], np.inf)
    monkeypatch.setattr(engine_table, "fmpy_run", lambda model: (names, planted))
    values, differing, largest = engine_table.compare("libcosim", "EulerRates",
                                                      ROOT / "dist" / "EulerRates.fmu")
    assert differing == 1 and largest > TOLERANCE["libcosim"]


def test_docs_table_is_current():
    for engine in engines.RUNNERS:
        require(engine)
    text = engine_table.DOC.read_text()
    assert engine_table.with_table(text, engine_table.table()) == text, \
        "regenerate: .venv/bin/python -m codegen"
