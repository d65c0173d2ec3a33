"""The Windows binaries, x86-64 (win64) and x86 (win32), in each FMU of codegen.project.MODELS
(cross-compiled with mingw-w64): the FMU holds them, they import only system DLLs and export what
the Linux binary exports, and the core's unit tests pass under wine. That their outputs have the
bits of the Linux binary's, every output at every step, is tests/python/test_platforms.py's."""
import os
import pathlib
import re
import shutil
import subprocess

import pytest

# One wine prefix (build-win64/wineprefix) for every wine test file: with pytest-xdist they run
# in one worker (--dist loadgroup), so that two wine processes never create the prefix at once.
pytestmark = [pytest.mark.xdist_group("wine"), pytest.mark.external]

ROOT = pathlib.Path(__file__).resolve().parents[2]
WIN64_BUILD = ROOT / "build-win64"
# What every Windows provides: the kernel and the system's C runtime.
SYSTEM_DLLS = {"kernel32.dll", "msvcrt.dll"}
WINDOWS = {"win64": "x86_64-w64-mingw32-objdump", "win32": "i686-w64-mingw32-objdump"}


def wine():
    for candidate in ("wine64", "wine", "/usr/lib/wine/wine64"):
        found = shutil.which(candidate)
        if found:
            return found
    pytest.fail("wine is missing: bash scripts/setup.sh --with-wine installs Debian's wine64")


# model: conftest's fixture, each model of codegen.project.MODELS with its FMU unzipped.


def binary(model, platform, extension):
    return pathlib.Path(model.unzipdir) / "binaries" / platform / f"{model.name}.{extension}"


@pytest.fixture(scope="module", params=sorted(WINDOWS))
def dll(model, request):
    path = binary(model, request.param, "dll")
    assert path.is_file(), f"{model.fmu_path} holds no binaries/{request.param}/{model.name}.dll"
    return path


def test_fmu_holds_every_platform(model):
    """The build packages the other platforms' binaries beside the .so (scripts/build.sh passes
    them to CMake); darwin64's is universal (tests/python/test_darwin_binaries.py)."""
    folders = sorted(p.name for p in (pathlib.Path(model.unzipdir) / "binaries").iterdir())
    assert folders == ["darwin64", "linux64", "win32", "win64"]
    for platform, extension in [("win64", "dll"), ("win32", "dll"), ("linux64", "so"),
                                ("darwin64", "dylib")]:
        assert binary(model, platform, extension).is_file()


def objdump(dll):
    tool = WINDOWS[dll.parent.name]
    return subprocess.run([tool, "-p", str(dll)], check=True, capture_output=True, text=True).stdout


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
