# QEMU's RISC-V "virt" machine, 32-bit, run in machine mode (-bios none).
# LUMAVEL_CPU is the -march of the code: rv32imac (default), rv32imc or rv32ec
# (no multiply/divide: libgcc's __mulsi3 and __divsi3 do it; RV32E: 16
# registers, ABI ilp32e), or any other RV32 without F/D that GCC knows. QEMU
# 7.2 models no RV32E or M-less CPU; such code runs on its rv32 CPU unchanged
# (the same instructions, so the counts are exact, as for Cortex-M0+ code on
# the M3 model). Read by cmake/riscv64-unknown-elf.cmake.
if(NOT LUMAVEL_CPU)
  set(LUMAVEL_CPU rv32imac)
endif()
if(NOT LUMAVEL_CPU MATCHES "^rv32[ei][a-z]*$" OR LUMAVEL_CPU MATCHES "[fdq]")
  message(FATAL_ERROR "qemu-riscv-virt: LUMAVEL_CPU=${LUMAVEL_CPU}: want an RV32 -march without F/D (rv32imac, rv32imc, rv32ec, ...)")
endif()
if(LUMAVEL_CPU MATCHES "^rv32e")
  set(_lumavel_abi ilp32e)
else()
  set(_lumavel_abi ilp32)
endif()
set(LUMAVEL_BOARD_FLAGS "-march=${LUMAVEL_CPU} -mabi=${_lumavel_abi}")
