"""Packs a staged FMU folder, FMI 2 or FMI 3, into a zip archive that depends on the files'
contents alone: entries sorted by path, each with the same fixed date and no extra fields (cmake -E
tar writes each file's access and change times, which differ from build to build), mode 755 or 644
from the file's executable bit. The date is 1980-01-02 00:00:00, or the UTC time of
SOURCE_DATE_EPOCH when it is set (https://reproducible-builds.org/specs/source-date-epoch/;
rounded down to even seconds and clamped to 1980..2107, what zip stores). Two builds of the same
sources give byte-identical .fmu files (scripts/release.sh checks it).

    python3 tools/zip_fmu.py STAGED_FOLDER ARCHIVE.fmu"""
import os
import pathlib
import sys
import time
import zipfile

DEFAULT_DATE = (1980, 1, 2, 0, 0, 0)


def fixed_date(environment=os.environ):
    """The one date of every entry: SOURCE_DATE_EPOCH's (seconds since 1970, UTC) or DEFAULT_DATE."""
    epoch = environment.get("SOURCE_DATE_EPOCH", "").strip()
    if not epoch:
        return DEFAULT_DATE
    if not epoch.isdigit():
        raise SystemExit(f"zip_fmu.py: SOURCE_DATE_EPOCH={epoch!r} is not a number of seconds")
    date = time.gmtime(int(epoch))[:6]
    date = min(max(date, (1980, 1, 1, 0, 0, 0)), (2107, 12, 31, 23, 59, 58))  # zip's range
    return date[:5] + (date[5] - date[5] % 2,)


def pack(folder, archive):
    folder = pathlib.Path(folder)
    date = fixed_date()
    files = sorted((p.relative_to(folder).as_posix(), p) for p in folder.rglob("*") if p.is_file())
    partial = pathlib.Path(str(archive) + ".partial")
    with zipfile.ZipFile(partial, "w") as out:
        for name, path in files:
            info = zipfile.ZipInfo(name, date_time=date)
            info.create_system = 3  # Unix, so that the mode below is read
            info.external_attr = (0o755 if os.access(path, os.X_OK) else 0o644) << 16
            info.compress_type = zipfile.ZIP_DEFLATED
            out.writestr(info, path.read_bytes(), compresslevel=9)
    os.replace(partial, archive)


if __name__ == "__main__":
    pack(*sys.argv[1:3])
