#!/usr/bin/env bash
# pathlab grade: passes unbiased renders (4 and 64 spp, several seeds, another estimator), fails
# biased ones (2% too bright, L2 missing, the cosine forgotten at the first bounce) and says
# brighter or darker; exact images; bad input.
#
# False alarms: grade fails an unbiased image with probability at most alpha = 0.01 (the default,
# used here); measured by `make grade-calibration` (tests/grade_calibration.sh: 258 honest images of
# 12 estimators at 1 to 1024 spp, 64x64 and 128x128) and published with the power in docs/grading.md.
# The seeds are fixed, so this test is deterministic; but after a change to the renderer's random
# streams, the 9 independent unbiased cases below (5 at 4 spp, 3 at 64 spp, 1 with another
# estimator) all pass with probability >= 0.99^9 = 91%, 5 with PATHLAB_FAST (>= 95%). A failing
# unbiased case is then worth one more seed before a bug hunt.
. "$(dirname "$0")/lib.sh"
if [ "${PATHLAB_FAST:-0}" != 0 ]; then
    SIZE=48x48 REF_SPP=512 SEEDS4="1 2" SEEDS64="1 2"        # the sanitizer build is ~15x slower
    # at 48x48 the whole image's error bar at 64 spp is 0.3-0.4% per channel: seed 1's own noise
    # (-0.5%) left 1.5% of a 2% bias, under the limit; 3% is found at |z| 7.5 to 11.4 (seeds 1-6)
    BRIGHT=1.03 BRIGHT_PCT=3
else
    SIZE=64x64 REF_SPP=1024 SEEDS4="1 2 3 4 5" SEEDS64="1 2 3"
    BRIGHT=1.02 BRIGHT_PCT=2
fi
# --sampler independent: grade's false-alarm rate (alpha) and power are those of independent samples
SCENE="scenes/cornell.obj --quiet --size $SIZE --bounces 0:3 --sampler independent"
R="$PATHLAB render $SCENE"

# grade_expect NAME WANT PATTERN IMAGE [FLAGS...]: grade IMAGE against the reference; wants exit
# status WANT and, if PATTERN is not empty, an output line matching it (grep -E). Shows the verdict.
grade_expect() {
    local name=$1 want=$2 pattern=$3 rc out; shift 3
    out=$($PATHLAB grade "$@" --ref "$TMP/ref.pfm" 2> "$TMP/err"); rc=$?
    echo "$out" > "$TMP/grade.txt"
    local verdict
    verdict=$(echo "$out" | grep -E '^(PASS|FAIL):|^  (brighter|darker)' | sed 's/^ *//' | paste -sd ';' -)
    if [ "$rc" -ne "$want" ]; then fail "$name: wanted exit $want: $verdict: $(ran "$rc" "$TMP/err" $PATHLAB grade "$@" --ref "$TMP/ref.pfm")"
    elif [ -n "$pattern" ] && ! echo "$out" | grep -qE -- "$pattern"; then fail "$name: no line matches '$pattern': $verdict"
    else pass "$name [$verdict]"; fi
}

start=$(date +%s)
$R --spp "$REF_SPP" --seed 1000 -o "$TMP/ref.pfm" --variance "$TMP/ref_var.pfm"

# 1. unbiased: the reference's estimator at 4 and 64 spp, each with several seeds
for s in $SEEDS4; do
    $R --spp 4 --seed "$s" -o "$TMP/u4_$s.pfm"
    grade_expect "unbiased, 4 spp, seed $s: pass" 0 "" "$TMP/u4_$s.pfm" --spp 4
done
for s in $SEEDS64; do
    $R --spp 64 --seed "$s" -o "$TMP/u64_$s.pfm"
    grade_expect "unbiased, 64 spp, seed $s: pass" 0 "" "$TMP/u64_$s.pfm" --spp 64
done
# ... another estimator (BRDF sampling only for direct light: other noise, same expectation)
$R --spp 64 --seed 7 --direct brdf -o "$TMP/brdf.pfm"
grade_expect "unbiased, another estimator (--direct brdf), 64 spp: pass" 0 "" "$TMP/brdf.pfm" --spp 64
# ... with the per-pixel Z-test for information: printed, not part of the verdict
grade_expect "unbiased, 64 spp, with --var: pass, per-pixel test printed" 0 "^pixels \(information only" \
    "$TMP/u64_1.pfm" --spp 64 --var "$TMP/ref_var.pfm" --ref-spp "$REF_SPP"

# 2. 2% too bright (3% on the sanitizer run's smaller images): every 64-spp image above, scaled
for s in $SEEDS64; do
    $PFMTOOL scale "$TMP/u64_$s.pfm" $BRIGHT "$TMP/b64_$s.pfm"
    grade_expect "$BRIGHT_PCT% too bright, 64 spp, seed $s: fail, brighter" 1 "^  brighter over the whole image: \+[1-3]\.[0-9]+%" "$TMP/b64_$s.pfm" --spp 64
done

# 3. L2 missing: L0 + L1 + L3 of a split render, against L0..L3
for spp in 4 64; do
    $R --spp $spp --seed 11 --split -o "$TMP/split$spp.pfm"
    $PFMTOOL sum "$TMP/noL2_$spp.pfm" "$TMP/split${spp}_L0.pfm" "$TMP/split${spp}_L1.pfm" "$TMP/split${spp}_L3.pfm"
    grade_expect "L2 missing, $spp spp: fail, darker" 1 "^  darker (over the whole image|on the image.s plain mean)" "$TMP/noL2_$spp.pfm" --spp $spp \
        --heatmap "$TMP/noL2_$spp.png"
done
# the heatmap shows the darker blocks in blue, and no red
colours=$(python3 -c '
import struct, sys, zlib
png = open(sys.argv[1], "rb").read(); pos = 8; idat = b""
while pos < len(png):
    n, kind = struct.unpack(">I4s", png[pos:pos + 8])
    if kind == b"IDAT": idat += png[pos + 8:pos + 8 + n]
    pos += 12 + n
w, h = struct.unpack(">II", png[16:24]); raw = zlib.decompress(idat); s = 3 * w + 1
px = [raw[y * s + 1 + 3 * x:y * s + 4 + 3 * x] for y in range(h) for x in range(w)]
print(sum(b[2] > 150 and b[0] < 100 for b in px), sum(b[0] > 150 and b[2] < 100 for b in px))' "$TMP/noL2_64.png" 2>&1)
set -- $colours
if [ "${1:-0}" -gt 0 ] 2>/dev/null && [ "${2:-1}" -eq 0 ]; then pass "heatmap: $1 blue (darker) pixels, no red"
else fail "heatmap of the missing-L2 image: blue and red pixel counts '$colours'"; fi

# 4. the cosine forgotten at the first bounce: a copy of src/ with the bug, built with the same cc
mkdir -p "$TMP/broken"
cp -r src "$TMP/broken/src"
sed -i 's|beta = v3_mul(beta, v3_scale(f, cos_p / pdf2_sa));|beta = v3_mul(beta, v3_scale(f, (k == 1 ? 1.0f : cos_p) / pdf2_sa));|' "$TMP/broken/src/tracer/integrator.c"
if cmp -s src/tracer/integrator.c "$TMP/broken/src/tracer/integrator.c"; then
    fail "cosine forgotten: the throughput line 'beta = v3_mul(beta, v3_scale(f, cos_p / pdf2_sa));' is no longer in src/tracer/integrator.c; update this test"
elif ! ${CC:-cc} -std=c99 -D_POSIX_C_SOURCE=200809L -O1 -I"$TMP/broken/src" -o "$TMP/broken/pathlab" "$TMP"/broken/src/*/*.c "${BUILD:-build}/gen/web_assets.c" -lm -lpthread 2> "$TMP/err"; then
    fail "cosine forgotten: the broken copy does not build: $(head -c 300 "$TMP/err")"
else
    for spp in 4 64; do
        "$TMP/broken/pathlab" render $SCENE --spp $spp --seed 12 -o "$TMP/nocos_$spp.pfm"
        grade_expect "cosine forgotten at the first bounce, $spp spp: fail, brighter" 1 "^  brighter (over the whole image|on the (whole )?image.s plain mean)" \
            "$TMP/nocos_$spp.pfm" --spp $spp
    done
fi

# 5. exact images: no noise, so any difference beyond float rounding is bias
$PFMTOOL const 32 32 0.5 0.25 1 "$TMP/c.pfm"
$PFMTOOL scale "$TMP/c.pfm" 1.0000001 "$TMP/c_ulp.pfm"
$PFMTOOL scale "$TMP/c.pfm" 1.001 "$TMP/c_bright.pfm"
cp "$TMP/c.pfm" "$TMP/ref.pfm"
rm -f "$TMP/ref_var.pfm"    # the 64x64 reference's variance: beside a 32x32 reference it is an error (below)
grade_expect "an exact image against itself: pass" 0 "" "$TMP/c.pfm"
grade_expect "an exact image 1 ulp off: pass (rounding)" 0 "" "$TMP/c_ulp.pfm"
grade_expect "an exact image 0.1% too bright: fail, every pixel exact and off" 1 "^  1024 of 1024 exact pixels differ" "$TMP/c_bright.pfm"

# 6. bad input: status 2 and the files named
$PFMTOOL const 16 16 1 1 1 "$TMP/small.pfm"
expect_status "missing image: status 2" 2 $PATHLAB grade "$TMP/none.pfm" --ref "$TMP/c.pfm"
expect_err "missing image named" "none.pfm"
expect_status "missing reference: status 2" 2 $PATHLAB grade "$TMP/c.pfm" --ref "$TMP/noref.pfm"
expect_err "missing reference named" "noref.pfm"
expect_status "sizes differ: a fail (status 1), the student's mistake" 1 $PATHLAB grade "$TMP/small.pfm" --ref "$TMP/c.pfm"
if grep -q "the wrong image size: 16x16, the reference is 32x32.*a reference at this size: pathlab render .*--size 16x16" "$TMP/out"; then pass "sizes differ: both sizes named, and a render command at the image's size"
else fail "sizes differ: no diagnosis with the command: $(head -c 300 "$TMP/out")"; fi
expect_status "no --ref: status 2" 2 $PATHLAB grade "$TMP/c.pfm"
$PFMTOOL const 32 32 0 0 0 "$TMP/zero.pfm"
$PFMTOOL const 16 16 0 0 0 "$TMP/zero16.pfm"
expect_status "--var of another size: status 2" 2 $PATHLAB grade "$TMP/c.pfm" --ref "$TMP/c.pfm" --var "$TMP/zero16.pfm"
expect_err "--var of another size: named" "zero16.pfm is 16x16, the reference .*c.pfm 32x32"
expect_status "--alpha 2: status 2" 2 $PATHLAB grade "$TMP/c.pfm" --ref "$TMP/c.pfm" --alpha 2
expect_err "--alpha 2: flag and value named" "^pathlab grade: --alpha expects .*got '2'"
expect_status "a class of two, one failing: status 1" 1 $PATHLAB grade "$TMP/c.pfm" "$TMP/c_bright.pfm" --ref "$TMP/c.pfm"
mkdir -p "$TMP/empty"
expect_status "an empty folder: status 2" 2 $PATHLAB grade "$TMP/empty" --ref "$TMP/c.pfm"
expect_err "an empty folder: said" "no image to grade"
mkdir -p "$TMP/class1"; cp "$TMP/c_bright.pfm" "$TMP/class1/"
expect_status "a folder without --ref: status 2, not a crash" 2 $PATHLAB grade "$TMP/class1"
expect_err "a folder without --ref: said" "needs an image .* and --ref REF.pfm"
# a folder: an image's extension in any case is graded (Bob.PFM was left out without a word), and
# what is not graded is counted on stderr
mkdir -p "$TMP/class2"; cp "$TMP/c.pfm" "$TMP/class2/alice.pfm"; cp "$TMP/c_bright.pfm" "$TMP/class2/Bob.PFM"
cp "$TMP/c.pfm" "$TMP/class2/x_var.pfm"; echo notes > "$TMP/class2/notes.txt"
expect_status "a folder with Bob.PFM (failing): graded, status 1" 1 $PATHLAB grade "$TMP/class2" --ref "$TMP/c.pfm"
if grep -q "class2/Bob.PFM: FAIL" "$TMP/out"; then pass "a folder: Bob.PFM graded"; else fail "a folder: Bob.PFM not graded: $(head -c 300 "$TMP/out")"; fi
expect_err "a folder: what is not graded counted" "the folder .*class2: not graded: 1 variance .*_var.pfm.*, 1 not .pfm or .hdr"
# a student's symbolic links leading out of the class folder are not read: one to the reference was
# taken for the reference (silently not graded), one to the grader's files was graded and its picture
# put in the student's page; a link inside the folder is read as the file it names
mkdir -p "$TMP/class4" "$TMP/secret4"; cp "$TMP/c.pfm" "$TMP/class4/alice.pfm"; cp "$TMP/c.pfm" "$TMP/secret4/s.pfm"
ln -s ../secret4/s.pfm "$TMP/class4/bob.pfm"; ln -s "$TMP/c.pfm" "$TMP/class4/carol.pfm"; ln -s alice.pfm "$TMP/class4/dave.pfm"
expect_status "links out of a class folder: status 2" 2 $PATHLAB grade "$TMP/class4" --ref "$TMP/c.pfm" --pages "$TMP/pages4"
for who in bob carol; do
    if grep -q "class4/$who.pfm: UNREADABLE, a symbolic link leading out of its folder: not read" "$TMP/out"; then pass "a link out of the folder ($who): not read, said in its row"
    else fail "a link out of the folder ($who): read: $(grep "$who" "$TMP/out" | head -c 300)"; fi
done
if grep -q "class4/dave.pfm: PASS" "$TMP/out"; then pass "a link inside the folder: graded"; else fail "a link inside the folder: $(grep dave "$TMP/out" | head -c 300)"; fi
if ls "$TMP/pages4" | grep -q bob; then fail "a link out of the folder: a page made for it: $(ls "$TMP/pages4")"; else pass "a link out of the folder: no page made for it"; fi
# a REF_var.pfm left from an earlier render of REF.pfm (re-rendered without --variance) was taken for
# the new reference's noise; its sidecar, naming none, now means none
mkdir -p "$TMP/stale"; $PATHLAB render scenes/cornell.obj --quiet --size 16x16 --spp 2 -o "$TMP/stale/ref.pfm" --variance "$TMP/stale/ref_var.pfm"
$PATHLAB render scenes/cornell.obj --quiet --size 16x16 --spp 16 -o "$TMP/stale/ref.pfm"
expect_status "a stale ref_var.pfm: graded" 0 $PATHLAB grade "$TMP/stale/ref.pfm" --ref "$TMP/stale/ref.pfm"
if grep -q "no REF_var.pfm" "$TMP/out" && ! grep -q "scatter against the reference's own noise" "$TMP/out"; then pass "a stale ref_var.pfm: not used"
else fail "a stale ref_var.pfm: used: $(grep -E "exact pixels|scatter" "$TMP/out" | head -c 300)"; fi
# a renamed reference (its sidecar still naming tmp_var.pfm) finds its variance beside it, checked by
# the variance's own sidecar; a variance copied without its sidecar is used as before
mkdir -p "$TMP/ren"; $PATHLAB render scenes/cornell.obj --quiet --size 16x16 --spp 8 -o "$TMP/ren/tmp.pfm" --variance "$TMP/ren/tmp_var.pfm"
for f in tmp.pfm tmp.pfm.meta tmp_var.pfm tmp_var.pfm.meta; do mv "$TMP/ren/$f" "$TMP/ren/${f/tmp/cornell}"; done
expect_status "a renamed reference: graded" 0 $PATHLAB grade "$TMP/ren/cornell.pfm" --ref "$TMP/ren/cornell.pfm"
if grep -q "scatter against the reference's own noise" "$TMP/out"; then pass "a renamed reference: its variance found beside it"
else fail "a renamed reference: its variance not used: $(grep -E "exact pixels" "$TMP/out" | head -c 200)"; fi
mv "$TMP/ren/cornell_var.pfm.meta" "$TMP/cornell_var_meta_aside"
expect_status "a variance without its sidecar: graded" 0 $PATHLAB grade "$TMP/ren/cornell.pfm" --ref "$TMP/ren/cornell.pfm"
if grep -q "scatter against the reference's own noise" "$TMP/out"; then pass "a variance without its sidecar: used"
else fail "a variance without its sidecar: not used: $(err_tail "$TMP/err")"; fi
# a teacher's store of references reached by links (grading/ref.pfm -> ../store/c.pfm, its variance
# beside the file it leads to): grade stopped on "a symbolic link leads out"
mkdir -p "$TMP/store" "$TMP/grading"; $PATHLAB render scenes/cornell.obj --quiet --size 16x16 --spp 8 -o "$TMP/store/c.pfm" --variance "$TMP/store/c_var.pfm"
rm "$TMP"/store/*.meta; ln -s ../store/c.pfm "$TMP/grading/ref.pfm"; ln -s ../store/c_var.pfm "$TMP/grading/ref_var.pfm"
expect_status "--ref a link to a store, its variance a link too: graded" 0 $PATHLAB grade "$TMP/store/c.pfm" --ref "$TMP/grading/ref.pfm"
if grep -q "scatter against the reference's own noise" "$TMP/out"; then pass "--ref a link to a store: its variance used"; else fail "--ref a link to a store: no variance: $(err_tail "$TMP/err")"; fi
# the old name of a renamed pair reused by the next render: the variance beside, of this render (its
# sidecar says so), is used; without its sidecar nothing shows it is this render's: refused
mv "$TMP/cornell_var_meta_aside" "$TMP/ren/cornell_var.pfm.meta"
$PATHLAB render scenes/cornell.obj --quiet --size 16x16 --spp 4 --seed 9 -o "$TMP/ren/tmp.pfm" --variance "$TMP/ren/tmp_var.pfm"
expect_status "a renamed pair whose old variance name is another render's: graded" 0 $PATHLAB grade "$TMP/ren/cornell.pfm" --ref "$TMP/ren/cornell.pfm"
expect_err "a renamed pair, the old name reused: the variance beside used, said" "names its variance tmp_var.pfm, now of another render; .*cornell_var.pfm beside it is this render's: used"
mv "$TMP/ren/cornell_var.pfm.meta" "$TMP/cornell_var_meta_aside"
expect_status "a renamed pair, the old name reused, the variance beside without a sidecar: refused" 2 $PATHLAB grade "$TMP/ren/cornell.pfm" --ref "$TMP/ren/cornell.pfm"
expect_err "... said: two renders mixed up" "tmp_var.pfm .*files of two renders mixed up"
mv "$TMP/cornell_var_meta_aside" "$TMP/ren/cornell_var.pfm.meta"
# a stale ref_var.pfm of the same scene under another --sky image is not this render's (sky-id)
mkdir -p "$TMP/sk2"; "$PFMTOOL" const 8 4 1 1 1 "$TMP/sk2/sky.pfm"
$PATHLAB render scenes/quad-light.obj --quiet --size 16x16 --spp 4 --sampler independent --sky "$TMP/sk2/sky.pfm" -o "$TMP/sk2/ref.pfm" --variance "$TMP/sk2/ref_var.pfm"
"$PFMTOOL" const 8 4 5 5 5 "$TMP/sk2/sky.pfm"
$PATHLAB render scenes/quad-light.obj --quiet --size 16x16 --spp 4 --sampler independent --sky "$TMP/sk2/sky.pfm" -o "$TMP/sk2/ref.pfm"
expect_status "a stale ref_var.pfm of another sky: graded" 0 $PATHLAB grade "$TMP/sk2/ref.pfm" --ref "$TMP/sk2/ref.pfm"
expect_err "a stale ref_var.pfm of another sky: not used, said" "ref_var.pfm is not the variance of .*ref.pfm"
# --ref a link to a store whose c_var.pfm is stale (c.pfm re-rendered without --variance): not used;
# and a store of content names (abc, x_var.pfm) reached by links beside --ref: the variance link used
mkdir -p "$TMP/st2/store" "$TMP/st2/grading"
$PATHLAB render scenes/cornell.obj --quiet --size 16x16 --spp 4 -o "$TMP/st2/store/c.pfm" --variance "$TMP/st2/store/c_var.pfm"
$PATHLAB render scenes/cornell.obj --quiet --size 16x16 --spp 8 -o "$TMP/st2/store/c.pfm"; ln -s ../store/c.pfm "$TMP/st2/grading/ref.pfm"
expect_status "--ref a link, a stale variance beside its file: graded" 0 $PATHLAB grade "$TMP/st2/store/c.pfm" --ref "$TMP/st2/grading/ref.pfm"
expect_err "--ref a link, a stale variance beside its file: not used, said" "c_var.pfm is not the variance of .*c.pfm"
mkdir -p "$TMP/st3/store" "$TMP/st3/grading"
$PATHLAB render scenes/cornell.obj --quiet --size 16x16 --spp 4 -o "$TMP/st3/store/abc.pfm" --variance "$TMP/st3/store/def.pfm"
ln -s ../store/abc.pfm "$TMP/st3/grading/ref.pfm"; ln -s ../store/abc.pfm.meta "$TMP/st3/grading/ref.pfm.meta"
ln -s ../store/def.pfm "$TMP/st3/grading/def.pfm"; ln -s ../store/def.pfm.meta "$TMP/st3/grading/def.pfm.meta"
expect_status "a store of content names reached by links: graded" 0 $PATHLAB grade "$TMP/st3/store/abc.pfm" --ref "$TMP/st3/grading/ref.pfm"
if grep -q "scatter against the reference's own noise" "$TMP/out"; then pass "a store of content names reached by links: the variance used"
else fail "a store of content names reached by links: no variance: $(err_tail "$TMP/err")"; fi
# an image scaled by 1e-30 was diagnosed "quantised to 8 bits" (each value within 1e-3 of 0 / 255)
mkdir -p "$TMP/q"; $PATHLAB render scenes/cornell.obj --quiet --size 32x32 --spp 64 -o "$TMP/q/ref.pfm" --variance "$TMP/q/ref_var.pfm"
$PATHLAB render scenes/cornell.obj --quiet --size 32x32 --spp 16 --seed 5 -o "$TMP/q/s.pfm"; "$PFMTOOL" scale "$TMP/q/s.pfm" 1e-30 "$TMP/q/tiny.pfm"
expect_status "an image x 1e-30: fails" 1 $PATHLAB grade "$TMP/q/tiny.pfm" --ref "$TMP/q/ref.pfm"
if grep -q "quantised" "$TMP/out"; then fail "an image x 1e-30: called quantised: $(grep -m1 quantised "$TMP/out")"; else pass "an image x 1e-30: not called quantised to 8 bits"; fi
# the reference inside the class folder: a student's bob.pfm -> ref.pfm was left out as the reference
# (now graded, flagged a copy); the teacher's --ref class5/ref.pfm -> ../refs5/c.pfm is the reference
mkdir -p "$TMP/class5" "$TMP/refs5"; cp "$TMP/c.pfm" "$TMP/class5/ref.pfm"; cp "$TMP/c.pfm" "$TMP/class5/alice.pfm"; ln -s ref.pfm "$TMP/class5/bob.pfm"
$PATHLAB grade "$TMP/class5" --ref "$TMP/class5/ref.pfm" > "$TMP/out" 2> "$TMP/err"
if grep -q "class5/bob.pfm: .*FLAGGED: identical to the reference" "$TMP/out"; then pass "a link to the reference inside the folder: graded, flagged a copy"
else fail "a link to the reference inside the folder: $(grep bob "$TMP/out" | head -c 200) $(err_tail "$TMP/err")"; fi
mkdir -p "$TMP/class6"; cp "$TMP/c.pfm" "$TMP/refs5/c.pfm"; ln -s ../refs5/c.pfm "$TMP/class6/ref.pfm"; cp "$TMP/c.pfm" "$TMP/class6/alice.pfm"
expect_status "--ref a link in the class folder: it is the reference, not a student (exit 0)" 0 $PATHLAB grade "$TMP/class6" --ref "$TMP/class6/ref.pfm"
# --heatmap FOLDER with one image (a class of one): FOLDER/NAME.png (it wrote to the folder's name: exit 2)
mkdir -p "$TMP/hm1"
expect_status "a class of one, --heatmap FOLDER: graded (a fail), status 1" 1 $PATHLAB grade "$TMP/class1" --ref "$TMP/c.pfm" --heatmap "$TMP/hm1"
if [ -s "$TMP/hm1/c_5fbright.png" ]; then pass "a class of one, --heatmap FOLDER: FOLDER/NAME.png written"
else fail "a class of one, --heatmap FOLDER: no $TMP/hm1/c_5fbright.png: $(ls "$TMP/hm1")"; fi
# a student named like the report, pages in the report's folder: refused before anything is written
mkdir -p "$TMP/class3" "$TMP/rep3"; cp "$TMP/c.pfm" "$TMP/class3/index.pfm"; cp "$TMP/c.pfm" "$TMP/class3/alice.pfm"
expect_status "index.pfm's page would be --report rep3/index.html: status 2" 2 $PATHLAB grade "$TMP/class3" --ref "$TMP/c.pfm" --report "$TMP/rep3/index.html" --pages "$TMP/rep3"
expect_err "index.pfm's page would be the report: said" "the page of .*index.pfm would be .*rep3/index.html, the --report itself"
expect_no_file "index.pfm's page would be the report: nothing written" "$TMP/rep3/alice.html"
# a flag given twice (a student's file named --ref=x.pfm, expanded by the shell's *.pfm) is refused
expect_status "--ref given twice: status 2" 2 $PATHLAB grade --ref "$TMP/c.pfm" "$TMP/c.pfm" "--ref=$TMP/c_bright.pfm"
expect_err "--ref given twice: said, with the way out" "--ref given twice .again as '--ref=.*c_bright.pfm'.: give it once.*put -- before the file names"
# a 4 MB run-length .hdr whose resolution line claims 8192x8192 (the wrong size): refused from its
# header, nothing decoded (it was decoded whole first: 793 MB, 1.4 s)
python3 - "$TMP/big.hdr" <<'PYEND'
import sys
n = 8192
line = bytes([2, 2, n >> 8, n & 255])
for c in range(4):
    left = n
    while left:
        k = min(127, left); line += bytes([128 + k, 128 if c < 3 else 129]); left -= k
open(sys.argv[1], 'wb').write(b'#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n' % (n, n) + line * n)
PYEND
if [ -x /usr/bin/time ]; then
    /usr/bin/time -f 'maxrss %M' -o "$TMP/time" $PATHLAB grade "$TMP/big.hdr" --ref "$TMP/c.pfm" > "$TMP/out" 2> "$TMP/err"; rc=$?
    rss=$(sed -n 's/^maxrss //p' "$TMP/time")
    if [ $rc = 1 ] && grep -q "the wrong image size: 8192x8192" "$TMP/out" && [ "${rss:-999999999}" -lt 200000 ]; then
        pass "an .hdr claiming 8192x8192: the wrong size, from its header ($rss KB)"
    else fail "an .hdr claiming 8192x8192: exit $rc, $rss KB (under 200000 wanted): $(head -c 300 "$TMP/out")"; fi
else skip "an .hdr claiming 8192x8192 refused from its header (needs /usr/bin/time)"; fi
expect_status "a class with an unreadable image: status 2" 2 $PATHLAB grade "$TMP/c.pfm" "$TMP/none.pfm" --ref "$TMP/c.pfm"
expect_status "--heatmap of an unknown format: status 2" 2 $PATHLAB grade "$TMP/c.pfm" --ref "$TMP/c.pfm" --heatmap "$TMP/h.jpg"
expect_err "--heatmap of an unknown format explained" "^pathlab grade: --heatmap .*h.jpg: a heatmap is a picture: use .png or .ppm"
expect_status "--heatmap h.pfm: refused (a picture, not a render), status 2" 2 $PATHLAB grade "$TMP/c.pfm" --ref "$TMP/c.pfm" --heatmap "$TMP/h.pfm"
expect_status "--ref before the image: status 0" 0 $PATHLAB grade --ref "$TMP/c.pfm" "$TMP/c.pfm"
# A black image but for one pixel, which holds all the reference's light (or 1e4; or an honest render
# with one value of 3.4e38), against ref/cornell.pfm (64x64, the whole light transport): every block
# is "rare-event noise" and the plain t is about 1 whatever that pixel, so these passed. The plain
# mean's standard error is 100% of the mean and more: too noisy to judge, a FAIL (a PASS needs 50%).
# The honest 16-spp render they are made from passes.
$PATHLAB render scenes/cornell.obj --quiet --size 64x64 --spp 16 --seed 301 -o "$TMP/honest64.pfm"
python3 - ref/cornell.pfm "$TMP/honest64.pfm" "$TMP" <<'PYEND'
import struct, sys
def rd(fn):
    d = open(fn, 'rb').read().split(b'\n', 3)
    w, h = map(int, d[1].split())
    return w, h, list(struct.unpack('<%df' % (3 * w * h), d[3][:12 * w * h]))
def wr(fn, w, h, v):
    open(fn, 'wb').write(b'PF\n%d %d\n-1\n' % (w, h) + struct.pack('<%df' % len(v), *v))
w, h, ref = rd(sys.argv[1])
_, _, honest = rd(sys.argv[2])
one = [0.0] * len(ref)
for c in range(3): one[3 * (w * h // 2 + w // 2) + c] = sum(ref[c::3])
wr(sys.argv[3] + '/one_pixel.pfm', w, h, one)
one[3 * (w * h // 2 + w // 2)] = 1e4
wr(sys.argv[3] + '/one_1e4.pfm', w, h, one)
honest[3 * 100 + 1] = 3.4e38
wr(sys.argv[3] + '/honest_3e38.pfm', w, h, honest)
PYEND
for f in honest64 one_pixel one_1e4 honest_3e38; do
    want=1; [ $f = honest64 ] && want=0
    out=$($PATHLAB grade "$TMP/$f.pfm" --ref ref/cornell.pfm 2>&1); rc=$?
    line=$(echo "$out" | grep -E "^(PASS|FAIL)|^  too noisy" | paste -sd ';' - | cut -c1-300)
    if [ $rc = $want ] && { [ $want = 0 ] || echo "$out" | grep -q "^  too noisy to judge: the whole image's mean is known to"; }; then
        pass "$f against ref/cornell.pfm: exit $rc [$line]"
    else fail "$f against ref/cornell.pfm: exit $rc, wanted $want$([ $want = 1 ] && echo ', too noisy to judge') [$line]"; fi
done
echo "grade tests took $(( $(date +%s) - start )) s (size $SIZE, reference $REF_SPP spp)"
exit 0
