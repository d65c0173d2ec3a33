# Cross-compiles the FMU for 32-bit Windows (x86-windows, FMI 2 win32) with Debian's mingw-w64
# (package gcc-mingw-w64-i686-win32). SSE2 arithmetic (-msse2 -mfpmath=sse), not the x87 unit's
# extended precision, so that every double operation rounds as on the 64-bit platforms; no FMA
# contraction (CMakeLists.txt). Baseline CPU: pentium4, the first with SSE2.
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86)

set(AK_MINGW_PREFIX i686-w64-mingw32)
find_program(CMAKE_C_COMPILER NAMES ${AK_MINGW_PREFIX}-gcc-win32 ${AK_MINGW_PREFIX}-gcc)
if(NOT CMAKE_C_COMPILER)
  message(FATAL_ERROR "No ${AK_MINGW_PREFIX}-gcc: install mingw-w64 (Debian: gcc-mingw-w64-i686-win32)")
endif()
find_program(CMAKE_RC_COMPILER NAMES ${AK_MINGW_PREFIX}-windres)
set(CMAKE_FIND_ROOT_PATH /usr/${AK_MINGW_PREFIX})
set(CMAKE_C_FLAGS_INIT "-march=pentium4 -mtune=generic -msse2 -mfpmath=sse")

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# Reproducible programs: no link time in the PE header (the FMU DLLs get it in CMakeLists.txt).
set(CMAKE_EXE_LINKER_FLAGS_INIT "-Wl,--no-insert-timestamp")
