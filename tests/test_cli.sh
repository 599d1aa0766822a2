#!/usr/bin/env bash
# The command line: errors name the file and line, exit with status 2, and write no output file.
. "$(dirname "$0")/lib.sh"
out=$TMP/out.pfm

expect_status "no arguments: usage, status 2" 2 $PATHLAB
expect_status "help: status 0" 0 $PATHLAB help
expect_status "unknown command" 2 $PATHLAB paint
expect_err "unknown command named" "unknown command 'paint'"

expect_status "missing scene file" 2 $PATHLAB render "$TMP/nope.obj" -o "$out"
expect_err "missing scene file named" "nope.obj"
expect_no_file "missing scene: no output" "$out"

for bad in "--spp abc" "--spp 0" "--spp 3.5" "--bounces 3:1" "--bounces x" "--light sun" "--dir mirror" \
           "--direct nee" "--size 0x10" "--size 64" "--eye 1,2" "--fov nan" "--threads -1" "--rr maybe" "--frobnicate"; do
    # shellcheck disable=SC2086
    expect_status "bad flag '$bad': status 2" 2 $PATHLAB render scenes/cornell.obj $bad -o "$out" --quiet
    expect_no_file "bad flag '$bad': no output" "$out"
done
# messages name the command, the flag and the value
expect_status "bad value: status 2" 2 $PATHLAB render scenes/cornell.obj --spp abc -o "$out"
expect_err "bad value: command, flag and value named" "^pathlab render: --spp expects .*got 'abc'"
expect_status "unknown flag: status 2" 2 $PATHLAB render scenes/cornell.obj --frobnicate -o "$out"
expect_err "unknown flag named" "^pathlab render: unknown flag '--frobnicate'"
expect_status "flag without its value: status 2" 2 $PATHLAB render scenes/cornell.obj -o
expect_err "flag without its value named" "^pathlab render: -o needs a value"
expect_status "two scenes: status 2" 2 $PATHLAB render scenes/cornell.obj scenes/cornell.obj -o "$out"
expect_err "two scenes: the second named" "^pathlab render: unexpected 'scenes/cornell.obj'"
expect_no_file "two scenes: no output" "$out"
expect_status "--variance as PNG refused" 2 $PATHLAB render scenes/cornell.obj -o "$out" --variance "$TMP/v.png"
expect_err "--variance as PNG explained" "--variance .*v.png.*pfm"
expect_status "negative numbers as values (--eye, --up): status 0" 0 \
    $PATHLAB render scenes/cornell.obj --eye 0,1,-3.5 --up 0,-1,0 --size 4x4 --spp 1 --quiet -o "$out"
expect_status "flags before the scene, output in capitals (.PFM): status 0" 0 \
    $PATHLAB render --size 4x4 --spp 1 --quiet -o "$TMP/OUT.PFM" scenes/cornell.obj
rm -f "$out"
expect_status "no -o" 2 $PATHLAB render scenes/cornell.obj
expect_status "unknown output extension" 2 $PATHLAB render scenes/cornell.obj -o "$TMP/x.jpg"
expect_err "unknown output extension explained" "use .pfm, .ppm or .png"
expect_status "--split without a last bounce" 2 $PATHLAB render scenes/cornell.obj --split -o "$out"

# a malformed OBJ: the message names file and line
printf 'v 0 0 0\nv 1 0 0\nv 0 1 zero\nf 1 2 3\n' > "$TMP/bad.obj"
expect_status "bad number in OBJ: status 2" 2 $PATHLAB render "$TMP/bad.obj" -o "$out" --quiet
expect_err "bad number in OBJ: file:line" "bad.obj:3:"
expect_no_file "bad OBJ: no output" "$out"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n' > "$TMP/badidx.obj"
expect_status "index out of range: status 2" 2 $PATHLAB render "$TMP/badidx.obj" -o "$out" --quiet
expect_err "index out of range: file:line" "badidx.obj:4:"

# a malformed view file beside a good OBJ
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' > "$TMP/tri.obj"
printf 'eye 0 0 5\nfov wide\n' > "$TMP/tri.view"
expect_status "bad view file: status 2" 2 $PATHLAB render "$TMP/tri.obj" -o "$out" --quiet
expect_err "bad view file: file:line" "tri.view:2:"
printf 'eye 0 0 5\ntarget 0 0 5\n' > "$TMP/tri.view"
expect_status "eye equals target: status 2" 2 $PATHLAB render "$TMP/tri.obj" -o "$out" --quiet

# a scene without emitters renders black at once, with a warning
rm -f "$TMP/tri.view"
expect_status "no emitters: status 0" 0 $PATHLAB render "$TMP/tri.obj" --size 8x8 -o "$out"
expect_err "no emitters: warning" "no emitters"
if [ -f "$out" ] && [ "$(tail -c 768 "$out" | tr -d '\0' | wc -c)" -eq 0 ]; then pass "no emitters: black image"; else fail "no emitters: image missing or not black"; fi

# an output that cannot be written: status 1, a message naming it, nothing left behind
expect_status "output in a missing folder: status 2, before rendering" 2 $PATHLAB render scenes/cornell.obj --size 8x8 --spp 1 --quiet -o "$TMP/no/such/dir/x.pfm"
expect_err "unwritable output named" "no/such/dir/x.pfm"
# the help lists the strategy names from the tables the parser reads: every name it shows is accepted
$PATHLAB help > "$TMP/help" 2>&1
if grep -q "{light\|{dir\|{direct" "$TMP/help"; then fail "help: a {name} placeholder was not expanded"
else pass "help: placeholders expanded"; fi
for flag in light dir direct; do
    names=$(sed -n "s/^  --$flag \([a-z|-]*\) .*/\1/p" "$TMP/help" | tr '|' ' ')
    [ -n "$names" ] || { fail "help: no line for --$flag"; continue; }
    bad=""
    for n in $names; do
        $PATHLAB render scenes/cornell.obj --$flag "$n" --size 4x4 --spp 1 --quiet -o "$TMP/h.pfm" 2> /dev/null || bad="$bad $n"
    done
    if [ -z "$bad" ]; then pass "help: every --$flag name it lists is accepted ($names)"
    else fail "help: --$flag names refused by the parser:$bad"; fi
done
exit 0
