#!/bin/bash
# SPDX-License-Identifier: MIT
# A watch's idle cost at N links (issue 44): a private mosquitto and rosmaster on loopback, a config
# of N mqtt2ros mappings nobody publishes on, `bridgescope watch --metrics` for SECONDS; prints the
# watch's CPU (% of a core) and RSS every 10 s. Run it with two binaries for an A/B in one session:
#
#   bench/watch_idle.sh BINARY [LINKS=10000] [SECONDS=120] [PORT_BASE=18830]
#
# The first ~60 s are the watch subscribing N ROS topics at the master (about 5 ms each); the
# figures after that are the idle cost.
set -euo pipefail
BIN=$(readlink -f "$1"); LINKS=${2:-10000}; SECS=${3:-120}; BASE=${4:-18830}
DIR=$(mktemp -d /tmp/bridgescope-idle-XXXXXX)
trap 'kill $MP $RP 2>/dev/null || true; rm -rf "$DIR"' EXIT
cd "$DIR"
{
    printf 'broker:\n  host: 127.0.0.1\n  port: %s\nclient:\n  id: idle_bridge\nbridge:\n  mqtt2ros:\n' "$BASE"
    for ((i = 0; i < LINKS; ++i)); do
        printf '    - {mqtt_topic: fleet/t%05d, ros_topic: /fleet/t%05d, primitive: true}\n' "$i" "$i"
    done
} > idle.yaml
printf 'listener %s 127.0.0.1\nallow_anonymous true\n' "$BASE" > m.conf
mosquitto -c m.conf > m.log 2>&1 & MP=$!
rosmaster --core -p $((BASE + 1)) > r.log 2>&1 & RP=$!
sleep 2
export ROS_MASTER_URI=http://127.0.0.1:$((BASE + 1))/ ROS_IP=127.0.0.1
"$BIN" watch idle.yaml --ros-master "$ROS_MASTER_URI" --metrics 127.0.0.1:$((BASE + 2)) --seconds "$SECS" \
    > w.out 2> w.err & WP=$!
hz=$(getconf CLK_TCK); prev=0
for ((t = 10; t <= SECS; t += 10)); do
    sleep 10
    [ -d /proc/$WP ] || break
    cpu=$(awk '{print $14 + $15}' /proc/$WP/stat)
    echo "t=${t}s cpu=$(( (cpu - prev) * 100 / hz / 10 ))% rss=$(awk '/VmRSS/{print $2}' /proc/$WP/status)kB"
    prev=$cpu
done
wait $WP || true
tail -2 w.err
