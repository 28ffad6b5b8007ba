# Blue pill: STM32F103C8 (Cortex-M3, 64 KiB flash, 20 KiB RAM). The core's
# capacities shrink to one 128-pixel line, 4 kernels and 16 frames of
# time-of-flight history so that it fits.
# Read by cmake/arm-none-eabi.cmake before the compilers are set up.
set(LUMAVEL_BOARD_FLAGS "-mcpu=cortex-m3 -mthumb -mfloat-abi=soft -DLUMAVEL_MAX_COLS=128 -DLUMAVEL_MAX_ROWS=1 -DLUMAVEL_MAX_KERNELS=4 -DLUMAVEL_TOF_FRAMES=16 -DLUMAVEL_MATCH_FRAMES=0")
# 64 KiB of flash: size first (-O3 took 66 KB, -Os 42 KB on 2026-12-07; the
# frame's work is a few per cent of a 72 MHz M3's time either way).
set(LUMAVEL_BOARD_OPT -Os)
