#!/usr/bin/env bash
# tests/run.sh — runs every test program (build/tests/test_*) and script (tests/test_*.sh), counts
# their "PASS"/"FAIL" lines and ends with the line "N passed, N failed". A program that exits nonzero
# without printing a FAIL line (a crash, a sanitizer report) counts as one failure.
# Environment: BUILD (build folder, default build), PATHLAB (the program, default ./pathlab),
# TEST_JOBS (how many test files run at once, default 2: much of a test file is serial — the shell,
# small renders, zcheck — so two at a time keep both cores busy; 1 runs them one after the other).
# A test file's lines are printed together when it ends, so the output is never interleaved.
set -u
cd "$(dirname "$0")/.."
BUILD=${BUILD:-build}
export PATHLAB=${PATHLAB:-./pathlab} BUILD
jobs=${TEST_JOBS:-2}
case $jobs in ''|*[!0-9]*|0) echo "tests/run.sh: TEST_JOBS must be a positive integer, got '$jobs'" >&2; exit 2 ;; esac
log=$(mktemp -d); trap 'rm -rf "$log"' EXIT
only=${1:-}

# The slowest files first, so that the last one to end is a short one (their names only order the
# list; a file missing from it runs after them).
slow="test_estimators.sh test_known.sh test_refs.sh test_passes.sh test_grade.sh test_parallel_recipe.sh"
list=()
for s in $slow; do [ -e "tests/$s" ] && list+=("tests/$s"); done
for t in "$BUILD"/tests/test_* tests/test_*.sh; do
    [ -e "$t" ] || continue
    case "$t" in *.d) continue ;; esac   # the compiler's dependency files
    case " $slow " in *" $(basename "$t") "*) continue ;; esac
    list+=("$t")
done

run_one() {   # FILE: runs it, leaves its output, exit status and milliseconds in $log
    local t=$1 name start rc
    name=$(basename "$t")
    start=$(date +%s%N)
    case "$t" in
        *.sh) bash "$t" > "$log/$name.out" 2>&1 ;;
        *) "$t" > "$log/$name.out" 2>&1 ;;
    esac
    rc=$?
    echo "$rc $(( ($(date +%s%N) - start) / 1000000 ))" > "$log/$name.end"
}

passed=0; failed=0
report() {   # NAME: prints the file's FAIL lines and its count line, adds to the totals
    local name=$1 rc ms p f
    read -r rc ms < "$log/$name.end"
    p=$(grep -c '^PASS ' "$log/$name.out"); f=$(grep -c '^FAIL ' "$log/$name.out")
    if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
        echo "FAIL $name: exited with status $rc without a FAIL line; its last lines:"
        tail -n 15 "$log/$name.out" | sed 's/^/    /'
        f=1
    fi
    grep '^FAIL ' "$log/$name.out" | sed "s/^/  [$name] /"
    printf '%-28s %3d passed, %d failed  (%d.%02ds)\n' "$name" "$p" "$f" $((ms / 1000)) $((ms % 1000 / 10))
    passed=$((passed + p)); failed=$((failed + f))
    rm -f "$log/$name.end"
}
report_ended() {   # reports the files that have ended since the last call
    local e
    for e in "$log"/*.end; do [ -e "$e" ] && report "$(basename "$e" .end)"; done
}

running=0
for t in "${list[@]}"; do
    name=$(basename "$t")
    [ -n "$only" ] && [[ "$name" != *"$only"* ]] && continue
    if [ "$running" -ge "$jobs" ]; then wait -n; running=$((running - 1)); report_ended; fi
    run_one "$t" &
    running=$((running + 1))
done
wait
report_ended
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
