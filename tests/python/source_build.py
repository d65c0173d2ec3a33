"""Rebuilding a source FMU the way sources/buildDescription.xml says: fmpy's builder (FMPy 0.3.32)
compiles the <SourceFile>s but links no <Library>, so the external libraries named there are
passed to its CMake as the link's standard libraries; and the libraries an ELF binary needs."""
import re
import subprocess
import xml.etree.ElementTree as ET

from fmpy.build import build_platform_binary


def external_libraries(unzipdir):
    root = ET.parse(f"{unzipdir}/sources/buildDescription.xml").getroot()
    return [library.get("name") for library in root.iter("Library") if library.get("external") == "true"]


def build_from_sources(unzipdir, build_dir):
    """fmpy's build of unzipdir's sources, warnings as errors, linked with its <Library>s."""
    libraries = " ".join(f"-l{name}" for name in external_libraries(unzipdir))
    build_platform_binary(unzipdir, build_dir=build_dir, all_warnings=True,
                          cmake_options={"CMAKE_COMPILE_WARNING_AS_ERROR:BOOL": "ON",
                                         "CMAKE_C_STANDARD_LIBRARIES:STRING": libraries})


def needed_libraries(binary):
    """The DT_NEEDED entries of an ELF shared library (readelf -d)."""
    dynamic = subprocess.run(["readelf", "-d", str(binary)], capture_output=True, text=True,
                             check=True).stdout
    return re.findall(r"\(NEEDED\)\s+Shared library: \[([^\]]+)\]", dynamic)
