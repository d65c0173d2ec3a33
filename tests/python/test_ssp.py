"""The SSP 1.0 system examples/ssp/ (RoundTrip.ssp): its archive, its .ssd against the SSP 1.0
schema that fmpy ships, the round trip theta_dot, theta_ddot -> AngularKinematics -> EulerRates
-> theta_dot, theta_ddot through fmpy's SSP master to 1e-10, and the picture in docs/."""
import os
import pathlib
import subprocess
import sys
import zipfile

import fmpy
import numpy as np
import pytest
from lxml import etree

from examples.ssp import round_trip, ssd_to_svg
from examples.ssp.make_ssp import make_ssp

ROOT = pathlib.Path(__file__).resolve().parents[2]

SCHEMA = pathlib.Path(fmpy.__file__).parent / "ssp" / "schema" / "SystemStructureDescription.xsd"


@pytest.fixture(scope="module")
def ssp(tmp_path_factory, fmu_path, euler_fmu_path):
    return make_ssp(ROOT / "dist", tmp_path_factory.mktemp("ssp") / "RoundTrip.ssp")


def test_archive_holds_the_ssd_and_the_built_fmus(ssp):
    with zipfile.ZipFile(ssp) as archive:
        assert sorted(archive.namelist()) == ["SystemStructure.ssd", "resources/AngularKinematics.fmu",
                                              "resources/EulerRates.fmu"]
        for model in ("AngularKinematics", "EulerRates"):
            assert archive.read(f"resources/{model}.fmu") == (ROOT / "dist" / f"{model}.fmu").read_bytes()


def test_ssd_validates_against_the_ssp_1_0_schema(ssp):
    schema = etree.XMLSchema(file=str(SCHEMA))
    with zipfile.ZipFile(ssp) as archive:
        ssd = etree.fromstring(archive.read("SystemStructure.ssd"))
    assert ssd.get("version") == "1.0"
    assert schema.validate(ssd), schema.error_log
    # The schema does reject a broken description: a connection without its end connector.
    connection = ssd.find(".//{*}Connection")
    del connection.attrib["endConnector"]
    assert not schema.validate(ssd)


def test_round_trip_recovers_the_rates(ssp, report):
    result, rows, errors = round_trip.run(ssp)
    away = result["singularity_distance"][rows] >= 0.1
    for name, error in errors.items():
        report(f"{name}: largest relative error {error[away].max():.2e} over {away.sum()} rows "
               f"with singularity_distance >= 0.1 ({error[~away].max():.2e} over the other "
               f"{(~away).sum()})")
        assert away.sum() > 100
        assert error[away].max() <= 1e-10
    # The comparison is sensitive: the truth of one sample later is far from what came back.
    later = np.column_stack([result[f"theta_dot[{i}]"][rows] for i in (1, 2, 3)])
    recovered = np.column_stack([result[f"theta_dot_recovered[{i}]"][rows] for i in (1, 2, 3)])
    assert np.max(np.linalg.norm(recovered - later, axis=1) / np.linalg.norm(later, axis=1)) > 1e-3


def test_the_one_command_passes(ssp):
    done = subprocess.run([sys.executable, str(ROOT / "examples" / "ssp" / "round_trip.py"),
                           "--ssp", str(ssp)], capture_output=True, text=True, timeout=300,
                          cwd=ROOT, env={**os.environ, "MPLBACKEND": "Agg"})
    assert done.returncode == 0, done.stdout + done.stderr
    assert "PASSED at 1e-10" in done.stdout


def test_docs_picture_is_drawn_from_this_ssd(ssp):
    with zipfile.ZipFile(ssp) as archive:
        drawn = ssd_to_svg.svg(archive.read("SystemStructure.ssd"))
    assert (ROOT / "docs" / "round_trip_ssp.svg").read_text() == drawn, \
        "regenerate: .venv/bin/python -m codegen"
    assert drawn.count("<path d=\"M") - 1 == 9  # 9 vector connections (arrow head aside)
