# Turns a cross-compiled executable into a firmware image: board linker script,
# linker map, .bin/.hex, a size report (flash, RAM, stack frames from
# -fstack-usage) after each link.
#
# lumavel_firmware_image(<target> LINKER_SCRIPT <file> [FLASH_BYTES n] [RAM_BYTES n])
include_guard(GLOBAL)
set(LUMAVEL_CMAKE_DIR ${CMAKE_CURRENT_LIST_DIR})
set(LUMAVEL_BOARDS_COMMON_DIR ${CMAKE_CURRENT_LIST_DIR}/../boards/common)

function(lumavel_firmware_image target)
  cmake_parse_arguments(F "" "LINKER_SCRIPT;FLASH_BYTES;RAM_BYTES" "" ${ARGN})
  set(out $<TARGET_FILE:${target}>)
  set(map ${CMAKE_CURRENT_BINARY_DIR}/${target}.map)
  # gcc, not g++, drives the link: no libstdc++ is linked (nor installed, on RISC-V).
  set_target_properties(${target} PROPERTIES LINKER_LANGUAGE C SUFFIX .elf
                        LINK_DEPENDS ${F_LINKER_SCRIPT})
  target_compile_options(${target} PRIVATE -fstack-usage)
  # LUMAVEL_IMAGE_LINK_OPTIONS: the toolchain file's C library choice
  # (newlib-nano on Arm; none on RISC-V).
  target_link_options(${target} PRIVATE -T${F_LINKER_SCRIPT} -L${LUMAVEL_BOARDS_COMMON_DIR}
                      ${LUMAVEL_IMAGE_LINK_OPTIONS} -Wl,-Map=${map} -Wl,--cref)
  add_custom_command(TARGET ${target} POST_BUILD
    COMMAND ${LUMAVEL_OBJCOPY} -O binary ${out} ${CMAKE_CURRENT_BINARY_DIR}/${target}.bin
    COMMAND ${LUMAVEL_OBJCOPY} -O ihex ${out} ${CMAKE_CURRENT_BINARY_DIR}/${target}.hex
    COMMAND ${CMAKE_COMMAND} -DELF=${out} -DSIZE=${LUMAVEL_SIZE} -DNAME=${target}
            -DFLASH_BYTES=${F_FLASH_BYTES} -DRAM_BYTES=${F_RAM_BYTES}
            -DSU_DIR=${CMAKE_BINARY_DIR} -P ${LUMAVEL_CMAKE_DIR}/LumavelSizeReport.cmake
    VERBATIM)
  # The forbidden-symbol check runs as a CTest test (tests/boards), not as a
  # post-build step: a failed post-build step would leave an "up to date" image.
endfunction()
