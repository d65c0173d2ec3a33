"""Releases a user can trust, the bounded part (scripts/release.sh does the full run: two clean
clones built and compared byte for byte): the packer gives the same bytes twice from one build tree
whatever the files' times, no build path or link time inside the binaries, one version everywhere,
SHA256SUMS that sha256sum -c accepts and that catches a changed byte, and release.sh refusing a
version without a CHANGELOG.md entry."""
import pathlib
import re
import shutil
import struct
import subprocess
import sys
import zipfile

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "cmake"))
from codegen.project import MODELS, VERSION  # noqa: E402
from zip_fmu import pack  # noqa: E402


@pytest.mark.parametrize("model", MODELS)
def test_two_packagings_are_byte_identical(model, tmp_path, fmu_path, euler_fmu_path):
    staged = ROOT / "build" / f"fmu_package_{model}"
    copy = shutil.copytree(staged, tmp_path / "staged")
    pack(copy, tmp_path / "one.fmu")
    for path in copy.rglob("*"):
        path.touch()  # other access and modification times
    pack(copy, tmp_path / "two.fmu")
    one = (tmp_path / "one.fmu").read_bytes()
    assert one == (tmp_path / "two.fmu").read_bytes()
    assert one == (ROOT / "dist" / f"{model}.fmu").read_bytes()


@pytest.mark.external  # reads the win64 DLL of the cross build
@pytest.mark.parametrize("model", MODELS)
def test_entries_carry_no_time_and_no_path(model, fmu_path, euler_fmu_path):
    with zipfile.ZipFile(ROOT / "dist" / f"{model}.fmu") as archive:
        entries = archive.infolist()
        assert [e.filename for e in entries] == sorted(e.filename for e in entries)
        assert {e.date_time for e in entries} == {(1980, 1, 2, 0, 0, 0)}
        assert {e.extra for e in entries} == {b""}
        linux = archive.read(f"binaries/linux64/{model}.so")
        windows = archive.read(f"binaries/win64/{model}.dll")
    for binary in (linux, windows):
        assert str(ROOT).encode() not in binary
        assert str(ROOT.resolve()).encode() not in binary
    pe_header = struct.unpack_from("<I", windows, 0x3C)[0]
    assert windows[pe_header:pe_header + 4] == b"PE\0\0"
    assert struct.unpack_from("<I", windows, pe_header + 8)[0] == 0  # TimeDateStamp


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
    (tmp_path / "README.md").write_text("not listed")
    subprocess.run(["bash", str(ROOT / "scripts" / "checksums.sh"), str(tmp_path)], check=True)
    listed = [line.split("  ")[1] for line in (tmp_path / "SHA256SUMS").read_text().splitlines()]
    assert listed == ["a.fmu", "sub/b.csv"]
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
