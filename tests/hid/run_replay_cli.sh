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
cut -d, -f1-5 est.csv > est5.csv && cut -d, -f1-5 out.csv > out5.csv
cmp -s est5.csv out5.csv || fail "replayed CSV columns 1-5 differ from the estimates as text"
"$READ" replay run.hidrep > stdout.csv || fail "replay to stdout"
cmp -s out.csv stdout.csv || fail "stdout and -o outputs differ"

# Record 3 starts at 8 + 2 * (1 + 38); flip a bit of its V field.
cp run.hidrep bad.hidrep
off=$((8 + 2 * 39 + 1 + 17))
byte=$(od -An -tu1 -j $off -N1 bad.hidrep | tr -d ' ')
printf "$(printf '\\%03o' $((byte ^ 4)))" | dd of=bad.hidrep bs=1 seek=$off conv=notrunc 2>/dev/null
printf '\046\001\001' >> bad.hidrep   # a record announcing 38 bytes, holding 2
"$READ" replay bad.hidrep -o bad.csv 2> bad.err
rc=$?
[ $rc -eq 2 ] || fail "corrupted file: exit $rc, expected 2"
grep -q "record 3 at byte 86.*CRC mismatch" bad.err || fail "CRC error not named: $(cat bad.err)"
grep -q "record 301 .*truncated" bad.err || fail "truncation not named: $(cat bad.err)"
rows=$(($(wc -l < bad.csv) - 1))
[ $rows -eq 299 ] || fail "expected the 299 good rows, got $rows"

"$READ" replay missing.hidrep > /dev/null 2> missing.err && fail "missing file accepted"
grep -q "missing.hidrep" missing.err || fail "missing file not named"
"$READ" replay est.csv > /dev/null 2> notrep.err && fail "CSV accepted as a report file"
grep -q "not a lumavel report file" notrep.err || fail "wrong message: $(cat notrep.err)"
for c in list stream info config replay; do
  "$READ" $c --help > help.txt || fail "$c --help exited $?"
  grep -q "usage: lumavel-read" help.txt || fail "$c --help has no usage line"
done
echo "replay CLI: ok"
