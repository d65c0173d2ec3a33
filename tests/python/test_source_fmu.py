"""The source FMU of every model: sources/ holds every C file the binary is built from, listed alike
by modelDescription.xml's <SourceFiles> and by sources/buildDescription.xml; fmpy's own build
function compiles a copy whose binaries were deleted, linked with the <Library> (libm) the build
description names, and the result needs libm and simulates exactly like ours."""
import pathlib
import shutil
import xml.etree.ElementTree as ET

import numpy as np
import pytest
from fmpy import read_model_description, simulate_fmu
from fmpy.model_description import read_build_description

from codegen.models import model_description_path
from source_build import build_from_sources, external_libraries, needed_libraries

ROOT = pathlib.Path(__file__).resolve().parents[2]
# FMI 2.0 leaves these to the importer: they must not be in sources/.
FMI_HEADERS = {"fmi2Functions.h", "fmi2FunctionTypes.h", "fmi2TypesPlatform.h"}


def cmake_fmu_sources(model):
    """The C files of the model's FMU as CMake compiled and packaged them (written at configure
    from cmake/generated.cmake); test_documentation.py checks that file is the generator's."""
    listing = ROOT / "build" / f"fmu_sources_{model}.txt"
    assert listing.is_file(), f"{listing} is missing: build first (bash scripts/build.sh)"
    return listing.read_text().split()


def repository_files(model):
    """{file name: path} of every source and header the model's FMU ships, from codegen."""
    from codegen import project
    from codegen.models import load
    m = load(model)
    paths = (m.core_sources + m.core_headers + project.MODEL_SOURCES + m.sources +
             m.headers + project.FMI2_SOURCES + project.FMI2_HEADERS)
    return {path.split("/")[-1]: ROOT / "fmu_src" / path for path in paths}


@pytest.fixture
def sources(model):
    return pathlib.Path(model.unzipdir) / "sources"


def test_source_files_are_listed_alike_everywhere(sources, model):
    listed = cmake_fmu_sources(model.name)
    description = ET.parse(model_description_path(model.name)).getroot()
    interfaces = [e for e in description if e.tag in ("CoSimulation", "ModelExchange")]
    assert interfaces
    for interface in interfaces:
        in_xml = [f.get("name") for f in interface.findall("SourceFiles/File")]
        assert sorted(in_xml) == sorted(listed), \
            f"<{interface.tag}><SourceFiles> of modelDescription.xml differs from CMakeLists.txt"
    build_description = read_build_description(str(sources.parent), validate=True)
    assert [c.modelIdentifier for c in build_description] == [model.name]
    assert build_description[0].sourceFileSets[0].sourceFiles == listed
    assert sorted(p.name for p in sources.glob("*.c")) == sorted(listed)


def test_sources_are_the_fmu_sources_of_the_repository(sources, model):
    """The model's C files and headers, nothing else (no tests, tools, FMI headers, nor another
    model's files), each the repository's."""
    shipped = {p.name for p in sources.iterdir()} - {"buildDescription.xml"}
    files = repository_files(model.name)
    assert shipped == set(files)
    assert set(cmake_fmu_sources(model.name)) == {n for n in files if n.endswith(".c")}
    assert not shipped & FMI_HEADERS
    for name in shipped:
        assert (sources / name).read_bytes() == files[name].read_bytes()


def test_fmpy_reads_the_source_files(model):
    configuration = model.description.buildConfigurations[0]
    assert configuration.modelIdentifier == model.description.coSimulation.modelIdentifier
    assert configuration.sourceFileSets[0].sourceFiles == cmake_fmu_sources(model.name)


def input_signals(description, times):
    """A smooth signal for every input of the model, each its own: fmpy's structured input."""
    inputs = [v.name for v in description.modelVariables if v.causality == "input"]
    signals = np.zeros(len(times), dtype=[("time", np.float64)] + [(n, np.float64) for n in inputs])
    signals["time"] = times
    for k, name in enumerate(inputs):
        signals[name] = 0.4 * np.sin((k + 1) * 0.7 * times) + 0.05 * k
    return signals


@pytest.mark.slow  # compiles the FMU
def test_copy_without_binaries_compiles_with_fmpy_and_simulates_identically(model, tmp_path, report):
    copy = tmp_path / "fmu"
    shutil.copytree(model.unzipdir, copy)
    shutil.rmtree(copy / "binaries")
    assert external_libraries(copy) == ["m"]  # sqrt...: not in libc
    build_from_sources(copy, tmp_path)
    rebuilt_binary = copy / "binaries" / "linux64" / f"{model.name}.so"
    # It needs what the packaged binary (linked with --no-undefined) needs: libm where that one
    # calls it (EulerRates does not), so that it loads where libm is not loaded yet.
    packaged = pathlib.Path(model.unzipdir) / "binaries" / "linux64" / f"{model.name}.so"
    assert set(needed_libraries(packaged)) <= set(needed_libraries(rebuilt_binary))
    assert read_model_description(str(copy)).guid == model.description.guid

    times = np.arange(0.0, 1.0 + 0.5e-2, 1e-2)
    names = [v.name for v in model.description.modelVariables if v.causality == "output"]

    def simulate(fmu):
        return simulate_fmu(fmu, stop_time=1.0, output_interval=1e-2, output=names,
                            input=input_signals(model.description, times))

    ours, rebuilt = simulate(model.fmu_path), simulate(str(copy))
    assert len(ours) == len(times)
    assert any(np.any(ours[name] != ours[name][0]) for name in names), "the outputs move"
    for name in ["time"] + names:
        assert np.array_equal(ours[name], rebuilt[name]), name
    report(f"{model.name}: binary rebuilt by fmpy from sources/: {len(times)} rows x {len(names)} "
           "outputs bit-identical to the packaged binary's")
