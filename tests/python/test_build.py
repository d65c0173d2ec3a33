"""The build: FMI headers found or a clear failure, and a binary that exports the FMI API only."""
import shutil
import subprocess
import sys

import pytest

CMAKE = shutil.which("cmake")

# Every function of the FMI 2.0 common and co-simulation APIs.
FMI2_CO_SIMULATION_API = """
GetTypesPlatform GetVersion SetDebugLogging Instantiate FreeInstance SetupExperiment
EnterInitializationMode ExitInitializationMode Terminate Reset GetReal GetInteger GetBoolean GetString
SetReal SetInteger SetBoolean SetString GetFMUstate SetFMUstate FreeFMUstate SerializedFMUstateSize
SerializeFMUstate DeSerializeFMUstate GetDirectionalDerivative SetRealInputDerivatives
GetRealOutputDerivatives DoStep CancelStep GetStatus GetRealStatus GetIntegerStatus GetBooleanStatus
GetStringStatus""".split()


def configure(root, build_dir, *options):
    return subprocess.run([CMAKE, "-S", str(root), "-B", str(build_dir), *options],
                          capture_output=True, text=True)


@pytest.mark.parametrize("options", [["-DFMI2_HEADERS_DIR=/nonexistent"],
                                     ["-DPython3_EXECUTABLE=/bin/false"]])
def test_configure_fails_clearly_without_fmi_headers(options, root, tmp_path):
    result = configure(root, tmp_path, *options)
    assert result.returncode != 0
    assert "FMI 2.0 headers not found" in result.stderr
    assert "-DFMI2_HEADERS_DIR" in result.stderr


def test_configure_finds_fmpy_headers_by_itself(root, tmp_path):
    result = configure(root, tmp_path, f"-DPython3_EXECUTABLE={sys.executable}",
                       f"-DAK_DIST_DIR={tmp_path / 'dist'}")
    assert result.returncode == 0, result.stderr
    assert "fmpy/c-code" in result.stdout
    assert "FMI platform: linux64" in result.stdout


def test_binary_exports_the_fmi_api_only(unzipdir):
    library = f"{unzipdir}/binaries/linux64/AngularKinematics.so"
    symbols = subprocess.run(["nm", "-D", "--defined-only", library], capture_output=True,
                             text=True, check=True).stdout.split("\n")
    exported = sorted(line.split()[-1] for line in symbols if " T " in line)
    assert exported and all(name.startswith("fmi2") for name in exported), exported
    assert len(FMI2_CO_SIMULATION_API) == 34
    assert {f"fmi2{name}" for name in FMI2_CO_SIMULATION_API} <= set(exported)
