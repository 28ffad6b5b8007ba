# libFuzzer run of the recording reader (fuzz_recording_reader.cpp: PNG and
# PGM frames, data.csv tables, camera and imu sensor.yaml), as a CTest test of
# LUMAVEL_FUZZ_READER_SECONDS (5 s: CI time; about 15 000 inputs); longer on demand:
#   build/tests/recording/fuzz_recording_reader -max_total_time=3600
# Needs clang with libFuzzer; skipped with a warning otherwise.
find_program(LUMAVEL_CLANGXX NAMES clang++-14 clang++)
if(NOT LUMAVEL_CLANGXX)
  message(WARNING "clang++ not found: the recording reader fuzz test is not built")
  return()
endif()
set(LUMAVEL_FUZZ_READER_SECONDS 5 CACHE STRING "libFuzzer run time of the recording reader, seconds")
find_library(LUMAVEL_YAML_CPP_LIB yaml-cpp)
find_library(LUMAVEL_PNG_LIB png)
if(NOT LUMAVEL_YAML_CPP_LIB OR NOT LUMAVEL_PNG_LIB)
  message(WARNING "libyaml-cpp or libpng not found by path: the recording reader fuzz test is not built")
  return()
endif()

set(_rec ${PROJECT_SOURCE_DIR}/host_sim/recording)
set(_srcs ${_rec}/src/csv_table.cpp ${_rec}/src/sensor_yaml.cpp ${_rec}/src/image_io.cpp
          ${_rec}/src/recording_error.cpp ${PROJECT_SOURCE_DIR}/tools/common/cli/src/path_check.cpp
          ${PROJECT_SOURCE_DIR}/tools/common/cli/src/decimal_text.cpp ${PROJECT_SOURCE_DIR}/tools/common/cli/src/line_ends.cpp
          ${PROJECT_SOURCE_DIR}/tools/common/cli/src/output_file.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/fuzz_recording_reader.cpp)
file(GLOB _hdrs ${_rec}/include/lumavel/host/*.hpp)
set(_bin ${CMAKE_CURRENT_BINARY_DIR}/fuzz_recording_reader)
add_custom_command(OUTPUT ${_bin}
  COMMAND ${LUMAVEL_CLANGXX} -std=c++17 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all
          -I${_rec}/include -I${PROJECT_SOURCE_DIR}/host_sim/reference/include
          -I${PROJECT_SOURCE_DIR}/tools/common/cli/include -I${PROJECT_SOURCE_DIR}/firmware/core/include -I${PROJECT_SOURCE_DIR}/firmware/units/include -I${PROJECT_SOURCE_DIR}/hal/include
          ${_srcs} ${LUMAVEL_YAML_CPP_LIB} ${LUMAVEL_PNG_LIB} -o ${_bin}
  DEPENDS ${_srcs} ${_hdrs}
  COMMENT "Building libFuzzer target fuzz_recording_reader with ${LUMAVEL_CLANGXX}")
add_custom_target(fuzz_recording_reader_bin ALL DEPENDS ${_bin})
add_test(NAME recording_fuzz_reader
  COMMAND ${_bin} -max_total_time=${LUMAVEL_FUZZ_READER_SECONDS} -rss_limit_mb=2048 -print_final_stats=1)
