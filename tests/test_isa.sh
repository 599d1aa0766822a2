#!/usr/bin/env bash
# One binary for every x86-64: the ray traversal is compiled for SSE2, AVX2 + FMA and AVX-512 and
# picked at start (geometry/bvh.h, bvh_isa), or forced with --isa NAME. Every copy must give the very
# same images: every scene of scenes/ is rendered (48x48, 4 spp, L0..L3 split) with each copy this
# CPU runs and compared byte for byte with the SSE2 copy's (test_bvh compares their hits ray by
# ray). An unknown or unrunnable name is refused with exit 2.
. "$(dirname "$0")/lib.sh"
$PATHLAB --version > "$TMP/v" || { fail "isa: --version failed"; exit 0; }
line=$(sed -n 's/^ray traversal: //p' "$TMP/v")
case $line in "") fail "isa: --version names no ray traversal: $(cat "$TMP/v")"; exit 0 ;; esac
pass "--version names the traversal in use: $line"
compiled=$(echo "$line" | sed -n 's/.*(compiled for \([^;]*\);.*/\1/p' | tr -d ',')
base=sse2; case " $compiled " in *" sse2 "*) ;; *) base=portable ;; esac
runs=""
for isa in $compiled; do
    case $isa in "("*|*")"|not|on|this|CPU) continue ;; esac
    $PATHLAB render scenes/cornell.obj --size 4x4 --spp 1 --isa "$isa" --quiet -o "$TMP/probe.pfm" 2> /dev/null && runs="$runs $isa"
done
if [ "$runs" = " $base" ] || [ -z "$runs" ]; then skip "isa: only the $base copy runs here (compiled for: $compiled)"; fi
differ=0; n=0
for scene in scenes/*.obj; do
    name=$(basename "$scene" .obj)
    for isa in $runs; do
        $PATHLAB render "$scene" --size 48x48 --spp 4 --bounces 0:3 --split --isa "$isa" --quiet -o "$TMP/$name-$isa.pfm" \
            || { fail "isa: render $scene --isa $isa failed"; differ=$((differ + 1)); }
    done
    for isa in $runs; do
        [ "$isa" = "$base" ] && continue
        for f in "" _L0 _L1 _L2 _L3; do
            n=$((n + 1))
            cmp -s "$TMP/$name-$isa$f.pfm" "$TMP/$name-$base$f.pfm" || { differ=$((differ + 1)); fail "isa: $scene$f: --isa $isa differs from $base"; }
        done
    done
done
[ "$differ" = 0 ] && pass "every scene, L0..L3 and their sum: the images of${runs} are byte-identical ($n comparisons with $base)"
expect_status "--isa with an unknown name: exit 2" 2 $PATHLAB render scenes/cornell.obj --size 4x4 --spp 1 --isa avx9 -o "$TMP/x.pfm"
expect_err "--isa with an unknown name: says so and lists the names" "avx9: no such instruction set \(compiled for .*$base"
expect_no_file "--isa with an unknown name: nothing written" "$TMP/x.pfm"
expect_status "--isa=NAME works as --isa NAME" 0 $PATHLAB render scenes/cornell.obj --size 4x4 --spp 1 --isa="$base" --quiet -o "$TMP/y.pfm"
exit 0
