#!/usr/bin/env bash
# tests/run.sh — runs every test program (build/tests/test_*) and script (tests/test_*.sh), counts
# their "PASS"/"FAIL" lines and ends with the failed checks again (a CI page may show only the tail)
# and the line "N passed, N failed". A program that exits nonzero
# without printing a FAIL line (a crash, a sanitizer report) counts as one failure.
# Environment: BUILD (build folder, default build), PATHLAB (the program, default ./pathlab),
# TEST_JOBS (how many test files run at once, default 2: much of a test file is serial — the shell,
# small renders, zcheck — so two at a time keep both cores busy; 1 runs them one after the other).
# A test file's lines are printed together when it ends, so the output is never interleaved; a
# file still running after 30 s gets a line "still running: NAME (1m30s, 12 passed, 0 failed so
# far)" every 30 s (its PASS/FAIL lines counted as they come), so a long file on a loaded machine
# is never minutes of silence, and its lines stay together at its end. "SKIP" lines (a check that
# cannot run here, e.g. without OpenImageIO) are counted apart; the last line stays "N passed, N failed".
# TEST_SOURCE_ONLY=skip (make test SAN=...): the files that read the sources or compile their own
# build and never run the one under test (test_layout, test_exports, test_bvh_native) are left out,
# with a line saying so: a sanitizer build cannot change what they find, the default build's
# make test runs them. TEST_EXCLUDE="test_a.sh test_b.sh": those files are left out too (with a line
# naming them; .ci/run uses it for gcc's sanitizer run, see there).
set -u
cd "$(dirname "$0")/.."
BUILD=${BUILD:-build}
export PATHLAB=${PATHLAB:-./pathlab} BUILD
jobs=${TEST_JOBS:-2}
case $jobs in ''|*[!0-9]*|0) echo "tests/run.sh: TEST_JOBS must be a positive integer, got '$jobs'" >&2; exit 2 ;; esac
log=$(mktemp -d)
hb=
trap '[ -n "$hb" ] && kill "$hb" 2> /dev/null; rm -rf "$log"' EXIT
only=${1:-}

# The slowest files first, so that the last one to end is a short one (their names only order the
# list; a file missing from it runs after them). Measured order, slowest first (make test from a fresh
# clone at 7f53e82, seconds on a loaded machine): test_refs 313, test_rr 301, test_sobol 240,
# test_grade_mistakes 240, test_estimators 200, test_known 180, test_grade 94, test_direct 90 (a C
# program), test_bvh 61, test_parallel_recipe 44, test_layout 39; test_rr and test_grade_mistakes used
# to start among the last and end minutes after the others.
slow="test_refs.sh test_rr.sh test_sobol.sh test_grade_mistakes.sh test_estimators.sh test_known.sh test_grade.sh
      test_direct test_bvh test_parallel_recipe.sh test_layout.sh"
# EST_ALL=1 (.ci/run): test_estimators runs all 48 combinations (minutes more), the longest file
[ "${EST_ALL:-0}" = 1 ] && slow="test_estimators.sh $(echo " $slow " | sed 's/ test_estimators\.sh / /')"
list=()
for s in $slow; do
    case $s in *.sh) t=tests/$s ;; *) t=$BUILD/tests/$s ;; esac
    [ -e "$t" ] && list+=("$t")
done
for t in "$BUILD"/tests/test_* tests/test_*.sh; do
    [ -e "$t" ] || continue
    case "$t" in *.d) continue ;; esac   # the compiler's dependency files
    case " $(echo $slow) " in *" $(basename "$t") "*) continue ;; esac
    list+=("$t")
done
source_only="test_layout.sh test_exports.sh test_bvh_native.sh"
if [ "${TEST_SOURCE_ONLY:-run}" = skip ]; then
    kept=()
    for t in "${list[@]}"; do case " $source_only " in *" $(basename "$t") "*) ;; *) kept+=("$t") ;; esac; done
    list=("${kept[@]}")
    echo "not run on this build (they read the sources or build their own, as in the default build's make test): $source_only"
fi
if [ -n "${TEST_EXCLUDE:-}" ]; then
    kept=()
    for t in "${list[@]}"; do case " $TEST_EXCLUDE " in *" $(basename "$t") "*) ;; *) kept+=("$t") ;; esac; done
    list=("${kept[@]}")
    echo "left out (TEST_EXCLUDE): $TEST_EXCLUDE"
fi

run_one() {   # FILE: runs it, leaves its output, exit status and milliseconds in $log
    local t=$1 name start rc
    name=$(basename "$t")
    start=$(date +%s%N)
    echo $((start / 1000000000)) > "$log/$name.run"
    case "$t" in
        *.sh) bash "$t" > "$log/$name.out" 2>&1 ;;
        *) "$t" > "$log/$name.out" 2>&1 ;;
    esac
    rc=$?
    rm -f "$log/$name.run"   # first: the heartbeat must not speak of a file that has ended
    echo "$rc $(( ($(date +%s%N) - start) / 1000000 ))" > "$log/$name.end"
}

heartbeat() {   # every 30 s, a line for each file still running (in the background until the end)
    local r name el s
    trap '[ -n "${s:-}" ] && kill "$s" 2> /dev/null; exit 0' TERM
    while :; do
        sleep 30 & s=$!; wait "$s"
        for r in "$log"/*.run; do
            [ -e "$r" ] || continue
            name=$(basename "$r" .run)
            el=$(( $(date +%s) - $(cat "$r" 2> /dev/null || date +%s) ))
            [ "$el" -ge 30 ] && [ -e "$r" ] || continue
            printf 'still running: %s (%dm%02ds, %d passed, %d failed so far)\n' "$name" $((el / 60)) $((el % 60)) \
                "$(grep -c '^PASS ' "$log/$name.out" 2> /dev/null)" "$(grep -c '^FAIL ' "$log/$name.out" 2> /dev/null)"
        done
    done
}

passed=0; failed=0; skipped=0
report() {   # NAME: prints the file's FAIL lines and its count line, adds to the totals
    local name=$1 rc ms p f k
    read -r rc ms < "$log/$name.end"
    p=$(grep -c '^PASS ' "$log/$name.out"); f=$(grep -c '^FAIL ' "$log/$name.out"); k=$(grep -c '^SKIP ' "$log/$name.out")
    if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
        sig=; [ "$rc" -gt 128 ] && sig=$(kill -l $((rc - 128)) 2> /dev/null) && sig=" (SIG${sig#SIG}: killed by a signal)"
        echo "FAIL $name: exited with status $rc$sig without a FAIL line; its last lines:"
        tail -n 15 "$log/$name.out" | sed 's/^/    /'
        f=1
    fi
    grep -E '^(FAIL|SKIP) ' "$log/$name.out" | sed "s/^/  [$name] /"
    [ "$f" -gt 0 ] && { grep -E '^FAIL ' "$log/$name.out" || echo "FAIL exited with status $rc"; } |
        head -n 5 | cut -c 1-300 | sed "s/^/  [$name] /" >> "$log/failures"
    printf '%-28s %3d passed, %d failed%s  (%d.%02ds)\n' "$name" "$p" "$f" "$([ "$k" -gt 0 ] && echo ", $k skipped")" \
        $((ms / 1000)) $((ms % 1000 / 10))
    passed=$((passed + p)); failed=$((failed + f)); skipped=$((skipped + k))
    rm -f "$log/$name.end"
}
report_ended() {   # reports the files that have ended since the last call
    local e
    for e in "$log"/*.end; do [ -e "$e" ] && report "$(basename "$e" .end)"; done
}

heartbeat & hb=$!
running=0; pids=()
for t in "${list[@]}"; do
    name=$(basename "$t")
    [ -n "$only" ] && [[ "$name" != *"$only"* ]] && continue
    if [ "$running" -ge "$jobs" ]; then wait -n; running=$((running - 1)); report_ended; fi
    run_one "$t" &
    pids+=($!)
    running=$((running + 1))
done
[ ${#pids[@]} -gt 0 ] && wait "${pids[@]}"
kill "$hb" 2> /dev/null; wait "$hb" 2> /dev/null; hb=
report_ended
[ "$skipped" -gt 0 ] && echo "$skipped checks skipped (a tool missing: see the SKIP lines above)"
# A whole run of the default build has at least the checks the README says (scripts/readme-figures.sh
# wrote them): fewer means a test lost checks, or the README is out of date (rerun that script).
if [ -z "$only" ] && [ -z "${TEST_EXCLUDE:-}" ] && [ "${TEST_SOURCE_ONLY:-run}" = run ] && [ -z "${PATHLAB_FAST:-}" ]; then
    mark="<!-- scripts/readme-figures.sh make test -->"
    [ "${EST_ALL:-0}" = 1 ] && mark="<!-- scripts/readme-figures.sh make test EST_ALL=1 -->"
    said=$(grep -F -- "$mark" README.md | sed -n 's/.*\*\*, \([0-9]*\) checks.*/\1/p' | head -n 1)
    total=$((passed + failed + skipped))
    if [ -n "$said" ] && [ "$total" -lt "$said" ]; then
        echo "FAIL README.md says $said checks, this run had $total: a test lost checks, or rerun scripts/readme-figures.sh"
        failed=$((failed + 1))
    fi
fi
# The failures again, last: a CI page that shows only the log's tail still names them.
if [ -s "$log/failures" ]; then echo "the failed checks (at most 5 a file):"; cat "$log/failures"; fi
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
