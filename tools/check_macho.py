"""Static check of a macOS binary of an FMU, which cannot run here: reads the Mach-O file (thin, or
universal with one slice per architecture) and, per slice, reports and checks
  - the CPU type (x86_64 or arm64) against the expected architectures;
  - the dynamic library's exported functions (its export trie, what dlsym finds; C names carry a
    leading underscore): every fmi2*/fmi3* function of the FMI header must be exported, and no
    other fmi* symbol;
  - the libraries it loads (LC_LOAD_DYLIB): only /usr/lib/libSystem.B.dylib, which every macOS
    has, and every undefined symbol bound to it (two-level namespace ordinal);
  - the minimum macOS version (LC_BUILD_VERSION or LC_VERSION_MIN_MACOSX), which must be stated.

    python3 tools/check_macho.py FILE.dylib ARCH[,ARCH] FUNCTIONS.txt
        ARCH: x86_64 or arm64; FUNCTIONS.txt: the required function names, one a line
Prints one line per slice; exit status 1 with the failures listed when a check fails.
The layouts are those of Apple's <mach-o/loader.h>, <mach-o/fat.h> and <mach-o/nlist.h>."""
import struct
import sys

CPU_NAMES = {0x01000007: "x86_64", 0x0100000C: "arm64", 7: "x86"}
LIBSYSTEM = "/usr/lib/libSystem.B.dylib"
LC_SYMTAB, LC_LOAD_DYLIB, LC_ID_DYLIB = 0x2, 0xC, 0xD
LC_LOAD_WEAK_DYLIB, LC_REEXPORT_DYLIB, LC_LAZY_LOAD_DYLIB = 0x80000018, 0x8000001F, 0x20
LC_LOAD_UPWARD_DYLIB = 0x80000023
LC_VERSION_MIN_MACOSX, LC_BUILD_VERSION = 0x24, 0x32
LC_DYLD_INFO, LC_DYLD_INFO_ONLY, LC_DYLD_EXPORTS_TRIE = 0x22, 0x80000022, 0x80000033
MH_DYLIB = 6
PLATFORM_MACOS = 1
N_STAB, N_TYPE, N_EXT, N_UNDF = 0xE0, 0x0E, 0x01, 0x0


def version(packed):
    """X.Y.Z nibbles xxxx.yy.zz of a Mach-O version word."""
    return f"{packed >> 16}.{(packed >> 8) & 0xFF}.{packed & 0xFF}"


def uleb(data, at):
    value = shift = 0
    while True:
        byte = data[at]
        at += 1
        value |= (byte & 0x7F) << shift
        shift += 7
        if byte < 0x80:
            return value, at


def export_trie(data, start, size):
    """Every name with a terminal node in the export trie at data[start:start+size]."""
    names, pending, seen = [], [(0, "")], set()
    while pending:
        node, prefix = pending.pop()
        if node in seen or node >= size:
            raise ValueError("malformed export trie")
        seen.add(node)
        at = start + node
        terminal, at = uleb(data, at)
        if terminal:
            names.append(prefix)
        at += terminal
        count = data[at]
        at += 1
        for _ in range(count):
            end = data.index(b"\0", at)
            label = data[at:end].decode()
            child, at = uleb(data, end + 1)
            pending.append((child, prefix + label))
    return names


def slices(data):
    """(offset, size) of every thin Mach-O inside data."""
    magic, = struct.unpack_from(">I", data)
    if magic == 0xCAFEBABE:
        count, = struct.unpack_from(">I", data, 4)
        return [struct.unpack_from(">II", data, 8 + 20 * i + 8) for i in range(count)]
    return [(0, len(data))]


def read_slice(data):
    """What the checks need of one thin 64-bit Mach-O."""
    magic, cputype, _, filetype, ncmds, _, _, _ = struct.unpack_from("<IiiIIIII", data)
    if magic != 0xFEEDFACF:
        raise ValueError(f"not a thin 64-bit little-endian Mach-O (magic {magic:#x})")
    info = {"cpu": CPU_NAMES.get(cputype & 0xFFFFFFFF, hex(cputype)), "dylib": filetype == MH_DYLIB,
            "libraries": [], "exports": None, "undefined": [], "min_os": None}
    at = 32
    for _ in range(ncmds):
        cmd, size = struct.unpack_from("<II", data, at)
        if cmd in (LC_LOAD_DYLIB, LC_LOAD_WEAK_DYLIB, LC_REEXPORT_DYLIB, LC_LAZY_LOAD_DYLIB,
                   LC_LOAD_UPWARD_DYLIB):
            name_offset, = struct.unpack_from("<I", data, at + 8)
            name = data[at + name_offset:at + size].split(b"\0", 1)[0].decode()
            info["libraries"].append(name)
        elif cmd == LC_BUILD_VERSION:
            platform, minos = struct.unpack_from("<II", data, at + 8)
            info["min_os"] = (("macOS " if platform == PLATFORM_MACOS else f"platform {platform} ")
                              + version(minos))
        elif cmd == LC_VERSION_MIN_MACOSX:
            info["min_os"] = "macOS " + version(struct.unpack_from("<I", data, at + 8)[0])
        elif cmd in (LC_DYLD_INFO, LC_DYLD_INFO_ONLY):
            export_off, export_size = struct.unpack_from("<II", data, at + 40)
            info["exports"] = export_trie(data, export_off, export_size) if export_size else []
        elif cmd == LC_DYLD_EXPORTS_TRIE:
            off, trie_size = struct.unpack_from("<II", data, at + 8)
            info["exports"] = export_trie(data, off, trie_size)
        elif cmd == LC_SYMTAB:
            symoff, nsyms, stroff, _ = struct.unpack_from("<IIII", data, at + 8)
            symbols = []
            for i in range(nsyms):
                strx, ntype, _, desc, _ = struct.unpack_from("<IBBHQ", data, symoff + 16 * i)
                name = data[stroff + strx:data.index(b"\0", stroff + strx)].decode()
                symbols.append((name, ntype, desc))
            info["symbols"] = symbols
        at += size
    for name, ntype, desc in info.get("symbols", []):
        if not ntype & N_STAB and ntype & N_EXT and ntype & N_TYPE == N_UNDF:
            info["undefined"].append((name, (desc >> 8) & 0xFF))  # library ordinal, 1-based
    return info


def check(path, architectures, required):
    """The failures (empty: all good) and one report line per slice."""
    data = open(path, "rb").read()
    failures, lines, found = [], [], []
    for offset, size in slices(data):
        try:
            info = read_slice(data[offset:offset + size])
        except (ValueError, struct.error, IndexError) as error:
            failures.append(f"{path}: slice at {offset}: {error}")
            continue
        cpu = info["cpu"]
        found.append(cpu)
        fail = [] if info["dylib"] else ["not a dynamic library (MH_DYLIB)"]
        exports = set(info["exports"] or [])
        missing = sorted(f for f in required if "_" + f not in exports)
        extra = sorted(e for e in exports if e.startswith("_fmi") and e[1:] not in required)
        if missing:
            fail.append(f"not exported: {', '.join(missing)}")
        if extra:
            fail.append(f"exports beyond the FMI header: {', '.join(extra)}")
        if info["libraries"] != [LIBSYSTEM]:
            fail.append(f"loads {info['libraries']}, not only {LIBSYSTEM}")
        unbound = [name for name, ordinal in info["undefined"]
                   if not 1 <= ordinal <= len(info["libraries"])
                   or info["libraries"][ordinal - 1] != LIBSYSTEM]
        if unbound:
            fail.append(f"undefined symbols not from libSystem: {', '.join(unbound)}")
        if info["min_os"] is None:
            fail.append("no minimum macOS version (LC_BUILD_VERSION, LC_VERSION_MIN_MACOSX)")
        failures += [f"{path} [{cpu}]: {f}" for f in fail]
        lines.append(f"{path} [{cpu}]: {len(exports)} exports ({len(required)} FMI functions), "
                     f"{len(info['undefined'])} undefined symbols from {', '.join(info['libraries'])}, "
                     f"minimum {info['min_os']}")
    if sorted(found) != sorted(architectures):
        failures.append(f"{path}: architectures {found}, expected {architectures}")
    return failures, lines


if __name__ == "__main__":
    if len(sys.argv) != 4:
        raise SystemExit(__doc__)
    names = {line.strip() for line in open(sys.argv[3]) if line.strip()}
    problems, report = check(sys.argv[1], sys.argv[2].split(","), names)
    print("\n".join(report + problems))
    sys.exit(1 if problems else 0)
