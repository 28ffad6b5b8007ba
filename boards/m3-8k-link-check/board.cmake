# Link-only target (issue 14): the estimator at 40x30 on a Cortex-M3 part with
# 8 KiB of RAM (an STM32F100C8-class chip). The column sums are taken as the
# rows arrive (ColumnStream: no frame buffers); the capacities shrink to 40x30,
# 3 kernels (the first three of the default set), 12 frames of time-of-flight
# history and no photometric match, so that the estimator, two row streams
# and a 2 KiB stack fit. Read by cmake/arm-none-eabi.cmake before the
# compilers are set up.
set(LUMAVEL_BOARD_FLAGS "-mcpu=cortex-m3 -mthumb -mfloat-abi=soft -DLUMAVEL_MAX_COLS=40 -DLUMAVEL_MAX_ROWS=30 -DLUMAVEL_MAX_KERNELS=3 -DLUMAVEL_TOF_FRAMES=12 -DLUMAVEL_MATCH_FRAMES=0")
# A part that small has little flash too: size first.
set(LUMAVEL_BOARD_OPT -Os)
