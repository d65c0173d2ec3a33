"""Tumbling.ssp (examples/ssp/make_tumbling_ssp.py), the SSP system fmpy, libcosim and Ecos all run:
self-contained (AttitudePropagator drives the other two), components and connections only, with
OMSimulator's vendor annotation, schema-valid; each engine's outputs equal fmpy's bit for bit on
the rows examples/ssp/engines.py's compare lines up (the masters' differences: docs/cosimulation.md)."""
import zipfile

import numpy as np
import pytest
from lxml import etree

from examples.ssp import engines as ssp_engines
from examples.ssp import make_tumbling_ssp
from test_engines import ROOT, engine_table, require
from test_ssp import SCHEMA as SCHEMA_FILE

pytestmark = pytest.mark.external  # the PyPI engines, as test_engines.py
SCHEMA = etree.XMLSchema(file=str(SCHEMA_FILE))


def ssd():
    with zipfile.ZipFile(engine_table.tumbling_ssp()) as archive:
        return etree.fromstring(archive.read("SystemStructure.ssd")), sorted(archive.namelist())


def test_the_system_is_component_only_schema_valid_and_self_contained():
    root, names = ssd()
    assert SCHEMA.validate(root), SCHEMA.error_log
    assert names == ["SystemStructure.ssd", "resources/AngularKinematics.fmu",
                     "resources/AttitudePropagator.fmu", "resources/EulerRates.fmu",
                     "resources/PointKinematics.fmu"]
    system = root.find("{*}System")
    assert system.find("{*}Connectors") is None  # no connector of the system's own
    for connection in system.iter("{*}Connection"):
        assert connection.get("startElement") and connection.get("endElement")
    stop = float(root.find("{*}DefaultExperiment").get("stopTime"))
    assert stop == ssp_engines.STEPS * ssp_engines.STEP  # the scenario the engines run
    annotation = system.find("{*}Annotations/{*}Annotation")
    assert annotation.get("type") == "org.openmodelica"
    assert annotation.find(".//{*}SimulationInformation/{*}FixedStepMaster") is not None
    # The schema does reject a broken system: a connection without its end connector.
    del system.find(".//{*}Connection").attrib["endConnector"]
    assert not SCHEMA.validate(root)


def test_the_propagator_drives_the_others(report):
    """In fmpy's run the inputs of AngularKinematics change at every step, and it recovers the
    propagator's omega_fixed of the step before (the Jacobi master's one-step delay)."""
    run = engine_table.fmpy_ssp_run()
    theta = np.column_stack([run[f"propagator.theta[{i}]"] for i in (1, 2, 3)])
    assert np.all(np.any(np.diff(theta, axis=0) != 0, axis=1))
    recovered = np.column_stack([run[f"kinematics.omega_fixed[{i}]"][1:] for i in (1, 2, 3)])
    truth = np.column_stack([run[f"propagator.omega_fixed[{i}]"][:-1] for i in (1, 2, 3)])
    error = float(np.max(np.abs(recovered - truth)))
    report(f"AngularKinematics recovers the propagator's omega_fixed to {error:.2g} rad/s")
    assert error <= 1e-14 and np.max(np.abs(truth)) >= 0.3


def test_the_accelerometer_reads_the_centripetal_acceleration_of_the_tumbling_body(report):
    """A held omega is a steady rotation (alpha 0): at the lever arm r the accelerometer reads
    omega (omega . r) - r |omega|^2, the closed form, from the first row fmpy hands over on."""
    run = engine_table.fmpy_ssp_run()
    omega, r = np.array(make_tumbling_ssp.OMEGA), np.array(make_tumbling_ssp.LEVER_ARM)
    expected = omega * (omega @ r) - r * (omega @ omega)
    reading = np.column_stack([run[f"accelerometer.specific_force[{i}]"] for i in (1, 2, 3)])
    error = float(np.max(np.abs(reading[ssp_engines.START:] - expected)))
    report(f"Tumbling.ssp: the accelerometer reads {np.round(expected, 3).tolist()} m/s2 within "
           f"{error:.2g}")
    assert error <= 1e-15 and np.max(np.abs(expected)) > 0.1


@pytest.mark.parametrize("engine", ["libcosim", "Ecos"])
def test_the_engine_runs_the_ssp_as_fmpy(engine, report):
    require(engine)
    values, differing, largest = engine_table.compare_ssp(engine)
    report(f"{engine} Tumbling.ssp: {values} values, {differing} differ in any bit")
    assert values == len(ssp_engines.outputs()) * (ssp_engines.STEPS - ssp_engines.START)
    assert largest == 0


def test_a_wrong_ssp_output_is_caught():
    reference = {name: column.copy() for name, column in engine_table.fmpy_ssp_run().items()}
    reference["rates.theta_dot[2]"][60] = np.nextafter(reference["rates.theta_dot[2]"][60], 0)
    values = engine_table.fmpy_ssp_run()
    assert ssp_engines.compare("fmpy", values, reference)[1] == 1


@pytest.mark.parametrize("engine,message", [("libcosim", "Unable to create execution"),
                                            ("Ecos", "No element named")])
def test_the_engines_refuse_round_trip_ssp(engine, message, tmp_path):
    """Why Tumbling.ssp exists: RoundTrip.ssp connects the system's own connectors."""
    require(engine)
    from examples.ssp.make_ssp import make_ssp
    with pytest.raises(Exception, match=message):
        ssp_engines.RUNNERS[engine](make_ssp(ROOT / "dist", tmp_path / "RoundTrip.ssp"))
