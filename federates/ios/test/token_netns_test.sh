#!/usr/bin/env bash
# The instructor station beyond the loopback refuses a client without the access token.
# Two network namespaces made here (never the machine's own network): "server" runs fedsim-ios
# bound to its veth address with a token, "client" asks it over the veth pair:
#   without the token -> 403, with a wrong token -> 403, with the token -> 200 (the control),
#   and the refusals are counted in the station's summary.
# Needs root and iproute2 (CI has both); says so and fails otherwise.
#   token_netns_test.sh <fedsim-ios binary>
set -euo pipefail
ios_bin="$1"
if [ "$(id -u)" -ne 0 ] || ! command -v ip > /dev/null; then
  echo "token_netns_test: needs root and iproute2 (ip netns) to make its own network namespaces" >&2
  exit 1
fi
suffix="$$"
server="fedsim-ios-srv-$suffix"
client="fedsim-ios-cli-$suffix"
work="$(mktemp -d)"
cleanup() {
  [ -n "${ios_pid:-}" ] && kill "$ios_pid" 2>/dev/null && wait "$ios_pid" 2>/dev/null || true
  ip netns del "$server" 2>/dev/null || true
  ip netns del "$client" 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT

ip netns add "$server"
ip netns add "$client"
ip link add "veth-s$suffix" type veth peer name "veth-c$suffix"
ip link set "veth-s$suffix" netns "$server"
ip link set "veth-c$suffix" netns "$client"
ip -n "$server" addr add 10.231.0.1/24 dev "veth-s$suffix"
ip -n "$client" addr add 10.231.0.2/24 dev "veth-c$suffix"
for ns in "$server" "$client"; do
  ip -n "$ns" link set lo up
done
ip -n "$server" link set "veth-s$suffix" up
ip -n "$client" link set "veth-c$suffix" up

token="fedsim-test-token-0123456789"
echo "$token" > "$work/token"
# DDS stays on the server namespace's own loopback (the default participant profile).
ip netns exec "$server" "$ios_bin" --bind 10.231.0.1 --http-port 8470 --token-file "$work/token" \
  --port-file "$work/port" --domain 199 > "$work/ios.log" 2>&1 &
ios_pid=$!
for _ in $(seq 1 100); do
  [ -s "$work/port" ] && break
  sleep 0.1
done
if [ ! -s "$work/port" ]; then
  echo "FAIL the station did not start:"; cat "$work/ios.log"; exit 1
fi

status() {  # HTTP status of GET / from the client namespace, with extra curl arguments
  ip netns exec "$client" curl -s -o /dev/null -w '%{http_code}' --max-time 5 "$@" http://10.231.0.1:8470/ || true
}
failures=0
expect() {
  if [ "$2" = "$3" ]; then echo "ok   $1: $3"; else echo "FAIL $1: got $3, expected $2"; failures=$((failures + 1)); fi
}
expect "no token from another host" 403 "$(status)"
expect "a wrong token" 403 "$(status -H 'Authorization: Bearer fedsim-test-token-0123456780')"
expect "the token (control)" 200 "$(status -H "Authorization: Bearer $token")"
expect "the token as the page's query" 200 "$(ip netns exec "$client" curl -s -o /dev/null -w '%{http_code}' --max-time 5 "http://10.231.0.1:8470/?token=$token" || true)"

kill -INT "$ios_pid"
wait "$ios_pid" || true
ios_pid=""
if grep -q "(2 refused)" "$work/ios.log"; then
  echo "ok   the station counted the 2 refusals"
else
  echo "FAIL the summary does not count 2 refusals:"; cat "$work/ios.log"; failures=$((failures + 1))
fi
[ "$failures" -eq 0 ] && echo "token test: all checks passed"
exit "$failures"
