# Cross toolchain: Debian's gcc-arm-none-eabi + libnewlib-arm-none-eabi
# (+ libstdc++-arm-none-eabi-dev for the C++ headers; no libstdc++ library is linked).
#
# The CPU comes from the board: boards/<LUMAVEL_BOARD>/board.cmake sets
# LUMAVEL_BOARD_FLAGS (e.g. -mcpu=cortex-m3 -mthumb and capacity defines) so
# that every target of the tree, the core included, is built for that CPU.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)
# Bare metal: try_compile cannot link an executable without a board's startup.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES LUMAVEL_BOARD LUMAVEL_CPU)

set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_ASM_COMPILER arm-none-eabi-gcc)
find_program(LUMAVEL_OBJCOPY arm-none-eabi-objcopy)
find_program(LUMAVEL_SIZE arm-none-eabi-size)
find_program(LUMAVEL_NM arm-none-eabi-nm)

set(LUMAVEL_BOARD_FLAGS "")
if(LUMAVEL_BOARD AND EXISTS ${CMAKE_CURRENT_LIST_DIR}/../boards/${LUMAVEL_BOARD}/board.cmake)
  include(${CMAKE_CURRENT_LIST_DIR}/../boards/${LUMAVEL_BOARD}/board.cmake)
endif()

# Extra flags for every target, e.g. the core's capacities for a measurement run:
#   -DLUMAVEL_EXTRA_FLAGS="-DLUMAVEL_MAX_COLS=128 -DLUMAVEL_MAX_ROWS=1 -DLUMAVEL_MAX_KERNELS=4"
if(LUMAVEL_EXTRA_FLAGS)
  string(APPEND LUMAVEL_BOARD_FLAGS " ${LUMAVEL_EXTRA_FLAGS}")
endif()
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES LUMAVEL_EXTRA_FLAGS)

# PRId64 & co. need newlib's headers ahead of GCC's (see docs notes).
set(_lumavel_common "${LUMAVEL_BOARD_FLAGS} -isystem /usr/include/newlib -ffunction-sections -fdata-sections -fstack-usage")
set(CMAKE_C_FLAGS_INIT "${_lumavel_common}")
set(CMAKE_CXX_FLAGS_INIT "${_lumavel_common} -fno-exceptions -fno-rtti -fno-threadsafe-statics -fno-use-cxa-atexit")
set(CMAKE_ASM_FLAGS_INIT "${LUMAVEL_BOARD_FLAGS}")
# Size first; the link drops unused sections and writes no libc start files.
set(CMAKE_C_FLAGS_RELEASE_INIT "-Os")
set(CMAKE_CXX_FLAGS_RELEASE_INIT "-Os")
set(CMAKE_C_FLAGS_MINSIZEREL_INIT "-Os")
set(CMAKE_CXX_FLAGS_MINSIZEREL_INIT "-Os")
set(CMAKE_EXE_LINKER_FLAGS_INIT "${LUMAVEL_BOARD_FLAGS} -nostartfiles -Wl,--gc-sections")
# Read by cmake/LumavelFirmwareImage.cmake: images link newlib-nano.
set(LUMAVEL_IMAGE_LINK_OPTIONS --specs=nano.specs)

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
