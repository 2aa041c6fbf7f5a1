#!/bin/sh
# cli_runner.sh - tests/run.sh itself: on tests made up here, it says which
# passed and failed, shows a skipped test as skipped with its reason (also in
# the list before the total), counts a test that checked nothing and gave no
# reason as failed, and ends with "N passed, N failed".
. "$(dirname "$0")/../shlib.sh"

mkdir -p "$tmp/t" "$tmp/build"
printf 'echo "ok one"\necho "ok two"\necho "2 passed, 0 failed"\n' >"$tmp/t/cli_good.sh"
printf 'echo "skip: the frobnicator is not installed"\necho "0 passed, 0 failed"\n' >"$tmp/t/cli_skips.sh"
printf 'echo "0 passed, 0 failed"\n' >"$tmp/t/cli_silent.sh"
printf 'echo "FAIL three: it broke"\necho "0 passed, 1 failed"\nexit 1\n' >"$tmp/t/cli_bad.sh"
(cd "$here/.." && sh tests/run.sh "$tmp/build" "$tmp/t/cli_good.sh" "$tmp/t/cli_skips.sh" "$tmp/t/cli_silent.sh" \
    "$tmp/t/cli_bad.sh") >"$out" 2>"$err"
rc=$?
check "a failing test fails the run (exit $rc)" test "$rc" -ne 0
check "a passing test's line" grep -qx 'cli_good.sh: 2 passed, 0 failed ([0-9]*s)' "$out"
check "a skipped test says it was skipped and why" \
    grep -qx 'cli_skips.sh: skipped: the frobnicator is not installed ([0-9]*s)' "$out"
check "the skipped tests are listed before the total" \
    grep -qx 'skipped: cli_skips.sh (the frobnicator is not installed)' "$out"
check "a test that checked nothing without a reason fails" grep -q '^cli_silent.sh: ran no check' "$out"
check "a failure's line shows its FAIL lines" grep -qx 'FAIL three: it broke' "$out"
check "the failing tests are named" grep -qx 'failing: cli_silent.sh cli_bad.sh' "$out"
check "the last line is the total" test "$(tail -n 1 "$out")" = "2 passed, 2 failed"

done_testing
