#!/usr/bin/env bash
# Builds the test suites that need no Vulkan device (the L-system library,
# dialects, turtle, instancing, export, scenes, the physics model, the fuzz
# corpora) with AddressSanitizer and UndefinedBehaviorSanitizer (gcc,
# -DPLANTFIELD_SANITIZE=ON, in build-sanitize/) and runs them: ctest's label
# "cpu". An out-of-bounds access, a use after free, a leak or undefined
# behaviour stops the test that meets it. Extra arguments go to ctest.
# Usage: tools/sanitize.sh [CTEST ARGS...]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${SANITIZE_BUILD_DIR:-$root/build-sanitize}
"$root/tools/deps.sh"
if [ ! -f "$build/build.ninja" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPLANTFIELD_SANITIZE=ON >/dev/null
fi
cmake --build "$build" --target lsys lsystem_tests dialect_tests turtle_tests instancing_tests export_tests \
  instance_graph_tests scene_tests physics_tests support_tests plantbench_memory_tests fuzz_corpus_tests
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir "$build" -L cpu --output-on-failure -j "$(nproc)" --timeout 900 "$@"
