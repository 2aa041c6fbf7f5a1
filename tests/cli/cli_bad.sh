#!/bin/sh
# cli_bad.sh BUILD - every malformed file in tests/bad/ through the command:
# `silk info FILE` and `silk render FILE -o OUT.png` must exit non-zero,
# print exactly the line in FILE.expected on stderr (and nothing on stdout),
# and leave no output file behind.  Run from the repository root (tests/run.sh
# does); prints "N passed, N failed" last.
build=${1:-build}
silk="$build/silk"
passed=0
failed=0

if [ ! -x "$silk" ]; then
  echo "cli_bad: $silk not built"
  echo "0 passed, 1 failed"
  exit 1
fi

tmp=$(mktemp -d "${TMPDIR:-/tmp}/silk-cli-bad.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT INT TERM
mkdir "$tmp/out"

check() {   # check NAME WHAT STATUS
  name=$1; what=$2; status=$3
  problem=""
  [ "$status" -ne 0 ] || problem="exit status 0"
  if ! cmp -s "$tmp/err" "$expected"; then
    problem="${problem:+$problem; }stderr is \"$(head -c 300 "$tmp/err")\", want \"$(cat "$expected")\""
  fi
  [ -s "$tmp/stdout" ] && problem="${problem:+$problem; }output on stdout"
  if [ -n "$(ls -A "$tmp/out")" ]; then
    problem="${problem:+$problem; }left $(ls -A "$tmp/out" | tr '\n' ' ')"
    rm -f "$tmp/out"/* "$tmp/out"/.[!.]* 2>/dev/null
  fi
  if [ -z "$problem" ]; then
    passed=$((passed + 1))
    echo "ok $what $name"
  else
    failed=$((failed + 1))
    echo "FAIL $what $name: $problem"
  fi
}

count=0
for expected in tests/bad/*.expected; do
  [ -e "$expected" ] || continue
  file=${expected%.expected}
  name=${file#tests/bad/}
  count=$((count + 1))

  "$silk" info "$file" >"$tmp/stdout" 2>"$tmp/err"
  check "$name" info $?

  "$silk" render "$file" -o "$tmp/out/out.png" >"$tmp/stdout" 2>"$tmp/err"
  check "$name" render $?
done

if [ "$count" -lt 40 ]; then
  echo "FAIL only $count files in tests/bad"
  failed=$((failed + 1))
fi
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
