#!/bin/sh
# run.sh FUZZ_BUILD SECONDS [HARNESS...] - run each libFuzzer harness for
# SECONDS (all of them when none is named), one after the other, from the
# seeds (FUZZ_BUILD/seeds, see fuzz/seeds.sh) and the corpus kept from
# earlier runs (FUZZ_BUILD/corpus/NAME).  Prints one line per harness:
# executions, executions per second, coverage (libFuzzer's cov: and ft:)
# and corpus size; the full log is FUZZ_BUILD/NAME.log.  A crash, a leak, a
# timeout (an input running over 10 s) or a failed check is a finding: the
# input is saved as FUZZ_BUILD/artifacts/NAME-*, and the script exits 1
# after the other harnesses ran.  Make it a regression input in
# tests/regress/ (tests/regress/README.md) once it is fixed.
set -u
fb=$1
secs=$2
shift 2
# every harness in fuzz/ unless some are named
harnesses=${*:-$(for f in fuzz/fuzz_*.c; do basename "$f" .c; done)}
status=0
mkdir -p "$fb/artifacts"
for h in $harnesses; do
    case $h in
        fuzz_obj) dict=fuzz/obj.dict; max=12000 ;;
        fuzz_ply) dict=fuzz/ply.dict; max=12000 ;;
        fuzz_stl) dict=fuzz/stl.dict; max=12000 ;;
        *) dict=fuzz/obj.dict; max=16000 ;;
    esac
    mkdir -p "$fb/corpus/$h"
    "$fb/$h" -max_total_time="$secs" -timeout=10 -rss_limit_mb=2560 -max_len=$max -dict=$dict \
        -print_final_stats=1 -artifact_prefix="$fb/artifacts/$h-" \
        "$fb/corpus/$h" "$fb/seeds/$h" >"$fb/$h.log" 2>&1
    rc=$?
    # the last status line: "#N DONE cov: C ft: F corp: K/S ... exec/s: E ..."
    last=$(grep -E '^#[0-9]+' "$fb/$h.log" | tail -n 1)
    execs=$(grep -E '^stat::number_of_executed_units' "$fb/$h.log" | awk '{print $2}')
    rate=$(grep -E '^stat::average_exec_per_sec' "$fb/$h.log" | awk '{print $2}')
    cov=$(echo "$last" | sed -nE 's/.* cov: ([0-9]+).*/\1/p')
    ft=$(echo "$last" | sed -nE 's/.* ft: ([0-9]+).*/\1/p')
    corp=$(echo "$last" | sed -nE 's/.* corp: ([0-9]+\/[0-9]+[a-zA-Z]*).*/\1/p')
    if [ "$rc" -eq 0 ]; then
        echo "$h: ${secs}s, ${execs:-?} runs, ${rate:-?} exec/s, cov ${cov:-?}, ft ${ft:-?}, corpus ${corp:-?}"
    else
        status=1
        echo "$h: FINDING (exit $rc) after ${execs:-?} runs; cov ${cov:-?}, ft ${ft:-?}; see $fb/$h.log"
        grep -E '^(==[0-9]+==ERROR|SUMMARY|fuzz: |.*runtime error)' "$fb/$h.log" | head -n 5
        ls "$fb/artifacts/$h-"* 2>/dev/null | head -n 3
    fi
done
exit $status
