# Cross-compiles the FMU for 64-bit Windows with Debian's mingw-w64 (package
# gcc-mingw-w64-x86-64-win32): cmake -S . -B build-win64 -DCMAKE_TOOLCHAIN_FILE=cmake/mingw-w64-x86_64.cmake
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)

set(AK_MINGW_PREFIX x86_64-w64-mingw32)
find_program(CMAKE_C_COMPILER NAMES ${AK_MINGW_PREFIX}-gcc-win32 ${AK_MINGW_PREFIX}-gcc)
if(NOT CMAKE_C_COMPILER)
  message(FATAL_ERROR "No ${AK_MINGW_PREFIX}-gcc: install mingw-w64 (Debian: gcc-mingw-w64-x86-64-win32)")
endif()
find_program(CMAKE_RC_COMPILER NAMES ${AK_MINGW_PREFIX}-windres)
set(CMAKE_FIND_ROOT_PATH /usr/${AK_MINGW_PREFIX})

# Headers and libraries from the mingw sysroot only; programs (Python for the FMI headers) from the host.
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# Reproducible programs: no link time in the PE header (the FMU DLLs get it in CMakeLists.txt).
set(CMAKE_EXE_LINKER_FLAGS_INIT "-Wl,--no-insert-timestamp")
