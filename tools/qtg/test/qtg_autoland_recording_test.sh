#!/bin/sh
# The ILS approach and autoland tests (data/qtg/b737/b737_ils_autoland_*.yaml) on recordings of
# their federation, as the main job's after-step evaluates one (fedsim qtg --recording DIR
# --only NAME --out DIR/qtg): both pass on their own runs, and each can fail:
#   - a tightened limit (touchdown at most 1000 ft beyond the threshold) fails each test;
#   - a perturbed recording (the aircraft 40 m further north: over 100 ft right of the
#     centreline) fails the centreline checks of the calm test;
#   - a recording without the navigation state, a truncated aircraft or navigation state, an
#     unknown test name, a missing recording folder and --recording without --only fail with a
#     message naming the file, folder or name.
# Usage: qtg_autoland_recording_test.sh FEDSIM TESTS_DIR SOURCE_DIR OUT_DIR
set -u
fedsim=$1 tests=$2 src=$3 out=$4
rm -rf "$out"
mkdir -p "$out"
fail=0
no() { echo "FAIL: $*"; fail=1; }

# the two federations, in-process (a few seconds each)
"$fedsim" run "$src/deploy/qtg/b737-ils-autoland.yaml" --in-process --quiet --progress 0 \
  --out "$out/calm" > "$out/calm.log" 2>&1 || { echo "FAIL: the calm run failed"; tail "$out/calm.log"; exit 1; }
"$fedsim" run "$src/deploy/qtg/b737-ils-autoland.yaml" --in-process --quiet --progress 0 \
  --scenario "$src/data/scenarios/crosswind_15kt_right.yaml" \
  --out "$out/crosswind" > "$out/crosswind.log" 2>&1 || { echo "FAIL: the crosswind run failed"; tail "$out/crosswind.log"; exit 1; }

# exactly the after-step the main job gets (the report beside the recording, PDF when it can)
"$fedsim" qtg --tests "$tests" --recording "$out/calm" --only b737_ils_autoland_calm --out "$out/calm/qtg" \
  2> "$out/calm_qtg.log" || no "the calm test failed on its own recording (see $out/calm/qtg/qtg_report.html)"
grep -q "id='b737_ils_autoland_calm'" "$out/calm/qtg/qtg_report.html" 2>/dev/null || no "no calm report"
grep -q "evaluated from this recording" "$out/calm/qtg/qtg_report.html" 2>/dev/null || no "the report does not say it read a recording"
"$fedsim" qtg --tests "$tests" --recording "$out/crosswind" --only b737_ils_autoland_crosswind \
  --out "$out/crosswind/qtg" --pdf off 2> "$out/crosswind_qtg.log" || no "the crosswind test failed on its own recording"

# a tightened limit fails each test, by the check's name
mkdir -p "$out/tight"
for t in calm crosswind; do
  sed 's/limits: {min: 200, max: 2700, unit: ft}/limits: {min: 200, max: 1000, unit: ft}/' \
    "$tests/b737/b737_ils_autoland_$t.yaml" > "$out/tight/b737_ils_autoland_$t.yaml"
  "$fedsim" qtg --tests "$out/tight" --recording "$out/$t" --only "b737_ils_autoland_$t" \
    --out "$out/tight/$t" --pdf off 2> "$out/tight_$t.log"
  rc=$?
  [ "$rc" -eq 1 ] || no "$t with touchdown at most 1000 ft: exit $rc, not 1"
  grep -q "touchdown distance beyond the threshold: " "$out/tight_$t.log" || no "$t: the tightened check is not named failed"
done

# a perturbed recording: latitude + 6.28e-6 rad (40 m north, 116 ft right of the centreline)
mkdir -p "$out/moved"
awk -F, -v OFS=, 'BEGIN { CONVFMT = "%.17g" }
  NR == 1 { for (i = 1; i <= NF; i++) if ($i == "latitude_rad") c = i; print; next }
  { $c = $c + 6.28e-6; print }' "$out/calm/fedsim_aircraft_state.csv" > "$out/moved/fedsim_aircraft_state.csv"
ln -s "$out/calm/fedsim_navigation_state.csv" "$out/calm/fedsim_autopilot_state.csv" "$out/moved/"
"$fedsim" qtg --tests "$tests" --recording "$out/moved" --only b737_ils_autoland_calm --out "$out/moved/qtg" \
  --pdf off 2> "$out/moved.log"
rc=$?
[ "$rc" -eq 1 ] || no "a recording 40 m off the approach: exit $rc, not 1"
grep -q "touchdown from the centreline (+ left): " "$out/moved.log" || no "the moved touchdown is not named failed"
grep -q "on the runway through the rollout" "$out/moved.log" || no "the moved rollout is not named failed"

# a recording without the navigation state: the file is named
mkdir -p "$out/no_nav"
ln -s "$out/calm/fedsim_aircraft_state.csv" "$out/calm/fedsim_autopilot_state.csv" "$out/no_nav/"
"$fedsim" qtg --tests "$tests" --recording "$out/no_nav" --only b737_ils_autoland_calm --out "$out/no_nav/qtg" \
  --pdf off 2> "$out/no_nav.log"
rc=$?
[ "$rc" -eq 1 ] || no "a recording without the navigation state: exit $rc, not 1"
grep -q "no_nav/fedsim_navigation_state.csv: missing" "$out/no_nav.log" || { no "the missing file is not named"; cat "$out/no_nav.log"; }

# a truncated recording (the first 100 s) is not the run
mkdir -p "$out/short"
head -n 5001 "$out/calm/fedsim_aircraft_state.csv" > "$out/short/fedsim_aircraft_state.csv"
ln -s "$out/calm/fedsim_navigation_state.csv" "$out/calm/fedsim_autopilot_state.csv" "$out/short/"
"$fedsim" qtg --tests "$tests" --recording "$out/short" --only b737_ils_autoland_calm --out "$out/short/qtg" \
  --pdf off 2> "$out/short.log"
rc=$?
[ "$rc" -eq 1 ] || no "a truncated recording: exit $rc, not 1"
grep -q "fedsim_aircraft_state.csv: ends at 100 s, before the test's 400 s" "$out/short.log" || { no "the truncation is not named"; cat "$out/short.log"; }

# ... and so is one whose navigation state stops at 100 s
mkdir -p "$out/short_nav"
head -n 5001 "$out/calm/fedsim_navigation_state.csv" > "$out/short_nav/fedsim_navigation_state.csv"
ln -s "$out/calm/fedsim_aircraft_state.csv" "$out/calm/fedsim_autopilot_state.csv" "$out/short_nav/"
"$fedsim" qtg --tests "$tests" --recording "$out/short_nav" --only b737_ils_autoland_calm \
  --out "$out/short_nav/qtg" --pdf off 2> "$out/short_nav.log"
rc=$?
[ "$rc" -eq 1 ] || no "a truncated navigation state: exit $rc, not 1"
grep -q "short_nav/fedsim_navigation_state.csv: ends at" "$out/short_nav.log" || { no "the truncated navigation state is not named"; cat "$out/short_nav.log"; }

# an unknown test, and --recording without --only: bad options (exit 2), named
"$fedsim" qtg --tests "$tests" --recording "$out/calm" --only b737_ils_autoland_typo --out "$out/typo" \
  --pdf off 2> "$out/typo.log"
rc=$?
[ "$rc" -eq 2 ] || no "an unknown test name: exit $rc, not 2"
grep -q "b737_ils_autoland_typo: no such test" "$out/typo.log" || no "the unknown name is not named"
"$fedsim" qtg --tests "$tests" --recording "$out/calm" --out "$out/all" --pdf off 2> "$out/all.log"
rc=$?
[ "$rc" -eq 2 ] || no "--recording without --only: exit $rc, not 2"
grep -q "needs --only" "$out/all.log" || no "--recording without --only is not explained"

"$fedsim" qtg --tests "$tests" --recording "$out/no_such_folder" --only b737_ils_autoland_calm \
  --out "$out/nofolder" --pdf off 2> "$out/nofolder.log"
rc=$?
[ "$rc" -eq 2 ] || no "a missing recording folder: exit $rc, not 2"
grep -q "no_such_folder" "$out/nofolder.log" || no "the missing folder is not named"

[ "$fail" -eq 0 ] && echo "PASS: both autoland tests pass on their runs; tightened, moved, partial and misnamed ones fail by name"
exit $fail
