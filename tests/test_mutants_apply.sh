#!/usr/bin/env bash
# Every mutant of tests/mutants/list.sh still applies cleanly to src/ (no fuzz) and agrees with its
# patch's header. make mutants (run by .ci/run) plants them and needs minutes; this check takes a
# second, so that a change to the code a patch edits is caught by make test, not after CI's first
# 20 minutes. A stale patch: tests/mutants/remake.sh NAME says how to remake it.
. "$(dirname "$0")/lib.sh"
. "$(dirname "$0")/mutants/lib.sh"
command -v patch > /dev/null || { skip "the mutants' patches apply (needs patch(1))"; exit 0; }
problems=$(list_problems)
if [ -z "$problems" ]; then pass "tests/mutants/list.sh and the $MUT_N patches agree (names, Test:, Env:)"
else fail "tests/mutants/list.sh and the patches disagree: $(echo "$problems" | paste -sd ';' -)"; fi
for ((i = 0; i < MUT_N; i++)); do
    n=${M_NAME[i]}
    [ -f "$(patch_file "$n")" ] || continue
    if why=$(patch_applies "$n" "$ROOT"); then pass "mutant $n applies cleanly to $(patch_src "$n" | paste -sd ' ' -)"
    else fail "mutant $n no longer applies to $(patch_src "$n" | paste -sd ' ' -) (remake it: tests/mutants/remake.sh $n): $(echo "$why" | xargs)"; fi
done
