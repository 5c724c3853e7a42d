# Shell helpers of the command-line tests (tests/lsystem/cli_test.sh,
# tests/install/install_test.sh), sourced by them after they set WORK (a
# scratch folder) and failures=0.

# fail MESSAGE: counts a failure and says what it was.
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# expect_run NAME EXPECTED_EXIT PATTERN -- command...: runs, checks the exit code and that stdout+stderr match PATTERN.
expect_run() {
    name=$1 code=$2 pattern=$3
    shift 4
    "$@" > "$WORK/out" 2>&1
    actual=$?
    [ "$actual" = "$code" ] || fail "$name: exit code $actual, expected $code: $(cat "$WORK/out")"
    grep -q -- "$pattern" "$WORK/out" || fail "$name: output does not match '$pattern': $(cat "$WORK/out")"
}
