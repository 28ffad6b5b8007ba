# Instruction budget benchmark on Cortex-M0+, M3 and M4 under QEMU (see
# bench_main.cpp). Builds lumavel_qemu_bench for each CPU (cross builds under
# CROSS_DIR/qemu-<cpu>), generates a synthetic stream per resolution with the
# host tool, runs each image with -icount shift=0 and prints its figures.
#   cmake -DSOURCE_DIR=<tree> -DCROSS_DIR=<build>/cross -DGEN=<lumavel_make_test_stream>
#         -P boards/qemu-mps2-an385/benchmark.cmake
# (or: cmake --build <build> --target firmware_benchmark_cortex_m)
find_program(QEMU qemu-system-arm)
if(NOT QEMU)
  message(FATAL_ERROR "qemu-system-arm not found")
endif()
set(work ${CROSS_DIR}/bench-streams)
file(MAKE_DIRECTORY ${work})
set(resolutions "40 30 120" "160 120 30")  # width height frames

# cpu -> the MPS2 model that runs it (ARMv6-M code runs on the M3 model unchanged).
set(variants "m0plus cortex-m0plus mps2-an385" "m3 cortex-m3 mps2-an385" "m4 cortex-m4 mps2-an386")
foreach(v IN LISTS variants)
  separate_arguments(v)
  list(GET v 0 dir)
  list(GET v 1 cpu)
  execute_process(COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${SOURCE_DIR} -DBINARY_DIR=${CROSS_DIR}/qemu-${dir}
                          -DBOARD=qemu-mps2-an385 -DTARGETS=lumavel_qemu_bench -DEXTRA_ARGS=-DLUMAVEL_CPU=${cpu}
                          -P ${SOURCE_DIR}/cmake/LumavelCrossBuild.cmake
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
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
  foreach(v IN LISTS variants)
    separate_arguments(v)
    list(GET v 0 dir)
    list(GET v 1 cpu)
    list(GET v 2 machine)
    set(cmd ${QEMU} -M ${machine} -icount shift=0 -nographic -monitor none -serial none
            -semihosting-config enable=on,target=native,arg=bench,arg=bench_${w}x${h}.lvs,arg=${cpu}
            -kernel ${CROSS_DIR}/qemu-${dir}/boards/qemu-mps2-an385/lumavel_qemu_bench.elf)
    execute_process(COMMAND ${cmd} WORKING_DIRECTORY ${work} RESULT_VARIABLE rc
                    OUTPUT_VARIABLE out ERROR_VARIABLE out TIMEOUT 300)
    message("${out}")
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "${cpu} benchmark at ${w}x${h} failed (exit ${rc})")
    endif()
  endforeach()
endforeach()
