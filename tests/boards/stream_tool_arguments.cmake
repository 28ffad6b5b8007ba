# The stream tools read their numeric arguments whole (tools/stream/include/
# lumavel/stream/tool_args.hpp): each malformed or out-of-range number is a
# usage error (exit 2) naming the argument, the value and the rule. atoi read
# "40x" as 40 and 4294967336 as 40, "1e9" frames as 1: the tools ran, exit 0.
# lumavel_app_host given a folder for its stream says so (was: 'not a lumavel
# stream (bad header)', what the bytes a folder cannot give look like).
# lumavel_app_host's results written over its stream (or a link to it)
# truncated the stream before reading it: refused, exit 1, the stream intact.
# The converter's stream written over its recording's cam0/data.csv destroyed
# it, exit 0: refused, the file intact.
#   cmake -DCONVERT=<lumavel_recording_to_stream> -DSIM=<lumavel-sim> -DGEN=<lumavel_make_test_stream> -DHOST_APP=<lumavel_app_host>
#         -DWORK=<dir> -P ...
file(MAKE_DIRECTORY ${WORK})
# expect(<regex the message must match> <command...>): exit 2 (usage; the app host's bad stream)
function(expect pattern)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 2 OR NOT err MATCHES "${pattern}")
    message(FATAL_ERROR "${ARGN}: expected exit 2 and '${pattern}', got exit ${rc}: ${err}")
  endif()
endfunction()
# The recording is not read before its arguments are: any folder name does.
expect("width: must be a whole number in 16\\.\\.2048, not '40x'" ${CONVERT} rec out.lvs 40x 30)
expect("width: must be a whole number in 16\\.\\.2048, not '4294967336'" ${CONVERT} rec out.lvs 4294967336 30)
expect("height: must be a whole number in 1\\.\\.2048, not '030'" ${CONVERT} rec out.lvs 40 030)
expect("frames: must be a whole number in 1\\.\\.1000000, not '1e9'" ${GEN} out.lvs 40 30 1e9)
expect("seed: must be a whole number in 0\\.\\.4294967295, not '-1'" ${GEN} out.lvs 40 30 10 -1)
expect("width: must be a whole number in 16\\.\\.2048, not '40x'" ${GEN} out.lvs 40x 30 10)
# An empty path was no usage error: the converter's and the generator's
# output went to standard output (the binary stream on the terminal), exit 0.
# (Each written out: an empty argument does not survive a function's ${ARGN}.)
function(expect_empty_path what name rc out err)
  if(NOT rc EQUAL 2 OR NOT err MATCHES "${name}: needs a path, not an empty one" OR NOT out STREQUAL "")
    message(FATAL_ERROR "${what}: expected exit 2, '${name}: needs a path, not an empty one' and nothing on "
                        "standard output, got exit ${rc}: ${err}")
  endif()
endfunction()
execute_process(COMMAND ${CONVERT} rec "" 40 30 WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
expect_empty_path("the converter, out.lvs ''" "out\\.lvs" "${rc}" "${out}" "${err}")
execute_process(COMMAND ${CONVERT} "" out.lvs 40 30 WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
expect_empty_path("the converter, recording dir ''" "recording dir" "${rc}" "${out}" "${err}")
execute_process(COMMAND ${GEN} "" 40 30 10 WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
expect_empty_path("the generator, out.lvs ''" "out\\.lvs" "${rc}" "${out}" "${err}")
# lumavel_app_host said an empty name as nothing (': cannot open for
# reading'); its usage exit is 1.
execute_process(COMMAND ${HOST_APP} "" out.lvr WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 1 OR NOT err MATCHES "in\\.lvs: needs a path, not an empty one")
  message(FATAL_ERROR "lumavel_app_host '' out.lvr: expected exit 1 and 'in.lvs: needs a path', got exit ${rc}: ${err}")
endif()
execute_process(COMMAND ${HOST_APP} in.lvs "" WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 1 OR NOT err MATCHES "out\\.lvr: needs a path, not an empty one")
  message(FATAL_ERROR "lumavel_app_host in.lvs '': expected exit 1 and 'out.lvr: needs a path', got exit ${rc}: ${err}")
endif()
expect("${WORK}: read error: Is a directory" ${HOST_APP} ${WORK} out.lvr)
# lumavel_app_host given '-' for its results made a file named '-', exit 0. Exit 1, nothing made.
file(REMOVE ${WORK}/-)
foreach(args "-;out.lvr" "in.lvs;-")
  execute_process(COMMAND ${HOST_APP} ${args} WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 1 OR NOT err MATCHES "- \\((in\\.lvs|out\\.lvr)\\): '-' stands for standard (input|output), which this tool does not use"
     OR EXISTS ${WORK}/-)
    message(FATAL_ERROR "lumavel_app_host ${args}: expected exit 1 and the '-' refusal, nothing made, got exit ${rc}: ${err}")
  endif()
endforeach()
# '-' as the stream made a file named '-' in the current folder, exit 0 (render,
# import-slider and calibrate --write refuse it); a folder that is not there
# was 'cannot create the stream: No such file or directory'. Exit 1, nothing made.
file(REMOVE ${WORK}/-)
foreach(tool convert gen)
  foreach(out - nowhere/x.lvs)
    if(tool STREQUAL "convert")
      set(cmd ${CONVERT} rec ${out} 40 30)
    else()
      set(cmd ${GEN} ${out} 40 30 2)
    endif()
    execute_process(COMMAND ${cmd} WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc ERROR_VARIABLE err)
    if(out STREQUAL "-")
      set(want "- \\(out\\.lvs\\): '-' stands for standard output, where no stream file is written")
    else()
      set(want "nowhere/x\\.lvs \\(out\\.lvs\\): cannot be created: its folder nowhere does not exist")
    endif()
    if(NOT rc EQUAL 1 OR NOT err MATCHES "${want}" OR EXISTS ${WORK}/-)
      message(FATAL_ERROR "${tool} out.lvs '${out}': expected exit 1 and '${want}', nothing made, got exit ${rc}: ${err}")
    endif()
  endforeach()
endforeach()
# A stream whose frames are larger than this build holds (lumavel_make_test_stream
# writes up to 2048 columns): 'record 0: frame larger than the build's
# capacity' said neither the stream's size nor the build's.
execute_process(COMMAND ${GEN} wide.lvs 2048 30 1 WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc ERROR_QUIET)
expect("wide.lvs: record 0: frame larger than the build's capacity: its header says 2048x30 pixels, this build takes at most [0-9]+x[0-9]+"
       ${HOST_APP} wide.lvs wide.lvr)
# A 0.1 s render to convert (its cam0/data.csv the output named).
file(REMOVE_RECURSE ${WORK}/rec)
execute_process(COMMAND ${SIM} render ${CMAKE_CURRENT_LIST_DIR}/../../host_sim/scenarios/paper_sim_aligned.yaml
                        ${WORK}/rec --resolution 40x30 --duration 0.1
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "render of the recording to convert failed: ${err}")
endif()
file(READ ${WORK}/rec/mav0/cam0/data.csv before)
expect("rec/mav0/cam0/data.csv \\(out.lvs\\): that is part of the recording being read \\(rec/mav0\\); write the stream elsewhere"
       ${CONVERT} rec rec/mav0/cam0/data.csv 40 30)
file(READ ${WORK}/rec/mav0/cam0/data.csv after)
if(NOT before STREQUAL after)
  message(FATAL_ERROR "the converter wrote over the recording's cam0/data.csv")
endif()
# A size the sensor cannot be binned up to: the hint names the converter's
# own arguments (was: 'choose a smaller --width/--height', options it has not).
execute_process(COMMAND ${CONVERT} rec up.lvs 41 30 WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 1 OR NOT err MATCHES "sensor.yaml:[0-9]+: cannot bin the 40x30 sensor up to the working resolution 41x30 \\(choose a smaller <width> <height>\\)")
  message(FATAL_ERROR "the converter at 41x30 from a 40x30 sensor: expected exit 1 and its arguments named, got exit ${rc}: ${err}")
endif()
# A gyro faster than the FIFO holds between two frames (100 kHz at 60 frames/s,
# 1667 samples an interval, 64 held): the app host says how many it dropped
# (was: unsaid, exit 0, 'capture errors 0').
file(READ ${CMAKE_CURRENT_LIST_DIR}/../../host_sim/scenarios/paper_sim_aligned.yaml scenario)
string(REPLACE "imu:\n  rate_hz: 200" "imu:\n  rate_hz: 100000" fast "${scenario}")
if(fast STREQUAL scenario)
  message(FATAL_ERROR "paper_sim_aligned.yaml holds no 'imu: rate_hz: 200' to raise")
endif()
file(WRITE ${WORK}/fast_gyro.yaml "${fast}")
file(REMOVE_RECURSE ${WORK}/fast)
execute_process(COMMAND ${SIM} render ${WORK}/fast_gyro.yaml ${WORK}/fast --resolution 40x30 --duration 0.1 -q
                RESULT_VARIABLE rc ERROR_VARIABLE err)
execute_process(COMMAND ${CONVERT} fast fast.lvs 40 30 WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc2 ERROR_VARIABLE err2)
execute_process(COMMAND ${HOST_APP} fast.lvs fast.lvr WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc3 ERROR_VARIABLE err3)
if(NOT rc EQUAL 0 OR NOT rc2 EQUAL 0 OR NOT rc3 EQUAL 0
   OR NOT err3 MATCHES "fast\\.lvs: warning: [0-9]+ of its gyro samples dropped: more came between two frames than the gyro FIFO holds \\(64 samples")
  message(FATAL_ERROR "a 100 kHz gyro through the app host: expected exit 0 and the dropped samples said, got ${rc}/${rc2}/${rc3}: ${err} ${err2} ${err3}")
endif()
# The app host's results onto the stream it reads, by name or through a link.
execute_process(COMMAND ${CONVERT} rec in.lvs 40 30 WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc ERROR_QUIET)
file(READ ${WORK}/in.lvs stream HEX)
file(REMOVE ${WORK}/link.lvr)
file(CREATE_LINK in.lvs ${WORK}/link.lvr SYMBOLIC)
foreach(out in.lvs link.lvr)
  execute_process(COMMAND ${HOST_APP} in.lvs ${out} WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 1 OR NOT err MATCHES "^${out}: that is the stream being read \\(in.lvs\\): write the results elsewhere")
    message(FATAL_ERROR "lumavel_app_host in.lvs ${out}: expected exit 1 and 'that is the stream being read', got exit ${rc}: ${err}")
  endif()
  file(READ ${WORK}/in.lvs after HEX)
  if(NOT stream STREQUAL after)
    message(FATAL_ERROR "lumavel_app_host in.lvs ${out}: the stream was written over")
  endif()
endforeach()
# A frame that does not decode ends the conversion, exit 1, and leaves no
# stream: the pairs before it were left as a shorter stream, which
# lumavel_app_host ran, exit 0. An earlier stream of that name is kept, and a
# write error gives its reason (was: 'write failed').
file(REMOVE_RECURSE ${WORK}/bad)
file(COPY ${WORK}/rec/ DESTINATION ${WORK}/bad)
file(GLOB frames ${WORK}/bad/mav0/cam1/data/*.png)
list(SORT frames)
list(GET frames 2 third)
file(WRITE ${third} "not an image")
file(REMOVE ${WORK}/bad.lvs)
execute_process(COMMAND ${CONVERT} bad bad.lvs 40 30 WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 1 OR NOT err MATCHES "^frame 2 \\(t=[0-9]+ ns, cam1\\): bad/mav0/cam1/data/[0-9]+\\.png: not a PNG or binary PGM file"
   OR EXISTS ${WORK}/bad.lvs)
  message(FATAL_ERROR "a recording with a damaged frame 2: expected exit 1, the frame named and no bad.lvs, got exit ${rc}: ${err}")
endif()
file(COPY_FILE ${WORK}/in.lvs ${WORK}/bad.lvs)
execute_process(COMMAND ${CONVERT} bad bad.lvs 40 30 WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc ERROR_QUIET)
file(READ ${WORK}/bad.lvs kept HEX)
if(NOT rc EQUAL 1 OR NOT kept STREQUAL stream)
  message(FATAL_ERROR "a damaged recording converted onto an earlier bad.lvs: expected exit 1 and the earlier stream kept")
endif()
if(EXISTS /dev/full)
  execute_process(COMMAND ${CONVERT} rec /dev/full 40 30 WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 1 OR NOT err MATCHES "^/dev/full: write error: No space left on device")
    message(FATAL_ERROR "the stream written to /dev/full: expected exit 1 and its reason, got exit ${rc}: ${err}")
  endif()
endif()
# lumavel_make_test_stream the same: a stream too short for its lens upload
# was refused, exit 1, but left behind without the upload.
file(REMOVE ${WORK}/short.lvs)
execute_process(COMMAND ${GEN} short.lvs 40 30 2 1 --lens barrel WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc
                ERROR_VARIABLE err)
if(NOT rc EQUAL 1 OR NOT err MATCHES "2 frames are too few to upload the lens" OR EXISTS ${WORK}/short.lvs)
  message(FATAL_ERROR "a test stream too short for its lens: expected exit 1 and no short.lvs, got exit ${rc}: ${err}")
endif()
if(EXISTS /dev/full)
  execute_process(COMMAND ${GEN} /dev/full 40 30 5 WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 1 OR NOT err MATCHES "^/dev/full: write error: No space left on device")
    message(FATAL_ERROR "a test stream written to /dev/full: expected exit 1 and its reason, got exit ${rc}: ${err}")
  endif()
endif()
