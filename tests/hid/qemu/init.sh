#!/bin/busybox sh
# /init of the HID end-to-end guest: mounts, runs the tests, powers off.
/bin/busybox mkdir -p /proc /sys /dev /tmp /sbin /usr/bin /usr/sbin
/bin/busybox --install -s
mount -t proc proc /proc
mount -t sysfs sysfs /sys
mount -t devtmpfs devtmpfs /dev
mount -t tmpfs tmpfs /tmp
echo "LUMAVEL-GUEST-START $(uname -r)"
sh /guest_tests.sh
echo "LUMAVEL-GUEST-DONE"
poweroff -f
