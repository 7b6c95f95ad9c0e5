#!/usr/bin/env bash
# deploy/containers/compose.yaml's federation, one federate per network namespace, each started
# exactly as its container would be: the service's command and environment (with the image's
# ENV, tests/hosts/compose_services.py), /opt/fedsim holding the image's files (bin, qos, data,
# containers;
# bind mounts in a private mount namespace) and "discovery" resolving to the Discovery Server's
# namespace (its own /etc/hosts). Podman could not start a container on the CI machine (crun:
# cgroups in hybrid mode; docs/hosts.md), so this is what runs the containers' commands here.
#   containers_test.sh BIN_DIR SOURCE_DIR WORK_DIR
# Checks: the lockstep run completes FEDSIM_FRAMES (300) frames and the recorder (a super client
# of the server) records every topic for every frame. Exits 77 where namespaces cannot be made.
set -euo pipefail
FH_BIN=$(cd "$1" && pwd)
SOURCE_DIR=$(cd "$2" && pwd)
FH_WORK="$3"
# shellcheck source=netns_lib.sh
source "$SOURCE_DIR/tests/hosts/netns_lib.sh"
fh_require_netns
rm -rf "$FH_WORK"
mkdir -p "$FH_WORK/out" "$FH_WORK/services" "$FH_WORK/logs"
RUN_LIMIT_S=90
export FEDSIM_FRAMES=300 FEDSIM_IOS_TOKEN=fedsim-containers-test
mapfile -t SERVICES < <(python3 "$SOURCE_DIR/tests/hosts/compose_services.py" \
  --compose "$SOURCE_DIR/deploy/containers/compose.yaml" \
  --containerfile "$SOURCE_DIR/deploy/containers/Containerfile" --out "$FH_WORK/services")

# /opt/fedsim/containers as the Containerfile makes it.
mkdir -p "$FH_WORK/image-containers"
cp "$SOURCE_DIR"/deploy/containers/fedsim_container_monitor.xml "$SOURCE_DIR"/deploy/containers/make-monitor-qos.sh "$FH_WORK/image-containers/"
"$SOURCE_DIR/deploy/containers/make-monitor-qos.sh" "$SOURCE_DIR/qos/fedsim_qos.xml" \
  "$FH_WORK/image-containers/fedsim_container_monitor.xml" "$FH_WORK/image-containers/fedsim_qos_monitor.xml"

fh_network c
# One host per service; service i gets 10.232.0.(10+i). Interface names must stay short: the
# bridge side is p-<i>.
declare -A ADDRESS PID
i=0
for svc in "${SERVICES[@]}"; do
  i=$((i + 1))
  ns="fh-c-$svc"
  fh_netns_add "$ns"
  ip link add eth0 netns "$ns" type veth peer name "p-$i" netns "$FH_BR"
  ip -n "$FH_BR" link set "p-$i" master br0
  ip -n "$FH_BR" link set "p-$i" up
  ip -n "$ns" addr add "10.232.0.$((10 + i))/24" dev eth0
  ip -n "$ns" link set eth0 up
  ADDRESS[$svc]="10.232.0.$((10 + i))"
done
# What the container network's DNS would answer.
{
  echo "127.0.0.1 localhost"
  for svc in "${SERVICES[@]}"; do echo "${ADDRESS[$svc]} $svc"; done
} > "$FH_WORK/hosts"

# start SERVICE: its command with its environment only, in its namespace, /opt/fedsim as in
# the image.
start() {
  local svc="$1"
  local -a argv env
  mapfile -d '' -t argv < "$FH_WORK/services/$svc.argv"
  mapfile -t env < "$FH_WORK/services/$svc.env"
  unshare --mount --propagation private -- sh -c '
      set -e
      mount -t tmpfs fedsim-opt /opt
      mkdir -p /opt/fedsim/bin /opt/fedsim/qos /opt/fedsim/data /opt/fedsim/out
      mount --bind "$1" /opt/fedsim/bin
      mount --bind "$2/qos" /opt/fedsim/qos
      mount --bind "$2/data" /opt/fedsim/data
      mkdir -p /opt/fedsim/containers
      mount --bind "$3/image-containers" /opt/fedsim/containers
      mount --bind "$3/out" /opt/fedsim/out
      mount --bind "$3/hosts" /etc/hosts
      ns=$4; shift 4
      cd /opt/fedsim
      exec ip netns exec "$ns" "$@"' \
    sh "$FH_BIN" "$SOURCE_DIR" "$FH_WORK" "fh-c-$svc" env -i "${env[@]}" "${argv[@]}" \
    > "$FH_WORK/logs/$svc.log" 2>&1 &
  FH_PIDS+=($!)
  PID[$svc]=$!
}

t0=$(date +%s.%N)
for svc in "${SERVICES[@]}"; do start "$svc"; done
# The lockstep members end with the timing federate (--shutdown-on-exit); the server and the
# instructor station run until stopped, as in compose.
deadline=$(( $(date +%s) + RUN_LIMIT_S ))
failed=""
for svc in timing io flight nav motion control_loading recorder; do
  pid=${PID[$svc]}
  while kill -0 "$pid" 2>/dev/null; do
    [ "$(date +%s)" -lt "$deadline" ] || fh_fail "the federation did not finish within ${RUN_LIMIT_S} s"
    sleep 0.2
  done
  wait "$pid" || failed="$failed $svc"
done
t1=$(date +%s.%N)
[ -z "$failed" ] || { tail -n 5 "$FH_WORK"/logs/*.log >&2; fh_fail "failed:$failed"; }
kill -0 "${PID[ios]}" 2>/dev/null || fh_fail "the instructor station stopped: $(tail -3 "$FH_WORK/logs/ios.log")"
fh_log "figure containers frames=$FEDSIM_FRAMES services=${#SERVICES[@]} run_s=$(awk "BEGIN{printf \"%.2f\", $t1 - $t0}") timing_wall_s=$(grep '"federate":"timing"' "$FH_WORK/logs/timing.log" | tail -1 | python3 -c 'import json,sys; print(json.load(sys.stdin)["wall_s"])')"
grep -q "\"frames\":$FEDSIM_FRAMES," "$FH_WORK/logs/timing.log" || fh_fail "timing did not run $FEDSIM_FRAMES frames"
n=0
for topic in aircraft_state pilot_controls navigation_state motion_state control_loading_state; do
  csv="$FH_WORK/out/fedsim_$topic.csv"
  [ -f "$csv" ] || fh_fail "not recorded: $topic ($(tail -3 "$FH_WORK/logs/recorder.log"))"
  rows=$(( $(wc -l < "$csv") - 1 ))
  [ "$rows" -ge $((FEDSIM_FRAMES - 1)) ] || fh_fail "$topic: $rows rows for $FEDSIM_FRAMES frames"
  n=$((n + 1))
done
fh_log "every service ran as its container would; $n topics recorded for $FEDSIM_FRAMES frames"
echo "containers test: all checks passed"
