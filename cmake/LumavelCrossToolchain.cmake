# What every cross toolchain file of the tree shares (arm-none-eabi.cmake,
# riscv64-unknown-elf.cmake include it): a bare-metal Generic system, the GNU
# tools by their prefix, the board's CPU flags and LUMAVEL_EXTRA_FLAGS in
# LUMAVEL_BOARD_FLAGS, the board's optimisation, and finding programs on the host only.
# Set LUMAVEL_TOOL_PREFIX (e.g. arm-none-eabi-) and CMAKE_SYSTEM_PROCESSOR first.
set(CMAKE_SYSTEM_NAME Generic)
# Bare metal: try_compile cannot link an executable without a board's startup.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES LUMAVEL_BOARD LUMAVEL_CPU LUMAVEL_EXTRA_FLAGS)

set(CMAKE_C_COMPILER ${LUMAVEL_TOOL_PREFIX}gcc)
set(CMAKE_CXX_COMPILER ${LUMAVEL_TOOL_PREFIX}g++)
set(CMAKE_ASM_COMPILER ${LUMAVEL_TOOL_PREFIX}gcc)
find_program(LUMAVEL_OBJCOPY ${LUMAVEL_TOOL_PREFIX}objcopy)
find_program(LUMAVEL_SIZE ${LUMAVEL_TOOL_PREFIX}size)
find_program(LUMAVEL_NM ${LUMAVEL_TOOL_PREFIX}nm)

# The CPU comes from the board: boards/<LUMAVEL_BOARD>/board.cmake sets
# LUMAVEL_BOARD_FLAGS (e.g. -mcpu=cortex-m3 -mthumb, -march/-mabi, capacity
# defines) so that every target of the tree, the core included, is built for it.
set(LUMAVEL_BOARD_FLAGS "")
if(LUMAVEL_BOARD AND EXISTS ${CMAKE_CURRENT_LIST_DIR}/../boards/${LUMAVEL_BOARD}/board.cmake)
  include(${CMAKE_CURRENT_LIST_DIR}/../boards/${LUMAVEL_BOARD}/board.cmake)
endif()
# Extra flags for every target, e.g. the core's capacities for a measurement run:
#   -DLUMAVEL_EXTRA_FLAGS="-DLUMAVEL_MAX_COLS=128 -DLUMAVEL_MAX_ROWS=1 -DLUMAVEL_MAX_KERNELS=4"
if(LUMAVEL_EXTRA_FLAGS)
  string(APPEND LUMAVEL_BOARD_FLAGS " ${LUMAVEL_EXTRA_FLAGS}")
endif()

# The link drops unused sections and writes no libc start files.
set(CMAKE_ASM_FLAGS_INIT "${LUMAVEL_BOARD_FLAGS}")
# Optimisation, the board's choice (board.cmake: LUMAVEL_BOARD_OPT): -Os where
# the flash is the limit (the blue pill, the 8 KiB part), -O3 otherwise (the
# QEMU images whose instructions per frame docs/benchmarks.md counts). Set as
# the Release flags themselves: CMake appends its own -O3 to a *_RELEASE_INIT
# value, which is how an "-Os" here was built at -O3 until 2026-12-07.
if(NOT LUMAVEL_BOARD_OPT)
  set(LUMAVEL_BOARD_OPT -O3)
endif()
set(CMAKE_C_FLAGS_RELEASE "${LUMAVEL_BOARD_OPT} -DNDEBUG" CACHE STRING "the board's optimisation (LUMAVEL_BOARD_OPT)" FORCE)
set(CMAKE_CXX_FLAGS_RELEASE "${LUMAVEL_BOARD_OPT} -DNDEBUG" CACHE STRING "the board's optimisation (LUMAVEL_BOARD_OPT)" FORCE)
set(CMAKE_C_FLAGS_MINSIZEREL_INIT "-Os")
set(CMAKE_CXX_FLAGS_MINSIZEREL_INIT "-Os")

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
