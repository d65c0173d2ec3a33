# The 32-bit x86 proof build (preset x86-musl): the FMU sources with the x86-windows flags
# (pentium4, SSE2 arithmetic, no x87 extended precision) for static musl executables that run
# here natively, where 32-bit wine cannot be installed (docs/platforms.md).
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR x86)
set(AK_ZIG_TARGET x86-linux-musl)
set(AK_ZIG_CPU pentium4)
set(AK_ZIG_EXTRA_FLAGS "-msse2 -mfpmath=sse")
include("${CMAKE_CURRENT_LIST_DIR}/zig.cmake")
