# Instruction budget benchmark on RV32 under QEMU, the twin of
# boards/qemu-mps2-an385/benchmark.cmake (see boards/common/semihosting/bench_main.cpp).
#   cmake -DSOURCE_DIR=<tree> -DCROSS_DIR=<build>/cross -DGEN=<lumavel_make_test_stream>
#         -P boards/qemu-riscv-virt/benchmark.cmake
# (or: cmake --build <build> --target firmware_benchmark_riscv)
set(BOARD qemu-riscv-virt)
set(TOOLCHAIN riscv64-unknown-elf)
set(QEMU_NAME qemu-system-riscv32)
# All on QEMU's rv32 CPU: rv32imc and rv32ec code executes there unchanged.
set(VARIANTS "qemu-rv32imac|rv32imac|-M virt -bios none" "qemu-rv32imc|rv32imc|-M virt -bios none"
             "qemu-rv32ec|rv32ec|-M virt -bios none")
include(${CMAKE_CURRENT_LIST_DIR}/../common/semihosting/benchmark.cmake)
