# Links tests/boards/uses_float.cpp for Cortex-M0+ and requires the
# forbidden-symbol checker to fail on it, naming a soft-float helper.
if(NOT GXX)
  message("SKIP: arm-none-eabi-g++ not found")
  return()
endif()
execute_process(COMMAND ${GXX} -mcpu=cortex-m0plus -mthumb -Os -fno-exceptions -nostartfiles
                        -nostdlib -Wl,-eReset_Handler ${SRC} -lgcc -o ${OUT}
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "could not link ${SRC}: ${err}")
endif()
get_filename_component(bin ${GXX} DIRECTORY)
execute_process(COMMAND ${CMAKE_COMMAND} -DELF=${OUT} -DNM=${bin}/arm-none-eabi-nm -P ${CHECKER}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
message("${out}")
if(rc EQUAL 0)
  message(FATAL_ERROR "checker accepted an image with a float multiply")
endif()
if(NOT out MATCHES "__aeabi_fmul")
  message(FATAL_ERROR "checker failed but did not name __aeabi_fmul")
endif()
message("checker rejected the float image as it should")
