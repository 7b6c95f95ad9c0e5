#!/usr/bin/env bash
# Multi-host federations in network namespaces (issue 11, items 1 and 2; docs/hosts.md).
#
#   hosts_test.sh BIN_DIR SOURCE_DIR WORK_DIR CASE [ARGS]
#   CASE identical                      : the lockstep run on two hosts (timing + flight on A; io,
#                                         nav, recorder on B) records the same CSV files, byte for
#                                         byte, as the single-host loopback run; a run with a
#                                         different input differs (negative control).
#   CASE lockstep LOSS% DELAY_MS FRAMES : the same with A's link impaired both ways; the run
#                                         completes, is still byte-identical to the loopback run
#                                         (a changed copy differs: negative control), and 3
#                                         instructor commands sent from B all arrive on A.
#   CASE realtime LOSS% DELAY_MS FRAMES : realtime over the impaired link: the run ends by itself
#                                         (never hangs), overruns are counted and printed; with a
#                                         delay of a frame period or more some must be counted.
#   CASE discovery-server               : no multicast: a Fast DDS Discovery Server on host DS,
#                                         every federate its client (fedsim_hosts_ds,
#                                         ROS_DISCOVERY_SERVER); identical to the reference; with
#                                         no server nothing is discovered (negative control).
# Prints the figures (run time, overruns, relay counts) as "[hosts] figure ..." lines.
# Exits 77 (skipped) where network namespaces cannot be made (not root, not permitted).
set -euo pipefail

FH_BIN=$(cd "$1" && pwd)
SOURCE_DIR=$(cd "$2" && pwd)
FH_WORK="$3"
CASE="$4"
shift 4
# shellcheck source=netns_lib.sh
source "$SOURCE_DIR/tests/hosts/netns_lib.sh"
fh_require_netns

# The loopback reference run's DDS domain (namespaced runs are isolated); FH_DOMAIN for a run
# beside CTest's.
DOMAIN=${FH_DOMAIN:-222}
RUN_LIMIT_S=60        # a run that takes longer is a hang: the test fails
rm -rf "$FH_WORK"
mkdir -p "$FH_WORK"

# The host each federate runs on.
host_of() {
  case "$1" in
    timing|flight) echo a ;;
    *) echo b ;;
  esac
}

# reference FRAMES MODE OUT: the single-host run (fedsim run on loopback); its command lines are
# kept in OUT/commands (one "name: command line" per federate).
reference() {
  local frames="$1" mode="$2" out="$3"
  mkdir -p "$out"
  # A lost tick is repeated after RESEND_S (timing's --resend-after; it changes no output).
  sed "s/@FRAMES@/$frames/g; s/@RESEND@/${RESEND_S:-0.25}/g; s/@INPUT_TIMEOUT@/3/g" \
    "$SOURCE_DIR/tests/hosts/hosts.yaml" > "$out/hosts.yaml"
  local t0 t1
  t0=$(date +%s.%N)
  timeout "$RUN_LIMIT_S" "$FH_BIN/fedsim" run "$out/hosts.yaml" --mode "$mode" --out "$out/run" \
    --domain "$DOMAIN" --progress 0 --quiet > "$out/fedsim-run.log" 2>&1 \
    || fh_fail "the loopback reference run failed: $(tail -5 "$out/fedsim-run.log")"
  t1=$(date +%s.%N)
  sed -n 's/^fedsim run: starting \([a-z_]*\): /\1: /p' "$out/fedsim-run.log" > "$out/commands"
  [ "$(wc -l < "$out/commands")" = 5 ] || fh_fail "expected 5 command lines from fedsim run"
  fh_log "figure reference mode=$mode frames=$frames join_s=$(join_seconds "$out/run/logs/timing.log") timing_wall_s=$(timing_field "$out/run/logs/timing.log" wall_s) run_s=$(awk "BEGIN{printf \"%.2f\", $t1 - $t0}")"
}

# timing_field LOG FIELD: a number from the timing federate's summary (its last JSON line).
timing_field() {
  grep '"federate":"timing"' "$1" | tail -1 | python3 -c "import json,sys; print(json.load(sys.stdin)['$2'])"
}

# federation REF OUT PROFILE [SED_EXPR]: runs REF's command lines, each in its host's namespace,
# with participant profile PROFILE, the recorder writing to OUT; SED_EXPR edits the lines (the
# negative control's input). Waits for every federate, at most RUN_LIMIT_S.
federation() {
  local ref="$1" out="$2" profile="$3" edit="${4:-}"
  mkdir -p "$out/logs"
  local name cmd pids=() t0 t1
  t0=$(date +%s.%N)
  while IFS= read -r line; do
    name="${line%%: *}"
    cmd="${line#*: }"
    cmd="${cmd//"$ref/run"/$out}"
    local this_profile="$profile"
    [ "$name" = recorder ] && this_profile="${FH_RECORDER_PROFILE:-$profile}"
    cmd="${cmd//--participant-profile fedsim_loopback/--participant-profile $this_profile}"
    [ -n "$edit" ] && cmd=$(sed "$edit" <<< "$cmd")
    # The hook runs once the other federates are up and before the first tick (fedsim run
    # starts the timing federate last).
    if [ "$name" = timing ] && [ -n "${FH_BEFORE_TIMING:-}" ]; then "$FH_BEFORE_TIMING"; fi
    # Word splitting is what fedsim run did: its arguments contain no spaces (hosts.yaml).
    # shellcheck disable=SC2086
    ip netns exec "$FH_NS-$FH_TAG-$(host_of "$name")" env ${FH_ENV:-} $cmd > "$out/logs/$name.log" 2>&1 &
    pids+=($!)
    FH_PIDS+=($!)
  done < "$ref/commands"
  local deadline=$(( $(date +%s) + RUN_LIMIT_S ))
  local pid failed=0
  for pid in "${pids[@]}"; do
    while kill -0 "$pid" 2>/dev/null; do
      [ "$(date +%s)" -lt "$deadline" ] || fh_fail "the federation did not finish within ${RUN_LIMIT_S} s (hang)"
      sleep 0.1
    done
    wait "$pid" || failed=1
  done
  t1=$(date +%s.%N)
  FH_RUN_S=$(awk "BEGIN{printf \"%.2f\", $t1 - $t0}")
  if [ "$failed" = 1 ]; then
    tail -n 3 "$out"/logs/*.log >&2
    fh_fail "a federate failed in $out"
  fi
}

# same_csv A B: every recorded CSV file of A is byte-identical in B (and there are some).
same_csv() {
  local n=0 f
  for f in "$1"/*.csv; do
    [ -e "$f" ] || break
    cmp -s "$f" "$2/$(basename "$f")" || return 1
    n=$((n + 1))
  done
  [ "$n" -ge 3 ]
}

# Static neighbour entries: an ARP exchange lost to the impairment would otherwise cost a second.
static_neighbours() {
  local h other mac
  for h in "$@"; do
    for other in "$@"; do
      [ "$h" = "$other" ] && continue
      mac=$(ip -n "$FH_NS-$FH_TAG-$other" -o link show eth0 | sed -n 's/.*link\/ether \([0-9a-f:]*\).*/\1/p')
      ip -n "$FH_NS-$FH_TAG-$h" neigh replace "10.232.0.$(octet "$other")" lladdr "$mac" dev eth0 nud permanent
    done
  done
}
octet() { case "$1" in a) echo 1 ;; b) echo 2 ;; ds) echo 3 ;; esac; }

case_identical() {
  reference 300 lockstep "$FH_WORK/ref"
  fh_network i
  fh_host a 1
  fh_host b 2
  federation "$FH_WORK/ref" "$FH_WORK/netns" fedsim_hosts
  fh_log "figure netns mode=lockstep frames=300 join_s=$(join_seconds "$FH_WORK/netns/logs/timing.log") timing_wall_s=$(timing_field "$FH_WORK/netns/logs/timing.log" wall_s) run_s=$FH_RUN_S"
  same_csv "$FH_WORK/ref/run" "$FH_WORK/netns" || fh_fail "the two-host run differs from the loopback run"
  fh_log "two-host lockstep run is byte-identical to the loopback run ($(ls "$FH_WORK/netns"/*.csv | wc -l) CSV files)"
  # Negative control: another input must show in the comparison.
  federation "$FH_WORK/ref" "$FH_WORK/netns-other" fedsim_hosts \
    "s#--profile [^ ]*#--profile $SOURCE_DIR/tests/hosts/different_input.csv#"
  if same_csv "$FH_WORK/ref/run" "$FH_WORK/netns-other"; then
    fh_fail "negative control: a run with a different input compared equal"
  fi
  fh_log "negative control: a different input differs"
  echo "hosts test identical: all checks passed"
}

# send_commands: 3 instructor commands from host B (snapshot: no federate here acts on it, so
# the recorded flight is unchanged), one after the other; a sim_command recorder on host A
# (started before) must record all three.
start_command_recorder() {
  fh_in a "$FH_BIN/fedsim" record --topics fedsim/sim_command --out "$FH_WORK/commands" \
    --participant-profile fedsim_hosts --duration "$1" --progress 0 --name command_recorder \
    > "$FH_WORK/command_recorder.log" 2>&1
  FH_CMD_RECORDER=$!
}
send_commands() {
  local i try
  for i in 1 2 3; do
    # A command that found no reader at all within --wait reached nobody (the recorder on A
    # creates its reader once it has discovered the sender, across the lossy link: seen to take
    # more than 10 s at 20% loss under load): it is sent again, at most 3 times.
    for try in 1 2 3; do
      ip netns exec "$FH_NS-$FH_TAG-b" "$FH_BIN/fedsim" command snapshot \
        --participant-profile fedsim_hosts --wait 10 > "$FH_WORK/command-$i.log" 2>&1 \
        || fh_fail "command $i could not be sent: $(cat "$FH_WORK/command-$i.log")"
      grep -q "sent to 0 reader" "$FH_WORK/command-$i.log" || break
      fh_log "command $i found no reader (try $try): sent again"
    done
  done
}
check_commands_arrived() {
  local csv="$FH_WORK/commands/fedsim_sim_command.csv" n
  # Each sender has exited (after waiting for acknowledgements): what the recorder has now is
  # all it will get. Stopping it writes its file.
  kill -TERM "$FH_CMD_RECORDER" 2>/dev/null || true
  wait "$FH_CMD_RECORDER" || true
  [ -f "$csv" ] || fh_fail "no command arrived on host A ($(tail -3 "$FH_WORK/command_recorder.log"))"
  n=$(( $(wc -l < "$csv") - 1 ))
  fh_log "figure commands sent=3 arrived=$n"
  [ "$n" = 3 ] || fh_fail "$n of 3 commands arrived on host A"
}

impaired_network() {
  local loss="$1" delay="$2"
  fh_network "$3"
  fh_log "impairment method: $FH_METHOD (loss ${loss}% and delay ${delay} ms each way on host A's link)"
  fh_host a 1 impaired "$loss" "$delay" 42
  fh_host b 2
  static_neighbours a b
}

relay_figures() {
  fh_stop_relays
  [ "$FH_METHOD" = relay ] && fh_log "figure relay $(grep '^{' "$FH_WORK/relay-a.log" || echo '{}')"
  return 0
}

case_lockstep() {
  local loss="$1" delay="$2" frames="$3"
  # With loss and no delay, repeat a lost tick sooner than the default 0.25 s (keeps the test short).
  if [ "$delay" = 0 ]; then RESEND_S=0.05; fi
  reference "$frames" lockstep "$FH_WORK/ref"
  impaired_network "$loss" "$delay" "l"
  start_command_recorder 40
  # While every federate but timing runs (so that each command waits for live readers only);
  # snapshot changes nothing these federates compute.
  FH_BEFORE_TIMING=send_commands federation "$FH_WORK/ref" "$FH_WORK/netns" fedsim_hosts
  check_commands_arrived
  relay_figures
  local t=$FH_WORK/netns/logs/timing.log
  fh_log "figure impaired mode=lockstep loss=$loss delay_ms=$delay frames=$(timing_field "$t" frames) timing_wall_s=$(timing_field "$t" wall_s) resent_ticks=$(timing_field "$t" resent_ticks) run_s=$FH_RUN_S"
  [ "$(timing_field "$t" frames)" = "$frames" ] || fh_fail "lockstep stopped before $frames frames"
  # Every lockstep input is repaired and waited for (common/runtime/federate.hpp): loss and
  # delay make the run slower, never different.
  local late
  late=$(grep -ho 'late_inputs=[0-9]*' "$FH_WORK"/netns/logs/*.log | tr '\n' ' ')
  fh_log "figure impaired late_inputs: $late"
  same_csv "$FH_WORK/ref/run" "$FH_WORK/netns" \
    || fh_fail "the impaired lockstep run differs from the loopback run: $(for f in "$FH_WORK"/ref/run/*.csv; do cmp "$f" "$FH_WORK/netns/$(basename "$f")" 2>&1; done | head -3 | tr '\n' ';') ($late)"
  fh_log "figure impaired_identical=yes (byte-identical to the loopback run)"
  # Negative control (the comparison can fail; case identical runs a different input): one
  # changed value in a copy of the recording must show.
  cp -r "$FH_WORK/netns" "$FH_WORK/netns-changed"
  sed -i '3s/,0,/,1,/' "$FH_WORK/netns-changed/fedsim_navigation_state.csv"
  if same_csv "$FH_WORK/ref/run" "$FH_WORK/netns-changed"; then
    fh_fail "negative control: a recording with a changed value compared equal"
  fi
  fh_log "negative control: a changed recording differs"
  echo "hosts test lockstep loss=$loss delay=$delay: all checks passed"
}

case_realtime() {
  local loss="$1" delay="$2" frames="$3"
  reference "$frames" realtime "$FH_WORK/ref"
  impaired_network "$loss" "$delay" "r"
  federation "$FH_WORK/ref" "$FH_WORK/netns" fedsim_hosts
  relay_figures
  local t=$FH_WORK/netns/logs/timing.log overruns
  overruns=$(timing_field "$t" overruns)
  fh_log "figure impaired mode=realtime loss=$loss delay_ms=$delay frames=$(timing_field "$t" frames) overruns=$overruns reference_overruns=$(timing_field "$FH_WORK/ref/run/logs/timing.log" overruns) lost=$(grep '"federate":"timing"' "$t" | tail -1 | python3 -c 'import json,sys; print(len(json.load(sys.stdin)["lost"]))') run_s=$FH_RUN_S"
  [ "$(timing_field "$t" frames)" = "$frames" ] || fh_fail "the realtime run stopped before $frames frames"
  # A one-way delay of a frame period or more cannot be met: a tick's acknowledgements come back
  # after at least twice the delay, so overruns must be counted, not hidden.
  if awk "BEGIN{exit !($delay >= 20)}" && [ "$overruns" = 0 ]; then
    fh_fail "no overrun counted with ${delay} ms each way at 50 Hz"
  fi
  echo "hosts test realtime loss=$loss delay=$delay: all checks passed"
}

# join_seconds TIMING_LOG: from "waiting for federates" to "federation ready" (the log's clock).
join_seconds() {
  python3 - "$1" <<'PY'
import re, sys
t = {}
for line in open(sys.argv[1]):
    m = re.match(r"(\d+):(\d+):(\d+\.\d+) ", line)
    if not m:
        continue
    s = int(m[1]) * 3600 + int(m[2]) * 60 + float(m[3])
    if "waiting for federates" in line: t.setdefault("wait", s)
    if "federation ready" in line: t.setdefault("ready", s)
print(f"{t['ready'] - t['wait']:.2f}" if len(t) == 2 else "none")
PY
}

case_discovery_server() {
  reference 300 lockstep "$FH_WORK/ref"
  fh_network d
  fh_host a 1
  fh_host b 2
  fh_host ds 3
  # Every federate a client of the server on host DS; the address comes from the environment.
  export FH_ENV="ROS_DISCOVERY_SERVER=10.232.0.3:11811"
  # Negative control first: with no server running, the client profile discovers nothing.
  ip netns exec "$FH_NS-$FH_TAG-b" env $FH_ENV FEDSIM_PARTICIPANT_PROFILE=fedsim_hosts_ds \
    "$FH_BIN/fedsim-io" --name io --duration 5 > "$FH_WORK/no-server-io.log" 2>&1 &
  FH_PIDS+=($!)
  if ip netns exec "$FH_NS-$FH_TAG-a" env $FH_ENV FEDSIM_PARTICIPANT_PROFILE=fedsim_hosts_ds \
       "$FH_BIN/fedsim-timing" --mode lockstep --expect io --frames 1 --join-timeout 3 \
       > "$FH_WORK/no-server-timing.log" 2>&1; then
    fh_fail "negative control: a federation formed with no Discovery Server running"
  fi
  grep -q "not ready" "$FH_WORK/no-server-timing.log" || fh_fail "negative control: $(tail -2 "$FH_WORK/no-server-timing.log")"
  fh_log "negative control: without the server nothing is discovered"
  fh_in ds fast-discovery-server -i 0 -l 10.232.0.3 -p 11811
  # A server tells a client only of the endpoints it matches; the recorder creates its readers
  # when it sees a topic's writer, so it must hear of every endpoint: a super client
  # (qos/fedsim_qos.xml, fedsim_hosts_ds_monitor; its command line differs only in the profile).
  export FH_RECORDER_PROFILE=fedsim_hosts_ds_monitor
  federation "$FH_WORK/ref" "$FH_WORK/netns" fedsim_hosts_ds
  local t=$FH_WORK/netns/logs/timing.log
  fh_log "figure discovery_server join_s=$(join_seconds "$t") timing_wall_s=$(timing_field "$t" wall_s) run_s=$FH_RUN_S"
  same_csv "$FH_WORK/ref/run" "$FH_WORK/netns" || fh_fail "the Discovery Server run differs from the loopback run"
  fh_log "Discovery Server run is byte-identical to the loopback run"
  echo "hosts test discovery-server: all checks passed"
}

case "$CASE" in
  identical) case_identical ;;
  lockstep) case_lockstep "$@" ;;
  realtime) case_realtime "$@" ;;
  discovery-server) case_discovery_server ;;
  *) fh_fail "unknown case '$CASE'" ;;
esac
