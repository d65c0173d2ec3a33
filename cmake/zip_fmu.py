"""Packs a staged FMU folder into a zip archive that depends on the files' contents alone: entries
in sorted order, each with the same fixed date and no extra fields (cmake -E tar writes each
file's access and change times, which differ from build to build), mode 755 or 644 from the
file's executable bit. Two builds of the same sources give byte-identical .fmu files
(scripts/release.sh checks it).

    python3 cmake/zip_fmu.py STAGED_FOLDER ARCHIVE.fmu"""
import os
import pathlib
import sys
import zipfile


def pack(folder, archive):
    folder = pathlib.Path(folder)
    files = sorted(p for p in folder.rglob("*") if p.is_file())
    partial = pathlib.Path(str(archive) + ".partial")
    with zipfile.ZipFile(partial, "w") as out:
        for path in files:
            info = zipfile.ZipInfo(path.relative_to(folder).as_posix(), date_time=(1980, 1, 2, 0, 0, 0))
            info.create_system = 3  # Unix, so that the mode below is read
            info.external_attr = (0o755 if os.access(path, os.X_OK) else 0o644) << 16
            info.compress_type = zipfile.ZIP_DEFLATED
            out.writestr(info, path.read_bytes(), compresslevel=9)
    os.replace(partial, archive)


if __name__ == "__main__":
    pack(*sys.argv[1:3])
