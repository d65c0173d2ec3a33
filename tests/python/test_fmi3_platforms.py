"""The FMI 3 binaries of the seven platforms in dist/fmi3/<Model>.fmu: each FMU holds all seven, the
Linux and Windows ones export every function of fmi3Functions.h (the darwin ones:
tests/python/test_darwin_binaries.py), fmi3GetVersion says 3.0. That they compute the same bits,
run under qemu and wine, is tests/python/test_platforms.py's."""
import pathlib
import subprocess

import pytest

from fmi3_support import MODELS, unzipped

pytestmark = pytest.mark.external  # the other platforms' binaries come from the cross builds


def binary(model, platform):
    path = pathlib.Path(unzipped(model)[0]) / "binaries" / platform / (
        model + {"windows": ".dll", "linux": ".so", "darwin": ".dylib"}[platform.split("-")[1]])
    assert path.is_file(), f"dist/fmi3/{model}.fmu holds no {path.name} for {platform}"
    return path


PLATFORMS = ["x86_64-linux", "aarch64-linux", "riscv64-linux", "x86_64-windows", "x86-windows",
             "x86_64-darwin", "aarch64-darwin"]


@pytest.mark.parametrize("model", MODELS)
def test_fmu_holds_the_seven_platforms(model):
    folders = sorted(p.name for p in (pathlib.Path(unzipped(model)[0]) / "binaries").iterdir())
    assert folders == sorted(PLATFORMS)
    for platform in PLATFORMS:
        binary(model, platform)


def header_functions():
    """Every function fmi3Functions.h declares (fmpy 0.3.32's copy, the one we compile with)."""
    import fmpy
    import re as regex
    header = (pathlib.Path(fmpy.__file__).parent / "c-code" / "fmi3Functions.h").read_text()
    return set(regex.findall(r"#define (fmi3\w+)\s+fmi3FullName\(", header))


@pytest.mark.parametrize("platform", ["x86_64-linux", "aarch64-linux", "riscv64-linux",
                                      "x86_64-windows", "x86-windows"])
@pytest.mark.parametrize("model", MODELS)
def test_every_function_of_the_header_is_exported(model, platform):
    expected = header_functions()
    assert len(expected) >= 70 and "fmi3GetAdjointDerivative" in expected
    path = binary(model, platform)
    if platform.endswith("windows"):
        objdump = ("x86_64" if platform.startswith("x86_64") else "i686") + "-w64-mingw32-objdump"
        table = subprocess.run([objdump, "-p", str(path)], check=True,
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
