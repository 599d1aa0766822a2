#!/usr/bin/env bash
# tests/run.sh — runs every test program (build/tests/test_*) and script (tests/test_*.sh), counts
# their "PASS"/"FAIL" lines and ends with the line "N passed, N failed". A program that exits nonzero
# without printing a FAIL line (a crash, a sanitizer report) counts as one failure.
# Environment: BUILD (build folder, default build), PATHLAB (the program, default ./pathlab).
set -u
cd "$(dirname "$0")/.."
BUILD=${BUILD:-build}
export PATHLAB=${PATHLAB:-./pathlab} BUILD
passed=0; failed=0
log=$(mktemp -d); trap 'rm -rf "$log"' EXIT
only=${1:-}
for t in "$BUILD"/tests/test_* tests/test_*.sh; do
    [ -e "$t" ] || continue
    case "$t" in *.d) continue ;; esac   # the compiler's dependency files
    name=$(basename "$t")
    [ -n "$only" ] && [[ "$name" != *"$only"* ]] && continue
    start=$(date +%s%N)
    case "$t" in
        *.sh) bash "$t" > "$log/out" 2>&1 ;;
        *) "$t" > "$log/out" 2>&1 ;;
    esac
    rc=$?
    ms=$(( ($(date +%s%N) - start) / 1000000 ))
    p=$(grep -c '^PASS ' "$log/out"); f=$(grep -c '^FAIL ' "$log/out")
    if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
        echo "FAIL $name: exited with status $rc without a FAIL line; its last lines:"
        tail -n 15 "$log/out" | sed 's/^/    /'
        f=1
    fi
    grep '^FAIL ' "$log/out" | sed "s/^/  [$name] /"
    printf '%-28s %3d passed, %d failed  (%d.%02ds)\n' "$name" "$p" "$f" $((ms / 1000)) $((ms % 1000 / 10))
    passed=$((passed + p)); failed=$((failed + f))
done
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
