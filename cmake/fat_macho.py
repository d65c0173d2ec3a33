"""Combines thin Mach-O files of different architectures into one universal ("fat") Mach-O, what
Apple's lipo -create makes: FMI 2 has a single darwin64 folder, and an importer on an Apple
silicon Mac (fmpy) loads binaries/darwin64/<Model>.dylib as on an Intel Mac, so that one file
carries both the x86_64 and the arm64 code (tools/check_macho.py checks each slice).

Layout (<mach-o/fat.h>, big-endian): fat_header (magic 0xcafebabe, number of slices), one fat_arch
per slice (CPU type, CPU subtype, file offset, size, alignment as a power of two), then each thin
file unchanged at an offset aligned to its page size (16 KiB for arm64, 4 KiB for x86_64). The
slices are in the order given; the output depends on the inputs' bytes alone.

    python3 cmake/fat_macho.py OUTPUT THIN...
"""
import os
import pathlib
import struct
import sys

FAT_MAGIC = 0xCAFEBABE
THIN_MAGIC_64 = 0xFEEDFACF  # little-endian 64-bit Mach-O, as x86_64 and arm64 use
PAGE_ALIGNMENT = {0x01000007: 12, 0x0100000C: 14}  # CPU_TYPE_X86_64, CPU_TYPE_ARM64


def thin_cpu(data, name):
    magic, cputype, cpusubtype = struct.unpack_from("<III", data)
    if magic != THIN_MAGIC_64:
        raise SystemExit(f"fat_macho.py: {name} is not a thin 64-bit Mach-O file")
    if cputype not in PAGE_ALIGNMENT:
        raise SystemExit(f"fat_macho.py: {name}: CPU type {cputype:#x} unknown here")
    return cputype, cpusubtype


def combine(thin_files):
    slices = [(path, pathlib.Path(path).read_bytes()) for path in thin_files]
    cpus = [thin_cpu(data, path) for path, data in slices]
    if len({cpu for cpu, _ in cpus}) != len(cpus):
        raise SystemExit("fat_macho.py: two slices of the same CPU type")
    header = struct.pack(">II", FAT_MAGIC, len(slices))
    offset = len(header) + 20 * len(slices)
    entries, body = b"", b""
    for (path, data), (cputype, cpusubtype) in zip(slices, cpus):
        align = PAGE_ALIGNMENT[cputype]
        start = -(-offset // (1 << align)) << align  # rounded up to the slice's page
        body += b"\0" * (start - offset) + data
        entries += struct.pack(">IIIII", cputype, cpusubtype, start, len(data), align)
        offset = start + len(data)
    return header + entries + body


if __name__ == "__main__":
    if len(sys.argv) < 4:
        raise SystemExit(__doc__)
    output = pathlib.Path(sys.argv[1])
    partial = output.with_name(output.name + ".partial")
    partial.write_bytes(combine(sys.argv[2:]))
    os.chmod(partial, 0o755)  # as the linker leaves a dylib
    os.replace(partial, output)
