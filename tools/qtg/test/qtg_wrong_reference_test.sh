#!/bin/sh
# Negative control: a test whose reference is deliberately wrong (a phugoid period 40 % off
# Lanchester's, and an airspeed time history 10 kt off the trim) must FAIL, with exit status 1
# and both checks named as failed in the report; the same test with the right values passes;
# a test file with a NaN fails by name (file:line: field).
# Usage: qtg_wrong_reference_test.sh FEDSIM_QTG DATA_DIR OUT_DIR
set -u
qtg=$1 data=$2 out=$3
rm -rf "$out"
"$qtg" --tests "$data" --only wrong_reference --out "$out/wrong" --pdf off
rc=$?
fail=0
[ "$rc" -eq 1 ] || { echo "FAIL: a wrong reference gave exit status $rc, not 1"; fail=1; }
report=$out/wrong/qtg_report.html
[ -s "$report" ] || { echo "FAIL: no report"; exit 1; }
[ "$(grep -c "class='fail'>FAIL</td></tr>" "$report")" -ge 2 ] || { echo "FAIL: the wrong checks are not both marked failed"; fail=1; }
"$qtg" --tests "$data" --only right_reference --out "$out/right" --pdf off
rc=$?
[ "$rc" -eq 0 ] || { echo "FAIL: the control with the right reference exited $rc"; fail=1; }
# an invalid test file is a failed test, named with file:line: field
mkdir -p "$out/bad"
sed 's/^rate_hz: 20/rate_hz: .nan/' "$data/right_reference.yaml" > "$out/bad/bad_rate.yaml"
cp "$data/right_reference.csv" "$out/bad/"
"$qtg" --tests "$out/bad" --out "$out/bad_report" --pdf off 2> "$out/bad.log"
rc=$?
[ "$rc" -eq 1 ] || { echo "FAIL: an invalid test file gave exit status $rc, not 1"; fail=1; }
grep -q "bad_rate.yaml:11: rate_hz" "$out/bad.log" || { echo "FAIL: no file:line: field message"; cat "$out/bad.log"; fail=1; }
[ "$fail" -eq 0 ] && echo "PASS: the wrong reference and the invalid file failed, the right one passed"
exit $fail
