# Runs one stream through the QEMU firmware image and through the host build
# of the same app, and requires bit-identical report files. The stream is
# synthetic (GEN), or a rendered recording converted by the stream tool
# (RENDER = lumavel-sim, SCENARIO, CONVERT = lumavel_recording_to_stream).
#   cmake -DGEN=<lumavel_make_test_stream> -DHOST_APP=<lumavel_app_host> -DELF=<image>
#         -DMACHINE=mps2-an385 -DWORK=<dir> -DWIDTH=40 -DHEIGHT=30 -DFRAMES=200 -P qemu_matches_host.cmake
#   (or -DRENDER=... -DSCENARIO=<yaml> -DCONVERT=... instead of -DGEN, FRAMES = a lower bound)
find_program(QEMU qemu-system-arm)
if(NOT QEMU)
  message("SKIP: qemu-system-arm not found (apt-get install --no-install-recommends qemu-system-arm)")
  return()
endif()
if(NOT EXISTS ${ELF})
  message("SKIP: ${ELF} not built (arm-none-eabi toolchain missing?)")
  return()
endif()
file(MAKE_DIRECTORY ${WORK})
set(stream ${WORK}/test.lvs)

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err
                  WORKING_DIRECTORY ${WORK} TIMEOUT 120)
  message("${what}: ${out}${err}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (exit ${rc})")
  endif()
endfunction()

if(SCENARIO)
  run("render" ${RENDER} render ${SCENARIO} ${WORK}/rec --resolution ${WIDTH}x${HEIGHT} --duration 2
      --seed 3 --quiet --force)
  run("convert" ${CONVERT} ${WORK}/rec ${stream} ${WIDTH} ${HEIGHT})
else()
  run("generate" ${GEN} ${stream} ${WIDTH} ${HEIGHT} ${FRAMES} 7)
endif()
run("host app" ${HOST_APP} ${stream} ${WORK}/host.lvr)
run("qemu ${MACHINE}" ${QEMU} -M ${MACHINE} -nographic -monitor none -serial none
    -semihosting-config enable=on,target=native,arg=lumavel,arg=test.lvs,arg=qemu.lvr -kernel ${ELF})
file(SIZE ${WORK}/host.lvr host_size)
math(EXPR min_size "(${FRAMES} - 3) * 44")  # a 42-byte report (+2 framing) per frame; 3 are dropped
if(host_size LESS min_size)
  message(FATAL_ERROR "host report file is ${host_size} bytes, expected >= ${min_size}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK}/host.lvr ${WORK}/qemu.lvr RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  execute_process(COMMAND cmp ${WORK}/host.lvr ${WORK}/qemu.lvr)
  message(FATAL_ERROR "QEMU (${MACHINE}) and host report streams differ")
endif()
message("QEMU (${MACHINE}) and host report streams are bit-identical (${host_size} bytes)")
