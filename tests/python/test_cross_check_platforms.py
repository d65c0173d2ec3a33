"""The cross-check master in C (the cross-check mode of tools/fmu_driver.c and tools/fmi3_driver.c,
tools/*_cross_check.c), which computes the results of dist/cross-check/'s folders whose binary
fmpy cannot load here (Windows under wine, aarch64-linux under qemu: scripts/cross_check_platforms.py).
On the x86_64-linux binary it must print what fmpy's master (examples/cross_check.py,
cross_check3.py) computes, bit for bit, for every model, FMI version and interface: then what it
prints with another platform's binary is what the cross-check master would compute with it. The
x86 code, which has no 32-bit wine here, computes that result too (the x86 proof build)."""
import pathlib

import numpy as np
import pytest

from codegen import project
from scripts.cross_check_platforms import HOST, RUNNERS, Runner, origin, runnable
from scripts.make_cross_check import reference_run

ROOT = pathlib.Path(__file__).resolve().parents[2]
FMUS = {"2.0": ROOT / "dist", "3.0": ROOT / "dist" / "fmi3"}


@pytest.mark.parametrize("interface", ["cs", "me"])
@pytest.mark.parametrize("version", sorted(FMUS))
@pytest.mark.parametrize("model", project.MODELS)
def test_c_master_prints_fmpys_result(model, version, interface, report):
    fmu = FMUS[version] / f"{model}.fmu"
    assert runnable(HOST[version], version), "build/fmu_driver or build/fmi3_driver is missing"
    names, fmpy_result = reference_run(fmu, interface)[3]
    c_names, c_result = reference_run(fmu, interface, platform=HOST[version])[3]
    assert c_names == names
    assert fmpy_result.shape == c_result.shape == (401, len(names))
    # Some outputs change in time (a master that skipped steps would not print the same).
    assert (np.ptp(fmpy_result[:, 1:], axis=0) > 0).all()
    differ = np.count_nonzero(fmpy_result.view(np.uint64) != c_result.view(np.uint64))
    assert differ == 0, f"{differ} of {c_result.size} values differ from fmpy's"
    report(f"{model} FMI {version} {interface}: {c_result.size} values bit for bit fmpy's")


def test_a_row_runs_only_with_its_launcher_and_driver(monkeypatch):
    """A row of RUNNERS whose launcher is not installed or whose driver is not built is not run:
    its folder gets the host's result (make_cross_check says so in its README); with both it is."""
    monkeypatch.setitem(RUNNERS, "riscv64-linux", Runner("build", launcher=("no-such-emulator",)))
    assert origin("riscv64-linux", "3.0") == "copied"
    monkeypatch.setitem(RUNNERS, "riscv64-linux", Runner("no-such-build"))
    assert origin("riscv64-linux", "3.0") == "copied"
    monkeypatch.setitem(RUNNERS, "riscv64-linux", Runner("build"))  # natively, build/'s driver
    assert origin("riscv64-linux", "3.0") == "own"
    assert origin("x86_64-darwin", "3.0") == "copied" and origin("x86_64-linux", "3.0") == "host"


@pytest.mark.external  # the x86 proof build (build-x86-musl)
@pytest.mark.parametrize("interface", ["cs", "me"])
@pytest.mark.parametrize("version", sorted(FMUS))
@pytest.mark.parametrize("model", project.MODELS)
def test_x86_code_computes_the_host_result(model, version, interface, report):
    """The x86-windows (win32) binaries do not run here, no 32-bit wine: their folders hold the
    host's result. The same sources with their x86 flags, linked into static x86 drivers (preset
    x86-musl), compute that result under the cross-check master bit for bit."""
    fmu = FMUS[version] / f"{model}.fmu"
    assert runnable("x86-linux-musl", version, model), "build-x86-musl's linked drivers are missing"
    names, host = reference_run(fmu, interface)[3]
    x86_names, x86 = reference_run(fmu, interface, platform="x86-linux-musl")[3]
    assert x86_names == names and x86.shape == host.shape == (401, len(names))
    differ = np.count_nonzero(host.view(np.uint64) != x86.view(np.uint64))
    assert differ == 0, f"{differ} of {x86.size} values differ from x86_64-linux's"
    report(f"{model} FMI {version} {interface}: {x86.size} values of the x86 code bit for bit "
           "x86_64-linux's")
