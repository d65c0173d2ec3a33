"""Releases a user can trust, the bounded part (scripts/release.sh does the full run: two clean
clones built and compared byte for byte): the one packer of the FMI 2 and FMI 3 FMUs gives the same
bytes twice from one build tree whatever the files' times, every entry with one date (fixed, or
SOURCE_DATE_EPOCH's) and mode 644 or 755, no build path or link time inside the binaries, one
version everywhere, SHA256SUMS of every file (README.md too) that sha256sum -c accepts and that
catches a changed byte, dist/README.md naming what the build writes, and release.sh refusing a
version without a CHANGELOG.md entry."""
import os
import pathlib
import re
import shutil
import struct
import subprocess
import zipfile

import pytest

from codegen.project import MODELS, VERSION
from tools.zip_fmu import DEFAULT_DATE, fixed_date, pack

ROOT = pathlib.Path(__file__).resolve().parents[2]


# (staged folder in build/, archive in dist/, binaries inside) of each model's FMI 2 and FMI 3 FMU
KINDS = {"fmi2": ("fmu_package_{}", "{}.fmu",
                  ["linux64/{}.so", "win64/{}.dll", "win32/{}.dll", "darwin64/{}.dylib"]),
         "fmi3": ("fmu3_package_{}", "fmi3/{}.fmu",
                  ["x86_64-linux/{}.so", "x86_64-windows/{}.dll", "aarch64-linux/{}.so",
                   "riscv64-linux/{}.so", "x86-windows/{}.dll", "x86_64-darwin/{}.dylib",
                   "aarch64-darwin/{}.dylib"])}
EPOCH = 1700000001  # 2023-11-14 22:13:21 UTC: zip keeps even seconds


def pack_twice(staged, tmp_path, monkeypatch, epoch=None):
    """Packs a copy of a staged FMU, touches every file (other times), packs it again."""
    if epoch is None:
        monkeypatch.delenv("SOURCE_DATE_EPOCH", raising=False)
    else:
        monkeypatch.setenv("SOURCE_DATE_EPOCH", str(epoch))
    copy = shutil.copytree(staged, tmp_path / "staged", dirs_exist_ok=True)
    pack(copy, tmp_path / "one.fmu")
    for path in copy.rglob("*"):
        os.utime(path, (EPOCH + 123457, EPOCH + 123457))  # other access and modification times
    pack(copy, tmp_path / "two.fmu")
    return (tmp_path / "one.fmu").read_bytes(), (tmp_path / "two.fmu").read_bytes()


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("model", MODELS)
def test_two_packagings_are_byte_identical(kind, model, tmp_path, monkeypatch, fmu_path,
                                           euler_fmu_path):
    staged, archive = (pattern.format(model) for pattern in KINDS[kind][:2])
    one, two = pack_twice(ROOT / "build" / staged, tmp_path, monkeypatch)
    assert one == two
    assert one == (ROOT / "dist" / archive).read_bytes()
    with zipfile.ZipFile(tmp_path / "one.fmu") as packed:
        assert {e.date_time for e in packed.infolist()} == {(1980, 1, 2, 0, 0, 0)}


@pytest.mark.parametrize("kind", KINDS)
def test_source_date_epoch_is_the_one_date(kind, tmp_path, monkeypatch, fmu_path):
    staged = ROOT / "build" / KINDS[kind][0].format(MODELS[0])
    one, two = pack_twice(staged, tmp_path, monkeypatch, epoch=EPOCH)
    assert one == two
    assert one != (ROOT / "dist" / KINDS[kind][1].format(MODELS[0])).read_bytes()
    with zipfile.ZipFile(tmp_path / "one.fmu") as packed:
        assert {e.date_time for e in packed.infolist()} == {(2023, 11, 14, 22, 13, 20)}
    for epoch, date in [("", DEFAULT_DATE), ("0", (1980, 1, 1, 0, 0, 0)),  # clamped to zip's range
                        ("5000000000", (2107, 12, 31, 23, 59, 58))]:
        assert fixed_date({"SOURCE_DATE_EPOCH": epoch}) == date


@pytest.mark.external  # reads the binaries of the cross builds
@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("model", MODELS)
def test_entries_carry_no_time_and_no_path(kind, model, fmu_path, euler_fmu_path):
    _, archive, binaries = KINDS[kind]
    with zipfile.ZipFile(ROOT / "dist" / archive.format(model)) as packed:
        entries = packed.infolist()
        assert [e.filename for e in entries] == sorted(e.filename for e in entries)
        assert {e.date_time for e in entries} == {DEFAULT_DATE}
        assert {e.extra for e in entries} == {b""}
        assert {e.create_system for e in entries} == {3}  # Unix: the mode below is read
        for entry in entries:
            executable = entry.filename.startswith("binaries/")
            assert entry.external_attr >> 16 == (0o755 if executable else 0o644), entry.filename
        found = [packed.read(f"binaries/{binary.format(model)}") for binary in binaries]
    for binary in found:
        assert str(ROOT).encode() not in binary
        assert str(ROOT.resolve()).encode() not in binary
    for windows in (binary for binary in found if binary[:2] == b"MZ"):  # x86_64 and x86
        pe_header = struct.unpack_from("<I", windows, 0x3C)[0]
        assert windows[pe_header:pe_header + 4] == b"PE\0\0"
        assert struct.unpack_from("<I", windows, pe_header + 8)[0] == 0  # TimeDateStamp


@pytest.mark.slow  # one LTO link
@pytest.mark.external  # links in the mingw-w64 build folder
@pytest.mark.parametrize("kind", KINDS)
def test_a_second_link_gives_the_same_dll(kind, tmp_path, fmu_path):
    """Two builds of one Windows DLL: build-win64's own link command run again, later, in another
    folder (as release.sh's second clone) gives the bytes of the DLL in dist/: no link time in the
    PE header. (ld derives the DLL's image base from the output path as written, relative here.)"""
    model = MODELS[0]
    folder = ROOT / "build-win64"
    target = model if kind == "fmi2" else f"{model}_fmi3"
    link = (folder / "CMakeFiles" / f"{target}.dir" / "link.txt").read_text().splitlines()[-1]
    output = re.search(r" -o (\S+\.dll) ", link).group(1)
    for name in ("CMakeFiles", "libkinematics_core.a"):  # the objects and libraries it links
        (tmp_path / name).symlink_to(folder / name)
    (tmp_path / output).parent.mkdir(parents=True)
    subprocess.run(link, shell=True, cwd=tmp_path, check=True)
    windows = next(b for b in KINDS[kind][2] if b.endswith(".dll")).format(model)
    with zipfile.ZipFile(ROOT / "dist" / KINDS[kind][1].format(model)) as packed:
        assert (tmp_path / output).read_bytes() == packed.read(f"binaries/{windows}")


def test_one_version_everywhere(fmu_path, euler_fmu_path):
    cache = (ROOT / "build" / "CMakeCache.txt").read_text()
    assert re.search(r"^CMAKE_PROJECT_VERSION:STATIC=(.*)$", cache, re.M).group(1) == VERSION
    assert f'set(AK_VERSION "{VERSION}")' in (ROOT / "cmake" / "generated.cmake").read_text()
    for model in MODELS:
        with zipfile.ZipFile(ROOT / "dist" / f"{model}.fmu") as archive:
            description = archive.read("modelDescription.xml").decode()
            documentation = archive.read("documentation/index.html").decode()
        assert re.search(r'^  version="([^"]*)"', description, re.M).group(1) == VERSION
        assert set(re.findall(r"version (\d+\.\d+\.\d+)", documentation)) == {VERSION}


def test_sha256sums_check_and_catch_a_changed_byte(tmp_path):
    (tmp_path / "sub").mkdir()
    (tmp_path / "a.fmu").write_bytes(b"first")
    (tmp_path / "sub" / "b.csv").write_bytes(b"second")
    (tmp_path / "README.md").write_text("shipped, so listed")
    subprocess.run(["bash", str(ROOT / "scripts" / "checksums.sh"), str(tmp_path)], check=True)
    listed = [line.split("  ")[1] for line in (tmp_path / "SHA256SUMS").read_text().splitlines()]
    assert listed == ["README.md", "a.fmu", "sub/b.csv"]
    check = ["sha256sum", "-c", "--quiet", "SHA256SUMS"]
    assert subprocess.run(check, cwd=tmp_path, capture_output=True).returncode == 0
    (tmp_path / "sub" / "b.csv").write_bytes(b"secone")
    assert subprocess.run(check, cwd=tmp_path, capture_output=True).returncode == 1


def test_release_refuses_a_version_without_changelog_entry(tmp_path):
    for name in ("scripts/release.sh", "codegen/project.py"):
        (tmp_path / name).parent.mkdir(exist_ok=True)
        shutil.copy(ROOT / name, tmp_path / name)
    (tmp_path / "CHANGELOG.md").write_text("# Changelog\n\n## 0.0.1\n- an older release\n")
    done = subprocess.run(["bash", str(tmp_path / "scripts" / "release.sh")], capture_output=True,
                          text=True, timeout=60)
    assert done.returncode == 1
    assert f"CHANGELOG.md has no entry for {VERSION}" in done.stderr


def test_dist_readme_names_what_the_build_writes(fmu_path, euler_fmu_path):
    dist = ROOT / "dist"
    readme = (dist / "README.md").read_text()
    named = set(re.findall(r"^- `([^`]+)`", readme, re.M))
    fmus = {f"{model}.fmu" for model in MODELS} | {f"fmi3/{model}.fmu" for model in MODELS}
    assert named == fmus | {"cross-check/", "ssp/RoundTrip.ssp", "SHA256SUMS"}
    built = {p.relative_to(dist).as_posix() for p in [*dist.glob("*.fmu"), *dist.glob("fmi3/*")]}
    assert built == fmus
    # python -m codegen writes it (codegen/docs.py): the working file is the committed one.
    committed = subprocess.run(["git", "show", ":dist/README.md"], cwd=ROOT, capture_output=True,
                               text=True, check=True).stdout
    assert committed == readme
