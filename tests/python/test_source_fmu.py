"""The source FMU: sources/ holds every C file the binary is built from, listed alike by
modelDescription.xml's <SourceFiles> and by sources/buildDescription.xml; fmpy's own build function
compiles a copy whose binaries were deleted, and the result simulates exactly like ours."""
import pathlib
import shutil
import xml.etree.ElementTree as ET

import numpy as np
import pytest
from fmpy import read_model_description, simulate_fmu
from fmpy.build import build_platform_binary
from fmpy.model_description import read_build_description

import reference
import trajectories

ROOT = pathlib.Path(__file__).resolve().parents[2]
# FMI 2.0 leaves these to the importer: they must not be in sources/.
FMI_HEADERS = {"fmi2Functions.h", "fmi2FunctionTypes.h", "fmi2TypesPlatform.h"}


def cmake_fmu_sources(model="AngularKinematics"):
    """The C files of the model's FMU as CMake compiled and packaged them (written at configure
    from cmake/generated.cmake); test_documentation.py checks that file is the generator's."""
    listing = ROOT / "build" / f"fmu_sources_{model}.txt"
    assert listing.is_file(), f"{listing} is missing: build first (bash scripts/build.sh)"
    return listing.read_text().split()


def repository_files(model="AngularKinematics"):
    """{file name: path} of every source and header the model's FMU ships, from codegen."""
    from codegen import project
    from codegen.models import load
    m = load(model)
    paths = (project.CORE_SOURCES + project.CORE_HEADERS + project.MODEL_SOURCES + m.sources +
             m.headers + project.FMI2_SOURCES + project.FMI2_HEADERS)
    return {path.split("/")[-1]: ROOT / "fmu_src" / path for path in paths}


@pytest.fixture(scope="module")
def sources(unzipdir):
    return pathlib.Path(unzipdir) / "sources"


def test_source_files_are_listed_alike_everywhere(sources, root):
    listed = cmake_fmu_sources()
    description = ET.parse(root / "modelDescription.xml").getroot()
    interfaces = [e for e in description if e.tag in ("CoSimulation", "ModelExchange")]
    assert interfaces
    for interface in interfaces:
        in_xml = [f.get("name") for f in interface.findall("SourceFiles/File")]
        assert sorted(in_xml) == sorted(listed), \
            f"<{interface.tag}><SourceFiles> of modelDescription.xml differs from CMakeLists.txt"
    build_description = read_build_description(str(sources.parent), validate=True)
    assert [c.modelIdentifier for c in build_description] == ["AngularKinematics"]
    assert build_description[0].sourceFileSets[0].sourceFiles == listed
    assert sorted(p.name for p in sources.glob("*.c")) == sorted(listed)


def test_sources_are_the_fmu_sources_of_the_repository(sources, root):
    """The model's C files and headers, nothing else (no tests, tools, FMI headers, nor the other
    model's files), each the repository's."""
    shipped = {p.name for p in sources.iterdir()} - {"buildDescription.xml"}
    files = repository_files()
    assert shipped == set(files)
    assert set(cmake_fmu_sources()) == {n for n in files if n.endswith(".c")}
    assert not shipped & FMI_HEADERS
    for name in shipped:
        assert (sources / name).read_bytes() == files[name].read_bytes()


def test_fmpy_reads_the_source_files(model_description):
    configuration = model_description.buildConfigurations[0]
    assert configuration.modelIdentifier == "AngularKinematics"
    assert configuration.sourceFileSets[0].sourceFiles == cmake_fmu_sources()


@pytest.mark.slow  # compiles the FMU
def test_copy_without_binaries_compiles_with_fmpy_and_simulates_identically(
        unzipdir, fmu_path, tmp_path, report):
    copy = tmp_path / "fmu"
    shutil.copytree(unzipdir, copy)
    shutil.rmtree(copy / "binaries")
    build_platform_binary(copy, build_dir=tmp_path, all_warnings=True,
                          cmake_options={"CMAKE_COMPILE_WARNING_AS_ERROR:BOOL": "ON"})
    assert (copy / "binaries" / "linux64" / "AngularKinematics.so").is_file()
    assert read_model_description(str(copy)).guid == read_model_description(fmu_path).guid

    times = np.arange(0.0, 2.0 + 0.5e-3, 1e-3)
    names = reference.INPUT_NAMES + reference.OUTPUT_NAMES

    def simulate(fmu):
        return simulate_fmu(fmu, stop_time=2.0, output_interval=1e-3, output=names,
                            input=trajectories.input_signals(times))

    ours, rebuilt = simulate(fmu_path), simulate(str(copy))
    assert len(ours) == len(times)
    for name in ["time"] + names:
        assert np.array_equal(ours[name], rebuilt[name]), name
    report(f"binary rebuilt by fmpy from sources/: {len(times)} rows x {len(names)} variables "
           "bit-identical to the packaged binary's")


@pytest.mark.slow  # compiles the FMU
def test_euler_rates_source_fmu_compiles_with_fmpy_and_simulates_identically(
        euler_unzipdir, euler_fmu_path, root, tmp_path):
    """The second model's source FMU: its own source list (EulerRates_variables.c, not the other
    model's), listed alike everywhere, rebuilt by fmpy into a binary that computes the same bits."""
    listed = cmake_fmu_sources("EulerRates")
    assert "EulerRates_variables.c" in listed and "AngularKinematics_variables.c" not in listed
    description = read_model_description(euler_fmu_path)
    assert description.buildConfigurations[0].sourceFileSets[0].sourceFiles == listed
    assert sorted(p.name for p in (pathlib.Path(euler_unzipdir) / "sources").glob("*.c")) == sorted(listed)
    copy = tmp_path / "fmu"
    shutil.copytree(euler_unzipdir, copy)
    shutil.rmtree(copy / "binaries")
    build_platform_binary(copy, build_dir=tmp_path, all_warnings=True,
                          cmake_options={"CMAKE_COMPILE_WARNING_AS_ERROR:BOOL": "ON"})
    names = ["theta_dot[1]", "theta_dot[2]", "theta_dot[3]", "theta_ddot[1]", "alpha_body[3]",
             "singularity_distance"]
    start = {"sequence": 11, "frame": 2, "theta[1]": 0.2, "theta[2]": 0.9, "omega[1]": 1.5,
             "omega[3]": -0.5, "omega_dot[2]": 2.0}

    def simulate(fmu):
        return simulate_fmu(fmu, stop_time=0.1, output_interval=0.01, output=names,
                            start_values=start)

    ours, rebuilt = simulate(euler_fmu_path), simulate(str(copy))
    for name in ["time"] + names:
        assert np.array_equal(ours[name], rebuilt[name]), name
    assert ours["singularity_distance"][-1] == pytest.approx(np.sin(0.9), rel=1e-15)
