"""The Windows x86-64 binary in each FMU of codegen.project.MODELS (cross-compiled with
mingw-w64): the FMU holds it, it imports only system DLLs, exports what the Linux binary exports,
and, driven under wine by our own small FMI master (tools/fmu_driver.c, cross-compiled too), prints
what the Linux binary prints, every output at every step (AttitudePropagator: its states
integrated over the steps)."""
import os
import pathlib
import re
import shutil
import subprocess

import numpy as np
import pytest

# One wine prefix (build-win64/wineprefix) for both wine test files: with pytest-xdist they run
# in one worker (--dist loadgroup), so that two wine processes never create the prefix at once.
pytestmark = [pytest.mark.xdist_group("wine"), pytest.mark.external]

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


# model: conftest's fixture, each model of codegen.project.MODELS with its FMU unzipped.


def binary(model, platform, extension):
    return pathlib.Path(model.unzipdir) / "binaries" / platform / f"{model.name}.{extension}"


@pytest.fixture(scope="module")
def dll(model):
    path = binary(model, "win64", "dll")
    assert path.is_file(), f"{model.fmu_path} holds no binaries/win64/{model.name}.dll"
    return path


def test_fmu_holds_both_binaries(model):
    """The build packages the DLL beside the .so (scripts/build.sh passes it to CMake)."""
    assert binary(model, "win64", "dll").is_file()
    assert binary(model, "linux64", "so").is_file()


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
    so = binary(model, "linux64", "so")
    dynamic = subprocess.run(["nm", "-D", "--defined-only", str(so)], check=True,
                             capture_output=True, text=True).stdout
    linux = {line.split()[-1] for line in dynamic.splitlines() if line.split()[-1].startswith("fmi2")}
    assert len(linux) >= 27
    assert exported == linux


def driver_rows(output, model):
    """The output names and the rows (STEPS x outputs) the driver printed."""
    lines = output.replace("\r\n", "\n").strip().splitlines()
    assert lines[0] == "fmi2GetVersion 2.0"
    names = lines[1].split()
    assert names[0] == "outputs" and names[1:] == model.outputs  # every output, in vr order
    rows = np.array([[float(x) for x in line.split()] for line in lines[2:]])
    assert rows.shape == (STEPS, 1 + len(model.outputs))
    assert np.array_equal(rows[:, 0], np.arange(STEPS))
    return names[1:], rows[:, 1:]


def vector_scale(names, values):
    """Per row, for each output, the largest magnitude among the outputs of its array (omega[1..3],
    R[1,1..3,3], q[1..4]; a scalar output is its own array)."""
    arrays = [name.split("[")[0] for name in names]
    scale = np.empty_like(values)
    for array in set(arrays):
        columns = [k for k, a in enumerate(arrays) if a == array]
        scale[:, columns] = np.abs(values[:, columns]).max(axis=1, keepdims=True)
    return scale


def in_ulp(difference, magnitude):
    """difference in units in the last place of magnitude."""
    return difference / np.spacing(np.maximum(magnitude, np.finfo(float).tiny))


@pytest.mark.slow  # wine starts
def test_dll_under_wine_computes_what_the_linux_binary_computes(dll, model, report):
    so = binary(model, "linux64", "so")
    linux = subprocess.run([str(ROOT / "build" / "fmu_driver"), str(so), str(STEPS), model.name],
                           check=True, capture_output=True, text=True, timeout=60)
    windows_path = "Z:" + str(dll).replace("/", "\\")
    windows = subprocess.run([wine(), str(WIN64_BUILD / "fmu_driver.exe"), windows_path, str(STEPS),
                              model.name],
                             env=wine_environment(), capture_output=True, text=True, timeout=300)
    assert windows.returncode == 0, windows.stderr[-2000:]
    names, a = driver_rows(linux.stdout, model)
    _, b = driver_rows(windows.stdout, model)
    assert np.isfinite(a).all()
    identical = np.count_nonzero(a == b)
    differ = a != b
    scale = vector_scale(names, a)
    # Differences can only come from the two C libraries' sin and cos (last bit): measure them
    # against the largest component of the same vector (array of outputs) in the row. Also in ulp
    # of the value itself: a value that is a rounding residue near zero (AngularKinematics at
    # theta[2] = pi/2 rounded: 1e-18 to 2e-16 where the exact value is 0) can be many of its own
    # ulp off while a tiny fraction of one ulp of its vector.
    worst = (np.abs(a - b) / np.maximum(scale, 1e-300)).max()
    own = in_ulp(np.abs(a - b), np.maximum(np.abs(a), np.abs(b)))[differ]
    of_vector = in_ulp(np.abs(a - b), scale)[differ]
    report(f"{model.name}: {STEPS} steps x {a.shape[1]} outputs: {identical} of {a.size} "
           f"bit-identical; the {a.size - identical} others differ by at most "
           f"{own.max(initial=0):.3g} ulp of their own value, {of_vector.max(initial=0):.2g} ulp "
           f"of their vector's largest component; worst difference {worst:.1e} of the vector's "
           f"largest component (tolerance 1e-15)")
    assert worst <= 1e-15
