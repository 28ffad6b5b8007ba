# The instruction-count benchmark of a semihosted board, included by the
# board's benchmark.cmake (script mode) after it sets:
#   BOARD      the board folder; TOOLCHAIN: its cmake/<TOOLCHAIN>.cmake
#   QEMU_NAME  the QEMU system emulator that runs it
#   VARIANTS   "<dir>|<LUMAVEL_CPU>|<QEMU machine arguments>" per code variant
# Builds lumavel_qemu_bench for each variant (cross builds under
# CROSS_DIR/<dir>: the bit-identity tests' build directories), generates a
# synthetic stream per resolution with the host tool, runs each image with
# -icount shift=0 and prints its figures (bench_main.cpp).
foreach(v SOURCE_DIR CROSS_DIR GEN BOARD TOOLCHAIN QEMU_NAME VARIANTS)
  if(NOT ${v})
    message(FATAL_ERROR "benchmark: ${v} not set")
  endif()
endforeach()
find_program(QEMU ${QEMU_NAME})
if(NOT QEMU)
  message(FATAL_ERROR "${QEMU_NAME} not found")
endif()
set(work ${CROSS_DIR}/bench-streams)
file(MAKE_DIRECTORY ${work})
set(resolutions "40 30 120" "160 120 30")  # width height frames

foreach(v IN LISTS VARIANTS)
  string(REPLACE "|" ";" v "${v}")
  list(GET v 0 dir)
  list(GET v 1 cpu)
  execute_process(COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${SOURCE_DIR} -DBINARY_DIR=${CROSS_DIR}/${dir}
                          -DBOARD=${BOARD} -DTOOLCHAIN=${TOOLCHAIN} -DTARGETS=lumavel_qemu_bench
                          -DEXTRA_ARGS=-DLUMAVEL_CPU=${cpu}
                          -P ${SOURCE_DIR}/cmake/LumavelCrossBuild.cmake
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0 OR out MATCHES "SKIP: ")
    message(FATAL_ERROR "building the ${cpu} benchmark failed:\n${out}")
  endif()
  string(REGEX MATCH "size lumavel_qemu_bench: [^\n]*" size_line "${out}")
  if(size_line)
    message("${cpu}: ${size_line}")
  endif()
endforeach()

foreach(r IN LISTS resolutions)
  separate_arguments(r)
  list(GET r 0 w)
  list(GET r 1 h)
  list(GET r 2 n)
  set(stream ${work}/bench_${w}x${h}.lvs)
  execute_process(COMMAND ${GEN} ${stream} ${w} ${h} ${n} 11 RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "generating ${stream} failed")
  endif()
  foreach(v IN LISTS VARIANTS)
    string(REPLACE "|" ";" v "${v}")
    list(GET v 0 dir)
    list(GET v 1 cpu)
    list(GET v 2 machine)
    separate_arguments(machine)
    set(cmd ${QEMU} ${machine} -icount shift=0 -nographic -monitor none -serial none
            -semihosting-config enable=on,target=native,arg=bench,arg=bench_${w}x${h}.lvs,arg=${cpu}
            -kernel ${CROSS_DIR}/${dir}/boards/${BOARD}/lumavel_qemu_bench.elf)
    execute_process(COMMAND ${cmd} WORKING_DIRECTORY ${work} RESULT_VARIABLE rc
                    OUTPUT_VARIABLE out ERROR_VARIABLE out TIMEOUT 300)
    message("${out}")
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "${cpu} benchmark at ${w}x${h} failed (exit ${rc})")
    endif()
  endforeach()
endforeach()
