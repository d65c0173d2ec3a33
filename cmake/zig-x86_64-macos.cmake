# x86_64-darwin (Intel Macs) with zig: macOS 10.13 or later, baseline x86-64 (SSE2, no FMA).
set(CMAKE_SYSTEM_NAME Darwin)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(AK_ZIG_TARGET x86_64-macos.10.13)
set(AK_ZIG_CPU x86_64)
include("${CMAKE_CURRENT_LIST_DIR}/zig.cmake")
