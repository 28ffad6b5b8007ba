#!/usr/bin/env bash
# Runs every test: the host build (unit tests, fixed vs float, firmware cross
# builds and QEMU runs, the HID kernel-in-the-loop test), then the unit
# suites again under AddressSanitizer + UndefinedBehaviorSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/setup-debian.sh
jobs=$(nproc)

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$jobs"
ctest --test-dir build --output-on-failure -j"$jobs"

# The unit suites again under the sanitizers (cross builds, emulator and kernel
# runs are the same bits as above; the sanitizers watch the host code).
# -O1 -g1 (line tables): half the compile time of -O2 -g under the
# sanitizers on this code, with file:line in every report.
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLUMAVEL_SANITIZE=ON \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" >/dev/null
cmake --build build-asan -j"$jobs" --target unit_tests
ctest --test-dir build-asan --output-on-failure -j"$jobs" -L unit
