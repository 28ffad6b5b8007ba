#!/usr/bin/env bash
# Installs the Debian 12 packages that lumavel builds, tests and runs with.
# Idempotent and quiet when everything is present; uses sudo when not root.
set -euo pipefail

packages=(
  # host build and tests
  build-essential cmake pkg-config cpputest libeigen3-dev libbenchmark-dev libcli11-dev
  # recordings, scenarios, images; plots drawn to PNG in the tests
  libpng-dev libyaml-cpp-dev librsvg2-bin
  # the keypoint stereo VO baseline (host only): the OpenCV modules it uses,
  # not libopencv-dev, which pulls every module and its dependencies
  libopencv-core-dev libopencv-imgproc-dev libopencv-video-dev libopencv-calib3d-dev
  # USB HID readout and the kernel-in-the-loop test
  libhidapi-dev libusb-1.0-0-dev qemu-system-x86 busybox-static cpio xz-utils kmod
  # fuzzing (libFuzzer)
  clang-14 libclang-rt-14-dev
  # firmware cross build and the emulated Cortex-M
  gcc-arm-none-eabi libnewlib-arm-none-eabi libstdc++-arm-none-eabi-dev qemu-system-arm
  # the RISC-V (RV32) build and its emulator (qemu-system-riscv32); no C
  # library, not picolibc: see boards/qemu-riscv-virt/README.md
  gcc-riscv64-unknown-elf qemu-system-misc
)

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  sudo=sudo
fi

# The HID kernel-in-the-loop test fetches a kernel package with apt-get
# download: it needs package lists even when nothing is missing.
if [ -z "$(ls /var/lib/apt/lists/ 2>/dev/null | grep -v -e lock -e partial)" ]; then
  $sudo apt-get update -qq
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
photo() { "$(dirname "$0")/fetch-photo.sh"; }
[ ${#missing[@]} -eq 0 ] && { photo; exit 0; }

if [ -n "$sudo" ] && ! command -v sudo >/dev/null; then
  echo "setup: need root or sudo to install: ${missing[*]}" >&2
  exit 1
fi
echo "setup: installing ${missing[*]}" >&2
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
photo
