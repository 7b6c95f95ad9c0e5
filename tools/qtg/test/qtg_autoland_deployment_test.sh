#!/bin/sh
# The QTG's autoland federation (deploy/qtg/b737-ils-autoland.yaml) must fly what the main job
# (deploy/ils-autoland.yaml) flies: their io, flight and nav members are compared line by line
# (on 2026-12-06 the main job's DDS lockstep run and this deployment's in-process run recorded
# byte-identical aircraft, navigation and autopilot state). The negative control: a member that
# differs must be reported.
# Usage: qtg_autoland_deployment_test.sh MAIN_DEPLOYMENT QTG_DEPLOYMENT SCRATCH_DIR
set -u
main=$1 qtg=$2 scratch=$3
mkdir -p "$scratch"
# the lines of member NAME: from "  - name: NAME" to the next member or top-level key
member() {
  awk -v want="$2" '
    /^  - name: / { on = ($3 == want) }
    /^[^ #]/ { on = 0 }
    on { print }' "$1"
}
compare() {
  fail=0
  for m in io flight nav; do
    a=$(member "$1" "$m"); b=$(member "$2" "$m")
    if [ -z "$a" ]; then echo "member $m missing from $1"; fail=1; continue; fi
    [ "$a" = "$b" ] || { echo "member $m differs between $1 and $2"; fail=1; }
  done
  return $fail
}
compare "$main" "$qtg" || { echo "FAIL: update $qtg to fly what $main flies"; exit 1; }
# negative control: another nav seed must be caught
sed 's/--seed, "7"/--seed, "8"/' "$qtg" > "$scratch/other_seed.yaml"
if compare "$main" "$scratch/other_seed.yaml" > /dev/null; then
  echo "FAIL: a different nav member was not noticed"; exit 1
fi
echo "PASS: the QTG's autoland federation flies the main job's io, flight and nav members"
