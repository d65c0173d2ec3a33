# Shared part of the zig cross toolchains (cmake/zig-<target>.cmake set AK_ZIG_TARGET, AK_ZIG_CPU,
# CMAKE_SYSTEM_NAME and CMAKE_SYSTEM_PROCESSOR, then include this): zig's clang (PyPI ziglang,
# pinned in requirements.txt) through the wrappers cmake/zig-cc, zig-ar and zig-ranlib. The target
# and CPU are explicit (zig compiles for the build machine's CPU only without -target), and with
# them the minimum OS version, which zig writes into the binary.
get_filename_component(_ak_zig_dir "${CMAKE_CURRENT_LIST_DIR}" ABSOLUTE)
set(CMAKE_C_COMPILER "${_ak_zig_dir}/zig-cc")
set(CMAKE_AR "${_ak_zig_dir}/zig-ar" CACHE FILEPATH "zig's llvm-ar")
set(CMAKE_RANLIB "${_ak_zig_dir}/zig-ranlib" CACHE FILEPATH "zig's llvm-ranlib")
set(CMAKE_C_FLAGS_INIT "-target ${AK_ZIG_TARGET} -mcpu=${AK_ZIG_CPU} ${AK_ZIG_EXTRA_FLAGS}")

# Nothing of the build machine: headers and libraries are zig's own for the target.
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# A dylib's install name is @rpath/<file>, not its build folder's path: two builds in two folders
# give the same bytes (scripts/release.sh), and no path of the build machine is shipped.
set(CMAKE_BUILD_WITH_INSTALL_NAME_DIR ON)
set(CMAKE_INSTALL_NAME_DIR "@rpath")
if(CMAKE_SYSTEM_NAME STREQUAL "Darwin")
  # No debug map: a Mach-O linker writes each object file's path (the build folder) into the
  # symbol table as stabs even without -g, and the LC_UUID hashes them; -S leaves them out.
  set(CMAKE_SHARED_LINKER_FLAGS_INIT "-Wl,-S")
endif()
