#!/usr/bin/env bash
# pathlab compare: one table row per estimator with finite metrics that agree with pathlab diff on
# the written images; the reference-variance correction; equal time gives a cheap estimator more
# samples than an expensive one; the mosaic has the layout's size and its labels have ink; bad
# input exits 2 with a clear message and writes nothing. About 2.5 s (5 s with the sanitizers and PATHLAB_FAST=1).
. "$(dirname "$0")/lib.sh"
S=scenes/cornell.obj
C="$PATHLAB compare $S --size 32x32 --threads 2 --quiet"
if [ "${PATHLAB_FAST:-}" = 1 ]; then SPP=4 SEC=0.25; else SPP=8 SEC=0.4; fi
near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; s = b < 0 ? -b : b; exit !(d <= t * s + 1e-12) }'; }
# csv COLUMN ROW FILE: a field of table.csv (row 1 = first estimator); labels and flags have no commas here
csv() { awk -F, -v c="$1" -v r="$2" 'NR == r + 1 { gsub(/"/, "", $c); print $c }' "$3"; }

# ---- equal spp, rendered reference ----
D=$TMP/eq
expect_status "compare: three estimators at equal spp, exit 0" 0 \
    $C --spp $SPP --ref-spp 64 --estimators "light,brdf,solid angle=--direct light --light solid-angle" -o "$D"
rows=$(($(wc -l < "$D/table.csv") - 1))
if [ "$rows" -eq 3 ] && [ "$(grep -c "^| " "$D/table.md")" -eq 4 ]; then pass "compare: one table row per estimator (csv and md)"
else fail "compare: $rows csv rows, expected 3: $(cat "$D/table.csv")"; fi
bad=$(awk -F, 'NR > 1 { for (i = 3; i <= 10; i++) if ($i !~ /^[0-9.e+-]+$/ || $i + 0 != $i + 0) print NR ": " $0 }' "$D/table.csv")
if [ -z "$bad" ] && [ "$(csv 3 3 "$D/table.csv")" = "$SPP" ]; then pass "compare: every metric finite, spp = $SPP"
else fail "compare: non-finite or missing metrics: $bad"; fi
missing=""
for f in light.pfm light.png heat-light.png brdf.pfm solid-angle.pfm solid-angle.png heat-solid-angle.png \
         reference.pfm reference_var.pfm mosaic.ppm mosaic.png table.md table.csv; do
    [ -s "$D/$f" ] || missing="$missing $f"
done
if [ -z "$missing" ]; then pass "compare: images, heatmaps, reference, mosaic and tables written"; else fail "compare: missing:$missing"; fi
# every PFM with its sidecar, each variance NAME_var.pfm named in its image's sidecar
bad=
for f in "$D"/*.pfm; do
    [ -s "$f.meta" ] || { bad="$bad $(basename "$f"): no sidecar;"; continue; }
    case $f in
    *_var.pfm) grep -q '^kind variance$' "$f.meta" || bad="$bad $(basename "$f"): not kind variance;" ;;
    *) grep -q '^kind mean$' "$f.meta" && grep -q "^variance $(basename "${f%.pfm}")_var.pfm$" "$f.meta" \
           && grep -q '^scene scenes/cornell.obj$' "$f.meta" || bad="$bad $(basename "$f"): $(paste -sd' ' "$f.meta" | cut -c1-200);" ;;
    esac
done
[ -z "$bad" ] && pass "compare: each of its $(ls "$D"/*.pfm | wc -l) PFMs has its sidecar; variances NAME_var.pfm, named by their image's" \
    || fail "compare: sidecars:$bad"
expect_status "compare: --ref without --ref-var, exit 0" 0 $C --spp 2 --estimators light --ref "$D/reference.pfm" -o "$TMP/found"
grep -q "its variance $D/reference_var.pfm" "$TMP/found/table.md" && pass "compare: --ref's variance REF_var.pfm found without --ref-var" \
    || fail "compare: --ref's variance not found: $(grep reference "$TMP/found/table.md" | head -2)"
if [ "$(csv 2 3 "$D/table.csv")" = "--direct light --light solid-angle" ] && [ "$(csv 1 3 "$D/table.csv")" = "solid angle" ]; then
    pass "compare: LABEL=FLAGS keeps the label and the flags"
else fail "compare: row 3 is '$(sed -n 4p "$D/table.csv")'"; fi
# RMSE, relMSE and MAE of the table are those of pathlab diff on the written images
for r in 1 2 3; do
    slug=$(csv 1 $r "$D/table.csv" | tr ' ' '-')
    out=$($PATHLAB diff "$D/$slug.pfm" "$D/reference.pfm")
    ok=1
    for kc in "RMSE 5" "relMSE 6" "MAE 7"; do
        set -- $kc
        want=$(echo "$out" | awk -v k="$1" '$1 == k { print $2 }')
        near "$(csv "$2" $r "$D/table.csv")" "$want" 1e-4 || ok=0
    done
    if [ $ok = 1 ]; then pass "compare: $slug: RMSE, relMSE, MAE agree with pathlab diff"
    else fail "compare: $slug: table $(sed -n "$((r + 1))p" "$D/table.csv") vs diff: $(echo $out)"; fi
done
# MSE = RMSE^2 - mean variance of the reference, and efficiency = 1 / (MSE time)
mv=$(awk '/^- MSE = RMSE\^2 - / { print $6; exit }' "$D/table.md" | tr -d ',')
r1=$(csv 5 1 "$D/table.csv"); m1=$(csv 8 1 "$D/table.csv"); t1=$(csv 4 1 "$D/table.csv"); e1=$(csv 9 1 "$D/table.csv")
if [ -n "$mv" ] && near "$m1" "$(awk -v r="$r1" -v v="$mv" 'BEGIN { print r * r - v }')" 2e-3 \
   && near "$e1" "$(awk -v m="$m1" -v t="$t1" 'BEGIN { print 1 / (m * t) }')" 2e-3; then
    pass "compare: MSE = RMSE^2 - mean reference variance ($mv), efficiency = 1/(MSE time)"
else fail "compare: MSE $m1, RMSE $r1, mean var '$mv', efficiency $e1, time $t1"; fi
if grep -q "reference: rendered with .--direct mis-power --light solid-angle --dir brdf. at 64 spp" "$D/table.md"; then
    pass "compare: the notes say how the reference was made"; else fail "compare: notes: $(grep reference "$D/table.md")"; fi

# ---- the mosaic: 32x32 panels scaled 4x to 128, 4 columns (reference + 3), two rows, one-line labels ----
geom=$(python3 - "$D/mosaic.ppm" <<'EOF'
import sys
d = open(sys.argv[1], 'rb').read()
parts = d.split(b'\n', 3)
w, h = map(int, parts[1].split()); px = parts[3]
def white(x0, x1, y0, y1):
    return sum(1 for y in range(y0, y1) for x in range(x0, x1) if px[3 * (y * w + x):3 * (y * w + x) + 3] == b'\xff\xff\xff')
# label bands: rows 4..16 over each panel column; the gaps between panels (x = 132..135) stay background
inks = [white(4 + i * 132, 4 + i * 132 + 128, 4, 17) for i in range(4)]
gap = px[3 * (100 * w + 133):3 * (100 * w + 133) + 3]
print(w, h, min(inks), gap.hex())
EOF
)
set -- $geom
if [ "$1" = 532 ] && [ "$2" = 294 ]; then pass "compare: mosaic is 532x294 (4 + 4 x (128 + 4) wide, 4 + 2 x (13 + 128 + 4) high)"
else fail "compare: mosaic geometry '$geom', expected 532x294"; fi
if [ "${3:-0}" -ge 15 ]; then pass "compare: every label band has white ink (fewest: $3 pixels)"; else fail "compare: a label band is empty: $geom"; fi
if [ "${4:-}" = "1d1d1f" ]; then pass "compare: panels are separated by background"; else fail "compare: gap pixel is '${4:-}'"; fi

# ---- a given reference and its variance: the correction is exactly the variance's mean ----
$PFMTOOL const 32 32 0.001 0.001 0.001 "$TMP/var.pfm"
expect_status "compare: --ref and --ref-var, exit 0" 0 \
    $C --spp 2 --estimators "mis-power" --ref "$D/reference.pfm" --ref-var "$TMP/var.pfm" -o "$TMP/given"
r=$(csv 5 1 "$TMP/given/table.csv"); m=$(csv 8 1 "$TMP/given/table.csv")
if near "$m" "$(awk -v r="$r" 'BEGIN { print r * r - 0.001 }')" 1e-4 && [ ! -e "$TMP/given/reference.pfm" ]; then
    pass "compare: MSE = RMSE^2 - 0.001 with a constant --ref-var 0.001; no reference rendered"
else fail "compare: RMSE $r, MSE $m"; fi

# ---- equal time: the cheapest estimator (no shadow rays) gets more spp than the dearest ----
expect_status "compare: equal time $SEC s, exit 0" 0 \
    $C --time $SEC --ref-spp 32 --estimators "brdf,light+solid-angle" -o "$TMP/time"
s1=$(csv 3 1 "$TMP/time/table.csv"); s2=$(csv 3 2 "$TMP/time/table.csv")
t1=$(csv 4 1 "$TMP/time/table.csv"); t2=$(csv 4 2 "$TMP/time/table.csv")
if [ "${s1:-0}" -gt "${s2:-0}" ]; then pass "compare: equal time: brdf $s1 spp > light+solid-angle $s2 spp"
else fail "compare: equal time: brdf $s1 spp, light+solid-angle $s2 spp"; fi
if awk -v a="$t1" -v b="$t2" -v s="$SEC" 'BEGIN { exit !(a > s / 4 && a < 3 * s && b > s / 4 && b < 3 * s) }'; then
    pass "compare: equal time: $t1 s and $t2 s, within a factor 4 below and 3 above $SEC s"
else fail "compare: equal time: $t1 s and $t2 s for $SEC s"; fi

# ---- bad input: exit 2, a message naming the problem, no DIR ----
expect_status "compare: unknown estimator name, exit 2" 2 $C --estimators "light,mis-pwoer" -o "$TMP/bad1"
expect_err "compare: unknown name named" "unknown name 'mis-pwoer'"
expect_no_file "compare: unknown name, no DIR" "$TMP/bad1"
expect_err "compare: the names are listed, dir-brdf among those of --dir" "uniform cosine dir-brdf \(--dir\)"
expect_status "compare: a label that names one of compare's files, exit 2" 2 $C --estimators "mosaic=dir-brdf+solid-angle mis-balance" -o "$TMP/bad9"
expect_err "compare: names expand to their flags (dir-brdf is --dir brdf)" "my mosaic=--dir brdf --light solid-angle --direct mis-balance"
expect_status "compare: a label named like a heatmap (heat-light), exit 2" 2 $C --estimators "heat-light=--direct light,light" -o "$TMP/bad13"
expect_err "compare: says it is a heatmap's name" "label 'heat-light' would write DIR/heat-light.png, a heatmap's name"
expect_no_file "compare: heatmap label, no DIR" "$TMP/bad13"
expect_status "compare: two estimators of one file name, exit 2" 2 $C --estimators "light,light" -o "$TMP/bad11"
expect_err "compare: both named, with their file" "estimators 'light' and 'light' would both write DIR/light.pfm"
expect_no_file "compare: reserved label, no DIR" "$TMP/bad9"
expect_status "compare: empty --estimators, exit 2" 2 $C --estimators "" -o "$TMP/bad10"
expect_no_file "compare: empty --estimators, no DIR" "$TMP/bad10"
expect_status "compare: bad flag value inside an estimator, exit 2" 2 $C --estimators "x=--direct sideways" -o "$TMP/bad2"
expect_err "compare: bad value named with its estimator" "sideways"
expect_no_file "compare: bad flag value, no DIR" "$TMP/bad2"
expect_status "compare: --spp inside an estimator, exit 2" 2 $C --estimators "light --spp 4" -o "$TMP/bad3"
expect_status "compare: two estimators with one file name, exit 2" 2 $C --estimators "light,Light=--direct light" -o "$TMP/bad4"
expect_err "compare: the clash is named" "both write"
expect_status "compare: --spp and --time, exit 2" 2 $C --spp 4 --time 1 --estimators light -o "$TMP/bad5"
$PFMTOOL const 16 16 1 1 1 "$TMP/small.pfm"
expect_status "compare: reference of another size, exit 2" 2 $C --estimators light --ref "$TMP/small.pfm" -o "$TMP/bad6"
expect_err "compare: both sizes named" "16x16.*32x32"
expect_no_file "compare: reference size mismatch, no DIR" "$TMP/bad6"
expect_status "compare: --mtl inside an estimator (the scene is loaded once for all), exit 2" 2 $C --estimators "light,b=--direct brdf --mtl $TMP/x.mtl" -o "$TMP/bad12"
expect_err "compare: says --mtl is for the scene" "estimator 'b': --mtl is for the scene"
expect_no_file "compare: --mtl inside an estimator, no DIR" "$TMP/bad12"
# a string flag's value inside an estimator outlives its parsing (it pointed into a stack buffer,
# and the view went to a file named by whatever was left there)
expect_status "compare: --write-view inside an estimator, exit 0" 0 $C --spp 1 --estimators "light --write-view $TMP/wv.view" -o "$TMP/wv"
if grep -q "^eye " "$TMP/wv.view" 2>/dev/null; then pass "compare: the view written where the estimator says"; else fail "compare: no view at $TMP/wv.view"; fi
expect_status "compare: estimators with different cameras, exit 2" 2 $C --estimators "light,b=--eye 0,1,5 --direct brdf" -o "$TMP/bad8"
expect_err "compare: the camera clash is named" "another camera"
expect_no_file "compare: different cameras, no DIR" "$TMP/bad8"
expect_status "compare: missing reference file, exit 2" 2 $C --estimators light --ref "$TMP/none.pfm" -o "$TMP/bad7"
expect_err "compare: missing reference named" "none.pfm"
# ---- what a hostile review of compare found (2026-12-08), each failing on the build before ----
# an estimator's own --time rendered fewer samples than its row and sidecar said
expect_status "compare: --time inside an estimator refused" 2 $C --spp 4 --estimators "a=--time 0.002,b=--direct brdf" -o "$TMP/bad20"
expect_err "compare: says --time is for all" "estimator 'a': --spp and --time are set for all estimators"
expect_no_file "compare: --time inside an estimator, no DIR" "$TMP/bad20"
expect_status "compare: --samples inside an estimator refused" 2 $C --spp 4 --estimators "a=--samples 0:4" -o "$TMP/bad21"
# its sidecars left out --material and --normals: --resume added Blinn samples to a diffuse render
expect_status "compare --material diffuse --normals geometric, exit 0" 0 $C --spp 2 --ref-spp 4 --estimators light --material diffuse --normals geometric -o "$TMP/mat"
if grep -q "^flags .*--material diffuse --normals geometric" "$TMP/mat/light.pfm.meta"; then pass "compare: the sidecar says --material and --normals"
else fail "compare: sidecar flags: $(grep '^flags' "$TMP/mat/light.pfm.meta")"; fi
# --ref inside -o: the estimator of its name replaced it
mkdir -p "$TMP/cref"; $PATHLAB render $S --size 32x32 --spp 4 --quiet -o "$TMP/cref/light.pfm"; cp "$TMP/cref/light.pfm" "$TMP/ref_before.pfm"
expect_status "compare: --ref in the output folder refused" 2 $C --spp 1 --estimators light,brdf --ref "$TMP/cref/./light.pfm" -o "$TMP/cref"
expect_err "compare: says the reference is in the output folder" "light.pfm is in the output folder"
if cmp -s "$TMP/cref/light.pfm" "$TMP/ref_before.pfm"; then pass "compare: the reference left whole"; else fail "compare: the reference was overwritten"; fi
# a NaN in --ref made every RMSE nan, exit 0
"$PFMTOOL" const 32 32 0.5 0.5 0.5 "$TMP/refnan.pfm"; printf '\x00\x00\xc0\x7f' | dd of="$TMP/refnan.pfm" bs=1 seek=$(($(stat -c %s "$TMP/refnan.pfm") - 4)) conv=notrunc 2> /dev/null
expect_status "compare: a --ref holding a NaN refused" 2 $C --spp 1 --estimators light --ref "$TMP/refnan.pfm" -o "$TMP/bad22"
expect_err "compare: the NaN named" "refnan.pfm: 1 pixel-channel is NaN"
# a reference noisier than the estimators: MSE floored at 1e-30 ranked them by their times, silently
expect_status "compare: a reference of 2 spp, exit 0" 0 $C --spp 64 --ref-spp 2 --estimators light,mis-power -o "$TMP/noisy"
expect_err "compare: an error below the reference's noise is said" "below the reference's own variance"
if [ "$(csv 8 1 "$TMP/noisy/table.csv")" = "nan" ]; then pass "compare: its MSE is nan, not 1e-30"; else fail "compare: MSE $(csv 8 1 "$TMP/noisy/table.csv")"; fi
# a REF_var.pfm left from an earlier render of REF.pfm was taken for the new one's variance
mkdir -p "$TMP/st"; $PATHLAB render $S --size 32x32 --spp 2 --quiet -o "$TMP/st/ref.pfm" --variance "$TMP/st/ref_var.pfm"
$PATHLAB render $S --size 32x32 --spp 64 --quiet -o "$TMP/st/ref.pfm"
expect_status "compare: a reference whose sidecar names no variance, exit 0" 0 $C --spp 4 --estimators light --ref "$TMP/st/ref.pfm" -o "$TMP/st/out"
mse=$(csv 8 1 "$TMP/st/out/table.csv"); rmse=$(csv 5 1 "$TMP/st/out/table.csv")
if near "$mse" "$(awk -v r="$rmse" 'BEGIN { print r * r }')" 1e-3; then pass "compare: the stale ref_var.pfm not used (MSE = RMSE^2, no noise taken off)"
else fail "compare: the stale ref_var.pfm was used: MSE $mse, RMSE $rmse"; fi
# an output name that is a folder was found after the renders (files written); a dangling link as -o too
mkdir -p "$TMP/late/index.html"
expect_status "compare: DIR/index.html a folder: refused before rendering" 2 $C --spp 1 --estimators light,brdf -o "$TMP/late"
expect_err "compare: DIR/index.html named" "late/index.html"
if [ -z "$(ls "$TMP/late" | grep -v index.html)" ]; then pass "compare: DIR/index.html a folder: nothing written"; else fail "compare: written: $(ls "$TMP/late")"; fi
ln -s "$TMP/nowhere" "$TMP/dangling"
expect_status "compare: -o a dangling link refused" 2 $C --spp 1 --estimators light -o "$TMP/dangling"
# a label holding | or a newline made columns or rows of table.md
expect_status "compare: labels with | and a newline, exit 0" 0 $C --spp 1 --ref-spp 2 --estimators $'a|b=--direct light,c\nd=--direct brdf' -o "$TMP/lab"
if [ "$(grep -c '^| ' "$TMP/lab/table.md")" -eq 3 ] && ! grep -q 'a|b' "$TMP/lab/table.md"; then pass "compare: table.md keeps one row per estimator, the | as text"
else fail "compare: table.md: $(grep '^|' "$TMP/lab/table.md" | head -5)"; fi
# names that set one flag twice: "light+brdf" rendered --direct brdf under the label light+brdf
expect_status "compare: light+brdf refused" 2 $C --spp 1 --estimators "light+brdf" -o "$TMP/bad23"
expect_err "compare: light+brdf: the flag set twice named" "estimator 'light\\+brdf' sets --direct twice"
# --write-view over the --orbiter, --sky inside -o, a folder named DIR/reference.png
printf 'c 278 273 280\np 0 0\nr 0 180\ns 1080 1080\nf 40 32 32\n' > "$TMP/cam.orbiter"; cp "$TMP/cam.orbiter" "$TMP/cam_before.orbiter"
expect_status "compare: --write-view = --orbiter refused" 2 $C --spp 1 --estimators light --orbiter "$TMP/cam.orbiter" --write-view "$TMP/./cam.orbiter" -o "$TMP/bad24"
if cmp -s "$TMP/cam.orbiter" "$TMP/cam_before.orbiter"; then pass "compare: the orbiter file left whole"; else fail "compare: the orbiter file was replaced"; fi
mkdir -p "$TMP/skyin"; "$PFMTOOL" const 8 4 1 1 1 "$TMP/skyin/light.pfm"
expect_status "compare: --sky inside -o refused" 2 $C --spp 1 --estimators light --sky "$TMP/skyin/light.pfm" -o "$TMP/skyin"
expect_err "compare: --sky inside -o named" "--sky .*light.pfm is in the output folder"
mkdir -p "$TMP/rp/reference.png"
expect_status "compare: DIR/reference.png a folder: refused before rendering" 2 $C --spp 1 --ref-spp 2 --estimators light -o "$TMP/rp"
if [ -z "$(ls "$TMP/rp" | grep -v reference.png)" ]; then pass "compare: DIR/reference.png a folder: nothing written"; else fail "compare: written: $(ls "$TMP/rp" | tr '\n' ' ')"; fi
# --write-view over a texture of the scene; a label holding a flag ("light --direct=brdf" was the label
# "light --direct" for --direct brdf)
mkdir -p "$TMP/ctex"; printf 'P3\n2 2\n255\n255 0 0 0 255 0 0 0 255 255 255 255\n' > "$TMP/ctex/t.ppm"
printf 'newmtl m\nKd 1 1 1\nKe 1 1 1\nmap_Kd t.ppm\n' > "$TMP/ctex/t.mtl"
printf 'mtllib t.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl m\nf 1/1 2/2 3/3\n' > "$TMP/ctex/t.obj"
cp "$TMP/ctex/t.mtl" "$TMP/ctex/t_before.mtl"
expect_status "compare: --write-view = the scene's MTL refused" 2 $PATHLAB compare "$TMP/ctex/t.obj" --size 8x8 --quiet --spp 1 --estimators light --write-view "$TMP/ctex/t.mtl" -o "$TMP/bad25"
if cmp -s "$TMP/ctex/t.mtl" "$TMP/ctex/t_before.mtl"; then pass "compare: the MTL left whole"; else fail "compare: the MTL was replaced"; fi
expect_status "compare: a label holding a flag refused" 2 $C --spp 1 --estimators "light --direct=brdf" -o "$TMP/bad26"
expect_err "compare: a label holding a flag: said" "before '=' holds a flag"
exit 0
