#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds the Debian package bridgescope_VERSION_ARCH.deb with CPack (cmake/Packaging.cmake,
# docs/PACKAGING.md) and prints its path.
#   scripts/package.sh                    a Release build in build-release (as run.sh), packaged
#   scripts/package.sh BUILD_DIR          that configured build, brought up to date, packaged
#   scripts/package.sh --no-build BUILD_DIR   packages BUILD_DIR as it is (the `package` test)
#   -o OUT_DIR                            where the .deb goes (default BUILD_DIR/package)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
usage() { sed -n '3,8s/^# \{0,1\}//p' "$0"; }
build=1
build_dir=""
out_dir=""
while [ $# -gt 0 ]; do
    case "$1" in
        -o) [ $# -ge 2 ] || { usage >&2; exit 2; }; out_dir="$2"; shift 2 ;;
        --no-build) build=0; shift ;;
        -h|--help) usage; exit 0 ;;
        -*) echo "package: unknown option $1" >&2; usage >&2; exit 2 ;;
        *) [ -z "$build_dir" ] || { usage >&2; exit 2; }; build_dir="$1"; shift ;;
    esac
done
if [ -z "$build_dir" ]; then
    build_dir="$root/build-release"
    if [ $build = 1 ]; then
        "$root/scripts/build.sh" "$build_dir" Release -DBRIDGESCOPE_BUILD_TESTS=OFF -DBRIDGESCOPE_BUILD_BENCH=OFF
    fi
elif [ $build = 1 ]; then
    "$root/scripts/setup.sh"
    cmake --build "$build_dir" -j "$(nproc)"
fi
config="$build_dir/CPackConfig.cmake"
if [ ! -f "$config" ]; then
    echo "package: $build_dir is not a configured build (no CPackConfig.cmake)" >&2
    exit 2
fi
out_dir="${out_dir:-$build_dir/package}"
mkdir -p "$out_dir"
version="$(sed -n 's/^set(CPACK_PACKAGE_VERSION "\(.*\)")$/\1/p' "$config")"
deb="$out_dir/bridgescope_${version}_$(dpkg --print-architecture).deb"
rm -f "$deb"
# CPack's own messages go to standard error: standard output is the package's path only.
cpack --config "$config" -B "$out_dir" >&2
rm -rf "$out_dir/_CPack_Packages"
if [ ! -f "$deb" ]; then
    echo "package: CPack did not write $deb" >&2
    exit 1
fi
echo "$deb"
