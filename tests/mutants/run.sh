#!/usr/bin/env bash
# tests/mutants/run.sh — mutation testing (`make mutants`): the tests must FAIL on broken code.
#
# Each mutant of tests/mutants/list.sh is one classic bug, a patch (tests/mutants/NAME.patch)
# applied to a copy of the working tree in a temporary folder (src/ itself is never touched). The
# copy is built, then ONE test (a tests/run.sh filter) runs on it and must print at least one FAIL
# line: the mutant is then "caught". First, every patch must apply cleanly to the unbroken copy
# (patch --dry-run, no fuzz) and agree with list.sh; then each test used runs once on the unbroken
# copy (the control) and must pass, so that a FAIL is the mutation's doing. Prints a table (mutant,
# bug, test, caught, seconds) and the first FAIL line of each mutant; exits 1 if a patch does not
# apply (a FAIL line names it and says how to remake it: tests/mutants/remake.sh NAME), a control
# fails, or a mutant survives. The copy starts from the tree's build/ when there is one (make
# rebuilds only what changed), so `make mutants` right after `make` or `make test` builds little.
#
# Usage: tests/mutants/run.sh [NAME...]     (only the named mutants)
# Environment: MUTANTS_KEEP=DIR keeps the copies and logs in DIR; MUTANTS_TIMEOUT (s, default 300);
# MUTANTS_CONTROLS_DONE=1 (.ci/run, right after a passing make test of the same tree) skips the
# controls of the tests that run with no environment: make test has just run them, the same files on
# the same code (the controls of PATHLAB_FAST=1 or PATHLAB_TEST_QUICK=1 runs still run).
set -u
. "$(dirname "$0")/lib.sh"
TIMEOUT=${MUTANTS_TIMEOUT:-300}
if [ -n "${MUTANTS_KEEP:-}" ]; then W=$MUTANTS_KEEP; rm -rf "$W"; mkdir -p "$W"
else W=$(mktemp -d); trap 'rm -rf "$W"' EXIT; fi

sel=()
if [ $# -gt 0 ]; then
    for n in "$@"; do i=$(mutant_index "$n") || { echo "no mutant named $n (see tests/mutants/list.sh)" >&2; exit 2; }; sel+=("$i"); done
else
    for ((i = 0; i < MUT_N; i++)); do sel+=("$i"); done
fi
bad=0
problems=$(list_problems)
if [ -n "$problems" ]; then
    echo "$problems" | sed 's/^/FAIL /'
    bad=1
fi

now() { date +%s%N; }
secs() { local ms=$((($2 - $1) / 1000000)); printf '%d.%d' $((ms / 1000)) $((ms % 1000 / 100)); }
# run_test DIR TEST ENV LOG: tests/run.sh TEST in DIR; prints the number of failures it reports
run_test() {
    local dir=$1 t=$2 env=$3 log=$4 f
    [ "$env" = - ] && env=
    # shellcheck disable=SC2086
    (cd "$dir" && env BUILD=build PATHLAB=./pathlab $env timeout "$TIMEOUT" nice -n 10 tests/run.sh "$t") > "$log" 2>&1
    f=$(sed -n 's/^[0-9]* passed, \([0-9]*\) failed$/\1/p' "$log" | tail -n 1)
    if [ -z "$f" ]; then echo timeout; else echo "$f"; fi
}

start_all=$(now)
echo "copying the working tree of $ROOT and building it (the base of every mutant)"
t0=$(now)
targets="pathlab build/tests/zcheck build/tests/pfmtool"
tests=()
for i in "${sel[@]}"; do
    key="${M_TEST[i]} ${M_ENV[i]}"
    [[ " ${tests[*]/%/|} " == *" $key|"* ]] || tests+=("$key")
    targets="$targets $(test_targets "${M_TEST[i]}")"
done
copy_tree "$W/base" || { echo "FAIL: could not copy the tree"; exit 1; }
# every patch must apply before anything runs: a stale one is a FAIL that names it, never a skip
stale=0; declare -A is_stale=()
for i in "${sel[@]}"; do
    n=${M_NAME[i]}
    if ! why=$(patch_applies "$n" "$W/base"); then
        echo "FAIL mutant $n: tests/mutants/$n.patch does not apply cleanly to $(patch_src "$n" | tr '\n' ' ')"
        echo "$why"; stale_hint "$n"; is_stale[$n]=1; stale=$((stale + 1))
    fi
done
echo "patches: $((${#sel[@]} - stale)) of ${#sel[@]} apply cleanly"
# shellcheck disable=SC2086
build_in "$W/base" $(echo "$targets" | tr ' ' '\n' | sort -u) || { echo "FAIL: the unbroken copy does not build"; exit 1; }
echo "built in $(secs "$t0" "$(now)") s"

echo "controls: each test on the unbroken copy must pass"
for key in "${tests[@]}"; do
    t=${key% *}; env=${key#* }
    if [ "${MUTANTS_CONTROLS_DONE:-0}" = 1 ] && [ "$env" = - ]; then
        echo "  done  $t: make test ran it on this tree just before and it passed (MUTANTS_CONTROLS_DONE=1)"; continue
    fi
    t0=$(now)
    f=$(run_test "$W/base" "$t" "$env" "$W/control_$t.log")
    if [ "$f" = 0 ]; then echo "  pass  $t ($env) $(secs "$t0" "$(now)") s"
    else echo "  FAIL  $t ($env): $f failures on the unbroken code, see below"; grep -m 5 'FAIL' "$W/control_$t.log" | cut -c1-200; bad=1; fi
done

rows=(); evidence=(); survived=0
for i in "${sel[@]}"; do
    n=${M_NAME[i]}; d="$W/m_$n"; log="$W/$n.log"
    t0=$(now)
    if [ -n "${is_stale[$n]:-}" ] || ! apply_mutant "$i" "$W/base" "$d"; then
        rows+=("$(printf '%-19s %-80s %-14s %-13s %6s' "$n" "${M_WHAT[i]}" "${M_TEST[i]}" "DOES NOT APPLY" -)")
        survived=$((survived + 1)); continue
    fi
    # shellcheck disable=SC2046
    if ! build_in "$d" $(test_targets "${M_TEST[i]}") 2> "$log"; then
        rows+=("$(printf '%-19s %-80s %-14s %-13s %6s' "$n" "${M_WHAT[i]}" "${M_TEST[i]}" "NO BUILD" -)")
        survived=$((survived + 1)); continue
    fi
    t1=$(now)
    f=$(run_test "$d" "${M_TEST[i]}" "${M_ENV[i]}" "$log")
    t2=$(now)
    case $f in
        0) caught=NO; survived=$((survived + 1)) ;;
        timeout) caught="yes (timeout)" ;;
        *) caught="yes ($f FAIL)" ;;
    esac
    rows+=("$(printf '%-19s %-80s %-14s %-13s %6s' "$n" "${M_WHAT[i]}" "${M_TEST[i]}" "$caught" "$(secs "$t1" "$t2")")")
    evidence+=("$n: $(grep -m 1 'FAIL' "$log" | sed 's/^ *//' | cut -c1-220)")
    echo "  $n: $caught (build $(secs "$t0" "$t1") s, test $(secs "$t1" "$t2") s)"
    [ -n "${MUTANTS_KEEP:-}" ] || rm -rf "$d"
done

echo
printf '%-19s %-80s %-14s %-13s %6s\n' mutant "what it breaks" test caught "test s"
for r in "${rows[@]}"; do echo "$r"; done
echo
echo "first FAIL line of each mutant:"
for e in "${evidence[@]}"; do echo "  $e"; done
echo
echo "${#sel[@]} mutants, $((${#sel[@]} - survived)) caught, $survived not caught ($stale of them do not apply); $(secs "$start_all" "$(now)") s in all"
[ "$stale" -eq 0 ] || echo "remake a patch that does not apply: tests/mutants/remake.sh NAME (it says what to do)"
[ "$bad" -eq 0 ] && [ "$survived" -eq 0 ]
