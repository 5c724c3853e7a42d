#!/usr/bin/env bash
# Builds the test suites that need no Vulkan device (the L-system library,
# dialects, turtle, instancing, export, scenes, the physics model, the fuzz
# corpora) with AddressSanitizer and UndefinedBehaviorSanitizer (gcc,
# -DPLANTFIELD_SANITIZE=ON, in build-sanitize/) and runs them: the target
# cpu_tests and ctest's label "cpu" (tests/CMakeLists.txt). An out-of-bounds
# access, a use after free, a leak or undefined behaviour stops the test that
# meets it. Extra arguments go to ctest.
# It compiles at -O1 with line tables only (-g1): instrumented code at -O2 -g
# took gcc 2.7 times as long to build, and the reports need no more than
# file:line in their stack traces. A unity build, as tools/build.sh's.
# Usage: tools/sanitize.sh [CTEST ARGS...]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${SANITIZE_BUILD_DIR:-$root/build-sanitize}
"$root/tools/deps.sh"
if [ ! -f "$build/build.ninja" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPLANTFIELD_SANITIZE=ON -DCMAKE_UNITY_BUILD=ON \
    "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" >/dev/null
fi
cmake --build "$build" --target cpu_tests
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir "$build" -L cpu --output-on-failure -j "$(nproc)" --timeout 900 "$@"
