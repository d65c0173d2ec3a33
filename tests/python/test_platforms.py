"""The same bits on every platform that runs here (docs/platforms.md): for every model and FMI
version, our own masters (tools/fmu_driver.c for FMI 2: 400 co-simulation steps of fixed inputs;
tools/fmi3_driver.c for FMI 3: every sequence and frame, with the directional, adjoint and output
derivatives) drive each platform's binary, and every printed value must have the bits that the
x86_64-linux binary of the FMU (gcc) prints, every call the same status. AttitudePropagator's
outputs come from its integrated states: the integration is compared too.

    x86_64-linux (zig)    the darwin builds' compiler, for x86_64-linux (preset zig-linux):
                          proves zig compiles our sources to the same arithmetic as gcc
    aarch64-linux         under qemu-aarch64 (preset aarch64)
    riscv64-linux         under qemu-riscv64 (preset riscv64)
    x86_64-windows        under wine (preset windows)
    x86 (linux-musl)      the 32-bit x86 proof build (preset x86-musl): the FMU's sources with
                          the x86-windows flags, statically linked into the driver, run natively
    x86-windows           under a 32-bit wine, when one is installed (not on Debian 12 here)
Each test reports how many values it compared."""
import functools
import os
import pathlib
import shutil
import subprocess

import numpy as np
import pytest

from codegen import project
from conftest import fmu_files
from fmi3_support import unzipped

# One wine prefix (build-win64/wineprefix) for every wine test file: with pytest-xdist they run in
# one worker (--dist loadgroup), so that two wine processes never create the prefix at once.
pytestmark = [pytest.mark.xdist_group("wine"), pytest.mark.external]

ROOT = pathlib.Path(__file__).resolve().parents[2]
STEPS = {2: "400", 3: "16"}
VALUE_LINES = ("outputs ", "directional ", "adjoint ", "output derivatives ")
EXTENSION = {"linux": "so", "windows": "dll"}
FMI2_FOLDER = {"x86_64-linux": "linux64", "x86_64-windows": "win64", "x86-windows": "win32"}


def run(command, **kwargs):
    done = subprocess.run([str(part) for part in command], capture_output=True, text=True,
                          timeout=900, **kwargs)
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-2000:]
    return done.stdout.replace("\r\n", "\n")


def fmu_binary(model, fmi, platform):
    """The binary of the platform packaged in dist/<model>.fmu (FMI 2) or dist/fmi3/."""
    if fmi == 2:
        folder, name = pathlib.Path(fmu_files(model)[0]), FMI2_FOLDER[platform]
    else:
        folder, name = pathlib.Path(unzipped(model)[0]), platform
    path = folder / "binaries" / name / f"{model}.{EXTENSION[platform.split('-')[1]]}"
    assert path.is_file(), f"the FMI {fmi} FMU of {model} holds no {path.name} for {platform}"
    return path


def driver_arguments(fmi, model, library):
    """fmu_driver LIBRARY STEPS MODEL, fmi3_driver LIBRARY MODEL STEPS."""
    return [library, STEPS[2], model] if fmi == 2 else [library, model, STEPS[3]]


def built(path):
    assert path.is_file(), f"{path.relative_to(ROOT)} is missing: bash scripts/test.sh builds it"
    return path


def driver(build, fmi, suffix=""):
    return built(ROOT / build / (("fmu_driver" if fmi == 2 else "fmi3_driver") + suffix))


def wine_environment():
    return dict(os.environ, WINEPREFIX=str(ROOT / "build-win64" / "wineprefix"), WINEDEBUG="-all",
                WINEDLLOVERRIDES="mscoree,mshtml=")


def windows_path(path):
    return "Z:" + str(path).replace("/", "\\")


def wine():
    for candidate in ("wine64", "wine", "/usr/lib/wine/wine64"):
        found = shutil.which(candidate)
        if found:
            return found
    pytest.fail("wine is missing: bash scripts/setup.sh --with-wine installs Debian's wine64")


def wine32():
    """A wine that runs 32-bit programs (Debian's wine32:i386), or None."""
    loader = pathlib.Path("/usr/lib/wine/wine")
    return str(loader) if loader.is_file() and shutil.which("wine") else None


def x86_64_linux(model, fmi):
    library = fmu_binary(model, fmi, "x86_64-linux")
    return run([driver("build", fmi)] + driver_arguments(fmi, model, library))


def zig_linux(model, fmi):
    folder = "fmu/binaries/linux64" if fmi == 2 else "fmu3/binaries/x86_64-linux"
    library = built(ROOT / "build-zig-linux" / folder / f"{model}.so")
    return run([driver("build-zig-linux", fmi)] + driver_arguments(fmi, model, library))


def under_qemu(arch, model, fmi):
    """The driver of build-<arch> under qemu-<arch>, with the C library of Debian's cross
    compiler for <arch>."""
    qemu = shutil.which(f"qemu-{arch}") or pytest.fail(f"qemu-{arch} missing: bash scripts/setup.sh")
    # FMI 2 has no <arch>-linux platform: its binary is the test build's, not the FMU's.
    library = (built(ROOT / f"build-{arch}" / "fmu" / "binaries" / "linux64" / f"{model}.so")
               if fmi == 2 else fmu_binary(model, fmi, f"{arch}-linux"))
    return run([qemu, "-L", f"/usr/{arch}-linux-gnu", driver(f"build-{arch}", fmi)]
               + driver_arguments(fmi, model, library))


def aarch64_linux(model, fmi):
    return under_qemu("aarch64", model, fmi)


def riscv64_linux(model, fmi):
    return under_qemu("riscv64", model, fmi)


def x86_64_windows(model, fmi):
    exe = driver("build-win64", fmi, ".exe")
    library = windows_path(fmu_binary(model, fmi, "x86_64-windows"))
    return run([wine(), exe] + driver_arguments(fmi, model, library), env=wine_environment())


def x86_linux_musl(model, fmi):
    exe = built(ROOT / "build-x86-musl" / f"{'fmu_driver' if fmi == 2 else 'fmi3_driver'}_{model}")
    return run([exe] + driver_arguments(fmi, model, "-"))  # the model is linked in


def x86_windows(model, fmi):
    loader = wine32() or pytest.skip(
        "no 32-bit wine (Debian's wine32:i386 is not installable here): the x86 code is proven by "
        "the x86-linux-musl build instead")
    exe = driver("build-win32", fmi, ".exe")
    library = windows_path(fmu_binary(model, fmi, "x86-windows"))
    return run([loader, exe] + driver_arguments(fmi, model, library), env=wine_environment())


PLATFORMS = {"x86_64-linux-zig": zig_linux, "aarch64-linux": aarch64_linux,
             "riscv64-linux": riscv64_linux, "x86_64-windows": x86_64_windows,
             "x86-linux-musl": x86_linux_musl, "x86-windows": x86_windows}


@functools.lru_cache(maxsize=None)
def reference(model, fmi):
    return x86_64_linux(model, fmi)


def split(printout, fmi):
    """(every printed value as its IEEE 754 bits, every other word in order: names, step numbers,
    call statuses)."""
    values, rest = [], []
    lines = printout.strip().splitlines()
    for number, line in enumerate(lines):
        words = line.split()
        if fmi == 2 and number >= 2:  # "k y1 y2 ...", each y printed with 17 digits
            rest.append(words[0])
            values += [float(word) for word in words[1:]]
        elif fmi == 3 and line.startswith(VALUE_LINES):
            head = [w for w in words if len(w) != 16]
            rest.append(" ".join(head))
            values += [int(w, 16) for w in words if len(w) == 16]
        else:
            rest.append(line)
    bits = (np.array(values, dtype=np.float64).view(np.uint64) if fmi == 2
            else np.array(values, dtype=np.uint64))
    return bits, rest


def ulps(a, b):
    """Distance of two arrays of double bits in units in the last place, across zero too: the bits
    as sign and magnitude mapped onto ordered integers."""
    def ordered(bits):
        signed = bits.view(np.int64)
        return np.where(signed < 0, -(signed & np.int64(0x7FFFFFFFFFFFFFFF)), signed)
    return np.abs(ordered(a) - ordered(b))


@pytest.mark.slow  # qemu, wine, 24 sequences x 2 frames
@pytest.mark.parametrize("platform", PLATFORMS)
@pytest.mark.parametrize("fmi", [2, 3], ids=["fmi2", "fmi3"])
@pytest.mark.parametrize("model", project.MODELS)
def test_platform_prints_the_bits_of_x86_64_linux(model, fmi, platform, report):
    expected_bits, expected_rest = split(reference(model, fmi), fmi)
    printout = PLATFORMS[platform](model, fmi)
    bits, rest = split(printout, fmi)
    assert expected_bits.size > 0 and np.isfinite(expected_bits.view(np.float64)).all()
    if fmi == 3:
        assert "errors 0" in printout
    assert rest == expected_rest  # the same variables, steps and call statuses
    assert bits.size == expected_bits.size
    differ = np.flatnonzero(bits != expected_bits)
    assert differ.size == 0, (
        f"{platform}: {differ.size} of {bits.size} values differ from x86_64-linux, by up to "
        f"{ulps(bits, expected_bits).max()} ulp; the first at value indices {differ[:5].tolist()}")
    report(f"{model} FMI {fmi} {platform}: {bits.size} values and {len(rest)} other words "
           f"bit-identical to x86_64-linux (gcc)")
