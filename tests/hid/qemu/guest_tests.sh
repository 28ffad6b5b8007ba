# HID end-to-end tests, run inside the QEMU guest by /init. Each check prints
# "LUMAVEL-TEST <name> PASS|FAIL [why]"; the host script decides from these.
set -u
export PATH=/usr/local/bin:/bin:/sbin:/usr/bin:/usr/sbin
M=/lib/modules
EST=/data/est.csv          # synthetic drive, served by the feeder (reconnect, live, permission)
ROWS=$(($(wc -l < $EST) - 1))
REC=/data/rec              # a rendered recording, served by lumavel-sim run --hid
SIM_EST=/data/expected.csv # lumavel-sim run REC's own estimates, computed on the host
SIM_ROWS=$(($(wc -l < $SIM_EST) - 1))

result() { echo "LUMAVEL-TEST $1 $2${3:+ $3}"; }
check() {  # check NAME COMMAND...: PASS if the command succeeds
  name=$1; shift
  if "$@" > /tmp/check.out 2>&1; then result "$name" PASS; else
    result "$name" FAIL "($(tail -c 600 /tmp/check.out | tr '\n' ' '))"; fi
}
load() {
  for m in "$@"; do insmod $M/$m.ko || echo "insmod $m failed"; done
}
# Polls until `lumavel-read list` sees the device (nodes appear asynchronously).
wait_listed() {
  i=0
  while [ $i -lt 100 ]; do
    lumavel-read --backend "$1" list > /tmp/list.out 2>&1 && return 0
    sleep 0.1; i=$((i + 1))
  done
  cat /tmp/list.out; return 1
}
start_feeder() {  # start_feeder LINK CSV STORE LINGER_MS
  hid_device_feeder --link "$1" --estimates "$2" --store "$3" --period-us 2000 \
    --linger-ms "$4" 2> /tmp/feeder.err &
  FEEDER=$!
}
stop_feeder() { kill $FEEDER 2> /dev/null; wait $FEEDER 2> /dev/null; }
# The simulator as the device: every estimate of the recording as a report,
# config sets kept in STORE, then feature reports answered until stopped.
# Under TCG the reader can stall for tens of ms: reports wait up to 5 s for it.
start_sim() {  # start_sim LINK STORE
  lumavel-sim run $REC --hid "$1" --hid-config "$2" --hid-wait-ms 5000 --hid-linger -1 -o /tmp/sim.csv \
    --plot /tmp/sim.svg 2> /tmp/sim.err &
  SIM=$!
}
stop_sim() {  # it stops cleanly (exit 0) and its own CSV equals the host's run
  kill $SIM 2> /dev/null; wait $SIM; rc=$?
  cat /tmp/sim.err
  [ $rc -eq 0 ] && cmp $SIM_EST /tmp/sim.csv
}
has() { grep -qx "$1" "$2" || { echo "missing \"$1\" in $2:"; cat "$2"; return 1; }; }

config_check() {  # BACKEND
  lumavel-read --backend "$1" config set width=80 cu0_px=39.5 cu1_px=39.5 tau_us=250000 \
      look=right baseline_m=-0.06 kernels=1:0.07,2:0.1,1:0.14 > /tmp/set.out || return 1
  lumavel-read --backend "$1" config get > /tmp/get.out || return 1
  cmp /tmp/set.out /tmp/get.out && has width=80 /tmp/get.out && has tau_us=250000 /tmp/get.out \
    && has look=right /tmp/get.out && has kernels=1:0.07,2:0.1,1:0.14 /tmp/get.out && has baseline_m=-0.06 /tmp/get.out || return 1
  lumavel-read --backend "$1" info > /tmp/info.out && has "config_source=set by host" /tmp/info.out \
    && has last_config_set=ok /tmp/info.out
}
refuse_check() {  # BACKEND: out-of-range values never leave the host
  lumavel-read --backend "$1" config set tau_us=5 2> /tmp/refuse.err  # refused before the device is opened
  [ $? -eq 1 ] && grep -q "command line: tau_us = 5: tau_us must be 1000..10000000 us" /tmp/refuse.err || return 1
  lumavel-read --backend "$1" config set cu0_px=100 2> /tmp/refuse.err  # refused against the device's width 80
  [ $? -eq 5 ] && grep -q "cu0_px = 100: cu must be 0..width - 1 px (with the device's configuration" /tmp/refuse.err
}
# A lens table from a file (as `lumavel-sim calibrate --write` makes them):
# uploaded in pieces, named by the configuration, read back piece by piece.
# It becomes /tmp/set.out, so persist_check checks that the tables persist.
lens_check() {  # BACKEND
  lumavel-read --backend "$1" config set --file /data/lens.cfg > /tmp/set.out || return 1
  lumavel-read --backend "$1" config get > /tmp/get.out || return 1
  cmp /tmp/set.out /tmp/get.out && has width=40 /tmp/get.out && has lens_cam1=none /tmp/get.out \
    && grep -q "^lens_cam0=0.01," /tmp/get.out && [ "$(grep ^lens_cam0= /tmp/get.out | tr , '\n' | wc -l)" -eq 41 ]
}
info_check() {  # BACKEND
  lumavel-read --backend "$1" info > /tmp/info.out && has board=lumavel-sim /tmp/info.out \
    && has resolution=40x30 /tmp/info.out && has firmware=0.1.0 /tmp/info.out
}
# A restarted lumavel-sim streams the same estimates again and serves the
# stored configuration. The stream is read to the end so that no report is
# left queued in the gadget for the next reader when this device is killed.
persist_check() {  # LINK BACKEND
  lumavel-read --backend "$2" stream -n $SIM_ROWS --timeout 60 --no-live -o /tmp/persist.csv 2> /tmp/persist.err &
  R=$!
  case $1 in hidg*) wait_line "connected to" /tmp/persist.err ;; esac
  start_sim "$1" /tmp/store.bin
  wait $R && csv_equal $SIM_EST /tmp/persist.csv || { cat /tmp/persist.err; kill $SIM; return 1; }
  wait_listed "$2" && lumavel-read --backend "$2" config get > /tmp/get2.out \
    && cmp /tmp/set.out /tmp/get2.out && lumavel-read --backend "$2" info > /tmp/info2.out \
    && has config_source=stored /tmp/info2.out
  rc=$?
  kill $SIM 2> /dev/null; wait $SIM 2> /dev/null
  return $rc
}

# The CSV read through HID equals the estimates: every row at the report's
# resolution (hid_csv_compare), and the shared six columns character for
# character (both sides print shortest round-trip decimals).
csv_equal() {  # EXPECTED ACTUAL
  hid_csv_compare "$1" "$2" || return 1
  cut -d, -f1-6 "$1" > /tmp/expected6.csv && cut -d, -f1-6 "$2" > /tmp/actual6.csv
  cmp /tmp/expected6.csv /tmp/actual6.csv || { diff /tmp/expected6.csv /tmp/actual6.csv | head -5; return 1; }
}

wait_line() {  # wait_line TEXT FILE: polls up to 20 s for TEXT in FILE
  i=0
  while ! grep -q "$1" "$2" 2> /dev/null; do
    [ $i -lt 200 ] || return 1
    sleep 0.1; i=$((i + 1))
  done
}

# A whole device life on one link, the device being `lumavel-sim run REC --hid`:
# stream (the CSV read must equal lumavel-sim run's own estimates), info,
# config set/get, refusal, persistence across a restart.
# The reader opens first: a USB device streams whether or not anyone listens
# (the gadget cannot tell), so reports sent before the open are not expected.
run_link() {  # PREFIX LINK BACKEND
  rm -f /tmp/store.bin /tmp/set.out
  case $2 in hidg*) check "$1-list" wait_listed "$3" ;; esac
  lumavel-read --backend "$3" stream -n $SIM_ROWS --timeout 60 --no-live -o /tmp/$1.csv 2> /tmp/$1.err &
  READER=$!
  case $2 in hidg*) wait_line "connected to" /tmp/$1.err ;; esac
  start_sim "$2" /tmp/store.bin
  case $2 in uhid*) check "$1-list" wait_listed "$3" ;; esac
  if wait $READER && csv_equal $SIM_EST /tmp/$1.csv > /tmp/cmp.out 2>&1 \
     && wait_line "reports sent through" /tmp/sim.err && grep -q " 0 overruns" /tmp/sim.err; then
    result "$1-stream" PASS
  else
    result "$1-stream" FAIL "($({ head -c 300 /tmp/cmp.out; tail -c 300 /tmp/$1.err; grep "^hid:" /tmp/sim.err; } | tr "\n" " "))"
  fi
  check "$1-info" info_check "$3"
  check "$1-config-set-get" config_check "$3"
  check "$1-config-refused" refuse_check "$3"
  check "$1-lens-set-get" lens_check "$3"
  check "$1-sim-exit" stop_sim
  check "$1-persist" persist_check "$2" "$3"
}

# --- uhid: a virtual HID device through hidraw -----------------------------
load hid hid-generic uhid
run_link uhid uhid hidraw

# Reconnect: the device goes away mid-stream and comes back.
head -n 201 $EST > /tmp/est_a.csv
{ head -n 1 $EST; tail -n +202 $EST; } > /tmp/est_b.csv
reconnect_check() {
  lumavel-read stream -n $ROWS --timeout 30 --no-live -o /tmp/reconnect.csv 2> /tmp/reconnect.err &
  READER=$!
  start_feeder uhid /tmp/est_a.csv /tmp/s.bin 1500
  wait $FEEDER
  sleep 1
  start_feeder uhid /tmp/est_b.csv /tmp/s.bin 1500
  wait $FEEDER
  wait $READER && csv_equal $EST /tmp/reconnect.csv && grep -q "went away" /tmp/reconnect.err
}
check uhid-reconnect reconnect_check

# The live one-line view (forced: stdout is not a terminal here), CSV to a file.
live_check() {
  lumavel-read stream --live -n 100 -o /tmp/live.csv > /tmp/live.out 2> /tmp/live.err &
  R=$!
  start_feeder uhid $EST /tmp/s.bin 0
  wait $R; rc=$?
  stop_feeder
  cat /tmp/live.out; echo
  [ $rc -eq 0 ] && grep -q " Hz  V .* m/s  s .* m  heading .* rad " /tmp/live.out \
    && [ $(wc -l < /tmp/live.csv) -eq 101 ]
}
check uhid-live-view live_check

# Permission denied: a clear message naming the udev rule.
permission_check() {
  start_feeder uhid $EST /tmp/s.bin -1
  wait_listed hidraw || return 1
  chmod 600 /dev/hidraw*
  su -s /bin/sh -c "/usr/local/bin/lumavel-read info 2> /tmp/perm.err" lumavel
  rc=$?
  stop_feeder
  cat /tmp/perm.err
  [ $rc -eq 4 ] && grep -q "70-lumavel.rules" /tmp/perm.err && grep -q "permission denied" /tmp/perm.err
}
check uhid-permission-denied permission_check
check no-device-message sh -c 'lumavel-read info 2> /tmp/nodev.err; [ $? -eq 3 ] && grep -q "no lumavel device" /tmp/nodev.err'

# --- USB gadget: a real USB HID device on dummy_hcd -------------------------
load usb-common usbcore usbhid udc-core dummy_hcd configfs libcomposite usb_f_hid
mount -t configfs none /sys/kernel/config
G=/sys/kernel/config/usb_gadget/lumavel
mkdir $G && cd $G
echo 0x1209 > idVendor; echo 0x0001 > idProduct; echo 0x0100 > bcdDevice
mkdir strings/0x409
echo lumavel > strings/0x409/manufacturer
echo "lumavel velocity sensor" > strings/0x409/product
echo e2e-0001 > strings/0x409/serialnumber
mkdir functions/hid.usb0
echo 0 > functions/hid.usb0/protocol
echo 0 > functions/hid.usb0/subclass
echo 62 > functions/hid.usb0/report_length
echo 1 > functions/hid.usb0/no_out_endpoint
cat /data/descriptor.bin > functions/hid.usb0/report_desc
mkdir -p configs/c.1/strings/0x409
echo lumavel > configs/c.1/strings/0x409/configuration
echo 100 > configs/c.1/MaxPower
ln -s functions/hid.usb0 configs/c.1/
ls /sys/class/udc > UDC
cd /
i=0; while [ ! -e /dev/hidg0 ] && [ $i -lt 100 ]; do sleep 0.1; i=$((i + 1)); done
enumerated() {
  i=0
  until grep -qx 1209 /sys/bus/usb/devices/*/idVendor 2> /dev/null; do
    [ $i -lt 200 ] || return 1
    sleep 0.1; i=$((i + 1))
  done
  [ -e /dev/hidg0 ]
}
check gadget-enumerated enumerated
run_link gadget-hidraw hidg:/dev/hidg0 hidraw
run_link gadget-libusb hidg:/dev/hidg0 libusb
