#!/usr/bin/env bash
# The command line a student expects: every command's --help and -h (status 0,
# its own usage on stdout, nothing on stderr), `pathlab help COMMAND`, --version; a typo gets a
# short error with "did you mean" and status 2, never the whole help; --flag=value everywhere
# --flag value is; camera flags checked (naming the flag) before the scene is loaded.
. "$(dirname "$0")/lib.sh"
out=$TMP/out.png

commands="render bench-rays check-sampling check-sampler diff grade compare merge convert version"
$PATHLAB help > "$TMP/all" 2>&1
all_lines=$(wc -l < "$TMP/all")
for c in $commands; do
    grep -q "pathlab $c" "$TMP/all" || fail "pathlab help: $c is not listed"
    for h in --help -h; do
        $PATHLAB $c $h > "$TMP/h" 2> "$TMP/herr"; rc=$?
        lines=$(wc -l < "$TMP/h")
        if [ "$rc" -eq 0 ] && grep -q "pathlab $c" "$TMP/h" && [ ! -s "$TMP/herr" ] && [ "$lines" -lt "$all_lines" ]; then
            pass "$c $h: status 0, its usage on stdout ($lines of the $all_lines lines of pathlab help)"
        else fail "$c $h: status $rc, $lines lines, stderr '$(head -c 200 "$TMP/herr")'"; fi
    done
    $PATHLAB help $c > "$TMP/h2" 2>&1
    if $PATHLAB $c --help 2>&1 | cmp -s - "$TMP/h2"; then pass "help $c: the same as $c --help"
    else fail "help $c differs from $c --help"; fi
done
# a command's help is its own: render's lists --spp, not grade's --alpha; grade's the other way
$PATHLAB render --help > "$TMP/h"
if grep -q -- "--spp" "$TMP/h" && ! grep -q -- "--alpha" "$TMP/h"; then pass "render --help: render's flags only"
else fail "render --help: not render's flags only"; fi
# --help wins wherever it is, even after a bad flag or a missing scene: a student asking for help gets it
expect_status "render nope.obj --spp abc --help: the help, status 0" 0 $PATHLAB render nope.obj --spp abc --help

expect_status "--version: status 0" 0 $PATHLAB --version
if grep -qE "^pathlab [0-9a-f]" "$TMP/out" || grep -q "^pathlab unknown" "$TMP/out"; then pass "--version prints 'pathlab REVISION'"
else fail "--version printed '$(cat "$TMP/out")'"; fi
$PATHLAB version > "$TMP/v1"; $PATHLAB --version > "$TMP/v2"
if cmp -s "$TMP/v1" "$TMP/v2"; then pass "version = --version"; else fail "version and --version differ"; fi

# typos: short, with the closest name; never the whole help
typo() {   # NAME WANT_PATTERN COMMAND...
    local name=$1 want=$2; shift 2
    expect_status "$name: status 2" 2 "$@"
    expect_err "$name: did you mean" "$want"
    local n; n=$(wc -l < "$TMP/err")
    if [ "$n" -le 2 ]; then pass "$name: short ($n line(s))"; else fail "$name: $n lines of error (the help?)"; fi
}
typo "pathlab rendr" "unknown command 'rendr'; did you mean 'render'\?" $PATHLAB rendr scenes/cornell.obj -o "$out"
typo "pathlab grdae" "did you mean 'grade'\?" $PATHLAB grdae x.pfm
typo "pathlab help rendr" "did you mean 'render'\?" $PATHLAB help rendr
typo "render --sp 4" "unknown flag '--sp'; did you mean '--spp'\?" $PATHLAB render scenes/cornell.obj --sp 4 -o "$out"
typo "render --sapmler sobol" "did you mean '--sampler'\?" $PATHLAB render scenes/cornell.obj --sapmler sobol -o "$out"
typo "render --varaince" "did you mean '--variance'\?" $PATHLAB render scenes/cornell.obj --varaince v.pfm -o "$out"
typo "grade --alhpa" "did you mean '--alpha'\?" $PATHLAB grade x.pfm --ref r.pfm --alhpa 0.01
typo "diff --heatmpa" "did you mean '--heatmap'\?" $PATHLAB diff a.pfm b.pfm --heatmpa h.png
typo "compare --estimatorz (its own flag)" "^pathlab compare: unknown flag '--estimatorz'; did you mean '--estimators'\?" $PATHLAB compare scenes/cornell.obj --estimatorz light -o "$TMP/cmp"
typo "compare --sampeler (a render flag)" "^pathlab compare: unknown flag '--sampeler'; did you mean '--sampler'\?" $PATHLAB compare scenes/cornell.obj --estimators light --sampeler sobol -o "$TMP/cmp"
typo "view --reff" "did you mean '--ref'\?" $PATHLAB view a.pfm --reff r.pfm -o "$TMP/v.html"
expect_status "a far-off flag: status 2" 2 $PATHLAB render scenes/cornell.obj --frobnicate -o "$out"
if grep -q "did you mean" "$TMP/err"; then fail "--frobnicate: a suggestion for a far-off word: $(cat "$TMP/err")"
else pass "--frobnicate: no suggestion (nothing is close)"; fi
expect_status "unknown command: status 2" 2 $PATHLAB paint
if [ "$(wc -l < "$TMP/err")" -le 2 ]; then pass "unknown command: short error, not the help"; else fail "unknown command: the help was printed"; fi

# --flag=value is --flag value
expect_status "render --spp=1 --size=8x8 --eye=0,1,3.5: status 0" 0 \
    $PATHLAB render scenes/cornell.obj --spp=1 --size=8x8 --eye=0,1,3.5 --quiet -o "$out"
expect_status "render -o=FILE is not --flag=value (single dash): status 2" 2 $PATHLAB render scenes/cornell.obj -o=x.png
rm -f "$out"
expect_status "render --spp=1 ... -o FILE: status 0" 0 $PATHLAB render scenes/cornell.obj --spp=1 --size=8x8 --seed=3 --quiet -o "$out"
if [ -s "$out" ]; then pass "--flag=value: the image was written"; else fail "--flag=value: no image"; fi
expect_status "render --spp=abc: status 2" 2 $PATHLAB render scenes/cornell.obj --spp=abc -o "$out"
expect_err "--spp=abc: the flag and value named" "--spp expects .*got 'abc'"
expect_status "render --quiet=1: status 2" 2 $PATHLAB render scenes/cornell.obj --quiet=1 -o "$out"
expect_err "--quiet=1: a switch takes no value" "--quiet takes no value"
expect_status "compare --estimators=light --spp=1: status 0" 0 $PATHLAB compare scenes/cornell.obj --estimators=light \
    --spp=1 --ref-spp=1 --size=8x8 --quiet -o "$TMP/cmp"
expect_status "grade --ref=X --alpha=0.05 (parses; no such image): status 2" 2 \
    $PATHLAB grade "$TMP/none.pfm" --ref="$TMP/none.pfm" --alpha=0.05
if grep -q "unknown flag" "$TMP/err"; then fail "grade --ref=X --alpha=A: refused as unknown flags"; else pass "grade --ref=X --alpha=A: understood"; fi

# camera flags: the flag named, before the scene is loaded (a missing scene reports the flag)
for bad in "--fov 0" "--fov=180" "--fov -5" "--up 0,0,0" "--size 0x5" "--eye 1,2"; do
    flag=${bad%%[ =]*}
    # shellcheck disable=SC2086
    expect_status "missing scene and $bad: status 2" 2 $PATHLAB render "$TMP/nope.obj" $bad -o "$out"
    expect_err "missing scene and $bad: $flag named, not the scene" "^pathlab render: $flag "
done
expect_status "--eye = --target: status 2" 2 $PATHLAB render "$TMP/nope.obj" --eye 1,1,1 --target 1,1,1 -o "$out"
expect_err "--eye = --target: named" "--eye and --target are the same point"
expect_status "--up along the view: status 2" 2 $PATHLAB render "$TMP/nope.obj" --eye 0,0,1 --target 0,0,0 --up 0,0,2 -o "$out"
expect_err "--up along the view: named" "--up is parallel"
expect_status "compare --fov 0: status 2" 2 $PATHLAB compare "$TMP/nope.obj" --estimators light --fov 0 -o "$TMP/cmp2"
expect_err "compare --fov 0: named" "--fov expects"
exit 0
