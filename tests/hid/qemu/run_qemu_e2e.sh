#!/bin/bash
# HID end-to-end test through a real Linux USB/HID stack: boots Debian's own
# kernel (downloaded with apt-get download, unpacked, never installed; cached
# under --build-dir) under qemu-system-x86_64 -accel tcg with a busybox
# initramfs holding lumavel-read, lumavel-sim with a tiny recording rendered
# here, the device-side feeder and their libraries. In the guest: uhid (hidraw
# backend) and a configfs USB gadget on dummy_hcd (hidraw and libusb backends),
# the device being `lumavel-sim run REC --hid ...`; see guest_tests.sh. Exit 0 pass, 1 fail,
# 77 skip (only where QEMU cannot run).
set -u
HERE=$(cd "$(dirname "$0")" && pwd)
BUILD= READ= SIM= FEEDER= COMPARE= MAKE=
while [ $# -gt 0 ]; do
  case $1 in
    --build-dir) BUILD=$2; shift 2 ;;
    --lumavel-read) READ=$2; shift 2 ;;
    --lumavel-sim) SIM=$2; shift 2 ;;
    --feeder) FEEDER=$2; shift 2 ;;
    --compare) COMPARE=$2; shift 2 ;;
    --make-estimates) MAKE=$2; shift 2 ;;
    *) echo "run_qemu_e2e.sh: unknown argument $1" >&2; exit 1 ;;
  esac
done
for v in BUILD:--build-dir READ:--lumavel-read SIM:--lumavel-sim FEEDER:--feeder COMPARE:--compare \
         MAKE:--make-estimates; do
  n=${v%%:*}
  [ -n "${!n}" ] || { echo "run_qemu_e2e.sh: missing ${v#*:} argument" >&2; exit 1; }
done
skip() { echo "SKIP: $*"; exit 77; }
fail() { echo "FAIL: $*" >&2; exit 1; }

QEMU=$(command -v qemu-system-x86_64) || skip "qemu-system-x86_64 not found (apt-get install qemu-system-x86)"
BUSYBOX=$(command -v busybox) || skip "busybox not found (apt-get install busybox-static)"
mkdir -p "$BUILD/kernel" || fail "cannot create $BUILD"
KDIR=$BUILD/kernel
MODS="hid hid-generic uhid usb-common usbcore usbhid udc-core dummy_hcd configfs libcomposite usb_f_hid"

# --- Debian's kernel, cached ------------------------------------------------
if [ ! -s "$KDIR/kernel.img" ] || [ ! -s "$KDIR/modules/usb_f_hid.ko" ]; then
  PKG=$(apt-cache depends linux-image-amd64 2>/dev/null | awk '/Depends: linux-image-[0-9]/ {print $2; exit}')
  [ -n "$PKG" ] || skip "cannot resolve Debian's linux-image-amd64 (apt-get update?): no kernel to boot"
  echo "downloading $PKG (cached in $KDIR)"
  rm -rf "$KDIR" && mkdir -p "$KDIR/unpack" "$KDIR/modules"
  (cd "$KDIR" && apt-get download "$PKG" > download.log 2>&1) ||
    skip "apt-get download $PKG failed (no network?): $(tail -1 "$KDIR/download.log")"
  dpkg-deb --fsys-tarfile "$KDIR"/"$PKG"_*.deb | tar -x -C "$KDIR/unpack" --wildcards \
      './boot/vmlinuz-*' '*/kernel/drivers/hid/*' '*/kernel/drivers/usb/*' '*/kernel/fs/configfs/*' ||
    fail "cannot unpack $PKG"
  for m in $MODS; do
    f=$(find "$KDIR/unpack" -name "$m.ko" | head -1)
    [ -n "$f" ] || fail "$PKG has no $m.ko"
    cp "$f" "$KDIR/modules/"
  done
  VMLINUZ=$(ls "$KDIR"/unpack/boot/vmlinuz-* | head -1)
  # The uncompressed kernel boots ~3 s faster under TCG: find the xz stream.
  off=$(LC_ALL=C grep -obUaP '\xfd7zXZ\x00' "$VMLINUZ" | head -1 | cut -d: -f1)
  if [ -n "$off" ] && tail -c +$((off + 1)) "$VMLINUZ" | xz -dc > "$KDIR/vmlinux" 2>/dev/null ||
     [ "$(head -c 4 "$KDIR/vmlinux" 2>/dev/null | od -An -c | tr -d ' ')" = "177ELF" ]; then
    mv "$KDIR/vmlinux" "$KDIR/kernel.img"
  else
    cp "$VMLINUZ" "$KDIR/kernel.img"
  fi
  echo "$PKG" > "$KDIR/package"
  rm -rf "$KDIR/unpack" "$KDIR"/*.deb
fi

# --- initramfs ----------------------------------------------------------------
ROOT=$BUILD/root
rm -rf "$ROOT" && mkdir -p "$ROOT"/{bin,lib/modules,usr/local/bin,data,etc} || fail "cannot create $ROOT"
cp "$BUSYBOX" "$ROOT/bin/busybox"
cp "$HERE/init.sh" "$ROOT/init" && chmod 755 "$ROOT/init"
cp "$HERE/guest_tests.sh" "$ROOT/guest_tests.sh"
cp "$KDIR"/modules/*.ko "$ROOT/lib/modules/"
cp "$READ" "$SIM" "$FEEDER" "$COMPARE" "$ROOT/usr/local/bin/"
LIBDIR=/usr/lib/x86_64-linux-gnu
# hidapi backends are dlopen()ed by lumavel-read: ldd does not see them.
EXTRA="$LIBDIR/libhidapi-hidraw.so.0 $LIBDIR/libhidapi-libusb.so.0"
for f in $EXTRA; do [ -e "$f" ] || fail "$f missing (apt-get install libhidapi-hidraw0 libhidapi-libusb0)"; done
copy_lib() {  # copies a library to the same path in the image, following symlinks
  [ -e "$ROOT$1" ] && return
  mkdir -p "$ROOT$(dirname "$1")" && cp -L "$1" "$ROOT$1"
}
for bin in "$BUSYBOX" "$READ" "$SIM" "$FEEDER" "$COMPARE" $EXTRA; do
  copy_lib_of=$(ldd "$bin" 2>/dev/null | awk '$2 == "=>" && $3 ~ /^\// {print $3} $1 ~ /^\// {print $1}')
  for lib in $copy_lib_of; do copy_lib "$lib"; done
done
for f in $EXTRA; do copy_lib "$f"; done
# hidapi-libusb converts USB strings with iconv: without gconv's UTF-16 they come back NULL.
for f in $LIBDIR/gconv/UTF-16.so $LIBDIR/gconv/gconv-modules $LIBDIR/gconv/gconv-modules.cache; do
  [ -e "$f" ] && copy_lib "$f"
done
[ -d $LIBDIR/gconv/gconv-modules.d ] && mkdir -p "$ROOT$LIBDIR/gconv" && cp -r $LIBDIR/gconv/gconv-modules.d "$ROOT$LIBDIR/gconv/"
printf "root:x:0:0:root:/:/bin/sh\nlumavel:x:1000:1000:lumavel:/tmp:/bin/sh\n" > "$ROOT/etc/passwd"
printf "root:x:0:\nlumavel:x:1000:\n" > "$ROOT/etc/group"

# The device for the streaming and config checks: lumavel-sim on a tiny
# recording rendered here (2 s, 40x30); its estimates, computed here, are what
# lumavel-read must read back in the guest.
SCENARIO=$HERE/../../../host_sim/scenarios/gyro_turning.yaml
rm -rf "$BUILD/rec"
"$SIM" render "$SCENARIO" "$BUILD/rec" --resolution 40x30 --duration 2 --quiet > "$BUILD/render.log" 2>&1 ||
  { tail -5 "$BUILD/render.log"; fail "lumavel-sim render $SCENARIO failed (log: $BUILD/render.log)"; }
"$SIM" run "$BUILD/rec" -o "$ROOT/data/expected.csv" --plot "$BUILD/expected.svg" --quiet ||
  fail "lumavel-sim run $BUILD/rec failed"
cp -r "$BUILD/rec" "$ROOT/data/rec" || fail "cannot copy the recording into $ROOT"
# A lens configuration for the 40-column device, as `config set --file` reads
# it: a cubic (barrel-like) correction of cam0's 41 column edges, up to 0.01 rad.
{
  echo "# lens check: cam0 gets a table, cam1 stays pinhole"
  echo "width=40"; echo "cu0_px=19.5"; echo "cu1_px=19.5"
  awk 'BEGIN { s = "lens_cam0="; for (u = 0; u <= 40; u++) { x = (u - 20) / 20; s = s (u ? "," : "") sprintf("%.5f", -0.01 * x * x * x) } print s }'
  echo "lens_cam1=none"
} > "$ROOT/data/lens.cfg"
echo "recording: $(( $(wc -l < "$ROOT/data/expected.csv") - 1 )) estimates, $(du -sh "$BUILD/rec" | cut -f1)"

# Feeder data (reconnect, live view, permission): a recording's estimates when
# given, else a synthetic drive.
EST=${LUMAVEL_HID_E2E_ESTIMATES:-}
if [ -n "$EST" ]; then
  cp "$EST" "$ROOT/data/est.csv" || fail "cannot read $EST"
else
  "$MAKE" 400 "$ROOT/data/est.csv" || fail "make_test_estimates failed"
fi
"$MAKE" 1 "$ROOT/data/one.csv" || fail "make_test_estimates failed"
"$FEEDER" --write-descriptor "$ROOT/data/descriptor.bin" || fail "cannot write the descriptor"

IMG=$BUILD/initramfs.cpio.gz
(cd "$ROOT" && find . | "$BUSYBOX" cpio -o -H newc 2>/dev/null | gzip -1 > "$IMG") || fail "cannot build $IMG"

# --- boot ------------------------------------------------------------------------
LOG=$BUILD/guest.log
echo "booting $(cat "$KDIR/package") under TCG (log: $LOG)"
start=$(date +%s)
timeout 600 "$QEMU" -accel tcg -m 768 -smp 1 -nographic -nodefaults -serial stdio -no-reboot \
  -kernel "$KDIR/kernel.img" -initrd "$IMG" \
  -append "console=ttyS0 panic=-1 quiet loglevel=3 rdinit=/init" < /dev/null > "$LOG" 2>&1
qrc=$?
echo "guest ran $(( $(date +%s) - start )) s (qemu exit $qrc)"
if ! grep -q "LUMAVEL-GUEST-START" "$LOG"; then
  tail -20 "$LOG"
  [ $qrc -eq 124 ] && fail "the guest did not start within 600 s"
  skip "QEMU cannot run here (exit $qrc): see $LOG"
fi
grep "LUMAVEL-TEST" "$LOG"
grep -q "LUMAVEL-GUEST-DONE" "$LOG" || { tail -30 "$LOG"; fail "the guest did not finish (timeout or crash): see $LOG"; }
EXPECTED="uhid-list uhid-stream uhid-info uhid-config-set-get uhid-config-refused uhid-sim-exit uhid-persist
  uhid-reconnect uhid-live-view uhid-permission-denied no-device-message gadget-enumerated
  gadget-hidraw-list gadget-hidraw-stream gadget-hidraw-info gadget-hidraw-config-set-get
  gadget-hidraw-config-refused gadget-hidraw-lens-set-get gadget-hidraw-sim-exit gadget-hidraw-persist
  gadget-libusb-list gadget-libusb-stream gadget-libusb-info gadget-libusb-config-set-get
  gadget-libusb-config-refused gadget-libusb-lens-set-get gadget-libusb-sim-exit gadget-libusb-persist
  uhid-lens-set-get"
bad=0
for t in $EXPECTED; do
  grep -q "^LUMAVEL-TEST $t PASS" "$LOG" || { echo "not passed: $t"; bad=1; }
done
[ $bad -eq 0 ] || fail "HID end-to-end checks failed (guest log: $LOG)"
echo "HID end-to-end: all $(echo $EXPECTED | wc -w) checks passed"
