#!/usr/bin/env bash
# Fuzzes the .lsys parser, rewriter and turtle with libFuzzer (clang, with
# address and undefined-behaviour sanitizers) for SECONDS (default 120).
# It works on a scratch corpus in build-fuzz/ seeded from tests/fuzz/corpus/
# and data/plants/, then merges what adds coverage back into
# tests/fuzz/corpus/, which the regular test suite replays. A crash leaves
# build-fuzz/crash-*: fix it, then add the input to tests/fuzz/crashers/.
# Usage: tools/fuzz.sh [SECONDS]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
seconds=${1:-120}
build=$root/build-fuzz
"$root/tools/deps.sh" fuzz
if [ ! -f "$build/build.ninja" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DPLANTFIELD_FUZZ=ON >/dev/null
fi
cmake --build "$build" --target lsys_fuzzer
fuzzer=$build/tests/fuzz/lsys_fuzzer
mkdir -p "$build/run-corpus"
cd "$build"
"$fuzzer" -max_total_time="$seconds" -max_len=4096 -timeout=10 -rss_limit_mb=4096 \
  -dict="$root/tests/fuzz/lsys.dict" "$build/run-corpus" "$root/tests/fuzz/corpus" "$root/data/plants"
# Keep only inputs that add coverage to what the repository already holds.
"$fuzzer" -merge=1 "$root/tests/fuzz/corpus" "$build/run-corpus" 2>/dev/null
echo "fuzz.sh: corpus now has $(ls "$root/tests/fuzz/corpus" | wc -l) inputs"
