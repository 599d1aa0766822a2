#!/usr/bin/env bash
# Renders in passes, addressable samples, merge and resume:
#  - a render stopped by SIGINT or SIGTERM writes the uniform-spp image it reached, byte for byte
#    the --spp N render of the spp it says; a second signal writes nothing and leaves no temporary file;
#  - --time writes as many spp as fit, byte for byte the --spp N render;
#  - --samples pieces, merged, equal the whole render within float rounding (means: 4 ulp, variances
#    1e-4 relative: they are recombined from float means), whatever the order of the pieces;
#  - --resume equals the longer render within the same rounding;
#  - merge and --resume refuse what is not the same render, naming the difference; merge refuses a
#    piece holding a NaN, and an output that is one of its inputs.
. "$(dirname "$0")/lib.sh"
R="$PATHLAB render scenes/cornell.obj --quiet --size 48x32"
MEAN_TOL=5e-7   # 4 ulp of a float (2^-21 relative): the sums are in double, only the stored means round
VAR_TOL=1e-4    # variances of the means are rebuilt from float means and variances: a little more rounding

close() {   # close NAME A B TOL
    local msg
    msg=$("$PFMTOOL" close "$2" "$3" "$4"); local rc=$?
    if [ $rc -eq 0 ]; then pass "$1 ($msg)"; else fail "$1: $msg (tolerance $4), status $rc"; fi
}
same_bytes() {   # same_bytes NAME A B
    if cmp -s "$2" "$3"; then pass "$1"; else fail "$1: $2 and $3 differ"; fi
}
meta() { sed -n "s/^$2 //p" "$1.meta"; }   # meta FILE KEY

# 1. a stopped render: SIGINT then SIGTERM, during a render far longer than the wait
for sig in INT TERM; do
    $PATHLAB render scenes/cornell.obj --size 96x64 --spp 1000000 --threads 2 -o "$TMP/stop.pfm" --variance "$TMP/stop_var.pfm" \
        2> "$TMP/err" & pid=$!
    sleep 1.5; kill -$sig $pid; wait $pid; rc=$?
    want=$([ $sig = INT ] && echo 130 || echo 143)
    if [ $rc -eq $want ]; then pass "SIG$sig: exit status $rc (128 + signal), after writing"; else fail "SIG$sig: exit status $rc, expected $want"; fi
    expect_err "SIG$sig: says where it stopped and what it wrote" "interrupted \(SIG$sig\) at [0-9]+ of 1000000 spp.*written .*stop.pfm and .*stop_var.pfm"
    n=$(meta "$TMP/stop.pfm" spp)
    if [ "$(meta "$TMP/stop.pfm" samples)" = "0:$n" ] && [ "$(meta "$TMP/stop.pfm" stopped)" = "SIG$sig" ] && [ "$n" -ge 1 ]; then
        pass "SIG$sig: the sidecar says samples 0:$n, stopped SIG$sig"
    else fail "SIG$sig: sidecar: $(cat "$TMP/stop.pfm.meta" | tr '\n' ' ')"; fi
    $PATHLAB render scenes/cornell.obj --quiet --size 96x64 --spp "$n" --threads 1 -o "$TMP/full.pfm" --variance "$TMP/full_var.pfm"
    same_bytes "SIG$sig at $n spp: the image is the --spp $n render, byte for byte (a uniform-spp image)" "$TMP/stop.pfm" "$TMP/full.pfm"
    same_bytes "SIG$sig at $n spp: the variance too" "$TMP/stop_var.pfm" "$TMP/full_var.pfm"
done

# 2. two signals: stop at once, nothing written, no temporary file
rm -f "$TMP"/two*
# the second signal must come while the pass is still running: the image is large (a pass of one
# sample at 640x480 is 0.3 s or more in every build), and it is sent as soon as the render has said
# that it took the first (a fixed 50 ms let the sanitizer build, now faster, write its image first)
$PATHLAB render scenes/cornell.obj --size 640x480 --spp 1000000 -o "$TMP/two.pfm" --variance "$TMP/two_var.pfm" 2> "$TMP/err" & pid=$!
sleep 1; kill -INT $pid
for _ in $(seq 1 500); do grep -q 'finishing the current pass' "$TMP/err" && break; sleep 0.005; done
kill -INT $pid; wait $pid; rc=$?
if [ $rc -eq 130 ]; then pass "two SIGINTs: exit status 130"; else fail "two SIGINTs: exit status $rc"; fi
if [ -z "$(ls "$TMP" | grep '^two')" ]; then pass "two SIGINTs: no image, no sidecar, no temporary file"
else fail "two SIGINTs left: $(ls "$TMP" | grep '^two' | tr '\n' ' ')"; fi

# 3. --time: as many passes as fit, and the image is the --spp N render
$PATHLAB render scenes/cornell.obj --size 96x64 --time 1 -o "$TMP/t.pfm" 2> "$TMP/err"
n=$(meta "$TMP/t.pfm" spp)
$PATHLAB render scenes/cornell.obj --quiet --size 96x64 --spp "$n" -o "$TMP/tn.pfm"
same_bytes "--time 1 reached $n spp: the image is the --spp $n render" "$TMP/t.pfm" "$TMP/tn.pfm"
$PATHLAB render scenes/cornell.obj --size 96x64 --time 0.5 --spp 1000000 -o "$TMP/t.pfm" 2> "$TMP/err"
expect_err "--time with --spp: says how many of the spp fitted" "--time 0.5 s: [0-9]+ of 1000000 spp fitted"
[ "$(meta "$TMP/t.pfm" stopped)" = time ] && pass "--time: the sidecar says stopped time" || fail "--time: no 'stopped time' in the sidecar"

# 4. --samples pieces merged = the whole render (image, variance, --split layers), in any order
F="--bounces 0:3 --split --seed 5"
$R $F --spp 24 -o "$TMP/whole.pfm" --variance "$TMP/whole_var.pfm"
$R $F --samples 0:7 -o "$TMP/a.pfm" --variance "$TMP/a_var.pfm"
$R $F --samples 7:8 -o "$TMP/b.pfm" --variance "$TMP/b_var.pfm"
mkdir -p "$TMP/far"; $R $F --samples 8:24 -o "$TMP/far/c.pfm" --variance "$TMP/far/c_var.pfm"
expect_status "merge of 3 pieces (one of 1 sample, one in another folder)" 0 $PATHLAB merge "$TMP/m.pfm" "$TMP/far/c.pfm" "$TMP/a.pfm" "$TMP/b.pfm" --variance "$TMP/m_var.pfm"
close "merged = whole: image" "$TMP/m.pfm" "$TMP/whole.pfm" $MEAN_TOL
close "merged = whole: variance of the mean" "$TMP/m_var.pfm" "$TMP/whole_var.pfm" $VAR_TOL
close "merged = whole: layer L0" "$TMP/m_L0.pfm" "$TMP/whole_L0.pfm" $MEAN_TOL
close "merged = whole: layer L3" "$TMP/m_L3.pfm" "$TMP/whole_L3.pfm" $MEAN_TOL
close "merged = whole: variance of layer L2" "$TMP/m_var_L2.pfm" "$TMP/whole_var_L2.pfm" $VAR_TOL
[ "$(meta "$TMP/m.pfm" samples)" = "0:24" ] && pass "merged sidecar: samples 0:24" || fail "merged sidecar: samples $(meta "$TMP/m.pfm" samples)"
$PATHLAB merge "$TMP/m2.pfm" "$TMP/a.pfm" "$TMP/b.pfm" "$TMP/far/c.pfm" --variance "$TMP/m2_var.pfm" 2> /dev/null
same_bytes "the order of the pieces does not matter (byte for byte)" "$TMP/m.pfm" "$TMP/m2.pfm"
# the merge is not a copy of one piece: each piece alone is far from the whole
if ! "$PFMTOOL" close "$TMP/a.pfm" "$TMP/whole.pfm" 1e-3 > /dev/null; then pass "one piece alone is not the whole (the test can fail)"
else fail "a piece of 7 samples equals the 24-sample render"; fi
expect_status "pieces with a gap merge (samples 0:7,8:24)" 0 $PATHLAB merge "$TMP/g.pfm" "$TMP/a.pfm" "$TMP/far/c.pfm"
[ "$(meta "$TMP/g.pfm" samples)" = "0:7,8:24" ] && pass "the gap is in the sidecar: 0:7,8:24" || fail "gap sidecar: $(meta "$TMP/g.pfm" samples)"

# 5. merge refuses what is not one render, and says why
for f in "" _L0 _L1 _L2 _L3; do cp "$TMP/b$f.pfm" "$TMP/nan$f.pfm"; cp "$TMP/b$f.pfm.meta" "$TMP/nan$f.pfm.meta"; done
printf '\000\000\300\177' | dd of="$TMP/nan.pfm" bs=1 seek=$(( $(head -n 3 "$TMP/nan.pfm" | wc -c) + 12 )) conv=notrunc 2> /dev/null
expect_status "merge: a piece with a NaN refused (it made the merge NaN)" 2 $PATHLAB merge "$TMP/x.pfm" "$TMP/a.pfm" "$TMP/nan.pfm"
expect_err "merge: names the piece and the NaN" "nan.pfm: 1 pixel-channel is NaN"
expect_no_file "merge: nothing written after a NaN piece" "$TMP/x.pfm"
cp "$TMP/a.pfm" "$TMP/self.pfm"; cp "$TMP/a.pfm.meta" "$TMP/self.pfm.meta"
expect_status "merge: -o one of the pieces refused" 2 $PATHLAB merge "$TMP/./self.pfm" "$TMP/self.pfm" "$TMP/b.pfm"
expect_err "merge: says -o is an input" "is the input .*self.pfm: write the merge to a new file"
$R $F --samples 5:10 -o "$TMP/over.pfm"
expect_status "merge: overlapping samples refused" 2 $PATHLAB merge "$TMP/x.pfm" "$TMP/a.pfm" "$TMP/over.pfm"
expect_err "merge: names the samples taken twice" "both have samples 5:7"
$R --bounces 0:3 --split --seed 6 --samples 7:8 -o "$TMP/seed.pfm"
expect_status "merge: another seed refused" 2 $PATHLAB merge "$TMP/x.pfm" "$TMP/a.pfm" "$TMP/seed.pfm"
expect_err "merge: names the seed" "differ in seed"
$R $F --rr off --samples 7:8 -o "$TMP/rr.pfm"
expect_status "merge: other flags refused" 2 $PATHLAB merge "$TMP/x.pfm" "$TMP/a.pfm" "$TMP/rr.pfm"
expect_err "merge: names the flags" "differ in flags"
$R $F --fov 30 --samples 7:8 -o "$TMP/cam.pfm"
expect_status "merge: another camera refused" 2 $PATHLAB merge "$TMP/x.pfm" "$TMP/a.pfm" "$TMP/cam.pfm"
expect_err "merge: names the camera" "differ in camera"
sed 's/^Kd .*/Kd 0.9 0.1 0.1/' scenes/cornell.mtl > "$TMP/cornell.mtl"; cp scenes/cornell.obj scenes/cornell.view "$TMP"/ 2>/dev/null
$PATHLAB render "$TMP/cornell.obj" --quiet --size 48x32 $F --samples 7:8 -o "$TMP/scene.pfm"
expect_status "merge: another scene (a material changed) refused" 2 $PATHLAB merge "$TMP/x.pfm" "$TMP/a.pfm" "$TMP/scene.pfm"
expect_err "merge: names the scene" "differ in scene"
cp "$TMP/b.pfm" "$TMP/nometa.pfm"
expect_status "merge: an image without sidecar refused" 2 $PATHLAB merge "$TMP/x.pfm" "$TMP/a.pfm" "$TMP/nometa.pfm"
expect_err "merge: says the sidecar is missing" "nometa.pfm has no sidecar"
$R $F --samples 7:8 -o "$TMP/novar.pfm"
expect_status "merge --variance: a piece without variance refused" 2 $PATHLAB merge "$TMP/x.pfm" "$TMP/a.pfm" "$TMP/novar.pfm" --variance "$TMP/x_var.pfm"
expect_err "merge --variance: names it" "novar.pfm was rendered without --variance"
expect_no_file "merge: nothing written after a refusal" "$TMP/x.pfm" "$TMP/x_var.pfm"

# 6. --resume: adds samples, and equals the longer render
$R $F --spp 10 -o "$TMP/res.pfm" --variance "$TMP/res_var.pfm"
expect_status "--resume from 10 to 24 spp" 0 $R $F --spp 24 -o "$TMP/res.pfm" --resume
close "resumed = the 24-spp render: image" "$TMP/res.pfm" "$TMP/whole.pfm" $MEAN_TOL
close "resumed = the 24-spp render: variance (kept up to date without naming it)" "$TMP/res_var.pfm" "$TMP/whole_var.pfm" $VAR_TOL
close "resumed = the 24-spp render: layer L1" "$TMP/res_L1.pfm" "$TMP/whole_L1.pfm" $MEAN_TOL
[ "$(meta "$TMP/res.pfm" samples)" = "0:24" ] && pass "resumed sidecar: samples 0:24" || fail "resumed sidecar: $(meta "$TMP/res.pfm" samples)"
expect_status "--resume when the spp are there already: nothing to do" 0 $R $F --spp 24 -o "$TMP/res.pfm" --resume
expect_err "--resume: says there is nothing to add" "already has 24 spp"
expect_status "--resume with other flags refused" 2 $R $F --rr 5 --spp 30 -o "$TMP/res.pfm" --resume
expect_err "--resume: names the flag and both values" "--rr is 5 on the command line but 3 in .*res.pfm's sidecar"
# --resume -o FILE alone: the scene, camera, size, flags and seed are the sidecar's
$R $F --spp 10 -o "$TMP/alone.pfm" --variance "$TMP/alone_var.pfm"
expect_status "--resume -o FILE --spp 24 alone (the rest from its sidecar)" 0 $PATHLAB render --resume --spp 24 -o "$TMP/alone.pfm"
expect_err "--resume: the stats line says the total and the samples added" " 24 spp in all \(14 added to the 10 it had\)"
close "--resume alone = the 24-spp render: image" "$TMP/alone.pfm" "$TMP/whole.pfm" $MEAN_TOL
close "--resume alone = the 24-spp render: layer L3" "$TMP/alone_L3.pfm" "$TMP/whole_L3.pfm" $MEAN_TOL
for bad in "--size 64x64|--size is 64x64 on the command line but 48x32" "--seed 6|--seed is 6 on the command line but 5" \
           "--bounces 0:2|--bounces is 0:2 on the command line but 0:3" "--pixel-center|--pixel-center is \(given\) on the command line but \(not given\)" \
           "--eye 1,2,3|--eye is 1,2,3 on the command line but "; do
    # shellcheck disable=SC2086
    expect_status "--resume -o FILE ${bad%%|*}: refused" 2 $PATHLAB render --resume --spp 30 ${bad%%|*} -o "$TMP/alone.pfm"
    expect_err "--resume -o FILE ${bad%%|*}: names the flag and both values" "${bad#*|}"
done
expect_status "--resume of a missing image refused" 2 $R --spp 30 -o "$TMP/none.pfm" --resume
expect_err "--resume: says there is nothing to resume" "does not exist"
expect_status "--resume needs --spp or --time" 2 $R -o "$TMP/res.pfm" --resume
expect_status "--samples with --spp refused" 2 $R --samples 0:4 --spp 4 -o "$TMP/x.pfm"
expect_status "--samples 4:4 refused" 2 $R --samples 4:4 -o "$TMP/x.pfm"
expect_err "--samples: says what it expects" "expects A:B"

# 7. progress in a log (stderr not a terminal): a line every 5 s with the spp, the time and an ETA a person reads
$PATHLAB render scenes/cornell.obj --size 96x64 --time 5.6 -o "$TMP/p.pfm" 2> "$TMP/err"
expect_err "progress in a log: one line after 5 s, with spp, elapsed time and ETA" "^progress: +[0-9]+%  [0-9]+ spp, --time 5\.6s  5\.[0-9]s elapsed, ETA 0\.[0-9]s$"

# 8. grade reads the reference's sidecar: provenance, the variance and --split layers it names, and
# for an image of another size the command that renders the reference at that size
mkdir -p "$TMP/g"
$R --bounces 0:4 --split --spp 32 -o "$TMP/g/ref.pfm" --variance "$TMP/g/ref_variance.pfm"
$R --bounces 0:1 --spp 8 --seed 9 -o "$TMP/direct.pfm"
expect_status "grade against a render --split --variance reference: the direct-only image fails" 1 $PATHLAB grade "$TMP/direct.pfm" --ref "$TMP/g/ref.pfm"
if grep -qE "^reference .*ref.pfm: 32 spp \(samples 0:32\), seed 1, scenes/cornell.obj --bounces 0:4" "$TMP/out"; then pass "grade prints the reference's provenance"
else fail "grade: no provenance line: $(head -c 300 "$TMP/out")"; fi
if grep -q "likely mistake: direct light only" "$TMP/out"; then pass "grade finds the layers ref_L0.pfm ... through the sidecar (names direct light only)"
else fail "grade did not use the sidecar's layers: $(grep -i likely "$TMP/out")"; fi
if grep -q "noise floor" "$TMP/out"; then pass "grade finds ref_variance.pfm through the sidecar"; else fail "grade did not find the variance the sidecar names"; fi
$R --bounces 0:4 --spp 4 --size 40x30 -o "$TMP/small.pfm"
expect_status "grade: an image of another size fails" 1 $PATHLAB grade "$TMP/small.pfm" --ref "$TMP/g/ref.pfm"
if grep -qE "a reference at this size: pathlab render scenes/cornell.obj --eye [-0-9.,e]+ --target [-0-9.,e]+ --up [-0-9.,e]+ --fov [0-9.]+ --size 40x30 --bounces 0:4 .* --seed 1 --spp 32 -o .*ref-40x30.pfm" "$TMP/out"
then pass "grade: the command for a reference at 40x30, with the reference's camera, flags and seed"
else fail "grade: no command from the sidecar: $(grep -o 'a reference at this size.*' "$TMP/out")"; fi

# 9. the files of a render are renamed together: a variance that cannot be written leaves no new image
$R --spp 2 -o "$TMP/set.pfm" --variance "$TMP/set_var.pfm"
cp "$TMP/set.pfm" "$TMP/set_before.pfm"
expect_status "a variance in a folder that does not exist: exit 2 (checked before rendering)" 2 $R --spp 4 --seed 3 -o "$TMP/set.pfm" --variance "$TMP/nofolder/v.pfm"
same_bytes "the image of the earlier render is left whole, not replaced by a half set" "$TMP/set.pfm" "$TMP/set_before.pfm"
if [ -z "$(ls "$TMP" | grep -E '\.pending|\.tmp')" ]; then pass "no temporary file left"; else fail "left: $(ls "$TMP" | grep -E '\.pending|\.tmp')"; fi

# 10. what a hostile review of merge and --resume found (2026-12-08), each failing on the build before
# a newline in the scene's name wrote lines of its own into the sidecar: "samples 0:1000" after 5
mkdir -p "$TMP/nl"; cp scenes/cornell.mtl "$TMP/nl/"; NL=$'evil\nsamples 0:1000\nx.obj'; cp scenes/cornell.obj "$TMP/nl/$NL"
$PATHLAB render "$TMP/nl/$NL" --quiet --size 8x8 --samples 0:5 -o "$TMP/nl/a.pfm"
[ "$(meta "$TMP/nl/a.pfm" samples)" = "0:5" ] && pass "a newline in the scene's name: the sidecar keeps samples 0:5" || fail "a newline in the scene's name: samples $(meta "$TMP/nl/a.pfm" samples | tr '\n' ' ')"
expect_status "a newline in the scene's name: --resume reloads that scene" 0 $PATHLAB render --resume -o "$TMP/nl/a.pfm" --spp 8 --quiet
[ "$(meta "$TMP/nl/a.pfm" samples)" = "0:8" ] && pass "a newline in the scene's name: resumed to 0:8" || fail "resumed: samples $(meta "$TMP/nl/a.pfm" samples | tr '\n' ' ')"
# a --sky path with a space could not be resumed (the flags line is split at spaces); a sky file changed
# under the same name merged with renders of the old one
mkdir -p "$TMP/sk"; "$PFMTOOL" const 8 4 1 1 1 "$TMP/sk/my sky.pfm"
Q="$PATHLAB render scenes/quad-light.obj --quiet --size 8x8 --sky"
$Q "$TMP/sk/my sky.pfm" --samples 0:2 -o "$TMP/sk/a.pfm" --variance "$TMP/sk/a_var.pfm"
expect_status "a --sky path with a space: resumed" 0 $PATHLAB render --resume -o "$TMP/sk/a.pfm" --spp 4 --quiet
"$PFMTOOL" const 8 4 5 5 5 "$TMP/sk/my sky.pfm"
$Q "$TMP/sk/my sky.pfm" --samples 4:6 -o "$TMP/sk/b.pfm" --variance "$TMP/sk/b_var.pfm"
expect_status "merge: renders of two different sky images of one name refused" 2 $PATHLAB merge "$TMP/sk/m.pfm" "$TMP/sk/a.pfm" "$TMP/sk/b.pfm"
expect_err "merge: says the sky images differ" "differ in --sky image"
expect_status "--resume under another sky image of that name refused" 2 $PATHLAB render --resume -o "$TMP/sk/a.pfm" --spp 8 --quiet
# merge: --variance naming the output wrote the variance there (exit 1); an output over an input's
# variance destroyed the pieces; --split layers merged alone were relabelled "total", then merged with totals
expect_status "merge: --variance = the output refused" 2 $PATHLAB merge "$TMP/mm.pfm" "$TMP/a.pfm" "$TMP/b.pfm" --variance "$TMP/./mm.pfm"
expect_no_file "merge: --variance = the output: nothing written" "$TMP/mm.pfm"
mkdir -p "$TMP/ov"; cp "$TMP"/a.pfm* "$TMP"/a_var.pfm* "$TMP"/b.pfm* "$TMP"/b_var.pfm* "$TMP/ov/"
cp "$TMP/ov/a_var.pfm" "$TMP/ov/a_var_before.pfm"
expect_status "merge over a piece's variance refused" 2 $PATHLAB merge "$TMP/ov/a_var.pfm" "$TMP/ov/a.pfm" "$TMP/ov/b.pfm"
expect_err "merge over a piece's variance: says whose" "write over .*a_var.pfm, a file of the input .*a.pfm"
same_bytes "merge over a piece's variance: the variance left whole" "$TMP/ov/a_var.pfm" "$TMP/ov/a_var_before.pfm"
mkdir -p "$TMP/ly"
$R --bounces 0:2 --split --samples 0:3 -o "$TMP/ly/a.pfm"; $R --bounces 0:2 --split --samples 3:6 -o "$TMP/ly/b.pfm"; $R --bounces 0:2 --samples 6:9 -o "$TMP/ly/c.pfm"
expect_status "merge of two L1 layers" 0 $PATHLAB merge "$TMP/ly/l1.pfm" "$TMP/ly/a_L1.pfm" "$TMP/ly/b_L1.pfm"
[ "$(meta "$TMP/ly/l1.pfm" layer)" = "L1" ] && pass "merged L1 layers stay layer L1" || fail "merged L1 layers: layer $(meta "$TMP/ly/l1.pfm" layer)"
expect_status "merge of the merged L1 with a total refused" 2 $PATHLAB merge "$TMP/ly/x.pfm" "$TMP/ly/l1.pfm" "$TMP/ly/c.pfm"
# 256 ranges near 2^62 need 10 kB: the samples line was cut at 8191 characters (an unreadable sidecar)
mkdir -p "$TMP/many"; B=4611686018427380000
$PATHLAB render scenes/cornell.obj --quiet --size 4x4 --samples $B:$((B + 1)) -o "$TMP/many/p0.pfm"
for i in $(seq 1 219); do
    cp "$TMP/many/p0.pfm" "$TMP/many/p$i.pfm"
    sed "s/^samples .*/samples $((B + 2 * i)):$((B + 2 * i + 1))/; s/^spp .*/spp 1/" "$TMP/many/p0.pfm.meta" > "$TMP/many/p$i.pfm.meta"
done
expect_status "merge of 220 one-sample pieces near 2^62" 0 $PATHLAB merge "$TMP/many/m.pfm" "$TMP"/many/p*.pfm
expect_status "its sidecar (a samples line of 9 kB) reads back: --resume says it has 220 spp" 0 $PATHLAB render --resume -o "$TMP/many/m.pfm" --spp 1 --quiet
expect_err "--resume read the 220 ranges" "already has 220 spp"
# a malformed sidecar stops --resume at its line (a second message, "needs a scene", followed it)
$R --spp 2 -o "$TMP/bad_meta.pfm"; sed -i 's/^seed .*/seed -1/' "$TMP/bad_meta.pfm.meta"
expect_status "--resume on a malformed sidecar: exit 2" 2 $PATHLAB render --resume -o "$TMP/bad_meta.pfm" --spp 4
if [ "$(wc -l < "$TMP/err")" -eq 1 ] && grep -q "bad_meta.pfm.meta:6: bad value" "$TMP/err"; then pass "--resume on a malformed sidecar: one message, its file and line"
else fail "--resume on a malformed sidecar: $(err_tail "$TMP/err")"; fi
# a scene's name starting with a space was read back without it (the reader trims values); a sidecar
# written before sky-id (none) still resumes a --sky render
mkdir -p "$TMP/lead"; cp scenes/cornell.mtl "$TMP/lead/"; cp scenes/cornell.obj "$TMP/lead/ lead.obj"
PABS=$(realpath "$PATHLAB")
(cd "$TMP/lead" && "$PABS" render " lead.obj" --quiet --size 8x8 --samples 0:2 -o a.pfm)
expect_status "a scene named ' lead.obj': resumed" 0 sh -c "cd '$TMP/lead' && '$PABS' render --resume -o a.pfm --spp 4 --quiet"
mkdir -p "$TMP/oldsky"; "$PFMTOOL" const 8 4 1 1 1 "$TMP/oldsky/sky.pfm"
$PATHLAB render scenes/quad-light.obj --quiet --size 8x8 --sky "$TMP/oldsky/sky.pfm" --samples 0:2 -o "$TMP/oldsky/a.pfm"
sed -i '/^sky-id /d' "$TMP/oldsky/a.pfm.meta"
expect_status "a --sky render's sidecar without sky-id (written before it): resumed" 0 $PATHLAB render --resume -o "$TMP/oldsky/a.pfm" --spp 4 --quiet
