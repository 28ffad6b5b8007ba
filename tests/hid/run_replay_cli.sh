#!/bin/sh
# lumavel-read replay end to end on report files: what the file link wrote
# decodes to the estimates; a corrupted record and a truncated tail are named
# and make the exit status 1; a duplicated record is named as duplicated;
# the command line: help, --version, usage errors exit 2; configuration
# files are checked before any device (config check).
set -u
READ=$1 FEEDER=$2 COMPARE=$3 MAKE=$4 DIR=$5
fail() { echo "FAIL: $*" >&2; exit 1; }
rm -rf "$DIR" && mkdir -p "$DIR" && cd "$DIR" || fail "cannot use $DIR"

mkdir -p adir
"$MAKE" 300 est.csv || fail "make_test_estimates"
"$FEEDER" --link file:run.hidrep --estimates est.csv --period-us 0 || fail "feeder"
"$READ" replay run.hidrep -o out.csv || fail "replay of a good file exited $?"
"$COMPARE" est.csv out.csv || fail "replayed CSV differs from the estimates"
cut -d, -f1-6 est.csv > est6.csv && cut -d, -f1-6 out.csv > out6.csv
cmp -s est6.csv out6.csv || fail "replayed CSV columns 1-6 differ from the estimates as text"
"$READ" replay run.hidrep > stdout.csv || fail "replay to stdout"
cmp -s out.csv stdout.csv || fail "stdout and -o outputs differ"

# Record 3 starts at 8 + 2 * (1 + 42); flip a bit of its V field.
cp run.hidrep bad.hidrep
off=$((8 + 2 * 43 + 1 + 17))
byte=$(od -An -tu1 -j $off -N1 bad.hidrep | tr -d ' ')
printf "$(printf '\\%03o' $((byte ^ 4)))" | dd of=bad.hidrep bs=1 seek=$off conv=notrunc 2>/dev/null
printf '\052\001\001' >> bad.hidrep   # a record announcing 42 bytes, holding 2
"$READ" replay bad.hidrep -o bad.csv 2> bad.err
rc=$?
[ $rc -eq 1 ] || fail "corrupted file: exit $rc, expected 1"
grep -q "record 3 at byte 94.*CRC mismatch" bad.err || fail "CRC error not named: $(cat bad.err)"
grep -q "record 301 .*truncated" bad.err || fail "truncation not named: $(cat bad.err)"
rows=$(($(wc -l < bad.csv) - 1))
[ $rows -eq 299 ] || fail "expected the 299 good rows, got $rows"

# Record 2 written twice: named as a duplicate, skipped, not a loss.
{ head -c $((8 + 2 * 43)) run.hidrep; tail -c +$((8 + 43 + 1)) run.hidrep; } > dup.hidrep
"$READ" replay dup.hidrep -o dup.csv 2> dup.err || fail "duplicated record: exit $?"
grep -q "duplicated report in dup.hidrep record 3 at byte 94: seq 1 again, skipped" dup.err \
  || fail "duplicate not named: $(cat dup.err)"
grep -q "lost" dup.err && fail "a duplicate reported as a loss: $(cat dup.err)"
cmp -s out.csv dup.csv || fail "the duplicate changed the CSV"

# -o named as long as a name may be (255 bytes): its temporary name, with
# '.tmpPID' after it, was too long, and the CSV refused ('File name too long').
long=$(printf 'v%.0s' $(seq 251)).csv
"$READ" replay run.hidrep -o "$long" 2> long.err || fail "replay -o a 255-byte name: exit $?: $(cat long.err)"
cmp -s out.csv "$long" || fail "replay -o a 255-byte name: the CSV differs"
rm -f "$long"
# Standard output appended to the report file being read (was: the CSV
# appended as the file was read, its lines then read as damaged records: the
# report file lost, exit 1 with dozens of 'malformed report' lines).
cp run.hidrep app.hidrep
"$READ" replay app.hidrep >> app.hidrep 2> app.err
rc=$?
[ $rc -eq 2 ] || fail "replay app.hidrep >> app.hidrep: exit $rc, expected 2: $(cat app.err)"
grep -q "app.hidrep (standard output): that is the report file being read" app.err || fail "stdout onto the report file: $(cat app.err)"
cmp -s run.hidrep app.hidrep || fail "replay >> onto the report file changed it"
# '>' (the shell empties the file first) said the same, not 'not a lumavel
# report file (no "LMVHID1" header)'.
cp run.hidrep app.hidrep
"$READ" replay app.hidrep > app.hidrep 2> app.err
rc=$?
[ $rc -eq 2 ] || fail "replay app.hidrep > app.hidrep: exit $rc, expected 2: $(cat app.err)"
grep -q "app.hidrep (standard output): that is the report file being read" app.err || fail "stdout > the report file: $(cat app.err)"
"$READ" replay missing.hidrep > /dev/null 2> missing.err && fail "missing file accepted"
grep -q "missing.hidrep" missing.err || fail "missing file not named"
"$READ" replay adir > /dev/null 2> dir.err && fail "a folder accepted as a report file"
grep -q "adir: is a folder, not a report file" dir.err || fail "folder as report file: $(cat dir.err)"
"$READ" replay est.csv -o refused.csv > /dev/null 2> notrep.err && fail "CSV accepted as a report file"
grep -q "not a lumavel report file" notrep.err || fail "wrong message: $(cat notrep.err)"
[ -e refused.csv ] && fail "a refused replay left refused.csv behind"
# -o a folder or in a missing folder: said as lumavel-sim run -o says it, before
# any device is looked for (was: 'adir: cannot create the CSV: Is a directory').
for c in stream replay; do
  arg=; [ $c = replay ] && arg=run.hidrep
  timeout 30 "$READ" $c $arg -o adir > /dev/null 2> odir.err
  rc=$?
  [ $rc -eq 1 ] || fail "$c -o a folder: exit $rc, expected 1: $(cat odir.err)"
  grep -q "^lumavel-read $c: error: adir (-o): is a folder, not a CSV file$" odir.err \
    || fail "$c -o a folder: wrong message: $(cat odir.err)"
  timeout 30 "$READ" $c $arg -o nofolder/x.csv > /dev/null 2> onf.err
  grep -q "^lumavel-read $c: error: nofolder/x.csv (-o): cannot be created: its folder nofolder does not exist$" onf.err \
    || fail "$c -o in a missing folder: wrong message: $(cat onf.err)"
done
# stream -o FIFO that no process reads: refused after 2 s, before any device
# is looked for (was: waited in open() for ever).
mkfifo nobody.fifo || fail "mkfifo"
timeout 30 "$READ" stream -o nobody.fifo > /dev/null 2> fifo.err
rc=$?
[ $rc -eq 1 ] || fail "stream -o FIFO nobody reads: exit $rc, expected 1: $(cat fifo.err)"
grep -q "nobody.fifo: cannot create the CSV: is a FIFO (named pipe) that no process reads" fifo.err \
  || fail "stream -o FIFO: wrong message: $(cat fifo.err)"
# stream -o /dev/full: the CSV header that cannot be written is the error,
# before any device is looked for (was: exit 3 'no device', the loss unsaid).
timeout 30 "$READ" stream --timeout 1 -o /dev/full > /dev/null 2> full.err
rc=$?
[ $rc -eq 1 ] || fail "stream -o /dev/full: exit $rc, expected 1: $(cat full.err)"
grep -q "^lumavel-read stream: error: /dev/full: write error: No space left on device$" full.err \
  || fail "stream -o /dev/full: wrong message: $(cat full.err)"
grep -q "no lumavel device" full.err && fail "stream -o /dev/full looked for a device: $(cat full.err)"
"$READ" replay run.hidrep -o /dev/full > /dev/null 2> rfull.err && fail "replay -o /dev/full exited 0"
grep -q "/dev/full: write error: No space left on device" rfull.err || fail "replay -o /dev/full: $(cat rfull.err)"
# `config set --file` checks the file before looking for a device: errors
# name the file, the line and the key, exit 1, nothing sent.
printf 'width=40\n# a comment\ntau_us=fast\n' > bad.cfg
"$READ" config set --file bad.cfg 2> badcfg.err
rc=$?
[ $rc -eq 1 ] || fail "bad config file: exit $rc, expected 1"
grep -q "bad.cfg:3: tau_us = fast: not a whole number; tau_us must be 1000..10000000 us" badcfg.err || fail "config file error not named: $(cat badcfg.err)"
printf 'width=40\nlens_cam0=0.1,0.2\n' > short.cfg
"$READ" config set --file short.cfg 2> short.err
grep -q "short.cfg:2: lens_cam0 = 0.1,0.2: 2 values, but width 40 needs 41" short.err || fail "short lens table not named: $(cat short.err)"
for c in list stream info config "config get" "config set" "config check" replay; do
  "$READ" $c --help > help.txt || fail "$c --help exited $?"
  head -n 1 help.txt | grep -q "^Usage: lumavel-read $c" || fail "$c --help does not start with its usage line"
  grep -q "^Exit status: 0 done, 1 bad input or failure" help.txt || fail "$c --help has no exit status"
done
"$READ" --version > version.txt || fail "--version exited $?"
grep -qx "lumavel-read [0-9]*\.[0-9]*\.[0-9]*" version.txt || fail "--version printed $(cat version.txt)"
usage() {  # ARGS...: a usage error, exit 2, with the help hint
  "$READ" "$@" > /dev/null 2> usage.err
  rc=$?
  [ $rc -eq 2 ] || fail "lumavel-read $*: exit $rc, expected 2"
  grep -q -e "(see lumavel-read.* --help)" -e "^Usage: lumavel-read" usage.err || fail "lumavel-read $*: no help hint: $(cat usage.err)"
}
usage
usage bogus
usage --backend usb list
usage stream --count many
usage replay x.hidrep -n 0  # was: every measurement, exit 0 (0 was the default's "no limit")
# was: waited for ever for a report (0 was the default's "never"); timeout(1) ends the old behaviour
timeout 10 "$READ" stream --timeout 0 > /dev/null 2> usage.err
rc=$?
[ $rc -eq 2 ] || fail "lumavel-read stream --timeout 0: exit $rc, expected 2: $(cat usage.err)"
grep -qF -- "--timeout: must be a number in (0, 1e+09], not '0'" usage.err || fail "stream --timeout 0: $(cat usage.err)"
usage stream --live --no-live
usage replay
usage replay a b
usage config
usage config set
usage config check

# config check: the whole file before any device, each refusal naming the
# file, the line, the key, the value and the rule.
refused() {  # EXPECTED-MESSAGE ARGS...
  want=$1; shift
  "$READ" config check "$@" > /dev/null 2> check.err
  rc=$?
  [ $rc -eq 1 ] || fail "config check $*: exit $rc, expected 1"
  grep -qF "$want" check.err || fail "config check $*: expected \"$want\", got: $(cat check.err)"
}
printf 'height=30\nwidth=0\n' > w0.cfg
refused "w0.cfg:2: width = 0: width must be 16..160 columns" --file w0.cfg
printf '# rig\nbaseline_m=5\n' > h5.cfg
refused "h5.cfg:2: baseline_m = 5: baseline |h| must be 0.001..1 m" --file h5.cfg
refused "command line: misalignment_rad = 0.5: misalignment must be -0.35..0.35 rad" misalignment_rad=0.5
refused "command line: kernels = 9:0.07: kernel orders must be 0..3" kernels=9:0.07
refused "command line: cu0_px = 63.5: cu must be 0..width - 1 px" width=40 cu0_px=63.5
refused "adir: is a folder, not a configuration file" --file adir
printf '\357\273\277width = 40\r\n  tau_us= 250000 \r\n' > bom.cfg  # UTF-8 BOM, CRLF, spaces around =
"$READ" config check --file bom.cfg > ok.txt 2> ok.err || fail "a BOM / spaces / CRLF file refused: $(cat ok.err)"
grep -q "^ok: 2 setting(s) checked" ok.txt || fail "config check printed $(cat ok.txt)"
"$READ" config check cu0_px=100 > /dev/null || fail "cu0_px=100 refused without a width to check it against"
# The help says where the settings go (was: "after the files", where --file
# takes them as file names), and they work there: before --file, after --.
"$READ" config check --help > help.txt || fail "config check --help"
grep -qF "before --file" help.txt || fail "config check --help: $(grep -A1 SETTINGS help.txt)"
printf 'width=40\n' > w40.cfg
printf 'height=30\nwidth=20\n' > w20.cfg
"$READ" config check height=30 --file w40.cfg > /dev/null 2> before.err || fail "a setting before --file: $(cat before.err)"
"$READ" config check --file w40.cfg w20.cfg -- height=30 > /dev/null 2> after.err || fail "two files, a setting after --: $(cat after.err)"
# config set refuses the same file before looking for a device.
"$READ" config set --file h5.cfg 2> set.err
rc=$?
[ $rc -eq 1 ] || fail "config set of a bad file: exit $rc, expected 1"
grep -qF "h5.cfg:2: baseline_m = 5" set.err || fail "config set: $(cat set.err)"
# Device errors are said like every other error: "lumavel-read COMMAND: error:".
"$READ" info > /dev/null 2> nodev.err
rc=$?
if [ $rc -eq 3 ]; then  # no device here (the usual case on a build machine)
  grep -q "^lumavel-read info: error: no lumavel device" nodev.err || fail "no-device message: $(cat nodev.err)"
fi
# --device paths that are not hidraw nodes never reach hidapi (Debian 12's
# hid_open_path crashed on them): exit 3, the path named and what it is;
# stream does not wait for a device that cannot appear there.
for dev in /dev/null /dev/zero run.hidrep .; do
  for c in info "config get" "config set width=40" "stream --timeout 1"; do
    timeout 10 "$READ" --device "$dev" $c > /dev/null 2> dev.err
    rc=$?
    [ $rc -eq 3 ] || fail "--device $dev $c: exit $rc, expected 3: $(cat dev.err)"
    grep -qF "$dev is " dev.err || fail "--device $dev $c: path not named: $(cat dev.err)"
    grep -qF "not a hidraw device" dev.err || fail "--device $dev $c: $(cat dev.err)"
  done
done
echo "replay CLI: ok"
