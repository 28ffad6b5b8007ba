# libFuzzer runs of the report and configuration parsers, 20 s each, as CTest
# tests. libFuzzer needs clang (Debian: clang-14 + libclang-rt-14-dev); the
# rest of the tree builds with the project's compiler, so the fuzz binaries
# are compiled by a custom command.
find_program(LUMAVEL_CLANGXX NAMES clang++-14 clang++)
set(LUMAVEL_FUZZ_SECONDS 20 CACHE STRING "libFuzzer run time per parser, seconds")
if(NOT LUMAVEL_CLANGXX)
  message(WARNING "clang++ not found: protocol fuzz tests not built (apt-get install clang-14 libclang-rt-14-dev)")
  return()
endif()

set(_proto ${PROJECT_SOURCE_DIR}/firmware/protocol)
set(_fuzz_srcs ${_proto}/src/crc.cpp ${_proto}/src/descriptor.cpp ${_proto}/src/reports.cpp
               ${_proto}/src/device_config.cpp ${_proto}/src/lens.cpp
               ${PROJECT_SOURCE_DIR}/firmware/app/src/estimator_config.cpp
               ${CMAKE_CURRENT_SOURCE_DIR}/fuzz_targets.cpp)
file(GLOB _fuzz_headers ${_proto}/include/lumavel/protocol/*.hpp ${_proto}/src/*.hpp
     ${PROJECT_SOURCE_DIR}/firmware/app/include/lumavel/app/estimator_config.hpp)

foreach(kind reports config)
  set(_bin ${CMAKE_CURRENT_BINARY_DIR}/fuzz_${kind})
  set(_defs "")
  if(kind STREQUAL "config")
    set(_defs -DLUMAVEL_FUZZ_CONFIG)
  endif()
  add_custom_command(OUTPUT ${_bin}
    COMMAND ${LUMAVEL_CLANGXX} -std=c++17 -g -O1 ${_defs}
            -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all
            -I${_proto}/include -I${PROJECT_SOURCE_DIR}/firmware/app/include -I${PROJECT_SOURCE_DIR}/firmware/core/include -I${PROJECT_SOURCE_DIR}/firmware/units/include
            ${_fuzz_srcs} -o ${_bin}
    DEPENDS ${_fuzz_srcs} ${_fuzz_headers}
    COMMENT "Building libFuzzer target fuzz_${kind} with ${LUMAVEL_CLANGXX}")
  add_custom_target(fuzz_${kind}_bin ALL DEPENDS ${_bin})
  # A fresh corpus directory per run keeps the test's cost fixed.
  add_test(NAME protocol_fuzz_${kind}
    COMMAND ${CMAKE_COMMAND} -E env ${_bin} -max_total_time=${LUMAVEL_FUZZ_SECONDS}
            -rss_limit_mb=2048 -print_final_stats=1)
endforeach()
