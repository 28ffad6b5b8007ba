# Instruction budget benchmark on Cortex-M0+, M3 and M4 under QEMU (see
# boards/common/semihosting/bench_main.cpp and benchmark.cmake there).
#   cmake -DSOURCE_DIR=<tree> -DCROSS_DIR=<build>/cross -DGEN=<lumavel_make_test_stream>
#         -P boards/qemu-mps2-an385/benchmark.cmake
# (or: cmake --build <build> --target firmware_benchmark_cortex_m)
set(BOARD qemu-mps2-an385)
set(TOOLCHAIN arm-none-eabi)
set(QEMU_NAME qemu-system-arm)
# cpu -> the MPS2 model that runs it (ARMv6-M code runs on the M3 model unchanged).
set(VARIANTS "qemu-m0plus|cortex-m0plus|-M mps2-an385" "qemu-m3|cortex-m3|-M mps2-an385"
             "qemu-m4|cortex-m4|-M mps2-an386")
include(${CMAKE_CURRENT_LIST_DIR}/../common/semihosting/benchmark.cmake)
