# ARM MPS2 AN385 (Cortex-M3) as modelled by QEMU; the same image layout runs
# on AN386 (Cortex-M4). LUMAVEL_CPU picks the code generation: cortex-m3
# (default), cortex-m4 (run with -M mps2-an386) or cortex-m0plus (ARMv6-M code,
# run on the M3 model: it executes the same instructions, for counting).
# Read by cmake/arm-none-eabi.cmake before the compilers are set up.
if(NOT LUMAVEL_CPU)
  set(LUMAVEL_CPU cortex-m3)
endif()
set(LUMAVEL_BOARD_FLAGS "-mcpu=${LUMAVEL_CPU} -mthumb -mfloat-abi=soft")
