"""The Windows x86-64 binary in the FMU (cross-compiled with mingw-w64): it imports only system
DLLs, exports what the Linux binary exports, and, driven under wine by our own small FMI master
(fmu_src/tools/fmu_driver.c, cross-compiled too), prints what the Linux binary prints."""
import os
import pathlib
import re
import shutil
import subprocess

import numpy as np
import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
WIN64_BUILD = ROOT / "build-win64"
STEPS = 400
# What every 64-bit Windows provides: the kernel and the system's C runtime.
SYSTEM_DLLS = {"kernel32.dll", "msvcrt.dll"}


def wine():
    for candidate in ("wine64", "wine", "/usr/lib/wine/wine64"):
        found = shutil.which(candidate)
        if found:
            return found
    pytest.fail("wine is missing: bash scripts/setup.sh --with-wine installs Debian's wine64")


@pytest.fixture(scope="module", params=["AngularKinematics", "EulerRates"])
def model(request, unzipdir, euler_unzipdir):
    """(model identifier, folder of its unzipped FMU)."""
    return request.param, pathlib.Path(unzipdir if request.param == "AngularKinematics" else euler_unzipdir)


@pytest.fixture(scope="module")
def dll(model):
    name, folder = model
    path = folder / "binaries" / "win64" / f"{name}.dll"
    assert path.is_file(), f"the FMU holds no binaries/win64/{name}.dll"
    return path


def objdump(dll):
    return subprocess.run(["x86_64-w64-mingw32-objdump", "-p", str(dll)], check=True,
                          capture_output=True, text=True).stdout


def test_dll_imports_only_system_dlls(dll):
    table = objdump(dll)
    imports = {name.lower() for name in re.findall(r"DLL Name: (\S+)", table)}
    assert imports and imports <= SYSTEM_DLLS, f"unexpected DLL dependencies: {imports - SYSTEM_DLLS}"
    # The math is mingw-w64's, linked in: the same code runs under wine and on Windows.
    imported_functions = set(re.findall(r"^\s+[0-9a-f]+\s+\d+\s+(\w+)$", table, re.MULTILINE))
    assert {"free", "calloc"} <= imported_functions
    assert not {"sin", "cos"} & imported_functions


def wine_environment():
    # A prefix of our own in build-win64/; no Mono or Gecko installer (nothing here needs them).
    return dict(os.environ, WINEPREFIX=str(WIN64_BUILD / "wineprefix"), WINEDEBUG="-all",
                WINEDLLOVERRIDES="mscoree,mshtml=")


@pytest.mark.slow  # wine starts
def test_core_unit_tests_pass_on_windows():
    done = subprocess.run([wine(), str(WIN64_BUILD / "test_kinematics.exe")], env=wine_environment(),
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-2000:]


def test_dll_exports_what_the_linux_binary_exports(dll, model):
    table = objdump(dll).split("[Ordinal/Name Pointer] Table", 1)[1].strip().split("\n\n", 1)[0]
    exported = set(re.findall(r"\]\s+(\w+)", table))
    so = model[1] / "binaries" / "linux64" / f"{model[0]}.so"
    dynamic = subprocess.run(["nm", "-D", "--defined-only", str(so)], check=True,
                             capture_output=True, text=True).stdout
    linux = {line.split()[-1] for line in dynamic.splitlines() if line.split()[-1].startswith("fmi2")}
    assert len(linux) >= 27
    assert exported == linux


def driver_rows(output):
    lines = output.replace("\r\n", "\n").strip().splitlines()
    assert lines[0] == "fmi2GetVersion 2.0"
    rows = np.array([[float(x) for x in line.split()] for line in lines[1:]])
    assert rows.shape == (STEPS, 13)
    assert np.array_equal(rows[:, 0], np.arange(STEPS))
    return rows[:, 1:]


@pytest.mark.slow  # wine starts
def test_dll_under_wine_computes_what_the_linux_binary_computes(dll, model, report):
    so = model[1] / "binaries" / "linux64" / f"{model[0]}.so"
    linux = subprocess.run([str(ROOT / "build" / "fmu_driver"), str(so), str(STEPS), model[0]],
                           check=True, capture_output=True, text=True, timeout=60)
    windows_path = "Z:" + str(dll).replace("/", "\\")
    windows = subprocess.run([wine(), str(WIN64_BUILD / "fmu_driver.exe"), windows_path, str(STEPS),
                              model[0]],
                             env=wine_environment(), capture_output=True, text=True, timeout=300)
    assert windows.returncode == 0, windows.stderr[-2000:]
    a, b = driver_rows(linux.stdout), driver_rows(windows.stdout)
    identical = np.count_nonzero(a == b)
    # Differences can only come from the two C libraries' sin and cos (last bit): measure them
    # against the largest component of the same vector (of three outputs) in the row.
    scale = np.repeat(np.abs(a).reshape(STEPS, 4, 3).max(axis=2), 3, axis=1)
    worst = (np.abs(a - b) / np.maximum(scale, 1e-300)).max()
    report(f"{model[0]}: {STEPS} steps x 12 outputs: {identical} of {a.size} bit-identical, "
           f"worst difference {worst:.1e} of the vector's largest component (tolerance 1e-15)")
    assert worst <= 1e-15
