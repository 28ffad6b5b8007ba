# Script mode, run by CTest from the host build: configures and builds
# one board of this tree with a cross toolchain file (cmake/<TOOLCHAIN>.cmake)
# in its own build directory, then optionally checks images for forbidden symbols.
#   cmake -DSOURCE_DIR=<tree> -DBINARY_DIR=<dir> -DBOARD=<folder> -DTARGETS="a;b"
#         [-DTOOLCHAIN=arm-none-eabi (default) | riscv64-unknown-elf]
#         [-DEXTRA_ARGS="-DX=y;..."] [-DCHECK_ELFS="sub/dir/x.elf;..."] [-DALLOW=<regex>]
#         -P LumavelCrossBuild.cmake
# Prints "SKIP: ..." (the test's SKIP_REGULAR_EXPRESSION) when the toolchain is missing.
foreach(v SOURCE_DIR BINARY_DIR BOARD TARGETS)
  if(NOT ${v})
    message(FATAL_ERROR "LumavelCrossBuild: ${v} not set")
  endif()
endforeach()
if(NOT TOOLCHAIN)
  set(TOOLCHAIN arm-none-eabi)
endif()

find_program(CROSS_GXX ${TOOLCHAIN}-g++)
find_program(CROSS_NM ${TOOLCHAIN}-nm)
if(TOOLCHAIN STREQUAL "arm-none-eabi")
  if(NOT CROSS_GXX OR NOT CROSS_NM)
    message("SKIP: arm-none-eabi toolchain not found (apt-get install gcc-arm-none-eabi "
            "libnewlib-arm-none-eabi libstdc++-arm-none-eabi-dev)")
    return()
  endif()
  # The C++ headers come in a separate Debian package.
  file(WRITE ${BINARY_DIR}-probe.cpp "#include <cstdint>\nint32_t probe;\n")
  execute_process(COMMAND ${CROSS_GXX} -mthumb -mcpu=cortex-m0plus -c ${BINARY_DIR}-probe.cpp
                          -o ${BINARY_DIR}-probe.o
                  RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
  if(NOT rc EQUAL 0)
    message("SKIP: arm-none-eabi-g++ has no C++ headers (apt-get install libstdc++-arm-none-eabi-dev)")
    return()
  endif()
elseif(TOOLCHAIN STREQUAL "riscv64-unknown-elf")
  # C++ headers: boards/common/cxx-shim; no C library (cmake/riscv64-unknown-elf.cmake).
  if(NOT CROSS_GXX OR NOT CROSS_NM)
    message("SKIP: riscv64-unknown-elf toolchain not found (apt-get install gcc-riscv64-unknown-elf)")
    return()
  endif()
else()
  message(FATAL_ERROR "LumavelCrossBuild: unknown TOOLCHAIN ${TOOLCHAIN}")
endif()

# Configure every time (about a second once cached): a target added to a board
# since the last run must be known to the build tool.
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${BINARY_DIR}
                        -DCMAKE_TOOLCHAIN_FILE=${SOURCE_DIR}/cmake/${TOOLCHAIN}.cmake
                        -DCMAKE_BUILD_TYPE=Release -DLUMAVEL_BOARD=${BOARD} ${EXTRA_ARGS}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cross configure of board ${BOARD} failed:\n${out}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BINARY_DIR} --parallel 2 --target ${TARGETS}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cross build of board ${BOARD} (${TARGETS}) failed")
endif()

foreach(elf IN LISTS CHECK_ELFS)
  get_filename_component(dir ${BINARY_DIR}/${elf} DIRECTORY)
  get_filename_component(name ${elf} NAME_WE)
  execute_process(COMMAND ${CMAKE_COMMAND} -DELF=${BINARY_DIR}/${elf} -DNM=${CROSS_NM}
                          -DMAP=${dir}/${name}.map "-DALLOW=${ALLOW}"
                          -P ${CMAKE_CURRENT_LIST_DIR}/LumavelCheckForbiddenSymbols.cmake
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${elf}: forbidden symbols (see above)")
  endif()
endforeach()
