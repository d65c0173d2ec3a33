"""No FMU carries a function its model never calls. The C files of each FMU's sources/ (what an
importer compiles, without link-time optimization) are compiled with a section per function and
linked as the FMU's shared library with --gc-sections: the linker keeps what the exported FMI
entry points reach and names every function it drops. Unoptimized (-O0), so that no function
goes by being inlined: each one dropped is a function of the source FMU that nothing calls.

The core's sources (the model's CORE list) and the model's own must lose none. The runtime and
the FMI layer must lose none in the FMI 2 FMU; the FMI 3 layer does not call the runtime's
scalar gets and sets (FMI 2's), so there the runtime is not checked."""
import pathlib
import re
import shutil
import subprocess
import zipfile

import pytest

from codegen import project
from codegen.models import load

ROOT = pathlib.Path(__file__).resolve().parents[2]
CORE_FILES = {path.split("/")[-1] for path in project.CORE_SOURCES}


def fmu_path(model, fmi):
    return ROOT / "dist" / (f"{model}.fmu" if fmi == 2 else f"fmi3/{model}.fmu")


def fmi_headers():
    import fmpy
    return pathlib.Path(fmpy.__file__).parent / "c-code"


def unzip_sources(fmu, folder):
    folder.mkdir()
    with zipfile.ZipFile(fmu) as archive:
        for name in archive.namelist():
            if name.startswith("sources/") and not name.endswith("/"):
                (folder / name.split("/")[-1]).write_bytes(archive.read(name))
    return folder


def dropped_functions(sources, build):
    """{(file, function)} of every function the linker drops from the shared library of the
    C files in `sources`."""
    objects = []
    for source in sorted(sources.glob("*.c")):
        obj = build / f"{source.stem}.o"
        subprocess.run(["gcc", "-std=c11", "-O0", "-fPIC", "-fvisibility=hidden",
                        "-ffunction-sections", f"-I{sources}", f"-I{fmi_headers()}", "-c",
                        str(source), "-o", str(obj)], check=True)
        objects.append(str(obj))
    link = subprocess.run(["gcc", "-shared", *objects, "-o", str(build / "fmu.so"), "-lm",
                           "-Wl,--gc-sections", "-Wl,--print-gc-sections"],
                          capture_output=True, text=True, check=True)
    return {(f"{pathlib.Path(obj).stem}.c", function) for function, obj in
            re.findall(r"removing unused section '\.text\.([^']+)' in file '([^']+)'", link.stderr)}


def checked_files(model, fmi, sources):
    shipped = {p.name for p in sources.glob("*.c")}
    if fmi == 2:
        return shipped
    own = {path.split("/")[-1] for path in load(model).sources}
    return shipped & (CORE_FILES | own | {n for n in shipped if n.startswith("fmi3_")}
                      | {f"{model}_fmi3_arrays.c"})


pytestmark = pytest.mark.skipif(shutil.which("gcc") is None, reason="needs gcc")


@pytest.mark.parametrize("fmi", [2, 3])
@pytest.mark.parametrize("model", project.MODELS)
def test_the_fmu_holds_no_function_its_model_never_calls(model, fmi, tmp_path, report):
    fmu = fmu_path(model, fmi)
    assert fmu.is_file(), f"{fmu} is missing: build first"
    sources = unzip_sources(fmu, tmp_path / "sources")
    build = tmp_path / "build"
    build.mkdir()
    dropped = dropped_functions(sources, build)
    checked = checked_files(model, fmi, sources)
    dead = sorted(f"{file}: {function}" for file, function in dropped if file in checked)
    assert not dead, f"{model} FMI {fmi} ships functions nothing calls: {dead}"
    shipped_core = sorted(p.name for p in sources.glob("*.c") if p.name in CORE_FILES)
    report(f"{model} FMI {fmi}: every function of {len(checked)} files reached from the FMI "
           f"entry points; core: {' '.join(shipped_core)}")


def test_a_function_nothing_calls_is_found(tmp_path):
    """The check above can fail: a function planted in a core source of the FMU is dropped and
    named."""
    sources = unzip_sources(fmu_path("EulerRates", 2), tmp_path / "sources")
    (sources / "kinematics_general.c").write_text(
        (sources / "kinematics_general.c").read_text()
        + "\ndouble ak_planted(double x);\ndouble ak_planted(double x) { return x + 1.0; }\n")
    build = tmp_path / "build"
    build.mkdir()
    assert ("kinematics_general.c", "ak_planted") in dropped_functions(sources, build)
