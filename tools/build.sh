#!/usr/bin/env bash
# Installs what is missing, configures once and builds (Release by default).
# The build is a unity build (CMake's CMAKE_UNITY_BUILD: the sources of a
# target compiled eight to a translation unit), which parses the shared
# headers (GoogleTest, the L-system library's) once per eight files instead
# of once per file: a fresh build takes far less time on a 2-core machine.
# UNITY_BUILD=OFF configures a build of one translation unit per source,
# quicker to rebuild after editing one file.
# Usage: tools/build.sh [TARGET...]   (BUILD_DIR, BUILD_TYPE and UNITY_BUILD override)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$root/build}
"$root/tools/deps.sh"
if [ ! -f "$build/build.ninja" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE="${BUILD_TYPE:-Release}" \
    -DCMAKE_UNITY_BUILD="${UNITY_BUILD:-ON}" >/dev/null
fi
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build "$build" "${targets[@]}"
