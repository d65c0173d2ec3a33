# Cross-compiles for 64-bit ARM Linux with Debian's gcc-aarch64-linux-gnu (and
# libc6-dev-arm64-cross); the binaries run on x86-64 under qemu-user:
#   qemu-aarch64 -L /usr/aarch64-linux-gnu build-aarch64/fmi3_driver ...
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)

find_program(CMAKE_C_COMPILER NAMES aarch64-linux-gnu-gcc)
if(NOT CMAKE_C_COMPILER)
  message(FATAL_ERROR "No aarch64-linux-gnu-gcc: install gcc-aarch64-linux-gnu libc6-dev-arm64-cross")
endif()
set(CMAKE_FIND_ROOT_PATH /usr/aarch64-linux-gnu)
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-aarch64 -L /usr/aarch64-linux-gnu)

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
