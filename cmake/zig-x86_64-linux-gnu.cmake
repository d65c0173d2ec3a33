# The compiler proof (preset zig-linux): the darwin builds' zig, for x86_64-linux (glibc), so that
# its binaries run here and print what gcc's print (tests/python/test_platforms.py).
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(AK_ZIG_TARGET x86_64-linux-gnu)
set(AK_ZIG_CPU x86_64)
include("${CMAKE_CURRENT_LIST_DIR}/zig.cmake")
