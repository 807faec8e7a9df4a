#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs every Debian package Bridgescope needs to build, test and run.
# Non-interactive and idempotent: when everything is present it only asks dpkg and exits.
set -euo pipefail

PACKAGES=(
    # toolchain
    g++ cmake ninja-build pkg-config ccache
    # fuzzing with libFuzzer, ASan and UBSan (scripts/fuzz.sh; test.sh runs every target briefly)
    clang-14 libclang-rt-14-dev llvm-14
    # Qt 6 (Widgets, Charts, Svg, Sql/SQLite, translations)
    qt6-base-dev libqt6opengl6-dev libxkbcommon-dev qt6-charts-dev qt6-svg-dev qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools
    libqt6sql6-sqlite libsqlite3-dev qtkeychain-qt6-dev
    # MQTT: the C++ package does not pull in the C library it needs
    libpaho-mqttpp-dev libpaho-mqtt-dev libssl-dev openssl
    # YAML
    libyaml-cpp-dev
    # Prometheus: the server and promtool the tests of `watch --metrics` run, and prometheus-cpp,
    # the peer bench_metrics compares the exposition with
    prometheus prometheus-cpp-dev
    # ROS 1 (roscpp, generic subscribers, bags, message headers used by tests)
    libroscpp-dev libtopic-tools-dev librosbag-dev pluginlib-dev ros-core-dev
    libstd-msgs-dev libgeometry-msgs-dev libsensor-msgs-dev
    # ROS 2 on the wire: Fast CDR, the serializer of ROS 2's default RMW, makes the test bytes
    libfastcdr-dev
    # ROS 2 on the wire: Cyclone DDS, the DDS library of bridgescope-dds (core/dds) and of the
    # test peers (tests/ros2peer)
    cyclonedds-dev cyclonedds-tools
    # bench_ros2 only (optional, the build leaves it out without them): its Fast DDS peer, and
    # Fast DDS's own code generator that makes that peer's message types from the IDL
    libfastrtps-dev fastddsgen
    python3-std-msgs python3-geometry-msgs python3-sensor-msgs python3-rospy python3-rostopic
    # servers the tests and the demo start
    mosquitto mosquitto-clients
    # experiments on two hosts over ssh, and their two-namespace test lab (tests/support/twohostlab.h)
    openssh-client openssh-server iproute2
    # headless GUI runs, report checks, reference computations
    xvfb xauth poppler-utils python3-numpy python3-yaml python3-genmsg
    # the Debian package (scripts/package.sh) and its test (tests/package): dpkg-shlibdeps for its
    # dependencies, PNG icons from the SVG, and the checkers (lintian, desktop file, AppStream,
    # MIME type, man --warnings, a ROS bag for the bag reader)
    dpkg-dev librsvg2-bin lintian desktop-file-utils appstream shared-mime-info man-db file python3-rosbag
)

missing=()
for p in "${PACKAGES[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$p")
    fi
done

if [ ${#missing[@]} -eq 0 ]; then
    exit 0
fi

echo "setup: installing ${#missing[@]} Debian package(s): ${missing[*]}"
SUDO=()
if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null; then
        SUDO=(sudo)
    else
        echo "setup: need root (or sudo) to install: ${missing[*]}" >&2
        exit 1
    fi
fi
export DEBIAN_FRONTEND=noninteractive
"${SUDO[@]}" apt-get update -qq
"${SUDO[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "setup: done"
