#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Self-test of bs_ros2peer (ctest: tst_ros2peer). On a domain of its own (100 + pid % 100):
#   - --help exits 0, bad arguments exit 2 with a message;
#   - one peer publishes the four types at 20 Hz, another subscribes to them: within 15 s the
#     subscriber prints recv lines with the right summaries, every sample starts with the
#     encapsulation header 00 01 00 00, DDS discovery shows rt/<topic> with pkg::msg::dds_::Type_
#     types, and ros_discovery_info shows the publisher's node with its 4 writers;
#   - SIGTERM ends the publisher cleanly (exit 0) and the subscriber sees its match go;
#   - a peer with --exit-hard --lease-ms 1000 vanishes without goodbye and its match goes within
#     the lease (plus slack);
#   - --many 40@7 with a relative prefix: 40 writers rt/selftest/t0007..t0046 in discovery, its node
#     with 40 writers on ros_discovery_info, and at rate 0 nothing sent.
#   selftest.sh PATH/TO/bs_ros2peer
set -u
peer="${1:?usage: selftest.sh PATH/TO/bs_ros2peer}"
work="$(mktemp -d "${TMPDIR:-/tmp}/ros2peer-selftest.XXXXXX")"
pids=()
cleanup() {
    for p in "${pids[@]}"; do kill -KILL "$p" 2>/dev/null; done
    wait 2>/dev/null
    rm -rf "$work"
}
trap cleanup EXIT

now_ms() { local t=${EPOCHREALTIME/./}; echo $((10#$t / 1000)); }
start_ms=$(now_ms)
elapsed() { echo "$(( ($(now_ms) - start_ms) ))ms"; }

fail() {
    echo "selftest: FAIL after $(elapsed): $*"
    for f in "$work"/*.out "$work"/*.err; do
        [ -s "$f" ] || continue
        echo "--- $(basename "$f") (last 15 lines)"
        tail -n 15 "$f"
    done
    exit 1
}

# wait_for FILE EXTENDED_REGEX SECONDS: until a line of FILE matches.
wait_for() {
    local deadline=$(( $(now_ms) + $3 * 1000 ))
    until grep -Eq -- "$2" "$1" 2>/dev/null; do
        [ "$(now_ms)" -lt "$deadline" ] || return 1
        sleep 0.05
    done
}

# wait_exit PID SECONDS: sets rc to the exit status, or 124 when still running after SECONDS.
wait_exit() {
    local deadline=$(( $(now_ms) + $2 * 1000 ))
    while kill -0 "$1" 2>/dev/null; do
        [ "$(now_ms)" -lt "$deadline" ] || { rc=124; return; }
        sleep 0.05
    done
    wait "$1"
    rc=$?
}

# --help and bad arguments.
"$peer" --help > "$work/help.out" 2>&1 || fail "--help exited $?"
grep -q -- '--domain N' "$work/help.out" || fail "--help does not describe --domain"
bad_args=(
    ""
    "--domain 233"
    "--domain x"
    "--domain 1 --pub /a:std_msgs/msg/Nope"
    "--domain 1 --pub /a"
    "--domain 1 --pub /a:std_msgs/msg/String:0"
    "--domain 1 --sub /a:std_msgs/msg/String:depth=0"
    "--domain 1 --sub /1a:std_msgs/msg/String"
    "--domain 1 --size 4194305"
    "--domain 1 --duration 3601"
    "--domain 1 --lease-ms 5"
    "--domain 1 --node /ns/"
    "--domain 1 --bogus"
    "--domain"
    "--domain 1 --many 0:/m:std_msgs/msg/String"
    "--domain 1 --many 5001:/m:std_msgs/msg/String"
    "--domain 1 --many 10@9995:/m:std_msgs/msg/String"
    "--domain 1 --many 5:/m/:std_msgs/msg/String"
    "--domain 1 --many 5:/m:std_msgs/msg/String:-1"
    "--domain 1 --many 100:/m:sensor_msgs/msg/PointCloud2:1 --size 4194304"
    "--domain 1 --many 2:/m:std_msgs/msg/String --many 2:/n:std_msgs/msg/String"
    "--domain 1 --raw /a:00010000"
    "--domain 1 --pub /a:std_msgs/msg/String --raw /a:0001000"
    "--domain 1 --pub /a:std_msgs/msg/String --raw /a:zz"
    "--domain 1 --pub /a:std_msgs/msg/String --raw /a:"
    "--domain 1 --pub /a:std_msgs/msg/String --raw /a:00 --raw /a:00"
    "--domain 1 --pub /a:std_msgs/msg/String --sub /a:std_msgs/msg/String --raw /a:00"
    "--domain 1 --graph-raw 0"
    "--domain 1 --pub /a:std_msgs/msg/String --stamp-delay /a:5"
    "--domain 1 --pub /a:benchmarking_suite/msg/TimeStamped --stamp-delay /a:60001"
    "--domain 1 --pub /a:benchmarking_suite/msg/TimeStamped --stamp-delay /b:5"
)
for args in "${bad_args[@]}"; do
    # shellcheck disable=SC2086 # word splitting wanted
    # Bounded: a command line that is accepted by mistake would otherwise run for its --duration.
    timeout 10 "$peer" $args > "$work/bad.out" 2> "$work/bad.err"
    rc=$?
    [ "$rc" = 124 ] && fail "'$args' was accepted and ran (killed after 10 s), want exit 2"
    [ "$rc" = 2 ] || fail "'$args' exited $rc, want 2"
    grep -q . "$work/bad.err" || fail "'$args': no message on stderr"
done
echo "selftest: --help and ${#bad_args[@]} bad command lines: ok ($(elapsed))"

domain=$(( 100 + $$ % 100 ))
echo "selftest: domain $domain"
"$peer" --domain "$domain" --node /selftest/listener --duration 60 --cdr --show-discovery \
    --sub /chatter:std_msgs/msg/String \
    --sub /pose:geometry_msgs/msg/PoseStamped \
    --sub /cloud:sensor_msgs/msg/PointCloud2 \
    --sub /opaque:bridgescope_test/msg/Opaque:best_effort,depth=5 \
    --sub /hard:std_msgs/msg/String \
    > "$work/sub.out" 2> "$work/sub.err" &
sub=$!
pids+=("$sub")
"$peer" --domain "$domain" --node /selftest/talker --duration 60 --size 4096 \
    --pub /chatter:std_msgs/msg/String:20 \
    --pub /pose:geometry_msgs/msg/PoseStamped:20 \
    --pub /cloud:sensor_msgs/msg/PointCloud2:20 \
    --pub /opaque:bridgescope_test/msg/Opaque:20:best_effort \
    > "$work/pub.out" 2> "$work/pub.err" &
pub=$!
pids+=("$pub")
"$peer" --domain "$domain" --node vanisher --duration 3 --lease-ms 1000 --exit-hard \
    --pub /hard:std_msgs/msg/String:20 > "$work/hard.out" 2> "$work/hard.err" &
hard=$!
pids+=("$hard")
"$peer" --domain "$domain" --node /selftest/many --duration 60 \
    --many 40@7:t:std_msgs/msg/String:0 > "$work/many.out" 2> "$work/many.err" &
many=$!
pids+=("$many")

# Everything within 15 s of starting the peers.
exchange_start=$(now_ms)
expect=(
    "sub.out|^ready$"
    "pub.out|^ready$"
    "pub.out|^matched /chatter 1$"
    "pub.out|^matched /opaque 1$"
    "pub.out|^sent /cloud [0-9]+$"
    "sub.out|^matched /pose 1$"
    "sub.out|^recv /chatter [0-9]+ hello [0-9]+$"
    "sub.out|^recv /pose [0-9]+ x=[0-9]+$"
    "sub.out|^recv /cloud [0-9]+ width=256 data=4096$"
    "sub.out|^recv /opaque [0-9]+ n=[0-9]+ blob=4096$"
    "sub.out|^cdr /cloud [0-9]+ [0-9]+ 00 01 00 00"
    "sub.out|^endpoint pub rt/chatter std_msgs::msg::dds_::String_$"
    "sub.out|^endpoint pub rt/pose geometry_msgs::msg::dds_::PoseStamped_$"
    "sub.out|^endpoint pub rt/cloud sensor_msgs::msg::dds_::PointCloud2_$"
    "sub.out|^endpoint pub rt/opaque bridgescope_test::msg::dds_::Opaque_$"
    "sub.out|^endpoint pub ros_discovery_info rmw_dds_common::msg::dds_::ParticipantEntitiesInfo_$"
    "sub.out|^node /selftest talker 0 4$"
    "sub.out|^node / vanisher 0 1$"
    "many.out|^ready$"
    "sub.out|^endpoint pub rt/selftest/t0007 std_msgs::msg::dds_::String_$"
    "sub.out|^endpoint pub rt/selftest/t0046 std_msgs::msg::dds_::String_$"
    "sub.out|^node /selftest many 0 40$"
)
for e in "${expect[@]}"; do
    file="${e%%|*}" regex="${e#*|}"
    left=$(( 15 - ($(now_ms) - exchange_start) / 1000 ))
    wait_for "$work/$file" "$regex" "$(( left > 0 ? left : 0 ))" || fail "no line matching '$regex' in $file within 15 s"
done
echo "selftest: four types exchanged, names and discovery as ROS 2 puts them: ok ($(( $(now_ms) - exchange_start ))ms after start)"

# Each summary matches what the publisher sends for its sample number, and every sample, large
# or small, starts with 00 01 00 00.
bad_line=$(grep -E '^recv ' "$work/sub.out" | awk '
    $2 == "/chatter" && !($4 == "hello" && $5 ~ /^[0-9]+$/ && NF == 5) { print; exit }
    $2 == "/pose" && $4 !~ /^x=[0-9]+$/ { print; exit }')
[ -z "$bad_line" ] || fail "unexpected summary: $bad_line"
bad_cdr=$(grep -E '^cdr ' "$work/sub.out" | awk '!($5 == "00" && $6 == "01" && $7 == "00" && $8 == "00") { print; exit }')
[ -z "$bad_cdr" ] || fail "encapsulation header is not 00 01 00 00: $bad_cdr"
echo "selftest: $(grep -c '^cdr ' "$work/sub.out") samples, each with header 00 01 00 00: ok"

# --many: exactly the 40 topics t0007..t0046, none sent at rate 0.
many_topics=$(grep -E '^endpoint pub rt/selftest/t[0-9]{4} ' "$work/sub.out" | sort -u | wc -l)
[ "$many_topics" = 40 ] || fail "--many 40@7: $many_topics distinct writers in discovery, want 40"
grep -Eq '^endpoint pub rt/selftest/t00(0[0-6]|4[7-9]) ' "$work/sub.out" && fail "--many 40@7: a writer outside t0007..t0046"
grep -q '^sent ' "$work/many.out" && fail "--many at rate 0 sent a sample"
echo "selftest: --many 40@7: 40 writers t0007..t0046 and their node, nothing sent: ok"

# The vanished peer (no goodbye, lease 1 s) is noticed: its process exits 0 at 3 s, its match
# goes at most a few seconds later.
wait_exit "$hard" 10
[ "$rc" = 0 ] || fail "--exit-hard peer exited $rc, want 0"
hard_gone=$(now_ms)
wait_for "$work/sub.out" "^matched /hard 0$" 5 || fail "the vanished peer's match did not go within 5 s"
echo "selftest: --exit-hard peer noticed gone $(( $(now_ms) - hard_gone ))ms after it exited: ok"

# SIGTERM: the publisher ends cleanly and says goodbye; its matches go at once.
term=$(now_ms)
kill -TERM "$pub"
wait_exit "$pub" 5
[ "$rc" = 0 ] || fail "publisher exited $rc after SIGTERM, want 0"
wait_for "$work/sub.out" "^matched /chatter 0$" 3 || fail "no 'matched /chatter 0' within 3 s of SIGTERM"
wait_for "$work/sub.out" "^matched /cloud 0$" 3 || fail "no 'matched /cloud 0' within 3 s of SIGTERM"
echo "selftest: SIGTERM: publisher exited 0, matches gone $(( $(now_ms) - term ))ms after: ok"

kill -INT "$sub"
wait_exit "$sub" 5
[ "$rc" = 0 ] || fail "subscriber exited $rc after SIGINT, want 0"
kill -TERM "$many"
wait_exit "$many" 5
[ "$rc" = 0 ] || fail "--many peer exited $rc after SIGTERM, want 0"
[ ! -s "$work/sub.err" ] && [ ! -s "$work/pub.err" ] && [ ! -s "$work/many.err" ] || fail "messages on stderr"
echo "selftest: passed in $(elapsed)"
