# aarch64-darwin (Apple silicon) with zig: macOS 11.0 (the first for Apple silicon) or later,
# CPU apple_m1, the first Apple silicon Mac.
set(CMAKE_SYSTEM_NAME Darwin)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(AK_ZIG_TARGET aarch64-macos.11.0)
set(AK_ZIG_CPU apple_m1)
include("${CMAKE_CURRENT_LIST_DIR}/zig.cmake")
