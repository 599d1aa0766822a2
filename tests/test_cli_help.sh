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
# pathlab help: each command's help under its heading, the same text as `help NAME`; every flag of a
# command's table (pathlab completion flags NAME) in its help, none described twice
for c in $commands; do
    awk -v h="==== pathlab $c ====" '$0 == h { on = 1; next } /^==== pathlab / { on = 0 } on' "$TMP/all" | sed '${/^$/d}' > "$TMP/section"
    $PATHLAB help $c > "$TMP/h"
    if [ -s "$TMP/section" ] && cmp -s "$TMP/section" "$TMP/h"; then pass "pathlab help: $c's help under its heading, as help $c"
    else fail "pathlab help: no heading '==== pathlab $c ====' followed by help $c's text"; fi
    $PATHLAB completion flags $c > "$TMP/flags"; rc=$?
    missing= twice=
    for f in $(cut -d' ' -f1 "$TMP/flags"); do
        case $f in --help|-h) continue ;; esac
        [ $c = compare ] && $PATHLAB completion flags render | grep -q -- "^$f\b" && [ $f != -o ] && [ $f != --spp ] && [ $f != --time ] && continue
        grep -qE -- "(^|[ [|(])$f([ =,]|$)" "$TMP/h" || missing="$missing $f"
        [ "$(grep -cE -- "^ *$f " "$TMP/h")" -le 1 ] || twice="$twice $f"
    done
    if [ $rc = 0 ] && [ -z "$missing$twice" ]; then pass "help $c: each of its $(wc -l < "$TMP/flags") flags there, none described twice"
    else fail "help $c: status $rc, flags missing:${missing:- none}; described twice:${twice:- none}"; fi
done

# the bash completion, generated from the flag tables: flags of the command, values of a list
$PATHLAB completion bash > "$TMP/completion.bash"
if bash -n "$TMP/completion.bash"; then pass "completion bash: a valid bash script"; else fail "completion bash: not valid bash"; fi
complete_words() {   # the words bash would offer after the command line "$@" (the last word being typed)
    bash -c '. "$1"; shift; COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); _pathlab; echo "${COMPREPLY[*]}"' _ "$TMP/completion.bash" "$@"
}
for t in "render --di|--dir --direct" "render --dir |uniform cosine brdf" "render --sampler sob|sobol sobol1" \
         "grade --al|--alpha" "ren|render" "help gr|grade" "compare --estim|--estimators" "view --ti|--title"; do
    line=${t%%|*} want=${t#*|}
    # shellcheck disable=SC2086
    if [ "${line: -1}" = " " ]; then got=$(complete_words pathlab $line ""); else got=$(complete_words pathlab $line); fi
    [ "$got" = "$want" ] && pass "completion: 'pathlab $line' offers '$want'" || fail "completion: 'pathlab $line' offers '$got', want '$want'"
done

# did you mean, for every flag of every command (two letters swapped) and the values of a list
for c in $commands; do
    bad=
    for f in $($PATHLAB completion flags $c | cut -d' ' -f1); do
        case $f in --help|-h|-?) continue ;; esac
        typo="--${f:3:1}${f:2:1}${f:4}"
        [ "$typo" = "$f" ] && continue
        $PATHLAB $c "$typo" x > /dev/null 2> "$TMP/err"; rc=$?
        [ $rc = 2 ] && grep -q -- "did you mean '$f'" "$TMP/err" || bad="$bad $typo->$f($rc: $(head -c 100 "$TMP/err"))"
    done
    [ -z "$bad" ] && pass "$c: every flag typed with two letters swapped gets 'did you mean' it" || fail "$c: no did you mean for:$bad"
done
typo "render --dir bdrf" "--dir expects one of uniform, cosine, brdf, got 'bdrf'; did you mean brdf\?" $PATHLAB render scenes/cornell.obj --dir bdrf -o "$out"
typo "render --sampler sobl" "did you mean sobol\?" $PATHLAB render scenes/cornell.obj --sampler sobl -o "$out"
typo "grade --reference" "unknown flag '--reference'; did you mean '--ref'\?" $PATHLAB grade x.pfm --reference r.pfm
expect_status "check-sampler --pdf cosin: status 2" 2 $PATHLAB check-sampler x.txt --pdf cosin
expect_err "check-sampler --pdf cosin: did you mean" "^pathlab check-sampler: --pdf expects one of .*, got 'cosin'; did you mean cosine\?"
expect_status "compare --estimators ligth: status 2" 2 $PATHLAB compare scenes/cornell.obj --estimators ligth -o "$TMP/cmp"
expect_err "compare --estimators ligth: did you mean" "unknown name 'ligth'; did you mean light\?"
# a student's file whose name starts with '-': after -- it is a file; without, the error says so
mkdir -p "$TMP/dash"; cp ref/cornell.pfm "$TMP/dash/-x.pfm"; REFP=$PWD/ref/cornell.pfm PL=$(cd "$(dirname "$PATHLAB")" && pwd)/$(basename "$PATHLAB")
(cd "$TMP/dash" && "$PL" grade --ref "$REFP" -- -x.pfm > out 2> err); rc=$?
if [ $rc = 0 ] && grep -q "^pathlab grade: -x.pfm against" "$TMP/dash/out"; then pass "grade --ref R -- -x.pfm grades the file -x.pfm"
else fail "grade -- -x.pfm: exit $rc: $(head -c 300 "$TMP/dash/err")"; fi
(cd "$TMP/dash" && "$PL" grade --ref "$REFP" -x.pfm > out 2> err); rc=$?
if [ $rc = 2 ] && grep -q "unknown flag '-x.pfm'; a file of that name: write ./-x.pfm, or put it after --" "$TMP/dash/err"; then pass "grade -x.pfm: status 2, says to write ./-x.pfm or put it after --"
else fail "grade -x.pfm: exit $rc: $(head -c 300 "$TMP/dash/err")"; fi
exit 0
