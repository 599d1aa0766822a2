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
# the copy every other is compared with: sse2, or the only one of a NATIVE=1 build (named after its flags)
base=sse2; case " $compiled " in *" sse2 "*) ;; *) base=${compiled%% *} ;; esac
runs=""
for isa in $compiled; do
    case $isa in "("*|*")"|not|on|this|CPU) continue ;; esac
    $PATHLAB render scenes/cornell.obj --size 4x4 --spp 1 --isa "$isa" --quiet -o "$TMP/probe.pfm" 2> /dev/null && runs="$runs $isa"
done
case " $runs " in
*" $base "*) [ "$runs" != " $base" ] || { skip "isa: only the $base copy runs here (compiled for: $compiled)"; runs=""; } ;;
*) skip "isa: one copy, for this processor only (NATIVE=1; compiled for: $compiled)"; runs="" ;;
esac
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
[ "$differ" = 0 ] && [ -n "$runs" ] && pass "every scene, L0..L3 and their sum: the images of${runs} are byte-identical ($n comparisons with $base)"
# "Runs on any x86-64": the whole binary, not only the traversal's copies, on processors without
# AVX-512 and without AVX, emulated by qemu-user (its -cpu models raise an illegal instruction for any
# instruction the model lacks, as a real processor would: a build with -march=native dies there). The
# dispatch must pick avx2 on a Haswell and sse2 on the baseline qemu64, and each render must equal the
# host's render with the sse2 copy byte for byte. Code that the compiler moved out of a copy (link-time
# optimisation inlines across files) would fail here. Sanitizer builds are not run under qemu.
case "$PATHLAB:$(uname -m):$base" in
*san*) skip "isa: the sanitizer build is not run under qemu" ;;
*:x86_64:sse2)
    if ! command -v qemu-x86_64 > /dev/null 2>&1; then skip "isa: qemu-x86_64 is missing (Debian's qemu-user; make test-deps installs it)"
    else
        # the course's BRDF with both lobes, MIS on small lights, the light tree, a sky: each rendered
        # here with the sse2 copy, then on each emulated processor
        runs_q=("cornell-glossy" "mis-plates" "many-lights --light tree" "cornell --sky 0.2,0.3,0.5")
        for i in "${!runs_q[@]}"; do
            name=${runs_q[$i]%% *} flags=${runs_q[$i]#$name}
            # shellcheck disable=SC2086
            $PATHLAB render "scenes/$name.obj" $flags --size 24x24 --spp 2 --bounces 0:3 --isa sse2 --quiet -o "$TMP/q$i-host.pfm" \
                || fail "isa: render scenes/$name.obj$flags --isa sse2 failed"
        done
        for model in Haswell:avx2 qemu64:sse2; do
            cpu=${model%%:*} want=${model#*:}
            got=$(qemu-x86_64 -cpu "$cpu" $PATHLAB --version 2> /dev/null | sed -n 's/^ray traversal: \([a-z0-9]*\).*/\1/p')
            [ "$got" = "$want" ] && pass "isa: on an emulated $cpu the dispatch picks $want" \
                || fail "isa: on an emulated $cpu the dispatch picks '$got', not $want"
            bad=0
            for i in "${!runs_q[@]}"; do
                name=${runs_q[$i]%% *} flags=${runs_q[$i]#$name}
                # shellcheck disable=SC2086
                qemu-x86_64 -cpu "$cpu" $PATHLAB render "scenes/$name.obj" $flags --size 24x24 --spp 2 --bounces 0:3 --quiet -o "$TMP/q$i-$cpu.pfm" 2> "$TMP/q.err" \
                    || { fail "isa: render scenes/$name.obj$flags on an emulated $cpu failed: $(tail -n 2 "$TMP/q.err")"; bad=1; continue; }
                cmp -s "$TMP/q$i-$cpu.pfm" "$TMP/q$i-host.pfm" || { fail "isa: scenes/$name.obj$flags on an emulated $cpu differs from the host's sse2 copy"; bad=1; }
            done
            [ "$bad" = 0 ] && pass "isa: the whole binary runs on an emulated $cpu ($want), the same images as the host's sse2 copy"
        done
    fi ;;
*:x86_64:*) skip "isa: a build for this processor only (NATIVE=1) is not run on others" ;;
esac
expect_status "--isa with an unknown name: exit 2" 2 $PATHLAB render scenes/cornell.obj --size 4x4 --spp 1 --isa avx9 -o "$TMP/x.pfm"
expect_err "--isa with an unknown name: says so and lists the names" "avx9: no such instruction set \(compiled for .*$base"
expect_no_file "--isa with an unknown name: nothing written" "$TMP/x.pfm"
expect_status "--isa=NAME works as --isa NAME" 0 $PATHLAB render scenes/cornell.obj --size 4x4 --spp 1 --isa="$base" --quiet -o "$TMP/y.pfm"
exit 0
