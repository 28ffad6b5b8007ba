# Cross toolchain: Debian's gcc-arm-none-eabi + libnewlib-arm-none-eabi
# (+ libstdc++-arm-none-eabi-dev for the C++ headers; no libstdc++ library is linked).
set(CMAKE_SYSTEM_PROCESSOR arm)
set(LUMAVEL_TOOL_PREFIX arm-none-eabi-)
include(${CMAKE_CURRENT_LIST_DIR}/LumavelCrossToolchain.cmake)

# PRId64 & co. need newlib's headers ahead of GCC's (see docs notes).
set(_lumavel_common "${LUMAVEL_BOARD_FLAGS} -isystem /usr/include/newlib -ffunction-sections -fdata-sections -fstack-usage")
set(CMAKE_C_FLAGS_INIT "${_lumavel_common}")
set(CMAKE_CXX_FLAGS_INIT "${_lumavel_common} -fno-exceptions -fno-rtti -fno-threadsafe-statics -fno-use-cxa-atexit")
set(CMAKE_EXE_LINKER_FLAGS_INIT "${LUMAVEL_BOARD_FLAGS} -nostartfiles -Wl,--gc-sections")
# Read by cmake/LumavelFirmwareImage.cmake: images link newlib-nano.
set(LUMAVEL_IMAGE_LINK_OPTIONS --specs=nano.specs)
