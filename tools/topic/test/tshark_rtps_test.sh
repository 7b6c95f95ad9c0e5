#!/usr/bin/env bash
# docs/monitoring.md's tshark recipe, run: tshark on loopback decodes fedsim's RTPS discovery
# and shows its topic and type names. A timing federate (domain 185, loopback profile) publishes
# fedsim/frame_tick and fedsim/federate_status while tshark listens on domain 185's port range
# (7400 + 250 * 185 = 53650 ..; not 173, which a replay test uses side by side under ctest -j). Endpoints (topic and type names: DATA(w), DATA(r)) are only
# announced to a participant that was discovered, so `fedsim topic list` joins as the second
# participant. Exit 77 (skipped) where tshark is not installed.
# Usage: tshark_rtps_test.sh BIN_DIR
set -euo pipefail
bin_dir=$1
domain=185
if ! command -v tshark > /dev/null; then
  echo "tshark not installed (deploy/install-deps.sh installs it): skipped"
  exit 77
fi
base=$((7400 + 250 * domain))
work=$(mktemp -d)
timing_pid=""
cleanup() {
  [ -n "$timing_pid" ] && kill "$timing_pid" 2> /dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT

tshark -i lo -f "udp portrange $base-$((base + 249))" -a duration:9 -Y rtps \
  -T fields -e rtps.param.topicName -e rtps.param.typeName > "$work/fields.txt" 2> "$work/tshark.err" &
tshark_pid=$!
# Start the federation once tshark captures (it says "Capturing on 'Loopback: lo'").
for _ in $(seq 50); do
  grep -q "Capturing on" "$work/tshark.err" && break
  sleep 0.1
done
"$bin_dir/fedsim-timing" --mode realtime --duration 4 --domain "$domain" > "$work/timing.log" 2>&1 &
timing_pid=$!
"$bin_dir/fedsim" topic list --domain "$domain" --wait 3 > "$work/list.txt" 2>&1 || true
wait "$tshark_pid" || { cat "$work/tshark.err"; exit 1; }
wait "$timing_pid" || true
timing_pid=""

echo "topics and types tshark saw on domain $domain:"
sort -u "$work/fields.txt" | sed '/^\s*$/d'
for expected in "fedsim/frame_tick" "fedsim::msg::FrameTick" "fedsim/federate_status"; do
  if ! grep -q "$expected" "$work/fields.txt"; then
    echo "FAILED: '$expected' not in tshark's RTPS fields"
    cat "$work/tshark.err"
    exit 1
  fi
done
echo "tshark shows fedsim's topic and type names"
