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
#
# The CPU comes from the board: boards/<LUMAVEL_BOARD>/board.cmake sets
# LUMAVEL_BOARD_FLAGS (-march, -mabi) so that every target of the tree, the
# core included, is built for that CPU.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR riscv32)
# Bare metal: try_compile cannot link an executable without a board's startup.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES LUMAVEL_BOARD LUMAVEL_CPU)

set(CMAKE_C_COMPILER riscv64-unknown-elf-gcc)
set(CMAKE_CXX_COMPILER riscv64-unknown-elf-g++)
set(CMAKE_ASM_COMPILER riscv64-unknown-elf-gcc)
find_program(LUMAVEL_OBJCOPY riscv64-unknown-elf-objcopy)
find_program(LUMAVEL_SIZE riscv64-unknown-elf-size)
find_program(LUMAVEL_NM riscv64-unknown-elf-nm)

set(LUMAVEL_BOARD_FLAGS "")
if(LUMAVEL_BOARD AND EXISTS ${CMAKE_CURRENT_LIST_DIR}/../boards/${LUMAVEL_BOARD}/board.cmake)
  include(${CMAKE_CURRENT_LIST_DIR}/../boards/${LUMAVEL_BOARD}/board.cmake)
endif()
if(LUMAVEL_EXTRA_FLAGS)
  string(APPEND LUMAVEL_BOARD_FLAGS " ${LUMAVEL_EXTRA_FLAGS}")
endif()
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES LUMAVEL_EXTRA_FLAGS)

set(_lumavel_shim ${CMAKE_CURRENT_LIST_DIR}/../boards/common/cxx-shim)
cmake_path(NORMAL_PATH _lumavel_shim)
# -ffreestanding for C only: it selects GCC's own stdint.h. C++ keeps the
# builtins (memcpy of 4 bytes is one load) and takes its headers from the shim.
set(_lumavel_common "${LUMAVEL_BOARD_FLAGS} -ffunction-sections -fdata-sections -fstack-usage -fno-asynchronous-unwind-tables -fno-unwind-tables")
set(CMAKE_C_FLAGS_INIT "${_lumavel_common} -ffreestanding")
set(CMAKE_CXX_FLAGS_INIT "${_lumavel_common} -isystem ${_lumavel_shim} -fno-exceptions -fno-rtti -fno-threadsafe-statics -fno-use-cxa-atexit")
set(CMAKE_ASM_FLAGS_INIT "${LUMAVEL_BOARD_FLAGS}")
set(CMAKE_C_FLAGS_RELEASE_INIT "-Os")
set(CMAKE_CXX_FLAGS_RELEASE_INIT "-Os")
set(CMAKE_C_FLAGS_MINSIZEREL_INIT "-Os")
set(CMAKE_CXX_FLAGS_MINSIZEREL_INIT "-Os")
# No C library, no start files: libgcc only (added last on the link line).
set(CMAKE_EXE_LINKER_FLAGS_INIT "${LUMAVEL_BOARD_FLAGS} -nostartfiles -nostdlib -Wl,--gc-sections")
set(CMAKE_C_STANDARD_LIBRARIES "-lgcc" CACHE STRING "" FORCE)
set(CMAKE_CXX_STANDARD_LIBRARIES "-lgcc" CACHE STRING "" FORCE)
# Read by cmake/LumavelFirmwareImage.cmake: the Arm toolchain links newlib-nano here.
set(LUMAVEL_IMAGE_LINK_OPTIONS "")

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
