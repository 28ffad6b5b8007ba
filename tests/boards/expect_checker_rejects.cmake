# Links tests/boards/uses_float.cpp for a soft-float core and requires the
# forbidden-symbol checker to fail on it, naming a soft-float helper.
#   cmake -DGXX=<cross g++> -DSRC=uses_float.cpp -DOUT=<elf> -DCHECKER=<LumavelCheckForbiddenSymbols.cmake>
#         [-DPREFIX=arm-none-eabi "-DARCH_FLAGS=-mcpu=cortex-m0plus -mthumb" -DEXPECT=__aeabi_fmul] -P ...
# (the defaults: Cortex-M0+; RISC-V: -DPREFIX=riscv64-unknown-elf
#  "-DARCH_FLAGS=-march=rv32imac -mabi=ilp32" -DEXPECT=__mulsf3; ARCH_FLAGS space-separated)
if(NOT PREFIX)
  set(PREFIX arm-none-eabi)
  set(ARCH_FLAGS -mcpu=cortex-m0plus -mthumb)
  set(EXPECT __aeabi_fmul)
endif()
separate_arguments(ARCH_FLAGS)
if(NOT GXX)
  message("SKIP: ${PREFIX}-g++ not found")
  return()
endif()
execute_process(COMMAND ${GXX} ${ARCH_FLAGS} -Os -fno-exceptions -nostartfiles
                        -nostdlib -Wl,-eReset_Handler ${SRC} -lgcc -o ${OUT}
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "could not link ${SRC}: ${err}")
endif()
get_filename_component(bin ${GXX} DIRECTORY)
execute_process(COMMAND ${CMAKE_COMMAND} -DELF=${OUT} -DNM=${bin}/${PREFIX}-nm -P ${CHECKER}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
message("${out}")
if(rc EQUAL 0)
  message(FATAL_ERROR "checker accepted an image with a float multiply")
endif()
if(NOT out MATCHES "${EXPECT}")
  message(FATAL_ERROR "checker failed but did not name ${EXPECT}")
endif()
message("checker rejected the float image as it should")
