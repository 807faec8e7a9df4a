#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The `package` test: packages a built tree with scripts/package.sh --no-build (CPack) and checks
# the .deb: its fields, its files, no RUNPATH and stripped programs, the desktop file, AppStream
# metadata, MIME type and manual page valid, the unpacked program runs (its version, config
# validate, the bag reader found beside it), and lintian finds no error.
# Usage: check_package.sh BUILD_DIR VERSION FIXTURES_DIR
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build_dir="$1"
version="$2"
fixtures="$3"
failures=0
fail() {
    echo "FAIL: $*" >&2
    failures=$((failures + 1))
}
pass() { echo "ok: $*"; }

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

# --- the package ---------------------------------------------------------------------------------
deb="$("$root/scripts/package.sh" --no-build -o "$tmp/out" "$build_dir")"
expected="$tmp/out/bridgescope_${version}_$(dpkg --print-architecture).deb"
[ "$deb" = "$expected" ] || { echo "FAIL: package.sh wrote '$deb', not $expected" >&2; exit 1; }
pass "scripts/package.sh wrote $(basename "$deb") ($(du -k "$deb" | cut -f1) kB)"

field() { dpkg-deb -f "$deb" "$1"; }
[ "$(field Package)" = bridgescope ] || fail "Package: $(field Package)"
[ "$(field Version)" = "$version" ] || fail "Version: $(field Version), the project is $version"
[ "$(field Section)" = science ] || fail "Section: $(field Section)"
[[ "$(field Maintainer)" == *"<"*"@"*">" ]] || fail "Maintainer: $(field Maintainer)"
for dep in libqt6core6 libqt6widgets6 libroscpp libyaml-cpp libpaho-mqttpp3 libqt6sql6-sqlite libddsc0debian; do
    [[ "$(field Depends)" == *"$dep"* ]] || fail "Depends lacks $dep (dpkg-shlibdeps): $(field Depends)"
done
# bridgescope-dds runs on Cyclone DDS: Fast DDS is no dependency any more (issue 31)
[[ "$(field Depends)" != *libfastrtps* ]] || fail "Depends still names Fast DDS: $(field Depends)"
for rec in mosquitto python3-rosmaster; do
    [[ "$(field Recommends)" == *"$rec"* ]] || fail "Recommends lacks $rec: $(field Recommends)"
done
pass "control fields (Depends: $(field Depends | tr ',' '\n' | wc -l) packages)"

listing="$(dpkg-deb -c "$deb" | awk '{print $6}')"
files=(
    ./usr/bin/bridgescope
    ./usr/libexec/bridgescope/bridgescope-bagreader
    ./usr/libexec/bridgescope/bridgescope-dds
    ./usr/share/applications/io.github.bridgescope.Bridgescope.desktop
    ./usr/share/metainfo/io.github.bridgescope.Bridgescope.metainfo.xml
    ./usr/share/mime/packages/bridgescope.xml
    ./usr/share/icons/hicolor/scalable/apps/bridgescope.svg
    ./usr/share/man/man1/bridgescope.1.gz
    ./usr/share/doc/bridgescope/copyright
    ./usr/share/doc/bridgescope/changelog.gz
    ./usr/share/bridgescope/prometheus/bridgescope-rules.yml
    ./usr/share/bridgescope/prometheus/prometheus.yml
    ./usr/share/bridgescope/prometheus/agent.yml
    ./usr/share/bridgescope/prometheus/federation.yml
)
sizes=(16 32 48 64 128 256)
for s in "${sizes[@]}"; do
    files+=("./usr/share/icons/hicolor/${s}x${s}/apps/bridgescope.png")
done
for f in "${files[@]}"; do
    grep -qxF "$f" <<<"$listing" || fail "the package lacks $f"
done
# Nothing but /usr (no build paths, no tests, no /usr/local).
if grep -v '^\./usr/' <<<"$listing" | grep -qvx '\./'; then
    fail "files outside /usr: $(grep -v '^\./usr/' <<<"$listing" | grep -vx '\./' | head -5)"
fi
pass "dpkg-deb -c lists the ${#files[@]} expected files"

# --- its files -----------------------------------------------------------------------------------
unpacked="$tmp/root"
dpkg-deb -x "$deb" "$unpacked"
usr="$unpacked/usr"
for exe in "$usr/bin/bridgescope" "$usr/libexec/bridgescope/bridgescope-bagreader" \
    "$usr/libexec/bridgescope/bridgescope-dds"; do
    if readelf -d "$exe" | grep -E 'RPATH|RUNPATH'; then
        fail "$exe has a search path (Debian forbids it): $(readelf -d "$exe" | grep -E 'RPATH|RUNPATH')"
    fi
    file -b "$exe" | grep -q ', stripped' || fail "$exe is not stripped: $(file -b "$exe")"
done
pass "programs stripped, no RPATH/RUNPATH (readelf -d)"

desktop="$usr/share/applications/io.github.bridgescope.Bridgescope.desktop"
desktop-file-validate "$desktop" || fail "desktop-file-validate $desktop"
grep -qx 'Exec=bridgescope %F' "$desktop" || fail "the desktop file's Exec is not 'bridgescope %F'"
grep -qx 'MimeType=.*application/x-bridgescope-run;.*' "$desktop" \
    || fail "the desktop file's MimeType lacks application/x-bridgescope-run"
# Listing YAML would make Bridgescope every YAML file's default program where none is set (GLib
# takes the first program that names the type itself over editors that take any text/plain).
if grep -q '^MimeType=.*yaml' "$desktop"; then
    fail "the desktop file claims YAML files: Bridgescope would become their default program"
fi
pass "desktop-file-validate"

metainfo="$usr/share/metainfo/io.github.bridgescope.Bridgescope.metainfo.xml"
appstreamcli validate --no-net "$metainfo" || fail "appstreamcli validate --no-net $metainfo"
grep -q "<launchable type=\"desktop-id\">$(basename "$desktop")</launchable>" "$metainfo" \
    || fail "the metainfo's launchable is not $(basename "$desktop")"
grep -q "<release version=\"$version\"" "$metainfo" || fail "the metainfo has no release $version"
pass "appstreamcli validate --no-net"

# The MIME type, compiled as update-mime-database does on installation (with freedesktop.org's
# types, for its parent application/vnd.sqlite3).
mime="$tmp/mime"
mkdir -p "$mime/packages"
cp "$usr/share/mime/packages/bridgescope.xml" /usr/share/mime/packages/freedesktop.org.xml "$mime/packages/"
if ! out="$(update-mime-database "$mime" 2>&1)" || grep -qi 'error\|invalid' <<<"$out"; then
    fail "update-mime-database: $out"
fi
grep -qx 'application/x-bridgescope-run:\*\.bsrun' "$mime/globs" || fail "no *.bsrun glob: $(grep bridgescope "$mime/globs")"
grep -qx 'application/x-bridgescope-run application/vnd.sqlite3' "$mime/subclasses" \
    || fail "application/x-bridgescope-run is not an application/vnd.sqlite3"
pass "MIME type application/x-bridgescope-run (*.bsrun)"

for s in "${sizes[@]}"; do
    png="$usr/share/icons/hicolor/${s}x${s}/apps/bridgescope.png"
    file -b "$png" | grep -q "PNG image data, $s x $s," || fail "$png: $(file -b "$png")"
done
pass "PNG icons of ${sizes[*]} pixels"

man="$usr/share/man/man1/bridgescope.1.gz"
gzip -t "$man" || fail "$man is not gzip"
warnings="$(LC_ALL=C.UTF-8 MANROFFSEQ='' MANWIDTH=80 man --warnings -E UTF-8 -l -Tutf8 -Z "$man" 2>&1 >/dev/null)"
[ -z "$warnings" ] || fail "man --warnings: $warnings"
zcat "$man" | grep -q "^\.TH BRIDGESCOPE 1 .*\"bridgescope $version\"" || fail "the manual page is not of version $version"
pass "man --warnings"

changelog="$usr/share/doc/bridgescope/changelog.gz"
zcat "$changelog" | head -1 | grep -q "^bridgescope ($version) " \
    || fail "the changelog's latest entry is not $version: $(zcat "$changelog" | head -1)"
head -1 "$usr/share/doc/bridgescope/copyright" | grep -q '^Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/' \
    || fail "the copyright file is not machine-readable"
grep -q 'Permission is hereby granted' "$usr/share/doc/bridgescope/copyright" || fail "the copyright file lacks the licence"
pass "changelog and copyright"

# --- the unpacked program ------------------------------------------------------------------------
run() { env -u LD_LIBRARY_PATH -u BRIDGESCOPE_BAGREADER -u BRIDGESCOPE_DDS QT_QPA_PLATFORM=offscreen LC_ALL=C.UTF-8 "$@"; }
out="$(run "$usr/bin/bridgescope" --version)" || fail "bridgescope --version exits $?"
[ "$out" = "bridgescope $version" ] || fail "bridgescope --version says '$out'"

# The manual page names every option and command that --help lists.
help="$(run "$usr/bin/bridgescope" --help)"
page="$(zcat "$man" | sed 's/\\-/-/g')"
mapfile -t options < <(sed -n 's/^  \(-[a-z], \)\{0,1\}\(--[a-z-]*\).*/\2/p' <<<"$help")
mapfile -t commands < <(sed -n '/^Commands:/,/^$/s/^  \([a-z]\+\).*/\1/p' <<<"$help")
if [ ${#options[@]} -lt 8 ] || [ ${#commands[@]} -lt 8 ]; then
    fail "cannot read --help: ${options[*]} / ${commands[*]}"
fi
for word in "${options[@]}" "${commands[@]}"; do
    grep -qF -- "$word" <<<"$page" || fail "the manual page does not mention $word (bridgescope --help does)"
done
pass "bridgescope --version; the manual page has the ${#options[@]} options and ${#commands[@]} commands of --help"

# `bridgescope rules` prints the Prometheus rules the package installs, byte for byte.
run "$usr/bin/bridgescope" rules >"$tmp/rules.yml" || fail "bridgescope rules exits $?"
cmp -s "$tmp/rules.yml" "$usr/share/bridgescope/prometheus/bridgescope-rules.yml" \
    || fail "bridgescope rules prints other rules than the package installs"
pass "bridgescope rules prints the installed rules"

valid="$fixtures/mqtt_client/ros1-era-params.yaml"
run "$usr/bin/bridgescope" config validate "$valid" || fail "config validate $valid exits $?"
printf 'bridge:\n  ros2mqtt:\n    - ros_topic: /a\n      mqtt_topic: a/#\n' >"$tmp/invalid.yaml"
status=0
out="$(run "$usr/bin/bridgescope" config validate "$tmp/invalid.yaml")" || status=$?
if [ $status != 1 ] || [[ "$out" != "$tmp/invalid.yaml:4:19: error: "* ]]; then
    fail "config validate of an invalid config: exit $status, '$out'"
fi
pass "config validate on a fixture and an invalid config"

# The bag reader is found beside the installed program (../libexec/bridgescope), not in the
# build tree, and reads the bag.
/usr/bin/python3 - "$tmp/chatter.bag" <<'PY'
import sys
import rosbag
from std_msgs.msg import String
with rosbag.Bag(sys.argv[1], "w") as bag:
    bag.write("/chatter", String(data="hello"))
PY
status=0
out="$(run "$usr/bin/bridgescope" --verbose report "$tmp/chatter.bag" 2>&1)" || status=$?
grep -qF "starting $usr/bin/../libexec/bridgescope/bridgescope-bagreader for $tmp/chatter.bag" <<<"$out" \
    || fail "the installed program did not start the installed bag reader: $out"
grep -qF 'it has: /chatter (std_msgs/String)' <<<"$out" || fail "the bag reader did not read the bag: $out"
[ $status = 2 ] || fail "report of a bag without stamps exits $status, not 2"
pass "the installed bag reader reads a bag"

# The ROS 2 participant runs in the installed DDS helper, found the same way.
status=0
domain=$((200 + $$ % 30))
out="$(run "$usr/bin/bridgescope" --verbose discover --ros 2 --ros-domain "$domain" --ros-localhost-only \
    --broker tcp://127.0.0.1:1 --seconds 1 2>&1)" || status=$?
# (the participant says the domain it joins, its supervisor the child it starts for it)
{ grep -qF "joining domain $domain" <<<"$out" && grep -qF "starting $usr/bin/../libexec/bridgescope/bridgescope-dds" <<<"$out"; } \
    || fail "the installed program did not start the installed DDS helper: $out"
grep -qF "restarted" <<<"$out" && fail "the installed DDS helper did not run: $out"
pass "the installed DDS helper runs the ROS 2 participant"

# --- lintian -------------------------------------------------------------------------------------
# Errors fail; warnings and notes are printed (docs/PACKAGING.md lists those expected).
status=0
lintian --fail-on error --display-info "$deb" >"$tmp/lintian.txt" 2>&1 || status=$?
grep -v 'running with root privileges' "$tmp/lintian.txt" || true
[ $status = 0 ] || fail "lintian found errors (exit $status)"
pass "lintian: no errors"

if [ $failures -gt 0 ]; then
    echo "$failures check(s) failed" >&2
    exit 1
fi
echo "the package is fine: $(basename "$deb")"
