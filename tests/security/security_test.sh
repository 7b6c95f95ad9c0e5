#!/usr/bin/env bash
# DDS Security end to end (docs/security.md), on 127.0.0.1 only (the default participant profile
# fedsim_loopback). Usage:
#   security_test.sh BIN_DIR SOURCE_DIR DOMAIN {arguments|federation|identical|wire}
#   arguments:  make-security.sh refuses bad arguments (and makes nothing); a participant asked to
#               be secure whose credentials are missing does not start, naming the file.
#   federation: a secured lockstep federation (timing + flight + recorder) started frozen runs to
#               the end; an unauthenticated participant, one with a certificate but no grant for
#               fedsim/sim_command, and one whose certificate comes from another CA can neither
#               unfreeze it nor read its aircraft state; the instructor's credentials can (the
#               negative controls). The federation's state is read over DDS by a granted reader.
#   identical:  a secured lockstep run (timing + flight + recorder, 500 frames) records exactly the
#               bytes the same run records unsecured.
#   wire:       the loopback traffic of a secured federation shows no topic type name and carries
#               encrypted submessages; the same federation unsecured shows them (the control).
#               Needs dumpcap and tshark (Debian's tshark); skipped (exit 77) without them.
set -uo pipefail

readonly BIN="$1" SRC="$2" DOMAIN="$3" WHAT="$4"
readonly MAKE="$SRC/deploy/security/make-security.sh"
export FEDSIM_DOMAIN="$DOMAIN" FEDSIM_QOS_FILE="${FEDSIM_QOS_FILE:-$SRC/qos/fedsim_qos.xml}"
unset FEDSIM_SECURITY_DIR FEDSIM_SECURITY_IDENTITY FEDSIM_PARTICIPANT_PROFILE

work="$(mktemp -d /tmp/fedsim-security-test.XXXXXX)"
pids=()
failures=0
cleanup() {
  local pid
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null; done
  for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null; done
  if [[ $failures -gt 0 ]]; then
    for log in "$work"/*.log; do [[ -f "$log" ]] && { echo "--- $log"; tail -n 20 "$log"; }; done
  fi
  rm -rf "$work"
}
trap cleanup EXIT

pass() { echo "ok: $*"; }
fail() { echo "FAILED: $*"; failures=$((failures + 1)); }

# expect_refused "what" "text the error must hold" command...: exit status not 0, message names it.
expect_refused() {
  local what="$1" text="$2"; shift 2
  local out status
  out="$("$@" 2>&1)"; status=$?
  if [[ $status -ne 0 && "$out" == *"$text"* ]]; then pass "$what"; else
    fail "$what (exit $status, wanted an error holding '$text'): $out"; fi
}

finish() {
  if [[ $failures -eq 0 ]]; then echo "security test ($WHAT): all checks passed"; exit 0; fi
  echo "security test ($WHAT): $failures check(s) failed"; exit 1
}

arguments_test() {
  expect_refused "no OUTDIR" "missing OUTDIR" "$MAKE"
  expect_refused "no identity" "no identity named" "$MAKE" "$work/a"
  expect_refused "unknown grant" "unknown grant 'root'" "$MAKE" "$work/a" flight:root
  expect_refused "path as a name" "is not a plain name" "$MAKE" "$work/a" ../flight
  expect_refused "name twice" "named twice" "$MAKE" "$work/a" flight flight:command
  expect_refused "readonly with a grant" "cannot be combined" "$MAKE" "$work/a" x:readonly,command
  expect_refused "bad --days" "--days 'nan'" "$MAKE" --days nan "$work/a" flight
  expect_refused "bad --domains" "MIN <= MAX <= 232" "$MAKE" --domains 9-300 "$work/a" flight
  [[ ! -e "$work/a" ]] && pass "a refused call makes nothing" || fail "a refused call made $work/a"

  # --deployment: every identity `fedsim run` needs, with the grants the graph implies.
  if FEDSIM_BIN="$BIN/fedsim" "$MAKE" --deployment "$SRC/deploy/backbone-demo.yaml" "$work/dep" \
       instructor:command >"$work/make.log" 2>&1; then
    local made
    made="$(grep -o "identity '.*' (grants: [a-z,]*)" "$work/make.log" | sort | tr '\n' ' ')"
    [[ "$made" == "identity 'consumer' (grants: none) identity 'fedsim-run' (grants: readonly) identity 'instructor' (grants: command) identity 'io' (grants: controls) identity 'recorder' (grants: none) identity 'recorder-data' (grants: readonly) identity 'timing' (grants: command) " ]] &&
      pass "--deployment makes the deployment's identities and grants" ||
      fail "--deployment made: $made"
  else fail "make-security.sh --deployment: $(cat "$work/make.log")"; fi
  expect_refused "--deployment of a missing file" "no such file" "$MAKE" --deployment "$work/none.yaml" "$work/b"

  "$MAKE" "$work/sec" flight io:controls >"$work/make.log" 2>&1 ||
    fail "make-security.sh flight io:controls: $(cat "$work/make.log")"
  # Negative control: the made identity starts its participant (which then finds no topic).
  FEDSIM_SECURITY_DIR="$work/sec" FEDSIM_SECURITY_IDENTITY=flight \
    "$BIN/fedsim" topic echo fedsim/aircraft_state -n 1 --wait 0.5 --timeout 0.5 >"$work/echo.log" 2>&1
  if grep -q "topic 'fedsim/aircraft_state' not found" "$work/echo.log" &&
     ! grep -q "Error\]" "$work/echo.log"; then
    pass "a made identity starts secured"
  else fail "a made identity does not start: $(cat "$work/echo.log")"; fi
  # The controls grant: io writes fedsim/pilot_controls with it; flight's certificate cannot.
  local profile="$SRC/data/profiles/elevator_doublets.csv"
  expect_refused "a certificate without the controls grant cannot write fedsim/pilot_controls" \
    "cannot create a writer for fedsim/pilot_controls" \
    timeout 10 env FEDSIM_SECURITY_DIR="$work/sec" FEDSIM_SECURITY_IDENTITY=flight \
    "$BIN/fedsim-io" --name io --profile "$profile"
  FEDSIM_SECURITY_DIR="$work/sec" timeout 3 "$BIN/fedsim-io" --name io --profile "$profile" \
    >"$work/io.log" 2>&1
  grep -q "ready ports=1" "$work/io.log" && pass "io, granted controls, starts its writer" ||
    fail "io with the controls grant did not start: $(cat "$work/io.log")"
  expect_refused "a missing certificate is named" "$work/sec/nobody/cert.pem" \
    env FEDSIM_SECURITY_DIR="$work/sec" FEDSIM_SECURITY_IDENTITY=nobody \
    "$BIN/fedsim" command freeze --wait 0.5
  rm "$work/sec/governance.p7s"
  expect_refused "a missing governance is named" "$work/sec/governance.p7s" \
    env FEDSIM_SECURITY_DIR="$work/sec" FEDSIM_SECURITY_IDENTITY=flight \
    "$BIN/fedsim" command freeze --wait 0.5
  expect_refused "an identity that is a path" "is not a plain name" \
    env FEDSIM_SECURITY_DIR="$work/sec" FEDSIM_SECURITY_IDENTITY=../flight \
    "$BIN/fedsim" command freeze --wait 0.5
  finish
}

# as IDENTITY DIR command...: runs a command with those credentials ("-" for none).
as() {
  local identity="$1" dir="$2"; shift 2
  if [[ "$identity" == - ]]; then "$@"; else
    FEDSIM_SECURITY_DIR="$dir" FEDSIM_SECURITY_IDENTITY="$identity" "$@"; fi
}

# run_state_seen IDENTITY DIR: the run_state of the next frame tick that identity reads ("" if none).
run_state_seen() {
  as "$1" "$2" "$BIN/fedsim" topic echo fedsim/frame_tick -n 1 --field run_state --wait 5 \
    --timeout 5 2>>"$work/echo.log" | grep -m 1 -o 'RUN_STATE_[A-Z]*'
}

# state_samples IDENTITY DIR: how many aircraft state samples that identity reads in a few seconds.
state_samples() {
  as "$1" "$2" "$BIN/fedsim" topic echo fedsim/aircraft_state -n 3 --field stamp.frame --wait 3 \
    --timeout 3 2>>"$work/echo.log" | grep -c '^[0-9]'
}

federation_test() {
  "$MAKE" "$work/sec" timing:command flight recorder recorder-data:readonly instructor:command intruder \
    >"$work/make.log" 2>&1 || { fail "make-security.sh: $(cat "$work/make.log")"; finish; }
  "$MAKE" "$work/other" instructor:command >>"$work/make.log" 2>&1 ||
    { fail "make-security.sh (other CA): $(cat "$work/make.log")"; finish; }
  export FEDSIM_SECURITY_DIR="$work/sec"  # every federate below is secured, as itself (--name)
  "$BIN/fedsim-timing" --name timing --mode lockstep --rate 50 --scale 1 --expect flight,recorder \
    --start freeze --frames 100000 --shutdown-on-exit >"$work/timing.log" 2>&1 & pids+=($!)
  "$BIN/fedsim-flight" --name flight --aircraft c172 --trim level --alt-ft 4000 --ktas 100 \
    --state-qos lockstep_data >"$work/flight.log" 2>&1 & pids+=($!)
  "$BIN/fedsim" record --name recorder --topics fedsim/aircraft_state --out "$work/rec" \
    --lockstep-member >"$work/recorder.log" 2>&1 & pids+=($!)
  unset FEDSIM_SECURITY_DIR

  local state
  state="$(run_state_seen instructor "$work/sec")"
  [[ -n "$state" ]] && pass "the instructor reads the secured ticks (run_state $state)" ||
    { fail "the instructor reads no tick from the secured federation"; finish; }
  local frozen="$state"

  # Each intruder tries to unfreeze it and to read the aircraft's state, all at once (they are
  # independent; waiting for each in turn would triple the test's time). A granted reader too.
  attempt() { local log="$work/attempt_$1.out"; shift; "$@" >"$log" 2>&1; echo "exit $?" >>"$log"; }
  attempt command_none as - "" "$BIN/fedsim" command run --wait 3 &
  attempt command_other as instructor "$work/other" "$BIN/fedsim" command run --wait 3 &
  attempt command_ungranted as intruder "$work/sec" "$BIN/fedsim" command run --wait 3 &
  attempt read_none state_samples - "" &
  attempt read_other state_samples instructor "$work/other" &
  attempt read_granted state_samples intruder "$work/sec" &
  wait_for_attempts() { local j; for j in $(jobs -p); do [[ " ${pids[*]} " == *" $j "* ]] || wait "$j"; done; }
  wait_for_attempts
  outcome() { cat "$work/attempt_$1.out"; }
  local out
  [[ "$(outcome command_none)" == *"sent to 0 reader(s)"* ]] &&
    pass "an unauthenticated command reaches nobody" || fail "an unauthenticated command: $(outcome command_none)"
  [[ "$(outcome command_other)" == *"sent to 0 reader(s)"* ]] &&
    pass "a command from another CA (granted there) reaches nobody" ||
    fail "a command from another CA: $(outcome command_other)"
  [[ "$(outcome command_ungranted)" == *"cannot create a writer for fedsim/sim_command"* ]] &&
    pass "a certificate without the command grant cannot write fedsim/sim_command" ||
    fail "a certificate without the command grant: $(outcome command_ungranted)"
  [[ "$(outcome read_none | head -n 1)" == 0 ]] && pass "an unauthenticated reader gets no aircraft state" ||
    fail "an unauthenticated reader got aircraft state: $(outcome read_none)"
  [[ "$(outcome read_other | head -n 1)" == 0 ]] && pass "a reader from another CA gets no aircraft state" ||
    fail "a reader from another CA got aircraft state: $(outcome read_other)"
  # Negative control of the two above: a certificate of this CA reads (no grant needed to read).
  [[ "$(outcome read_granted | head -n 1)" == 3 ]] && pass "a reader of this CA gets aircraft state" ||
    fail "a reader of this CA got no aircraft state: $(outcome read_granted)"
  # The federation reports the four refused participants (two without a certificate, two of
  # another CA); the ungranted intruder authenticates, so it is not among them.
  local refused
  refused="$(grep -c "refused remote participant" "$work/timing.log")"
  [[ $refused -ge 4 ]] && pass "the timing federate reported $refused refused participants" ||
    fail "the timing federate reported $refused refused participants, not the 4 intruders"
  state="$(run_state_seen instructor "$work/sec")"
  [[ "$state" == "$frozen" ]] && pass "still frozen after the intruders' commands" ||
    fail "the run state went from $frozen to '$state' after the intruders' commands"

  # Negative control: the same command with the instructor's credentials works.
  out="$(as instructor "$work/sec" "$BIN/fedsim" command run --wait 3 2>&1)"
  [[ "$out" =~ sent\ to\ [1-9] ]] && pass "the instructor's command is delivered ($out)" ||
    fail "the instructor's command: $out"
  state="$(run_state_seen instructor "$work/sec")"
  [[ -n "$state" && "$state" != "$frozen" ]] && pass "the instructor unfroze it (run_state $state)" ||
    fail "the instructor's command did not unfreeze it (run_state '$state')"
  out="$(as instructor "$work/sec" "$BIN/fedsim" command shutdown --wait 3 2>&1)"

  [[ "$out" =~ sent\ to\ [1-9] ]] || fail "the instructor's shutdown: $out"
  local names=(timing flight recorder) status i
  for i in 0 1 2; do
    for _ in $(seq 100); do kill -0 "${pids[$i]}" 2>/dev/null || break; sleep 0.1; done
    if kill -0 "${pids[$i]}" 2>/dev/null; then
      fail "${names[$i]} still runs 10 s after the shutdown command"
      continue
    fi
    wait "${pids[$i]}"; status=$?
    [[ $status -eq 0 ]] && pass "${names[$i]} ended cleanly" || fail "${names[$i]} exit status $status"
  done
  local rows
  rows="$(($(wc -l <"$work/rec/fedsim_aircraft_state.csv" 2>/dev/null || echo 1) - 1))"
  [[ $rows -ge 100 ]] && pass "the secured recorder recorded $rows aircraft states" ||
    fail "the secured recorder recorded $rows aircraft states"
  finish
}

# lockstep_run LABEL [identity-dir]: timing + flight + recorder, lockstep as fast as possible,
# 500 frames; the recorder's aircraft state lands in LABEL/.
lockstep_run() {
  local label="$1" dir="${2:-}" timing status
  export FEDSIM_SECURITY_DIR="$dir"
  "$BIN/fedsim-flight" --name flight --aircraft c172 --trim level --alt-ft 4000 --ktas 100 \
    --state-qos lockstep_data >"$work/flight_$label.log" 2>&1 & pids+=($!)
  "$BIN/fedsim" record --name recorder --topics fedsim/aircraft_state --out "$work/$label" \
    --lockstep-member >"$work/recorder_$label.log" 2>&1 & pids+=($!)
  timeout 60 "$BIN/fedsim-timing" --name timing --mode lockstep --scale 0 --frames 500 \
    --expect flight,recorder --shutdown-on-exit >"$work/timing_$label.log" 2>&1
  status=$?
  unset FEDSIM_SECURITY_DIR
  [[ $status -eq 0 ]] && pass "$label: the lockstep run ended cleanly" ||
    fail "$label: the timing federate exited with status $status"
  for _ in $(seq 100); do kill -0 "${pids[-1]}" 2>/dev/null || kill -0 "${pids[-2]}" 2>/dev/null || break
    sleep 0.1; done
}

identical_test() {
  "$MAKE" "$work/sec" timing:command flight recorder recorder-data:readonly >"$work/make.log" 2>&1 ||
    { fail "make-security.sh: $(cat "$work/make.log")"; finish; }
  lockstep_run plain
  lockstep_run secured "$work/sec"
  local csv=fedsim_aircraft_state.csv rows
  rows="$(($(wc -l <"$work/secured/$csv" 2>/dev/null || echo 1) - 1))"
  [[ $rows -eq 500 ]] && pass "secured: the recorder recorded all 500 frames" ||
    fail "secured: the recorder recorded $rows of 500 frames"
  cmp -s "$work/plain/$csv" "$work/secured/$csv" &&
    pass "the secured run's aircraft state is byte-identical to the unsecured run's" ||
    fail "the secured and unsecured recordings differ: $(cmp "$work/plain/$csv" "$work/secured/$csv" 2>&1)"
  finish
}

# capture LABEL [identity-dir]: a short federation (a realtime timing federate and an instructor
# reading its ticks) on this test's domain, its loopback traffic captured to LABEL.pcapng.
# Only this domain's RTPS ports: 7400 + 250 * domain + 0..140 (64 participants, Fast DDS's
# default port mapping).
capture() {
  local label="$1" dir="${2:-}" base=$((7400 + 250 * DOMAIN)) cap timing
  dumpcap -i lo -f "udp portrange $base-$((base + 140))" -w "$work/$label.pcapng" \
    >"$work/dumpcap_$label.log" 2>&1 &
  cap=$!
  for _ in $(seq 100); do grep -q "Capturing on" "$work/dumpcap_$label.log" && break; sleep 0.05; done
  FEDSIM_SECURITY_DIR="$dir" "$BIN/fedsim-timing" --name timing --rate 50 --frames 100 \
    >"$work/timing_$label.log" 2>&1 &
  timing=$!
  FEDSIM_SECURITY_DIR="$dir" FEDSIM_SECURITY_IDENTITY=instructor "$BIN/fedsim" topic echo \
    fedsim/frame_tick -n 3 --field frame --wait 5 --timeout 5 >"$work/echo_$label.log" 2>&1 ||
    fail "$label: the instructor read no ticks: $(cat "$work/echo_$label.log")"
  wait "$timing"
  kill -INT "$cap"; wait "$cap"
}

# frames LABEL FILTER: how many captured frames match that display filter.
frames() { tshark -r "$work/$1.pcapng" -Y "$2" 2>/dev/null | wc -l; }

wire_test() {
  if ! command -v dumpcap >/dev/null || ! command -v tshark >/dev/null; then
    echo "security test (wire): skipped, dumpcap and tshark are not installed"; exit 77
  fi
  "$MAKE" "$work/sec" timing:command instructor:readonly >"$work/make.log" 2>&1 ||
    { fail "make-security.sh: $(cat "$work/make.log")"; finish; }
  capture plain
  capture secured "$work/sec"
  # Discovery (SEDP) names every endpoint's topic type in clear, unless it is encrypted.
  local type_filter='frame contains "fedsim::msg::FrameTick"'
  local plain_types secured_types secured_bodies
  plain_types="$(frames plain "$type_filter")"
  secured_types="$(frames secured "$type_filter")"
  secured_bodies="$(frames secured 'rtps.sm.id == 0x30')"  # SEC_BODY: an encrypted submessage
  [[ $plain_types -gt 0 ]] && pass "unsecured: $plain_types packets show the type name (the control)" ||
    fail "unsecured: no captured packet shows the type name: the capture sees nothing"
  [[ $secured_types -eq 0 ]] && pass "secured: no packet shows a topic type name" ||
    fail "secured: $secured_types packets show the type name in clear"
  [[ $secured_bodies -gt 0 ]] && pass "secured: $secured_bodies packets carry encrypted submessages" ||
    fail "secured: no encrypted submessage (SEC_BODY) captured"
  finish
}

case "$WHAT" in
  arguments) arguments_test ;;
  federation) federation_test ;;
  identical) identical_test ;;
  wire) wire_test ;;
  *) echo "security_test.sh: unknown test '$WHAT' (arguments, federation, identical, wire)"; exit 2 ;;
esac
