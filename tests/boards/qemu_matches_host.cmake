# Runs one stream through the QEMU firmware image and through the host build
# of the same app, and requires bit-identical report files. The stream is
# synthetic (GEN), or a rendered recording converted by the stream tool
# (RENDER = lumavel-sim, SCENARIO, CONVERT = lumavel_recording_to_stream).
#   cmake -DGEN=<lumavel_make_test_stream> -DHOST_APP=<lumavel_app_host> -DELF=<image>
#         -DMACHINE=mps2-an385 -DWORK=<dir> -DWIDTH=40 -DHEIGHT=30 -DFRAMES=200 -P qemu_matches_host.cmake
#   QEMU: qemu-system-arm (default), or e.g. -DQEMU_NAME=qemu-system-riscv32
#   -DQEMU_PACKAGE=qemu-system-misc -DMACHINE=virt "-DMACHINE_ARGS=-bios none" (space-separated)
#   (or -DRENDER=... -DSCENARIO=<yaml> -DCONVERT=... instead of -DGEN, FRAMES = a lower bound)
# -DLENS=ON (with GEN): the stream uploads barrel lens tables (GEN --lens
# barrel). The host also runs the same stream with all-zero tables (--lens
# flat: what a device that ignored the tables would report); the test then
# requires the lens configuration accepted, and the estimates with the lens
# to differ from those without it, on the host and on the target.
if(NOT QEMU_NAME)
  set(QEMU_NAME qemu-system-arm)
  set(QEMU_PACKAGE qemu-system-arm)
endif()
separate_arguments(MACHINE_ARGS)
find_program(QEMU ${QEMU_NAME})
if(NOT QEMU)
  message("SKIP: ${QEMU_NAME} not found (apt-get install --no-install-recommends ${QEMU_PACKAGE})")
  return()
endif()
if(NOT EXISTS ${ELF})
  message("SKIP: ${ELF} not built (cross toolchain missing?)")
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
elseif(LENS)
  run("generate" ${GEN} ${stream} ${WIDTH} ${HEIGHT} ${FRAMES} 7 --lens barrel)
  run("generate flat lens" ${GEN} ${WORK}/flat.lvs ${WIDTH} ${HEIGHT} ${FRAMES} 7 --lens flat)
  run("host app, flat lens" ${HOST_APP} ${WORK}/flat.lvs ${WORK}/host_flat.lvr)
else()
  run("generate" ${GEN} ${stream} ${WIDTH} ${HEIGHT} ${FRAMES} 7)
endif()
run("host app" ${HOST_APP} ${stream} ${WORK}/host.lvr)
run("qemu ${MACHINE}" ${QEMU} -M ${MACHINE} ${MACHINE_ARGS} -nographic -monitor none -serial none
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

if(LENS)
  include(${CMAKE_CURRENT_LIST_DIR}/report_file.cmake)
  read_report_file(${WORK}/host.lvr host)
  read_report_file(${WORK}/host_flat.lvr flat)
  read_report_file(${WORK}/qemu.lvr qemu)
  # The info get after the lens configuration: accepted (config_status 0), set by the host (source 2).
  foreach(run host flat)
    if(NOT ${run}_INFO)
      message(FATAL_ERROR "${run}: no device-info reply after the lens configuration")
    endif()
    report_byte(${${run}_INFO} 30 status)
    report_byte(${${run}_INFO} 31 source)
    if(NOT status EQUAL 0 OR NOT source EQUAL 2)
      message(FATAL_ERROR "${run}: lens configuration not applied (config_status ${status}, source ${source})")
    endif()
  endforeach()
  # Same frames, same requests: the estimates may differ only once the tables apply.
  list(LENGTH host_MEASUREMENTS count)
  set(same_before 0)
  set(differ 0)
  set(qemu_differ 0)
  math(EXPR last "${count} - 1")
  foreach(i RANGE ${last})
    list(GET host_MEASUREMENTS ${i} a)
    list(GET flat_MEASUREMENTS ${i} b)
    list(GET qemu_MEASUREMENTS ${i} q)
    if(NOT a STREQUAL b)
      math(EXPR differ "${differ} + 1")
    elseif(differ EQUAL 0)
      math(EXPR same_before "${same_before} + 1")
    endif()
    if(NOT q STREQUAL b)
      math(EXPR qemu_differ "${qemu_differ} + 1")
    endif()
  endforeach()
  math(EXPR upload_frame "${FRAMES} * 7 / 10 - 3")  # 3 dropped frames before it
  if(same_before LESS upload_frame)
    message(FATAL_ERROR "estimates with and without the lens differ from report ${same_before} on, "
                        "before the lens upload (report ${upload_frame})")
  endif()
  if(differ EQUAL 0 OR qemu_differ EQUAL 0)
    message(FATAL_ERROR "the lens changed no estimate (host: ${differ}, QEMU: ${qemu_differ} of ${count} "
                        "reports differ from the flat-lens run)")
  endif()
  message("lens: ${differ} of ${count} measurement reports differ from the flat-lens run "
          "(host; QEMU ${qemu_differ}), the first ${same_before} are identical")
endif()
