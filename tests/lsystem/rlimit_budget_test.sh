#!/bin/sh
# The default memory budget sees the process's resource limits, not only the
# machine's available memory (lsystem/common/machine_memory.h): under a 1 GiB
# address space an export that would pass it is refused by name instead of
# failing as std::bad_alloc. Not in the sanitizer run (no "cpu" label):
# AddressSanitizer reserves terabytes of shadow address space at start, which
# no address-space limit admits.
# Usage: rlimit_budget_test.sh LSYS DATA_DIR
set -u
LSYS=$1
DATA=$2
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
failures=0
. "$(dirname "$0")/../support/expect.sh"

expect_run rlimit-memory-budget 2 'memory budget: export needs 1.6 GiB, the limit is [0-9.]* MiB' -- prlimit --as=1073741824 "$LSYS" export "$DATA/plants/fractal_bush.lsys" -n 6 -o "$WORK/rlimit.glb"
[ -e "$WORK/rlimit.glb" ] && fail "rlimit-memory-budget: a file was written"
expect_run rlimit-memory-budget-help 0 'the smallest; now [0-9.]* MiB' -- prlimit --as=1073741824 "$LSYS" derive --help
exit $failures
