#!/usr/bin/env bash
# docs/make_guide.sh — regenerates every picture (PNG, written by pathlab) and every figure quoted
# in docs/guide.md, into docs/guide/. Run from anywhere: `docs/make_guide.sh`.
#
# Run time: 66 s on the 2-core machine when quiet (130 s of CPU), 137 s when other jobs shared it
# (measured 2026-11-22; each run writes its own time to docs/guide/run.txt).
#
# Fixed seeds and --threads 2 everywhere, so every picture and every number is the same on every run
# (pathlab's images do not depend on the thread count), except the times and the equal-time
# comparison (--time), whose sample counts depend on the speed of the machine.
# Needs ./pathlab and build/tests/pfmtool (`make` and `make build/tests/pfmtool`, or `make test`).
set -euo pipefail
cd "$(dirname "$0")/.."
P=${PATHLAB:-./pathlab}
PFMTOOL=build/tests/pfmtool
G=docs/guide
[ -x "$P" ] || make -s pathlab
[ -x "$PFMTOOL" ] || make -s "$PFMTOOL"
mkdir -p "$G"
rm -f "$G"/*.png "$G"/*.txt "$G"/*.md
rm -rf "$G"/compare-*
W=$(mktemp -d); trap 'rm -rf "$W"' EXIT
T0=$(date +%s.%N); LOAD0=$(cut -d" " -f1-3 /proc/loadavg)
CB=scenes/cornell.obj
MP=scenes/mis-plates.obj
R=(--threads 2 --quiet --sampler independent)   # the guide shows the slides' Monte Carlo, and grades with it
say() { echo "== $*" >&2; }
# mean of an image (over pixels and RGB): pathlab diff against a black image prints it
mean() { local w h; read -r w h < <(sed -n 2p "$1"); "$PFMTOOL" const "$w" "$h" 0 0 0 "$W/zero.pfm" >/dev/null
         "$P" diff "$1" "$W/zero.pfm" | sed -n 's/^mean *\([^ ]*\) +- \([^ ]*\).*/\1 \2/p'; }

# ---- 1. First image --------------------------------------------------------------------------
say "1. first image"
"$P" render $CB --threads 2 --size 256x256 --spp 128 --seed 1 -o $G/cornell.png 2> "$W/first.err"
grep -E " triangles | spp, .*Mrays/s" "$W/first.err" > $G/first-render.txt   # the scene line and the stats line (not the progress lines of a log)
# rays per sample, from the counts of the stats line
sed -n 's/.*(camera \([0-9]*\), continuation \([0-9]*\), shadow \([0-9]*\);.*/\1 \2 \3/p' "$W/first.err" |
    awk '{ printf "per camera ray: %.2f continuation rays, %.2f shadow rays\n", $2 / $1, $3 / $1 }' >> $G/first-render.txt

# ---- 2. L0 ... L4 --------------------------------------------------------------------------------
say "2. bounces"
EXPO=(0 0 1 3 5)                                     # stops, per bounce: L3 and L4 are dark
: > $G/bounces.txt
for k in 0 1 2 3 4; do
    "$P" render $CB "${R[@]}" --size 256x256 --spp 256 --seed 2 --bounce $k --exposure "${EXPO[$k]}" -o $G/L$k.png
    echo "L$k: --bounce $k --exposure ${EXPO[$k]}" >> $G/bounces.txt
done
for k in 1 2 3 4; do
    "$P" render $CB "${R[@]}" --spp 128 --seed 2 --bounces 0:$k --size 192x192 -o $G/L0-$k.png
done
# The means: one render, every bounce in its own PFM (--split), each compared with a black image.
"$P" render $CB --threads 2 --size 256x256 --spp 256 --seed 2 --bounces 0:8 --split \
    -o "$W/s.pfm" 2> "$W/split.err"
tail -n 1 "$W/split.err" > $G/split-render.txt
{
    echo "mean radiance of each bounce, Cornell box 256x256, 256 spp, seed 2, over pixels and RGB:"
    echo "(pathlab render scenes/cornell.obj --size 256x256 --spp 256 --seed 2 --bounces 0:8 --split -o s.pfm;"
    echo " pathlab diff s_Lk.pfm zero.pfm, zero.pfm = build/tests/pfmtool const 256 256 0 0 0)"
    prev=""
    for k in 0 1 2 3 4 5 6 7 8; do
        f="$W/s_L$k.pfm"
        read -r m se < <(mean "$f")
        ratio=""; [ -n "$prev" ] && ratio=$(awk -v a="$m" -v b="$prev" -v k="$k" 'BEGIN { if (b > 0) printf "  L%d/L%d = %.3f", k, k - 1, a / b }')
        printf "L%-2s mean %-10s +- %-8s%s\n" "$k" "$m" "$se" "$ratio"
        prev=$m
    done
    read -r m se < <(mean "$W/s.pfm"); echo "sum mean $m +- $se"
    echo "running sums L0..Lk as a fraction of L0..L8:"
    acc=0
    for k in 0 1 2 3 4 5 6 7 8; do
        read -r mk _ < <(mean "$W/s_L$k.pfm")
        acc=$(awk -v a="$acc" -v b="$mk" 'BEGIN { printf "%.9g", a + b }')
        awk -v a="$acc" -v t="$m" -v k="$k" 'BEGIN { printf "L0..L%d %.4f  (missing %.2f%%)\n", k, a / t, 100 * (1 - a / t) }'
    done
} > $G/bounce-means.txt

# ---- 3. Comparing estimators --------------------------------------------------------------------
say "3. compare: Cornell box"
C="light,brdf,mis-balance,mis-power"
"$P" compare $CB --estimators "$C" --size 128x128 --spp 16 --seed 3 --threads 2 \
    -o "$W/cmp-cornell" 2> "$W/cb.err"
mkdir -p $G/compare-cornell; cp "$W/cmp-cornell/mosaic.png" "$W/cmp-cornell/table.md" $G/compare-cornell/

# How often each light of mis-plates is chosen (pdf1): sides from scenes/README.md, Ke = 16/side^2.
awk 'BEGIN { n = split("0.06 0.2 0.6 1.8", side, " "); for (i = 1; i <= n; i++) tot += side[i]^2
    print "mis-plates: probability of choosing each light (both triangles of its square)"
    print "side    area     --light area   --light power (Ke = 16/side^2: equal power)"
    for (i = 1; i <= n; i++) printf "%-6s  %-7.4f  %-13.5f  %.2f\n", side[i], side[i]^2, side[i]^2 / tot, 1 / n }' \
    > $G/light-choice.txt

say "3. compare: mis-plates, --bounce 1 --light power"
"$P" compare $MP --estimators "$C" --bounce 1 --light power --size 128x128 --spp 16 --ref-spp 1024 --seed 3 \
    --threads 2 -o "$W/cmp-plates" 2> "$W/mp.err"
mkdir -p $G/compare-plates; cp "$W/cmp-plates/mosaic.png" "$W/cmp-plates/table.md" $G/compare-plates/

say "3. compare: mis-plates, --light area (the same reference)"
"$P" compare $MP --estimators "$C" --bounce 1 --light area --size 128x128 --spp 16 --seed 3 \
    --threads 2 --ref "$W/cmp-plates/reference.pfm" --ref-var "$W/cmp-plates/reference_var.pfm" -o "$W/cmp-plates-area" 2> "$W/mpa.err"
mkdir -p $G/compare-plates-area; cp "$W/cmp-plates-area/mosaic.png" "$W/cmp-plates-area/table.md" $G/compare-plates-area/

say "3. compare: mis-plates, equal time"
"$P" compare $MP --estimators "$C" --bounce 1 --light power --size 128x128 --time 1 --seed 3 \
    --threads 2 --ref "$W/cmp-plates/reference.pfm" --ref-var "$W/cmp-plates/reference_var.pfm" -o "$W/cmp-plates-time" 2> "$W/mpt.err"
mkdir -p $G/compare-plates-time; cp "$W/cmp-plates-time/table.md" $G/compare-plates-time/

# ---- 4. Grading ----------------------------------------------------------------------------------
say "4. grade"
REF=ref/cornell.pfm
if [ ! -f "$REF" ]; then   # the reference `make refs` writes; made here the same way if missing
    REF="$W/cornell-ref.pfm"
    "$P" render $CB "${R[@]}" --size 64x64 --spp 4096 --seed 3010 -o "$REF"
    echo "ref/cornell.pfm missing: rendered with --size 64x64 --spp 4096 --seed 3010" > $G/ref-note.txt
fi
S=(--size 64x64 --spp 64 --seed 4)
"$P" render $CB "${R[@]}" "${S[@]}" -o "$W/good.pfm"
"$P" render $CB "${R[@]}" "${S[@]}" --bounces 0:1 -o "$W/direct.pfm"
"$PFMTOOL" scale "$W/good.pfm" 1.02 "$W/bright.pfm" >/dev/null
"$P" render $CB "${R[@]}" "${S[@]}" -o $G/grade-good.png
"$P" render $CB "${R[@]}" "${S[@]}" --bounces 0:1 -o $G/grade-direct.png
g() {  # name image: the verdict and the exit code, as a student sees them
    set +e; "$P" grade "$W/$2.pfm" --ref "$REF" --heatmap "$G/heat-$1.png" > "$W/g.out" 2>&1; local rc=$?; set -e
    { sed "s|$W/||; s|$REF|ref/cornell.pfm|" "$W/g.out"; echo "exit code $rc"; } > "$G/grade-$1.txt"
}
g good good; g direct direct; g bright bright
for x in good direct; do
    "$P" diff "$W/$x.pfm" "$REF" --heatmap $G/diff-$x.png --scale 0.15 | sed "s|$W/||" > $G/diff-$x.txt
done

# A PFM written by the student's own code: the snippet of the guide, compiled and read back.
cc -std=c99 -Wall -Wextra -pedantic -O2 -o "$W/write_pfm" $G/write_pfm.c
(cd "$W" && ./write_pfm)
"$PFMTOOL" const 64 64 0.5 0.5 0.5 "$W/grey.pfm" >/dev/null
{ echo "pathlab grade mine.pfm --ref grey.pfm  (grey.pfm = pfmtool const 64 64 0.5 0.5 0.5)"
  set +e; "$P" grade "$W/mine.pfm" --ref "$W/grey.pfm" | sed "s|$W/||g"; set -e; } > $G/write_pfm.txt
grep -q '2048 of them brighter, .*(the top)' $G/write_pfm.txt ||
    { echo "make_guide.sh: write_pfm.c's image is not read top half bright" >&2; exit 1; }

# ---- the log of the run --------------------------------------------------------------------------
for d in compare-cornell compare-plates compare-plates-area compare-plates-time; do sed -i "s|$W/||g" $G/$d/table.md; done
for f in cb mp mpa mpt; do grep -v '^\(\[\|.*%\)' "$W/$f.err" | sed "s|$W/||g" > $G/compare-$f.log || true; done
secs=$(awk -v a="$T0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.0f", b - a }')
times > "$W/times"   # here, not in $( ): a subshell has no children
cpu=$(tail -n 1 "$W/times" | awk '{ split($1, m, "m"); split($2, n, "m"); printf "%.0f", 60 * (m[1] + n[1]) + m[2] + n[2] }')
echo "docs/make_guide.sh: $secs s wall, $cpu s CPU (pathlab's user + sys) on $(nproc) cores, load average before: $LOAD0" \
    > $G/run.txt
say "done in $secs s"
