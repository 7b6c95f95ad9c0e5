# shellcheck shell=bash
# Network namespaces as "hosts" for fedsim's multi-host tests (sourced by tests/hosts/*.sh).
#
# Layout: one namespace per host (fh-<tag>-<host>), one namespace holding only a bridge
# (fh-<tag>-br, bridge br0); each host joins the bridge through a veth pair, or through
# fedsim-netem-relay (a TAP device on each side) when that link is impaired. Addresses are
# 10.232.0.0/24 and exist only inside these namespaces: the root namespace's interfaces are never
# touched, and every namespace (with its interfaces) goes away in the EXIT trap.
# Needs root and `ip netns`; a test that cannot create a namespace exits 77 (CTest SKIP_RETURN_CODE).

# FH_NS_PREFIX (default fh) starts every namespace name: two runs of these tests at the same
# time on one machine (e.g. by hand beside CTest) need different prefixes.
FH_NS="${FH_NS_PREFIX:-fh}"
FH_NETNS_CREATED=()
FH_PIDS=()
FH_RELAY_PIDS=()

fh_log() { echo "[hosts] $*"; }
fh_fail() { echo "[hosts] FAIL: $*" >&2; exit 1; }

# Exits 77 with the reason when this machine cannot run namespace tests.
fh_require_netns() {
  local probe="$FH_NS-probe-$$"
  if [ "$(id -u)" != 0 ]; then echo "SKIP: network namespace tests need root (CI runs as root)"; exit 77; fi
  if ! command -v ip >/dev/null; then echo "SKIP: iproute2 (ip) is not installed"; exit 77; fi
  if ! ip netns add "$probe" 2>/dev/null; then echo "SKIP: 'ip netns add' is not permitted here"; exit 77; fi
  ip netns del "$probe"
}

fh_cleanup() {
  local pid
  for pid in "${FH_PIDS[@]}" "${FH_RELAY_PIDS[@]}"; do
    kill -TERM "$pid" 2>/dev/null || true
  done
  for pid in "${FH_PIDS[@]}" "${FH_RELAY_PIDS[@]}"; do
    wait "$pid" 2>/dev/null || true
  done
  local ns
  for ns in "${FH_NETNS_CREATED[@]}"; do
    # Anything still running in the namespace is ours (started by this test).
    ip netns pids "$ns" 2>/dev/null | xargs -r kill -KILL 2>/dev/null || true
    ip netns del "$ns" 2>/dev/null || true
  done
}

fh_netns_add() {
  ip netns del "$1" 2>/dev/null || true   # a leftover of a killed earlier run of this test
  ip netns add "$1" || fh_fail "cannot create namespace $1"
  FH_NETNS_CREATED+=("$1")
  ip -n "$1" link set lo up
}

# fh_network TAG: the bridge namespace.
fh_network() {
  FH_TAG="$1"
  FH_BR="$FH_NS-$FH_TAG-br"
  trap fh_cleanup EXIT
  trap 'exit 130' INT TERM
  fh_netns_add "$FH_BR"
  ip -n "$FH_BR" link add br0 type bridge
  ip -n "$FH_BR" link set br0 up
  FH_METHOD=$(fh_impairment_method)
}

# fh_host NAME ADDRESS_LAST_OCTET [impaired LOSS_PERCENT DELAY_MS SEED]: a host on the bridge;
# an impaired host's link drops and delays frames both ways (tc netem where the kernel has it,
# else fedsim-netem-relay; fh_network sets FH_METHOD).
fh_host() {
  local name="$1" octet="$2" ns="$FH_NS-$FH_TAG-$1"
  fh_netns_add "$ns"
  if [ "${3:-}" = impaired ] && [ "$FH_METHOD" = netem ]; then
    ip link add eth0 netns "$ns" type veth peer name "p-$name" netns "$FH_BR" \
      || fh_fail "cannot create the veth pair of host $name"
    # Both directions, as the relay does: egress of the host and egress towards it.
    tc -n "$ns" qdisc add dev eth0 root netem delay "${5}ms" loss "${4}%"
    tc -n "$FH_BR" qdisc add dev "p-$name" root netem delay "${5}ms" loss "${4}%"
  elif [ "${3:-}" = impaired ]; then
    local log="$FH_WORK/relay-$name.log"
    "$FH_BIN/fedsim-netem-relay" --ns-a "$ns" --tap-a eth0 --ns-b "$FH_BR" --tap-b "p-$name" \
      --loss "$4" --delay-ms "$5" --seed "$6" >"$log" 2>&1 &
    FH_RELAY_PIDS+=($!)
    local _
    for _ in $(seq 50); do grep -q '^ready' "$log" && break; sleep 0.1; done
    grep -q '^ready' "$log" || fh_fail "fedsim-netem-relay did not start: $(cat "$log")"
  else
    ip link add eth0 netns "$ns" type veth peer name "p-$name" netns "$FH_BR" \
      || fh_fail "cannot create the veth pair of host $name"
  fi
  ip -n "$FH_BR" link set "p-$name" master br0
  ip -n "$FH_BR" link set "p-$name" up
  ip -n "$ns" addr add "10.232.0.$octet/24" dev eth0
  ip -n "$ns" link set eth0 up
  # Multicast discovery leaves through eth0 (the only interface besides lo).
  ip -n "$ns" route add 224.0.0.0/4 dev eth0
}

# Stops the relays: each prints its counts (JSON) into its log.
fh_stop_relays() {
  local pid
  for pid in "${FH_RELAY_PIDS[@]}"; do kill -TERM "$pid" 2>/dev/null || true; wait "$pid" 2>/dev/null || true; done
  FH_RELAY_PIDS=()
}

# fh_in HOST CMD...: runs CMD in host HOST's namespace, in the background (pid in FH_PIDS).
fh_in() {
  local host="$1"; shift
  ip netns exec "$FH_NS-$FH_TAG-$host" "$@" &
  FH_PIDS+=($!)
}

# fh_impairment_method: how loss and delay are made on this kernel.
fh_impairment_method() {
  local ns="$FH_NS-$FH_TAG-br"
  if ip -n "$ns" link add fhnetemprobe type dummy 2>/dev/null; then
    if tc -n "$ns" qdisc add dev fhnetemprobe root netem delay 1ms 2>/dev/null; then
      ip -n "$ns" link del fhnetemprobe; echo netem; return
    fi
    ip -n "$ns" link del fhnetemprobe
  fi
  echo relay
}
