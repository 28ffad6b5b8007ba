# libFuzzer run of the scenario loader (fuzz_scenario_loader.cpp), seeded
# with the committed scenarios, as a CTest test of LUMAVEL_FUZZ_SCENARIO_SECONDS
# (5 s: CI time); longer on demand:
#   build/tests/render/fuzz_scenario_loader -max_total_time=3600 DIR_WITH_SEEDS
# Needs clang with libFuzzer; skipped with a warning otherwise.
find_program(LUMAVEL_CLANGXX NAMES clang++-14 clang++)
find_library(LUMAVEL_YAML_CPP_LIB yaml-cpp)
if(NOT LUMAVEL_CLANGXX OR NOT LUMAVEL_YAML_CPP_LIB)
  message(WARNING "clang++ or libyaml-cpp not found: the scenario loader fuzz test is not built")
  return()
endif()
set(LUMAVEL_FUZZ_SCENARIO_SECONDS 5 CACHE STRING "libFuzzer run time of the scenario loader, seconds")

set(_render ${PROJECT_SOURCE_DIR}/host_sim/render)
set(_lens ${PROJECT_SOURCE_DIR}/host/lens)
set(_srcs ${_render}/src/scenario_loader.cpp ${_lens}/src/lens_distortion.cpp ${_render}/src/photometric_presets.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/fuzz_scenario_loader.cpp ${PROJECT_SOURCE_DIR}/tools/common/cli/src/path_check.cpp
          ${PROJECT_SOURCE_DIR}/tools/common/cli/src/decimal_text.cpp ${PROJECT_SOURCE_DIR}/tools/common/cli/src/line_ends.cpp
          ${PROJECT_SOURCE_DIR}/host_sim/recording/src/csv_table.cpp
          ${PROJECT_SOURCE_DIR}/host_sim/recording/src/recording_error.cpp)
file(GLOB _hdrs ${_render}/include/lumavel/host/render/*.hpp ${_lens}/include/lumavel/host/*.hpp)
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
get_target_property(_eigen_inc Eigen3::Eigen INTERFACE_INCLUDE_DIRECTORIES)
set(_bin ${CMAKE_CURRENT_BINARY_DIR}/fuzz_scenario_loader)
add_custom_command(OUTPUT ${_bin}
  COMMAND ${LUMAVEL_CLANGXX} -std=c++17 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all
          -I${_render}/include -I${_lens}/include -I${PROJECT_SOURCE_DIR}/host_sim/recording/include
          -I${PROJECT_SOURCE_DIR}/host_sim/reference/include -I${PROJECT_SOURCE_DIR}/tools/common/cli/include -I${PROJECT_SOURCE_DIR}/firmware/core/include -I${PROJECT_SOURCE_DIR}/firmware/units/include
          -I${PROJECT_SOURCE_DIR}/hal/include -I${_eigen_inc}
          ${_srcs} ${LUMAVEL_YAML_CPP_LIB} -o ${_bin}
  DEPENDS ${_srcs} ${_hdrs}
  COMMENT "Building libFuzzer target fuzz_scenario_loader with ${LUMAVEL_CLANGXX}")
add_custom_target(fuzz_scenario_loader_bin ALL DEPENDS ${_bin})
# A fresh seed directory per run (libFuzzer adds to it) keeps the cost fixed.
set(_seeds ${CMAKE_CURRENT_BINARY_DIR}/fuzz_scenario_seeds)
add_test(NAME render_fuzz_scenario_loader
  COMMAND sh -c "rm -rf '${_seeds}' && mkdir -p '${_seeds}' && cp '${PROJECT_SOURCE_DIR}'/host_sim/scenarios/*.yaml '${_seeds}' && '${_bin}' -max_total_time=${LUMAVEL_FUZZ_SCENARIO_SECONDS} -rss_limit_mb=2048 -print_final_stats=1 '${_seeds}'")
