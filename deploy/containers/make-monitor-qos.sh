#!/bin/sh
# Writes OUT: qos/fedsim_qos.xml with fedsim_container_monitor.xml's participant profile added
# (the recorder's QoS file in the containers). The profile names the host "discovery", which
# Fast DDS resolves while parsing, so it cannot live in qos/fedsim_qos.xml itself (that file must
# load everywhere). Used by the Containerfile and by tests/hosts/containers_test.sh.
#   make-monitor-qos.sh QOS_XML MONITOR_XML OUT
set -eu
[ $# = 3 ] || { echo "usage: make-monitor-qos.sh QOS_XML MONITOR_XML OUT" >&2; exit 2; }
grep -q '</profiles>' "$1" || { echo "make-monitor-qos: no </profiles> in $1" >&2; exit 1; }
{
  sed '/<\/profiles>/,$d' "$1"
  sed -n '/<participant profile_name=/,/<\/participant>/p' "$2"
  sed -n '/<\/profiles>/,$p' "$1"
} > "$3"
grep -q 'profile_name="fedsim_container_monitor"' "$3" || { echo "make-monitor-qos: no profile in $2" >&2; exit 1; }
