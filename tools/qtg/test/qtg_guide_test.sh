#!/bin/sh
# Flies the repository's whole QTG (data/qtg) and checks the run: exit status 0 (every test
# passed), the report exists, names every test and has a plot; with chromium on PATH the PDF too.
# The federation tests (the 737 autoland) run `fedsim run --in-process` with FEDSIM.
# Usage: qtg_guide_test.sh FEDSIM_QTG TESTS_DIR OUT_DIR [FEDSIM]
set -u
qtg=$1 tests=$2 out=$3
rm -rf "$out"
"$qtg" --tests "$tests" --out "$out" --pdf auto ${4:+--fedsim "$4"}
rc=$?
report=$out/qtg_report.html
fail=0
[ -s "$report" ] || { echo "FAIL: no report $report"; exit 1; }
for f in $(find "$tests" -name '*.yaml' | sort); do
  name=$(basename "$f" .yaml)
  grep -q "id='$name'" "$report" || { echo "FAIL: test $name missing from the report"; fail=1; }
done
if command -v chromium >/dev/null 2>&1; then
  [ -s "$out/qtg_report.pdf" ] || { echo "FAIL: chromium is installed but no PDF"; fail=1; }
fi
grep -q '<svg' "$report" || { echo "FAIL: no plot in the report"; fail=1; }
[ "$rc" -eq 0 ] || { echo "FAIL: fedsim-qtg exited $rc (a test failed; see $report)"; fail=1; }
[ "$fail" -eq 0 ] && echo "PASS: the QTG passed; report $report"
exit $fail
