"""The macOS binaries of every FMU, which cannot run here, checked statically by
tools/check_macho.py: FMI 2's binaries/darwin64/<Model>.dylib is universal (x86_64 and arm64: fmpy
loads darwin64 on Intel and Apple silicon Macs alike), FMI 3's x86_64-darwin and aarch64-darwin
dylibs are thin; every slice exports every function of the FMI header (and the same fmi* functions
as the Linux binary), loads only libSystem, binds every undefined symbol to it and states its
minimum macOS version: 10.13 for x86_64, 11.0 for arm64 (cmake/zig-*-macos.cmake)."""
import pathlib
import re
import subprocess

import fmpy
import pytest

from codegen import project
from conftest import fmu_files
from fmi3_support import unzipped
from tools import check_macho

pytestmark = pytest.mark.external  # the darwin binaries come from the cross builds

ROOT = pathlib.Path(__file__).resolve().parents[2]

MINIMUM = {"x86_64": "macOS 10.13.0", "arm64": "macOS 11.0.0"}
CASES = [(2, "darwin64", ["x86_64", "arm64"]), (3, "x86_64-darwin", ["x86_64"]),
         (3, "aarch64-darwin", ["arm64"])]


def header_functions(fmi):
    header = (pathlib.Path(fmpy.__file__).parent / "c-code" / f"fmi{fmi}Functions.h").read_text()
    return set(re.findall(rf"#define (fmi{fmi}\w+)\s+fmi{fmi}FullName\(", header))


def linux_exports(fmi, model):
    folder = (pathlib.Path(fmu_files(model)[0]) / "binaries" / "linux64" if fmi == 2
              else pathlib.Path(unzipped(model)[0]) / "binaries" / "x86_64-linux")
    symbols = subprocess.run(["nm", "-D", "--defined-only", str(folder / f"{model}.so")],
                             check=True, capture_output=True, text=True).stdout
    return {line.split()[-1] for line in symbols.splitlines() if line.split()[-1].startswith("fmi")}


@pytest.mark.parametrize("fmi, platform, architectures", CASES,
                         ids=[case[1] for case in CASES])
@pytest.mark.parametrize("model", project.MODELS)
def test_darwin_binary_passes_the_static_checks(model, fmi, platform, architectures, report):
    folder = pathlib.Path(fmu_files(model)[0] if fmi == 2 else unzipped(model)[0])
    path = folder / "binaries" / platform / f"{model}.dylib"
    assert path.is_file(), f"the FMI {fmi} FMU of {model} holds no binaries/{platform}/{path.name}"
    required = header_functions(fmi)
    assert len(required) >= (44 if fmi == 2 else 75)
    assert linux_exports(fmi, model) == required  # the Linux binary exports the same set
    failures, lines = check_macho.check(str(path), architectures, required)
    assert not failures, "\n".join(failures)
    for architecture in architectures:  # the minimum macOS version each slice states
        assert any(f"[{architecture}]" in line and line.endswith(MINIMUM[architecture])
                   for line in lines), lines
    report("; ".join(line[line.rindex(" ["):].strip() for line in lines))


def test_the_checker_finds_a_missing_export_and_a_wrong_architecture(tmp_path):
    """The checker can fail: a required function the binary does not export, a slice missing."""
    path = pathlib.Path(unzipped("EulerRates")[0]) / "binaries" / "aarch64-darwin" / "EulerRates.dylib"
    failures, _ = check_macho.check(str(path), ["arm64", "x86_64"],
                                    header_functions(3) | {"fmi3NoSuchFunction"})
    assert any("not exported: fmi3NoSuchFunction" in f for f in failures)
    assert any("expected ['arm64', 'x86_64']" in f for f in failures)
    broken = tmp_path / "broken.dylib"
    broken.write_bytes(path.read_bytes()[:64])
    assert check_macho.check(str(broken), ["arm64"], header_functions(3))[0]
