#!/usr/bin/env bash
# Installs, builds everything and runs every test with ctest; exits non-zero
# on any failure. Extra arguments go to ctest, e.g. tools/test.sh -R Golden
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$root/build}
"$root/tools/build.sh"
ctest --test-dir "$build" --output-on-failure -j "$(nproc)" --timeout 600 "$@"
