#!/usr/bin/env bash
# grade's one-line verdicts say what each number is computed over: "over the whole image", "on the
# whole image's plain mean" or "over its significant blocks (WHERE)"; a place never stands beside a
# whole-image number as if it were its scope (it follows "significant in:"). Three images of the
# Cornell box against ref/cornell.pfm (64x64, 16 spp): honest, x1.3 (the fit fails), flipped
# vertically (only blocks fail); a few seconds.
. "$(dirname "$0")/lib.sh"
mkdir -p "$TMP/class"
run_ok "render" $PATHLAB render scenes/cornell.obj --size 64x64 --spp 16 --seed 41 --sampler independent --quiet -o "$TMP/class/a.pfm"
run_ok "scale" "$PFMTOOL" scale "$TMP/class/a.pfm" 1.3 "$TMP/class/b.pfm"
run_ok "flip" python3 tests/mistakes.py flip-v "$TMP/class/a.pfm" "$TMP/class/c.pfm"
$PATHLAB grade "$TMP/class" --ref ref/cornell.pfm > "$TMP/out" 2> "$TMP/err"
rows=$(grep -E '/[abc]\.pfm: (PASS|FAIL)' "$TMP/out")
num='[+-][0-9]+\.[0-9]+%'
while IFS= read -r row; do
    name=${row%%: *}; name=${name##*/}
    if grep -qE "$num( \+- [0-9.]+%)? in [a-z]+ over the whole image|$num on the whole image's plain mean|$num over its significant blocks" <<< "$row" \
       && ! grep -qE "$num( \+- [0-9.]+% in [a-z]+)? \((most|the|a|top|bottom|left|right)" <<< "$row"; then
        pass "grade: $name's number says its scope: $(cut -c1-160 <<< "${row#*: }")"
    else fail "grade: $name's number does not say what it is computed over: $row"; fi
done <<< "$rows"
[ "$(wc -l <<< "$rows")" = 3 ] && pass "grade: three rows" || fail "grade: rows '$rows'; stderr ends: $(err_tail "$TMP/err")"
exit 0
