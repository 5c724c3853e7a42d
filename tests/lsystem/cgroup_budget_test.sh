#!/bin/sh
# The default memory budget sees a cgroup's memory limit, as containers and CI
# runners set it (lsystem/common/machine_memory.h): in a cgroup of 1 GiB on a
# machine with more free, an export that would pass the limit is refused by
# name, and `lsys derive --help` reports a budget under the limit. The test
# makes the cgroup itself — v2 where the unified hierarchy delegates the
# memory controller, else v1 — which needs root; elsewhere it exits 77, which
# ctest reports as skipped, saying why. Not in the sanitizer run (no "cpu"
# label): the limit is the point, and AddressSanitizer's shadow memory counts.
# Usage: cgroup_budget_test.sh LSYS DATA_DIR
set -u
LSYS=$1
DATA=$2
WORK=$(mktemp -d)
failures=0
. "$(dirname "$0")/../support/expect.sh"

limit=1073741824
group=""
if grep -qw memory /sys/fs/cgroup/cgroup.subtree_control 2>/dev/null &&
  mkdir "/sys/fs/cgroup/plantfield-budget-$$" 2>/dev/null; then
  group=/sys/fs/cgroup/plantfield-budget-$$
  echo $limit > "$group/memory.max"
elif mkdir "/sys/fs/cgroup/memory/plantfield-budget-$$" 2>/dev/null; then
  group=/sys/fs/cgroup/memory/plantfield-budget-$$
  echo $limit > "$group/memory.limit_in_bytes"
else
  echo "cgroup_budget_test: cannot make a memory cgroup here (needs root and a writable memory controller)"
  rm -rf "$WORK"
  exit 77
fi
trap 'rmdir "$group" 2>/dev/null; rm -rf "$WORK"' EXIT

# in_group COMMAND...: runs the command as a member of the cgroup.
in_group() { sh -c 'echo $$ > "$0/cgroup.procs" && exec "$@"' "$group" "$@"; }

expect_run cgroup-memory-budget 2 'memory budget: export needs 1.6 GiB, the limit is [0-9.]* MiB' -- in_group "$LSYS" export "$DATA/plants/fractal_bush.lsys" -n 6 -o "$WORK/cgroup.glb"
[ -e "$WORK/cgroup.glb" ] && fail "cgroup-memory-budget: a file was written"
expect_run cgroup-memory-budget-help 0 'the smallest; now [0-9.]* MiB' -- in_group "$LSYS" derive --help
exit $failures
