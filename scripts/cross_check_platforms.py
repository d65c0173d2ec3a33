"""Each platform folder's result of dist/cross-check/ from that folder's own binary.

fmpy here loads only x86_64-linux binaries; the others run in the cross-check mode of our C
masters (tools/fmu_driver_cross_check.c, tools/fmi3_driver_cross_check.c: the call sequence of
examples/cross_check.py and cross_check3.py, call for call), built for the platform and started
as RUNNERS says. tests/python/test_cross_check_platforms.py proves that on the x86_64-linux binary
the C master prints fmpy's result bit for bit, so a platform's run is what the cross-check master
would compute with that binary.

RUNNERS: a binaries/ folder name (FMI 2's and FMI 3's) -> how its binary runs here. A platform
of another architecture is one row: its build folder (the preset's, with the drivers) and the
command that starts them, such as
    "riscv64-linux": Runner("build-riscv64", **qemu("riscv64")),
A folder that is not in RUNNERS, or whose launcher or drivers are missing, gets the host's result
(HOST, through fmpy); proof() names the test that proves its binary computes the same bits."""
import dataclasses
import os
import pathlib
import shutil
import subprocess
import tempfile
import zipfile

import numpy as np

from examples.cross_check3 import layout

ROOT = pathlib.Path(__file__).resolve().parent.parent
HOST = {"2.0": "linux64", "3.0": "x86_64-linux"}  # the folders whose result fmpy computes


@dataclasses.dataclass(frozen=True)
class Runner:
    build: str  # the build folder of the platform's drivers (fmu_driver, fmi3_driver)
    launcher: tuple = ()  # the program that runs the platform's programs here (the first found
    arguments: tuple = ()  # of these names or paths) and its arguments; () natively
    windows: bool = False  # a Windows program: .exe, Windows paths, the wine prefix
    linked: bool = False  # one static driver per model with its FMI functions linked in

    def launch(self):
        """The launcher's command, or None when it is not installed here."""
        if not self.launcher:
            return []
        for candidate in self.launcher:
            found = shutil.which(candidate)
            if found:
                return [found, *self.arguments]
        return None

    def driver(self, fmi_version, model):
        name = ("fmu_driver" if fmi_version == "2.0" else "fmi3_driver") + (
            f"_{model}" if self.linked else "") + (".exe" if self.windows else "")
        return ROOT / self.build / name


def qemu(architecture):
    """qemu's user mode for a Linux architecture, with Debian's cross libraries of it."""
    return dict(launcher=(f"qemu-{architecture}",),
                arguments=("-L", f"/usr/{architecture}-linux-gnu"))


WINE64 = dict(launcher=("wine64", "wine", "/usr/lib/wine/wine64"), windows=True)
# Debian's wine32:i386, which is not installable here (docs/platforms.md)
WINE32 = dict(launcher=("/usr/lib/wine/wine",), windows=True)
RUNNERS = {
    "linux64": Runner("build"),
    "x86_64-linux": Runner("build"),
    "aarch64-linux": Runner("build-aarch64", **qemu("aarch64")),
    "riscv64-linux": Runner("build-riscv64", **qemu("riscv64")),
    "win64": Runner("build-win64", **WINE64),
    "x86_64-windows": Runner("build-win64", **WINE64),
    "win32": Runner("build-win32", **WINE32),
    "x86-windows": Runner("build-win32", **WINE32),
    # Not a folder of the FMUs: the x86 proof build (docs/platforms.md), the x86-windows sources
    # and flags in static x86 programs, which tests/python/test_cross_check_platforms.py runs.
    "x86-linux-musl": Runner("build-x86-musl", linked=True),
}

# Where a folder's binary does not run here: the test that proves it computes the host's bits.
DARWIN = ("tests/python/test_darwin_binaries.py checks it statically (architecture, exports, "
          "libSystem only), and tests/python/test_platforms.py runs the same sources built by its "
          "compiler (zig, preset zig-linux) to the bits of x86_64-linux")
X86 = ("tests/python/test_cross_check_platforms.py runs the same sources with its x86 flags "
       "(preset x86-musl, static x86 programs) under this master to this result bit for bit; the "
       "build machine has no 32-bit wine")
NOT_RUN = {"darwin64": DARWIN, "x86_64-darwin": DARWIN, "aarch64-darwin": DARWIN,
           "win32": X86, "x86-windows": X86}
# A platform of RUNNERS whose launcher or drivers are missing on the machine that makes the folder
RUN_BY_TEST = ("tests/python/test_platforms.py runs it (under wine or qemu, docs/platforms.md) to "
               "the bits of x86_64-linux")


def proof(platform):
    """The test that proves the bits of a binary that did not run here."""
    return NOT_RUN.get(platform, RUN_BY_TEST)


def wine_environment():
    """The wine prefix of the tests (build-win64/wineprefix), no Mono or Gecko installer."""
    return dict(os.environ, WINEPREFIX=str(ROOT / "build-win64" / "wineprefix"),
                WINEDEBUG="-all", WINEDLLOVERRIDES="mscoree,mshtml=")


def runnable(platform, fmi_version, model="AngularKinematics"):
    """(runner, command prefix) of the platform's binary, or None when it cannot run here; model:
    whose driver, for a linked one."""
    runner = RUNNERS.get(platform)
    if runner is None:
        return None
    launch = runner.launch()
    if launch is None or not runner.driver(fmi_version, model).is_file():
        return None
    return runner, launch


def binary_name(model, platform):
    if platform in ("win64", "win32") or platform.endswith("-windows"):
        return f"{model}.dll"
    return f"{model}.{'dylib' if 'darwin' in platform else 'so'}"


def hex_words(values):
    return " ".join(f"{int(bits):016x}" for bits in np.asarray(values, np.float64).view(np.uint64))


def driver_command(description, interface, input_names, output_names):
    """(the cross-check mode's arguments after LIBRARY and MODEL, the column of each output among
    the printed values)."""
    states = str(description.numberOfContinuousStates)
    if description.fmiVersion == "2.0":
        vr = {v.name: v.valueReference for v in description.modelVariables}
        in_vrs, out_vrs = [vr[n] for n in input_names], [vr[n] for n in output_names]
        n_out, picks = len(out_vrs), list(range(len(out_vrs)))
    else:
        in_vrs, out_vrs, n_out, picks = layout(description, input_names, output_names)
    return ([interface, states, ",".join(map(str, in_vrs)), str(len(input_names)),
             ",".join(map(str, out_vrs)), str(n_out)], picks)


def run_binary(fmu, platform, description, interface, times, input_names, inputs, output_names):
    """The outputs (len(times) x outputs) that the FMU's binary of the platform computes under
    the cross-check master, or None when that binary cannot run here."""
    version, model = description.fmiVersion, description.modelName
    found = runnable(platform, version, model)
    if found is None:
        return None
    runner, launch = found
    arguments, picks = driver_command(description, interface, input_names, output_names)
    rows = "".join(hex_words(np.concatenate([[t], row])) + "\n" for t, row in zip(times, inputs))
    folder = pathlib.Path(tempfile.mkdtemp(prefix="cross-check-"))
    try:
        library_argument = "-"  # a linked driver has the model in it
        if not runner.linked:
            with zipfile.ZipFile(fmu) as archive:
                library = pathlib.Path(archive.extract(
                    f"binaries/{platform}/{binary_name(model, platform)}", folder))
            library_argument = ("Z:" + str(library).replace("/", "\\")) if runner.windows \
                else str(library)
        head = [library_argument, "cross-check", model] if version == "2.0" \
            else [library_argument, model, "cross-check"]
        command = [*launch, str(runner.driver(version, model)), *head, *arguments]
        # Under wine, a run that fails is tried once more: beside the suite's other wine runs,
        # wine has exited 1 at start with nothing on stderr. A binary that fails fails again.
        for _ in range(2 if runner.windows else 1):
            done = subprocess.run(command, input=rows, capture_output=True, text=True,
                                  timeout=300, env=wine_environment() if runner.windows else None)
            if done.returncode == 0:
                break
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    if done.returncode != 0:
        raise RuntimeError(f"{platform} {model} {interface}: the driver exited "
                           f"{done.returncode}: {done.stderr[-2000:]}")
    lines = done.stdout.replace("\r\n", "\n").strip().splitlines()
    values = np.array([[int(word, 16) for word in line.split()] for line in lines],
                      dtype=np.uint64).view(np.float64)
    if values.shape[0] != len(times):
        raise RuntimeError(f"{platform} {model} {interface}: {values.shape[0]} rows printed, "
                           f"{len(times)} expected")
    return values[:, picks]


def origin(platform, fmi_version):
    """What computed the folder's result: 'own' (its binary, here), 'host' (fmpy, the host's
    binary, which is the folder's own on the host) or 'copied' (the host's, the binary cannot
    run here)."""
    if platform == HOST[fmi_version]:
        return "host"
    return "own" if runnable(platform, fmi_version) else "copied"
