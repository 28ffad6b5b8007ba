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

cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLUMAVEL_SANITIZE=ON >/dev/null
cmake --build build-asan -j"$jobs"
# Emulator and kernel runs are the same bits as above; the sanitizers watch host code.
ctest --test-dir build-asan --output-on-failure -j"$jobs" -LE emulation
