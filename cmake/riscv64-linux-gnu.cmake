# Cross-compiles for 64-bit RISC-V Linux with Debian's gcc-riscv64-linux-gnu (and
# libc6-dev-riscv64-cross); the binaries run on x86-64 under qemu-user:
#   qemu-riscv64 -L /usr/riscv64-linux-gnu build-riscv64/fmi3_driver ...
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR riscv64)

find_program(CMAKE_C_COMPILER NAMES riscv64-linux-gnu-gcc)
if(NOT CMAKE_C_COMPILER)
  message(FATAL_ERROR "No riscv64-linux-gnu-gcc: install gcc-riscv64-linux-gnu libc6-dev-riscv64-cross")
endif()
# RV64GC with hardware doubles (lp64d), the base every 64-bit RISC-V Linux distribution targets,
# stated rather than left to the compiler's default. Its D extension has fused multiply-adds:
# -ffp-contract=off (every target, CMakeLists.txt) keeps them out, as on aarch64.
set(CMAKE_C_FLAGS_INIT "-march=rv64gc -mabi=lp64d")
set(CMAKE_FIND_ROOT_PATH /usr/riscv64-linux-gnu)
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-riscv64 -L /usr/riscv64-linux-gnu)

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
