#!/bin/sh
# tests/run.sh BUILD [TEST...] - runs every test program in BUILD/tests and
# every shell test tests/*/cli_*.sh (or only the TESTs given), prints each
# one's result as it ends, and ends with the total "N passed, N failed".
# A test that skips says why on a line "skip: REASON"; its result line
# says so, and so does a list of the skipped tests before the total.  A test
# that runs no check and gives no reason fails.
#
# Tests run SILK_TEST_JOBS at a time (default: the number of CPUs, at most
# 2): each worker takes the next test nobody has claimed (a claim is an
# atomic mkdir), so a long test does not hold up the others; the tests that
# took longest last time (BUILD/tests/NAME.secs) start first, so that the
# run ends about when the longest one does.  Every test writes only its own
# log and temporary directory.
build=${1:-build}
mkdir -p "$build/tests"
work=$(mktemp -d "${TMPDIR:-/tmp}/silk-run.XXXXXX")
trap 'rm -rf "$work"' EXIT

jobs=${SILK_TEST_JOBS:-$(nproc 2>/dev/null || getconf _NPROCESSORS_ONLN 2>/dev/null || echo 1)}
case "$jobs" in ''|*[!0-9]*) jobs=1 ;; esac
[ -z "${SILK_TEST_JOBS:-}" ] && [ "$jobs" -gt 2 ] && jobs=2
[ "$jobs" -lt 1 ] && jobs=1

[ $# -gt 0 ] && shift
all=
[ $# -gt 0 ] && all=$*
[ $# -gt 0 ] || for t in "$build"/tests/test_* tests/*/cli_*.sh; do
  [ -e "$t" ] || continue
  case "$t" in *.d|*.o|*.log|*.txt|*.png|*.ppm|*.secs) continue;; esac
  [ -d "$t" ] && continue
  all="$all $t"
done
# Longest first (a test not timed yet counts as long); the report keeps
# the usual order.
list=$(for t in $all; do
  s=$(cat "$build/tests/$(basename "$t").secs" 2>/dev/null || echo 1000)
  echo "$s $t"
done | sort -k1,1nr -s | cut -d' ' -f2-)

# run_one TEST: its log, its result file ("passed failed status seconds"),
# and its line on stdout.
run_one() {
  t=$1
  name=$(basename "$t")
  log="$build/tests/$name.log"
  start=$(date +%s)
  # a failing image comparison leaves the frame and its difference here
  SILK_TEST_OUT=$build/tests/out
  export SILK_TEST_OUT
  case "$t" in
    *.sh) sh "$t" "$build" >"$log" 2>&1; rc=$? ;;
    *) "$t" >"$log" 2>&1; rc=$? ;;
  esac
  secs=$(( $(date +%s) - start ))
  echo "$secs" >"$build/tests/$name.secs"
  line=$(grep -E '^[0-9]+ passed, [0-9]+ failed' "$log" | tail -n 1)
  skip=$(grep -E '^skip: ' "$log" | head -n 1 | sed 's/^skip: //')
  if [ -z "$line" ]; then
    { echo "$name: no result line (exit $rc)"; tail -n 20 "$log"; } >"$work/$name.out"
    echo "0 1 $rc $secs" >"$work/$name.result"
  else
    p=${line%% passed*}; f=${line#*passed, }; f=${f%% failed*}
    # A non-zero exit with no failed check still counts as one failure, and
    # so does a test that checked nothing without saying why.
    [ "$rc" -ne 0 ] && [ "$f" -eq 0 ] && f=1
    [ "$p" -eq 0 ] && [ "$f" -eq 0 ] && [ -z "$skip" ] && f=1 && line="ran no check and said no reason to skip"
    {
      if [ "$p" -eq 0 ] && [ "$f" -eq 0 ]; then
        echo "$name: skipped: $skip (${secs}s)"
        echo "$skip" >"$work/$name.skip"
      else
        echo "$name: $line (${secs}s)${skip:+; skip: $skip}"
      fi
      if [ "$f" -ne 0 ] || [ "$rc" -ne 0 ]; then grep -E '^(FAIL|not ok)' "$log" | head -n 20; fi
    } >"$work/$name.out"
    echo "$p $f $rc $secs" >"$work/$name.result"
  fi
  cat "$work/$name.out"
}

worker() {
  for t in $list; do
    mkdir "$work/claim-$(basename "$t")" 2>/dev/null || continue
    run_one "$t"
  done
}

k=0
while [ "$k" -lt "$jobs" ]; do
  worker &
  k=$((k + 1))
done
wait

passed=0; failed=0; broken=""
for t in $all; do
  name=$(basename "$t")
  if [ ! -e "$work/$name.result" ]; then
    failed=$((failed + 1)); broken="$broken $name"; continue
  fi
  read -r p f rc secs <"$work/$name.result"
  passed=$((passed + p)); failed=$((failed + f))
  if [ "$f" -ne 0 ] || [ "$rc" -ne 0 ]; then broken="$broken $name"; fi
done
skipped=
for t in $all; do
  name=$(basename "$t")
  [ -e "$work/$name.skip" ] && skipped="$skipped${skipped:+; }$name ($(cat "$work/$name.skip"))"
done
[ -n "$skipped" ] && echo "skipped: $skipped"
[ -n "$broken" ] && echo "failing:$broken"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
