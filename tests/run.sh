#!/bin/sh
# Runs every test program in BUILD/tests (and the shell tests in tests/*.sh),
# prints each one's result, and ends with the total "N passed, N failed".
build=${1:-build}
passed=0; failed=0; broken=""
for t in "$build"/tests/test_* tests/cli_*.sh; do
  [ -e "$t" ] || continue
  case "$t" in *.d|*.o|*.log|*.txt|*.png|*.ppm) continue;; esac
  [ -d "$t" ] && continue
  name=$(basename "$t")
  log="$build/tests/$name.log"
  mkdir -p "$build/tests"
  start=$(date +%s)
  case "$t" in
    *.sh) sh "$t" "$build" >"$log" 2>&1; rc=$? ;;
    *) "$t" >"$log" 2>&1; rc=$? ;;
  esac
  secs=$(( $(date +%s) - start ))
  line=$(grep -E '^[0-9]+ passed, [0-9]+ failed' "$log" | tail -n 1)
  if [ -z "$line" ]; then
    echo "$name: no result line (exit $rc)"; tail -n 20 "$log"
    failed=$((failed + 1)); broken="$broken $name"; continue
  fi
  p=${line%% passed*}; f=${line#*passed, }; f=${f%% failed*}
  passed=$((passed + p)); failed=$((failed + f))
  if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then failed=$((failed + 1)); broken="$broken $name"; fi
  echo "$name: $line (${secs}s)"
  if [ "$f" -ne 0 ] || [ "$rc" -ne 0 ]; then grep -E '^(FAIL|not ok)' "$log" | head -n 20; broken="$broken $name"; fi
done
[ -n "$broken" ] && echo "failing:$broken"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
