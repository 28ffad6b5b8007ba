#!/bin/sh
# lumavel-read replay end to end on report files: what the file link wrote
# decodes to the estimates; a corrupted record and a truncated tail are named
# and make the exit status 2.
set -u
READ=$1 FEEDER=$2 COMPARE=$3 MAKE=$4 DIR=$5
fail() { echo "FAIL: $*" >&2; exit 1; }
rm -rf "$DIR" && mkdir -p "$DIR" && cd "$DIR" || fail "cannot use $DIR"

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
[ $rc -eq 2 ] || fail "corrupted file: exit $rc, expected 2"
grep -q "record 3 at byte 94.*CRC mismatch" bad.err || fail "CRC error not named: $(cat bad.err)"
grep -q "record 301 .*truncated" bad.err || fail "truncation not named: $(cat bad.err)"
rows=$(($(wc -l < bad.csv) - 1))
[ $rows -eq 299 ] || fail "expected the 299 good rows, got $rows"

"$READ" replay missing.hidrep > /dev/null 2> missing.err && fail "missing file accepted"
grep -q "missing.hidrep" missing.err || fail "missing file not named"
"$READ" replay est.csv > /dev/null 2> notrep.err && fail "CSV accepted as a report file"
grep -q "not a lumavel report file" notrep.err || fail "wrong message: $(cat notrep.err)"
# `config set --file` checks the file before looking for a device: errors
# name the file, the line and the key, exit 1, nothing sent.
printf 'width=40\n# a comment\ntau_us=fast\n' > bad.cfg
"$READ" config set --file bad.cfg 2> badcfg.err
rc=$?
[ $rc -eq 1 ] || fail "bad config file: exit $rc, expected 1"
grep -q "bad.cfg:3: tau_us: \"fast\" is not an integer" badcfg.err || fail "config file error not named: $(cat badcfg.err)"
printf 'width=40\nlens_cam0=0.1,0.2\n' > short.cfg
"$READ" config set --file short.cfg 2> short.err
grep -q "lens_cam0: 2 values, but width 40 needs 41" short.err || fail "short lens table not named: $(cat short.err)"
for c in list stream info config replay; do
  "$READ" $c --help > help.txt || fail "$c --help exited $?"
  grep -q "usage: lumavel-read" help.txt || fail "$c --help has no usage line"
done
echo "replay CLI: ok"
