# Link-only target: proves the estimator core links on Cortex-M0+ (ARMv6-M,
# no FPU, no divide) without soft-float, heap or exceptions. Read by
# cmake/arm-none-eabi.cmake before the compilers are set up.
set(LUMAVEL_BOARD_FLAGS "-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft")
