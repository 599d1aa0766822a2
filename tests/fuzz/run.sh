#!/usr/bin/env bash
# tests/fuzz/run.sh BUILD TARGET... — `make fuzz`'s runner: each harness BUILD/fuzz/fuzz_TARGET runs
# FUZZ_SECONDS (default 60), FUZZ_JOBS of them at once (default: the number of cores), from a copy
# of its seeds (tests/fuzz/corpus/TARGET/, unchanged) in BUILD/fuzz-work/TARGET/corpus. Every target runs, even after a failure; the exit status is 1 if any
# found a crash, a leak, a timeout (-timeout, seconds per input) or an out-of-memory (-rss_limit_mb),
# with the reproducer's path and the command that replays it. FUZZ_ARGS: more libFuzzer flags.
set -u
cd "$(dirname "$0")/../.."
build=${1:?usage: tests/fuzz/run.sh BUILD TARGET...}; shift
secs=${FUZZ_SECONDS:-60}
case $secs in ''|*[!0-9]*|0) echo "tests/fuzz/run.sh: FUZZ_SECONDS must be a positive integer, got '$secs'" >&2; exit 2 ;; esac
max_len() {   # the largest input each target gets: a few times its largest seed
    case $1 in scene) echo 16384 ;; pfm) echo 8192 ;; *) echo 4096 ;; esac
}
# fuzz_one TARGET: runs one harness; its verdict line in $work/verdict (PASS ... or FAIL ...)
fuzz_one() {
    local t=$1 bin=$build/fuzz/fuzz_$1 work=$build/fuzz-work/$1 rc execs rate cov repro
    rm -rf "$work/corpus" "$work/tmp" "$work/verdict"
    mkdir -p "$work/corpus" "$work/findings" "$work/tmp"
    cp tests/fuzz/corpus/"$t"/* "$work/corpus/" 2>/dev/null
    echo "== fuzz $t: $secs s from $(ls "$work/corpus" | wc -l) seeds (log: $work/log)"
    # -close_fd_mask=3: the readers' error messages would slow it down and bury libFuzzer's own
    # lines (libFuzzer keeps a copy of stderr for its reports and the sanitizers').
    # shellcheck disable=SC2086
    TMPDIR=$work/tmp "$bin" -max_total_time="$secs" -max_len="$(max_len "$t")" -timeout=10 -rss_limit_mb=2048 \
        -malloc_limit_mb=1024 -close_fd_mask=3 -print_final_stats=1 -artifact_prefix="$work/findings/" \
        ${FUZZ_ARGS:-} "$work/corpus" >"$work/log" 2>&1
    rc=$?
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/log" | tail -n 1)
    rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$work/log" | tail -n 1)
    cov=$(grep -o 'cov: [0-9]*' "$work/log" | tail -n 1)
    if [ "$rc" = 0 ]; then
        echo "PASS fuzz $t: ${execs:-?} execs in $secs s (${rate:-?}/s), $cov, no crash, leak, timeout or OOM" > "$work/verdict"
    else
        repro=$(sed -n 's/.*Test unit written to \(.*\)/\1/p' "$work/log" | tail -n 1)
        grep -E '^==[0-9]+==ERROR|runtime error|ALARM|out-of-memory|SUMMARY' "$work/log" | head -n 5
        echo "FAIL fuzz $t (exit $rc, after ${execs:-?} execs): reproducer ${repro:-none written}; replay: $bin ${repro:-FILE}; log $work/log" > "$work/verdict"
    fi
    rm -rf "$work/tmp"
}
# FUZZ_JOBS harnesses at once (default: one per core; each is one process on one core)
jobs_max=${FUZZ_JOBS:-$(nproc 2>/dev/null || echo 2)}
case $jobs_max in ''|*[!0-9]*|0) echo "tests/fuzz/run.sh: FUZZ_JOBS must be a positive integer, got '$jobs_max'" >&2; exit 2 ;; esac
for t in "$@"; do
    [ -x "$build/fuzz/fuzz_$t" ] || { echo "tests/fuzz/run.sh: $build/fuzz/fuzz_$t is missing (make fuzz builds it)" >&2; exit 2; }
done
for t in "$@"; do
    while [ "$(jobs -rp | wc -l)" -ge "$jobs_max" ]; do wait -n; done
    fuzz_one "$t" &
done
wait
failed=()
for t in "$@"; do
    v=$(cat "$build/fuzz-work/$t/verdict" 2>/dev/null) || v="FAIL fuzz $t: no verdict (the runner itself failed)"
    echo "$v"
    case $v in PASS*) ;; *) failed+=("$t") ;; esac
done
[ ${#failed[@]} = 0 ] || { echo "make fuzz: ${#failed[@]} target(s) failed: ${failed[*]}"; exit 1; }
