# Cross toolchain for RV32 boards: Debian's gcc-riscv64-unknown-elf (its
# multilibs cover rv32imac/ilp32, rv32im (used for rv32imc), rv32e/ilp32e
# (rv32ec), rv32em (rv32emc) and more: riscv64-unknown-elf-gcc -print-multi-lib).
#
# Debian ships no C++ library headers and no C library for this compiler
# except picolibc (1 GB installed); the firmware needs neither: C++ headers come
# from the small shim boards/common/cxx-shim (see its README), the four memory
# functions from boards/common/mem_routines.cpp, and images link with
# -nostdlib against libgcc alone (64-bit division; multiply and divide on cores
# without M).
set(CMAKE_SYSTEM_PROCESSOR riscv32)
set(LUMAVEL_TOOL_PREFIX riscv64-unknown-elf-)
include(${CMAKE_CURRENT_LIST_DIR}/LumavelCrossToolchain.cmake)

set(_lumavel_shim ${CMAKE_CURRENT_LIST_DIR}/../boards/common/cxx-shim)
cmake_path(NORMAL_PATH _lumavel_shim)
# -ffreestanding for C only: it selects GCC's own stdint.h. C++ keeps the
# builtins (memcpy of 4 bytes is one load) and takes its headers from the shim.
set(_lumavel_common "${LUMAVEL_BOARD_FLAGS} -ffunction-sections -fdata-sections -fstack-usage -fno-asynchronous-unwind-tables -fno-unwind-tables")
set(CMAKE_C_FLAGS_INIT "${_lumavel_common} -ffreestanding")
set(CMAKE_CXX_FLAGS_INIT "${_lumavel_common} -isystem ${_lumavel_shim} -fno-exceptions -fno-rtti -fno-threadsafe-statics -fno-use-cxa-atexit")
# No C library, no start files: libgcc only (added last on the link line).
set(CMAKE_EXE_LINKER_FLAGS_INIT "${LUMAVEL_BOARD_FLAGS} -nostartfiles -nostdlib -Wl,--gc-sections")
set(CMAKE_C_STANDARD_LIBRARIES "-lgcc" CACHE STRING "" FORCE)
set(CMAKE_CXX_STANDARD_LIBRARIES "-lgcc" CACHE STRING "" FORCE)
# Read by cmake/LumavelFirmwareImage.cmake: the Arm toolchain links newlib-nano here.
set(LUMAVEL_IMAGE_LINK_OPTIONS "")
