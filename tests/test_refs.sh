#!/usr/bin/env bash
# Fresh renders of every scene agree with the references of ref/ (ref/MANIFEST.md, group `scenes`:
# 64x64, jittered pixels, 2048..8192 spp): the full transport (ref/SCENE.pfm) and L0..L3 one by one
# (ref/SCENE_split_Lk.pfm), and the references' L0+L1+L2+L3 agree with a fresh --bounces 0:3 render.
# The fresh renders use other seeds and 1/32..1/64 of the references' samples (SPP below).
#
# Two independent checks per comparison:
#  (a) tests/zcheck with each image's own variance of the pixel mean: per pixel-channel
#      z = (a - ref) / sqrt(var_a + var_ref) at alpha = 0.01 with Sidak's correction over the 12288
#      pixel-channels, at least BAR = 99.5% must pass (61 may fail). Measured on the Cornell box at
#      256 spp: L2 19 and L3 29 failing channels, every one with z < 0 and a tiny estimated variance:
#      dark pixels whose rare bright paths none of the 256 samples found, so the fresh render is
#      low AND its variance estimate is too small (the estimate fails, not the estimator; a jittered
#      pixel whose lit sliver no sample hit is the same case). tests/test_estimators.sh uses 99.75%
#      at 4096 spp; here at 128 spp L2 and L3 had 0.9952 and 0.9894 pass, at 256 spp L3 0.9975. 8x8 blocks
#      and the whole image at alpha = 1 - 0.99^(1/n), n the comparisons of this file, so the file
#      as a whole has a 1% false-alarm rate. A pixel that is 0 with variance 0 in both images
#      (black background, the back of a light) has z = 0 and passes; an exact value (the furnaces'
#      L0) differs only by float rounding, which zcheck allows.
#  (b) OpenImageIO's idiff, which knows nothing of our statistics: it fails when more than
#      IDIFF_PCT % of the pixels differ by more than F in some channel. F is derived from the noise
#      of this very comparison: F = 5 sigma99, sigma99 the 99th percentile over pixel-channels of
#      sqrt(var_a + var_ref). A channel with sigma <= sigma99 exceeds 5 sigma with probability
#      < 1e-6 if Gaussian (Chebyshev's worst case 4%, hence the bar); the other 1% may.
#      IDIFF_PCT = 3 (worst case: the noisiest 1% of channels all in different pixels).
#      Per-pixel bar 98% on mis-plates (see below); sphere-furnace at 64 spp had 0.9883, now 128 spp.
#      F is floored at 1e-5 of the reference's largest value for noiseless images (furnace L0).
# The sum check: var of the references' sum is taken as the sum of their variances. The layers of
# one render are correlated, so the true variance is up to (sum of sigmas)^2 <= 4x that; it is 1/32
# or less of the fresh render's variance, so this changes z by at most 5%.
#
# Negative checks that must fail: every fresh full render times 1.02 (zcheck); a fresh 0:3 render
# against the references' L0+L1+L3 (L2 missing) on the scenes where L2 is not tiny (zcheck); every
# fresh full render times 2, a forgotten factor (idiff).
#
# PATHLAB_FAST=1 (sanitizer builds, ~10x slower): the Cornell box only, and one render (--bounces 0:3
# --split, 256 spp) instead of three: its layers against the references' layers, its total against
# their sum, the negative checks on that total. Fewer samples do not work: at 32 spp 2-7% of the
# pixel-channels fail (the heavy tails above) and the image z of the 2% error is only 2.4.
. "$(dirname "$0")/lib.sh"
ZCHECK=$BUILD/tests/zcheck
REF=${REF:-ref}
FAST=${PATHLAB_FAST:-0}
[ "$FAST" = 1 ] || FAST=0
t0=$(date +%s)
# scene:spp:flags (the references' estimator flags, ref/make_refs.sh)
SCENES=${REF_SCENES:-"cornell:256: cornell-glossy:256: furnace:256: quad-light:256:--light=solid-angle
        sphere-furnace:128: mis-plates:256:--light=solid-angle"}
IDIFF_PCT=3
BAR=0.995
# PATHLAB_FAST=1: the Cornell box only, one split render (its total stands in for the others).
[ "$FAST" = 1 ] && SCENES=${REF_SCENES:-cornell:256:}
# Comparisons at the suite alpha: per scene full + L0..L3 + the sum = 6 (5 when FAST).
n=0; for s in $SCENES; do n=$((n + 6 - FAST)); done
ASUITE=$(awk -v n="$n" 'BEGIN { printf "%.3g", 1 - exp(log(0.99) / n) }')

# zc NAME WANT A VA B VB: WANT 0 (agree) or 1 (told apart). Agree = the per-pixel test at 0.01 with
# its bar and the block and image tests at ASUITE all pass.
zc() {
    local name=$1 want=$2; shift 2
    local o1 o2 r1 r2 got
    o1=$("$ZCHECK" "$@" --alpha 0.01 --block 0 --pixel-pass $BAR 2>&1); r1=$?
    o2=$("$ZCHECK" "$@" --alpha "$ASUITE" --block 8 --pixel-pass 0 2>&1); r2=$?
    if [ $r1 -ge 2 ] || [ $r2 -ge 2 ]; then fail "$name: zcheck could not compare: $o1 $o2"; return; fi
    got=$(( r1 | r2 ))
    local px rest
    px=$(grep -oE 'pixels [0-9.]+ pass' <<< "$o1" | head -1)
    rest="$(grep -oE 'blocks [0-9]+/[0-9]+ fail' <<< "$o2"), $(grep -oE 'image \|z\| [0-9.]+' <<< "$o2")"
    if [ "$got" -eq "$want" ]; then pass "$name ($px; $rest at alpha $ASUITE)"
    else fail "$name: zcheck says $([ $got = 0 ] && echo agree || echo differ), wanted $([ $want = 0 ] && echo agree || echo differ): $o1 | $o2"; fi
}

# The idiff checks are queued and run at the end in one oiiotool (--diff is idiff's comparison, with
# the same -fail/-failpercent/-warn options): an OpenImageIO tool takes ~1 s of CPU only to start (it
# loads 261 libraries), which made the 36 idiff runs of this file 2/3 of its time.
IDQ=$TMP/idiff.queue; : > "$IDQ"
# id NAME WANT A A_VAR REF REF_VAR: queues idiff at F from the noise; WANT 0 (pass) or 2 (idiff fails)
id() {
    have_oiio || { skip "$1 (needs OpenImageIO's idiff)"; return; }
    printf '%s\t' "$@" >> "$IDQ"; echo >> "$IDQ"
}

# id_run: F for each queued check (F above, from A_VAR, REF_VAR and REF), one oiiotool over all of
# them, a PASS or FAIL line each, in the order they were queued
id_run() {
    [ -s "$IDQ" ] || return 0
    python3 - "$IDQ" "$IDIFF_PCT" > "$TMP/idiff.args" <<'EOF' || { fail "idiff checks: no thresholds (python3?)"; return; }
import struct, sys
def read(p):
    with open(p, 'rb') as f:
        assert f.readline().strip() == b'PF'
        w, h = map(int, f.readline().split())
        s = float(f.readline())
        return struct.unpack(('<' if s < 0 else '>') + '%df' % (3 * w * h), f.read(12 * w * h))
pct = sys.argv[2]
for line in open(sys.argv[1]):
    name, want, a, va, b, vb = line.rstrip('\n').split('\t')[:6]
    sig = sorted((x + y) ** 0.5 for x, y in zip(read(va), read(vb)))
    F = '%.6g' % max(5 * sig[int(0.99 * (len(sig) - 1))], 1e-5 * max(abs(x) for x in read(b)))
    print('\n'.join(['--fail', F, '--failpercent', pct, '--warn', F, '--warnpercent', pct, a, b, '--diff']))
EOF
    mapfile -t args < "$TMP/idiff.args"
    oiiotool "${args[@]}" > "$TMP/idiff.out" 2>&1
    # one block per comparison, from its "Computing diff of" line to its verdict (PASS, WARNING, FAILURE)
    awk '/^Computing diff of/ { n++ } n { print n "\t" $0 }' "$TMP/idiff.out" > "$TMP/idiff.blocks"
    local i=0 name want a va b vb F verdict over rc
    while IFS=$'\t' read -r name want a va b vb; do
        i=$((i + 1)); F=${args[$(( (i - 1) * 11 + 1 ))]}
        verdict=$(awk -F'\t' -v i="$i" '$1 == i && $2 ~ /^(PASS|WARNING|FAILURE)$/ { print $2 }' "$TMP/idiff.blocks")
        over=$(awk -F'\t' -v i="$i" '$1 == i && $2 ~ /pixels .* over/ { print $2; exit }' "$TMP/idiff.blocks" | xargs)
        case $verdict in PASS) rc=0 ;; WARNING) rc=1 ;; FAILURE) rc=2 ;; *) rc=none ;; esac
        if [ "$rc" = "$want" ]; then pass "$name (idiff status $rc, F $F: ${over:-no pixel over})"
        elif [ "$rc" = none ]; then fail "$name: oiiotool gave no verdict: $(tail -3 "$TMP/idiff.out" | xargs)"
        else fail "$name: idiff status $rc, wanted $want (F $F: ${over:-no pixel over})"; fi
    done < "$IDQ"
}

have_oiio || echo "note: idiff not found (OpenImageIO tools; make test-deps installs them as root or with sudo): its checks are skipped"
seed=900
for s in $SCENES; do
    IFS=: read -r name spp flags <<< "$s"
    flags=${flags//=/ }
    scene=scenes/$name.obj r=$REF/$name
    seed=$((seed + 10))
    f=$TMP/$name
    # shellcheck disable=SC2086
    if ! $PATHLAB render "$scene" --quiet --size 64x64 --spp "$spp" --seed $((seed + 1)) $flags --bounces 0:3 --split -o "$f.s.pfm" --variance "$f.sv.pfm"; then
        fail "$name: the split render failed"; continue
    fi
    # mis-plates: L2 and L3 are faint (dark backdrop) and heavy-tailed; at 256 spp 1.4% of L3's
    # pixel-channels failed (measured 0.9863 pass), so its per-pixel bar is 98%
    BAR=0.995; [ "$name" = mis-plates ] && BAR=0.98
    for k in 0 1 2 3; do
        zc "$name L$k, $spp spp, matches ${r}_split_L$k.pfm" 0 "$f.s_L$k.pfm" "$f.sv_L$k.pfm" "${r}_split_L$k.pfm" "${r}_split_L${k}_var.pfm"
        id "$name L$k against ${r}_split_L$k.pfm with idiff" 0 "$f.s_L$k.pfm" "$f.sv_L$k.pfm" "${r}_split_L$k.pfm" "${r}_split_L${k}_var.pfm"
    done
    "$PFMTOOL" sum "$f.rsum.pfm" "${r}_split_L"{0,1,2,3}.pfm && "$PFMTOOL" sum "$f.rsumv.pfm" "${r}_split_L"{0,1,2,3}_var.pfm
    "$PFMTOOL" sum "$f.no2.pfm" "${r}_split_L"{0,1,3}.pfm && "$PFMTOOL" sum "$f.no2v.pfm" "${r}_split_L"{0,1,3}_var.pfm
    if [ "$FAST" = 1 ]; then
        # the split render's own L0..L3 total stands in for the 0:3 and the full renders
        cp "$f.s.pfm" "$f.03.pfm"; cp "$f.sv.pfm" "$f.03v.pfm"
        full=$f.s.pfm fullv=$f.sv.pfm rfull=$f.rsum.pfm rfullv=$f.rsumv.pfm rname="the sum of ${r}_split_L0..L3"
    else
        # shellcheck disable=SC2086
        if ! $PATHLAB render "$scene" --quiet --size 64x64 --spp "$spp" --seed "$seed" $flags -o "$f.pfm" --variance "$f.var.pfm" ||
           ! $PATHLAB render "$scene" --quiet --size 64x64 --spp "$spp" --seed $((seed + 2)) $flags --bounces 0:3 -o "$f.03.pfm" --variance "$f.03v.pfm"; then
            fail "$name: a render failed"; continue
        fi
        zc "$name full transport, $spp spp, matches $r.pfm" 0 "$f.pfm" "$f.var.pfm" "$r.pfm" "${r}_var.pfm"
        id "$name full transport against $r.pfm with idiff" 0 "$f.pfm" "$f.var.pfm" "$r.pfm" "${r}_var.pfm"
        full=$f.pfm fullv=$f.var.pfm rfull=$r.pfm rfullv=${r}_var.pfm rname=$r.pfm
    fi
    # the references' layers add up to a fresh --bounces 0:3 render (not split, but for PATHLAB_FAST)
    zc "$name: L0+L1+L2+L3 of ref/ matches a --bounces 0:3 render" 0 "$f.03.pfm" "$f.03v.pfm" "$f.rsum.pfm" "$f.rsumv.pfm"
    # negative checks
    "$PFMTOOL" scale "$full" 1.02 "$f.x102.pfm"
    zc "$name: a render 2% too bright is told apart from $rname" 1 "$f.x102.pfm" "$fullv" "$rfull" "$rfullv"
    "$PFMTOOL" scale "$full" 2 "$f.x2.pfm"
    # not on mis-plates: its F (2.5) is set by the noisy edges of the lights seen directly, and the
    # dark rest doubled stays under it (measured: 2.95% of the pixels over F, under the 3% bar)
    [ "$name" = mis-plates ] || id "$name: idiff catches a render twice too bright" 2 "$f.x2.pfm" "$fullv" "$rfull" "$rfullv"
    case $name in cornell|furnace|cornell-glossy)
        zc "$name: L0+L1+L3 (L2 missing) is told apart from a --bounces 0:3 render" 1 "$f.03.pfm" "$f.03v.pfm" "$f.no2.pfm" "$f.no2v.pfm" ;;
    esac
done
id_run
echo "test_refs: $n comparisons at alpha $ASUITE for blocks and images, $(( $(date +%s) - t0 )) s"
