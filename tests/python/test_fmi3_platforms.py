"""The FMI 3 binaries of the three platforms, proven by running them: our own FMI 3 importer
(tools/fmi3_driver.c), built for each platform, drives the binary packaged in dist/fmi3/<Model>.fmu
(AttitudePropagator too: its outputs come from the states fmi3DoStep integrates)
through every sequence (and frame) and prints every output, directional, adjoint and output
derivative as IEEE 754 bits. aarch64-linux (run under qemu-aarch64, cross-compiled with
-ffp-contract=off) prints exactly what x86_64-linux prints. x86_64-windows (run under wine)
agrees to the last bit wherever glibc's and mingw-w64's sin and cos agree, and within 2 units in
the last place elsewhere (the FMI 2 DLL has the same difference, test_windows_binary.py)."""
import os
import pathlib
import shutil
import subprocess

import numpy as np
import pytest

from fmi3_support import MODELS, unzipped

# One wine prefix (build-win64/wineprefix) for both wine test files: with pytest-xdist they run
# in one worker (--dist loadgroup), so that two wine processes never create the prefix at once.
pytestmark = [pytest.mark.xdist_group("wine"), pytest.mark.external]

ROOT = pathlib.Path(__file__).resolve().parents[2]
STEPS = "4"


def run(command, **kwargs):
    done = subprocess.run(command, capture_output=True, text=True, timeout=600, **kwargs)
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-2000:]
    return done.stdout.replace("\r\n", "\n")


def binary(model, platform):
    path = pathlib.Path(unzipped(model)[0]) / "binaries" / platform / (
        model + (".dll" if "windows" in platform else ".so"))
    assert path.is_file(), f"dist/fmi3/{model}.fmu holds no {path.name} for {platform}"
    return path


@pytest.fixture(scope="module")
def linux_printouts():
    return {m: run([str(ROOT / "build" / "fmi3_driver"), str(binary(m, "x86_64-linux")), m, STEPS])
            for m in MODELS}


@pytest.mark.parametrize("model", MODELS)
def test_aarch64_binary_under_qemu_prints_the_same_bits(model, linux_printouts, report):
    qemu = shutil.which("qemu-aarch64") or pytest.fail("qemu-aarch64 missing: bash scripts/setup.sh")
    driver = ROOT / "build-aarch64" / "fmi3_driver"
    assert driver.is_file(), "build-aarch64/fmi3_driver missing: bash scripts/build.sh"
    arm = run([qemu, "-L", "/usr/aarch64-linux-gnu", str(driver), str(binary(model, "aarch64-linux")),
               model, STEPS])
    assert "errors 0" in arm
    assert arm == linux_printouts[model]
    report(f"{model}: aarch64-linux under qemu: {numbers(arm).size} values and "
           f"{len(status_lines(arm))} statuses bit-identical to x86_64-linux")


def wine():
    for candidate in ("wine64", "wine", "/usr/lib/wine/wine64"):
        found = shutil.which(candidate)
        if found:
            return found
    pytest.fail("wine is missing: bash scripts/setup.sh --with-wine installs Debian's wine64")


def numbers(printout):
    """Every printed value (outputs and derivatives), as doubles."""
    values = []
    for line in printout.splitlines():
        if line.startswith(("outputs ", "directional ", "adjoint ", "output derivatives ")):
            values += [int(w, 16) for w in line.split() if len(w) == 16]
    return np.array(values, dtype=np.uint64).view(np.float64)


def status_lines(printout):
    return [line for line in printout.splitlines()
            if not line.startswith(("outputs ", "directional ", "adjoint ", "output derivatives "))]


@pytest.mark.parametrize("model", MODELS)
def test_windows_binary_under_wine_computes_the_same(model, linux_printouts, report):
    env = dict(os.environ, WINEPREFIX=str(ROOT / "build-win64" / "wineprefix"), WINEDEBUG="-all",
               WINEDLLOVERRIDES="mscoree,mshtml=")
    dll = "Z:" + str(binary(model, "x86_64-windows")).replace("/", "\\")
    windows = run([wine(), str(ROOT / "build-win64" / "fmi3_driver.exe"), dll, model, STEPS], env=env)
    assert "errors 0" in windows
    linux = linux_printouts[model]
    assert status_lines(windows) == status_lines(linux)  # every call's status the same
    a, b = numbers(linux), numbers(windows)
    assert a.shape == b.shape and a.size > 0
    same = np.count_nonzero(a.view(np.uint64) == b.view(np.uint64))
    ulps = np.abs(a.view(np.int64) - b.view(np.int64))
    close = np.isclose(a, b, rtol=0, atol=4 * np.spacing(np.maximum(np.abs(a), 1.0)))
    assert close.all(), np.flatnonzero(~close)[:5]
    report(f"{model}: x86_64-windows under wine: {same} of {a.size} values bit-identical to "
           f"x86_64-linux, the others within {int(ulps.max())} ulp of their own or 4 ulp of 1")


def header_functions():
    """Every function fmi3Functions.h declares (fmpy 0.3.32's copy, the one we compile with)."""
    import fmpy
    import re as regex
    header = (pathlib.Path(fmpy.__file__).parent / "c-code" / "fmi3Functions.h").read_text()
    return set(regex.findall(r"#define (fmi3\w+)\s+fmi3FullName\(", header))


@pytest.mark.parametrize("platform", ["x86_64-linux", "aarch64-linux", "x86_64-windows"])
@pytest.mark.parametrize("model", MODELS)
def test_every_function_of_the_header_is_exported(model, platform):
    expected = header_functions()
    assert len(expected) >= 70 and "fmi3GetAdjointDerivative" in expected
    path = binary(model, platform)
    if platform.endswith("windows"):
        table = subprocess.run(["x86_64-w64-mingw32-objdump", "-p", str(path)], check=True,
                               capture_output=True, text=True).stdout
        table = table.split("[Ordinal/Name Pointer] Table", 1)[1].split("\n\n", 1)[0]
        exported = {word for word in table.split() if word.startswith("fmi3")}
    else:
        symbols = subprocess.run(["nm", "-D", "--defined-only", str(path)], check=True,
                                 capture_output=True, text=True).stdout
        exported = {line.split()[-1] for line in symbols.splitlines()}
    assert {name for name in exported if name.startswith("fmi")} == expected


def test_get_version_is_3_0():
    import ctypes
    library = ctypes.CDLL(str(binary("AngularKinematics", "x86_64-linux")))
    library.fmi3GetVersion.restype = ctypes.c_char_p
    assert library.fmi3GetVersion() == b"3.0"
