#!/usr/bin/env bash
# A class's files cannot attack the teacher who grades them:
#  - a name read from a sidecar (the variance of FILE.pfm.meta) is an input: resolved against the
#    image's folder and confined to it (no absolute path, no "..", no link leading out), a regular
#    file whose own sidecar says it is this image's variance (samples, seed, scene, size), and it is
#    never written: view, merge and render --resume refuse it (exit 2, saying why) and leave the
#    teacher's files as they were; --resume rewrites only STEM_var.pfm beside -o or --variance;
#  - a sidecar that lies about the size of its image, or a FIFO named FILE.pfm.meta, is refused at once,
#    and a sidecar's flags line that names what a render never writes there (--write-view) too;
#  - 40,000 material names made to collide in a fixed hash load in a blink;
#  - grade compares a PFM's header (channels, size) with the reference's before reading its pixels:
#    a sparse 1 GiB greyscale file is refused in a blink, without gigabytes of memory;
#  - sidecar numbers are bounded as the command line bounds them (indices 2^62, counts 2^30): the
#    resume arithmetic never overflows, and the sidecar it writes reads back;
#  - a page that cannot be written says why, exit 2; odd camera numbers get messages that say what is wrong.
. "$(dirname "$0")/lib.sh"
S=$PWD/scenes/cornell.obj
P=$PATHLAB; case $P in /*) ;; *) P=$PWD/$PATHLAB ;; esac
cd "$TMP" || exit 0
r() { $P render "$S" --size 16x16 --sampler independent --quiet "$@"; }
# Sanitizer builds reserve terabytes of virtual memory: no ulimit -v there (the sparse files are then
# refused from their header all the same, and the out-of-memory render is left out)
case "$PATHLAB" in *san*) LIMIT=: ;; *) LIMIT="ulimit -v 400000" ;; esac
mkdir teacher stu other
r --spp 4 -o teacher/ref.pfm --variance teacher/ref_var.pfm || { fail "hostile files: the first render failed"; exit 0; }
r --spp 4 --seed 3 -o stu/a.pfm --variance stu/a_var.pfm
r --spp 4 --seed 9 -o stu/c.pfm --variance stu/c_var.pfm
sums() { md5sum teacher/* | md5sum; }
before=$(sums)
# forge NAME VARIANCE: stu/NAME.pfm, a copy of stu/a.pfm whose sidecar names VARIANCE
forge() { cp stu/a.pfm "stu/$1.pfm"; sed "s|^variance .*|variance $2|" stu/a.pfm.meta > "stu/$1.pfm.meta"; }
ln -s ../teacher/ref_var.pfm stu/link_var.pfm
ln -s ../teacher/ref_var.pfm stu/planted_var.pfm; cp stu/a.pfm stu/planted.pfm
ln -s ../teacher stu/sub
mkfifo stu/f.pfm stu/fifo2.pfm.meta
mkdir stu/dir.pfm
forge abs "$TMP/teacher/ref_var.pfm"; forge up ../teacher/ref_var.pfm; forge link link_var.pfm; forge sub sub/ref_var.pfm
forge fifo f.pfm; forge dir dir.pfm; forge dev /dev/zero; forge seed c_var.pfm; forge mean a.pfm
for c in "abs:an absolute path" "up:a path with '..'" "link:outside the image's folder" "sub:outside the image's folder" \
         "fifo:not a regular file" "dir:a folder, not a file" "dev:an absolute path" "seed:seed differs" "mean:expected a variance"; do
    n=${c%%:*}; why=${c#*:}
    expect_status "view: a sidecar naming its variance '$n': refused, exit 2, no hang" 2 timeout 10 $P view stu/$n.pfm -o $n.html
    expect_err "view: a sidecar naming its variance '$n': says why" "$why"
    expect_no_file "view: a sidecar naming its variance '$n': no page" $n.html
done
expect_status "view: a link STEM_var.pfm beside the image leading to the teacher's variance: refused" 2 $P view stu/planted.pfm -o p.html
expect_err "view: says the link leads out" "planted_var.pfm: outside the image's folder"
cp stu/a.pfm stu/lay.pfm; sed 's|^variance .*|variance a_var.pfm|; $a layers 1:1' stu/a.pfm.meta > stu/lay.pfm.meta
ln -s ../teacher/ref.pfm stu/lay_L1.pfm
expect_status "view: a layer beside the image that links to the teacher's reference: refused" 2 $P view stu/lay.pfm -o lay.html
expect_err "view: says the layer leads out" "lay_L1.pfm: outside the image's folder"
cp stu/a.pfm stu/fifo2.pfm
expect_status "view: a FIFO named FILE.pfm.meta: refused at once" 2 timeout 10 $P view stu/fifo2.pfm -o f2.html
expect_status "view: a sidecar naming its own variance by its bare name: shown" 0 $P view stu/a.pfm -o a.html
cp stu/a.pfm stu/renamed.pfm; cp stu/a.pfm.meta stu/renamed.pfm.meta
expect_status "view: the variance found through the sidecar of a renamed image" 0 $P view stu/renamed.pfm -o r.html
if grep -q '"sd":"pathlab-sd-0"' r.html; then pass "view: that variance is on the page"; else fail "view: the variance named by the sidecar is missing"; fi
ln -s "$TMP/stu" linked
expect_status "view: an image in a symlinked folder finds its own variance" 0 $P view linked/renamed.pfm -o l.html
# render --resume: the variance rewritten is the one the command line names
cp teacher/ref.pfm stu/s.pfm; sed "s|^variance .*|variance $TMP/teacher/ref_var.pfm|" teacher/ref.pfm.meta > stu/s.pfm.meta
expect_status "resume: a sidecar naming the teacher's variance by its path: refused" 2 r --spp 8 --resume -o stu/s.pfm
expect_err "resume: says the name is refused" "s.pfm.meta names its variance .*an absolute path"
forge t "a_var.pfm"
expect_status "resume: a sidecar naming another file of its folder as the variance to update: refused" 2 r --spp 8 --seed 3 --resume -o stu/t.pfm
expect_err "resume: says which variance --resume rewrites" "rewrites is the one the command line names: stu/t_var.pfm beside -o, or --variance"
[ "$(sums)" = "$before" ] && pass "resume and view: the teacher's files untouched" || fail "resume and view: the teacher's files changed"
# a sidecar's flags line replayed by --resume holds only what a render writes there: a planted
# --write-view would have written anywhere (the view was written before the resume's checks ran)
cp stu/a.pfm stu/wv.pfm; sed "s|^flags \(.*\)$|flags \1 --write-view $TMP/teacher/planted.view|" stu/a.pfm.meta > stu/wv.pfm.meta
expect_status "resume: a sidecar whose flags line has --write-view: refused" 2 r --spp 8 --resume -o stu/wv.pfm
expect_err "resume: says the sidecar was edited" "wv.pfm.meta: its flags line has --write-view, which a render does not write there"
expect_no_file "resume: the view the sidecar names is not written" "$TMP/teacher/planted.view"
r --spp 4 -o other/y.pfm --variance other/yv.pfm
expect_status "resume: a variance of another name, given with --variance: updated" 0 r --spp 8 --resume -o other/y.pfm --variance other/yv.pfm
grep -q "^samples 0:8" other/yv.pfm.meta && pass "resume: --variance holds the 8 samples" || fail "resume: --variance not updated"
r --spp 4 -o other/x.pfm --variance other/x_var.pfm
expect_status "resume: STEM_var.pfm beside -o updated without naming it" 0 r --spp 8 --resume -o other/x.pfm
grep -q "^samples 0:8" other/x_var.pfm.meta && pass "resume: STEM_var.pfm holds the 8 samples" || fail "resume: STEM_var.pfm not updated"
# a sidecar that lies about its image's size (an 8x8 image said to be 16x16): refused before combining
$P render "$S" --size 8x8 --spp 4 --sampler independent --quiet -o other/w.pfm --variance other/w_var.pfm
sed -i 's|size 8x8|size 16x16|' other/w.pfm.meta other/w_var.pfm.meta
expect_status "resume: an 8x8 image whose sidecar says 16x16: refused" 2 r --spp 8 --resume -o other/w.pfm
expect_err "resume: says the sizes differ" "other/w.pfm is 8x8, but its render is 16x16"
# numbers near INT64_MAX: refused as the command line refuses them; at the bound, no overflow
r --samples 0:4 -o other/n.pfm --variance other/n_var.pfm
sed -i 's|^samples .*|samples 0:2,9223372036854775805:9223372036854775807|' other/n.pfm.meta other/n_var.pfm.meta
expect_status "resume: sample ranges near INT64_MAX: refused" 2 r --spp 10 --resume -o other/n.pfm
expect_err "resume: says the index is beyond 2^62" "n.pfm.meta:[0-9]+: a sample index beyond 2\^62"
sed -i 's|^samples .*|samples 0:2,4611686018427387900:4611686018427387902|' other/n.pfm.meta other/n_var.pfm.meta
expect_status "resume: samples up to 2^62 - 2, 6 more: refused (they would pass 2^62)" 2 r --spp 10 --resume -o other/n.pfm
expect_err "resume: says the new indices would pass 2^62" "6 more would pass 2\^62"
sed -i 's|^samples .*|samples 0:2,4611686018427387896:4611686018427387898|' other/n.pfm.meta other/n_var.pfm.meta
expect_status "resume: samples up to 2^62 - 6, 6 more: done" 0 r --spp 10 --resume -o other/n.pfm
expect_status "merge: the resumed sidecar reads back" 0 $P merge other/m.pfm other/n.pfm
# material names made to collide in FNV-1a's low 20 bits (each block of 4 bytes maps those bits of the
# standard basis to themselves): with a fixed hash and linear probing, 40,000 of them took seconds,
# 100,000 took 73 s; the hash's basis is now drawn per process and its bits mixed
awk 'BEGIN { n = split("0JZx 12ha 3y2n 70TU 8JbH DUtu FYK6 IHDG Ldvv PIan Xheo Ymqy ZX33 aWdX fG09 jZc5 lMRg uilr vAmh", b, " ")
             for (i = 0; i < 40000; i++) printf "newmtl %s%s%s%s\nKd 0.5 0.5 0.5\n", b[i % n + 1], b[int(i / n) % n + 1], b[int(i / n / n) % n + 1], b[int(i / n / n / n) % n + 1]
             print "newmtl light\nKe 1 1 1" }' > flood.mtl
printf 'mtllib flood.mtl\nusemtl light\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' > flood.obj
start=$(date +%s%N)
expect_status "mtl: 40,000 material names of one FNV-1a low 20 bits: loaded" 0 timeout 60 $P render flood.obj --size 4x4 --spp 1 --quiet -o flood.pfm
ms=$(( ($(date +%s%N) - start) / 1000000 ))
[ "$ms" -lt 3000 ] && pass "mtl: those names in $ms ms (seconds with a fixed hash)" || fail "mtl: 40,000 colliding names took $ms ms"
# grade: the header first
printf 'Pf\n16384 16384\n-1\n' > big.pfm && truncate -s $((18 + 16384 * 16384 * 4)) big.pfm
start=$(date +%s%N)
expect_status "grade: a sparse 1 GiB greyscale PFM against a colour reference: refused" 2 \
    bash -c "$LIMIT; exec $P grade big.pfm --ref teacher/ref.pfm"
ms=$(( ($(date +%s%N) - start) / 1000000 ))
expect_err "grade: says greyscale against colour" 'greyscale \("Pf", 1 channel\) against a colour reference'
[ "$ms" -lt 5000 ] && pass "grade: the sparse PFM refused in $ms ms (${LIMIT#ulimit -v })" || fail "grade: the sparse PFM took $ms ms"
printf 'PF\n16384 16384\n-1\n' > big3.pfm && truncate -s $((18 + 16384 * 16384 * 12)) big3.pfm
expect_status "grade: a sparse 3 GiB colour PFM of another size: a fail, unread" 1 \
    bash -c "$LIMIT; exec $P grade big3.pfm --ref teacher/ref.pfm"
mkfifo ref_fifo.pfm.meta; cp teacher/ref.pfm ref_fifo.pfm
expect_status "grade: a FIFO as the reference's sidecar: no hang" 0 timeout 10 $P grade stu/a.pfm --ref ref_fifo.pfm
# errors that say what is wrong
printf 'eye 278 273 -800\ntarget 278 273 0\nup 0 1 0\nfov 1e-40\nsize 8 8\n' > tiny.view
expect_status "view file fov 1e-40: refused" 2 r --spp 1 --view tiny.view -o v.pfm
expect_err "view file fov 1e-40: says the fov's range" "tiny.view:4: fov must be from 0.01"
expect_status "--fov 1e-40: refused" 2 r --spp 1 --fov 1e-40 -o v.pfm
expect_err "--fov 1e-40: says the fov's range" "fov expects a vertical field of view in degrees, from 0.01"
printf 'c 0 0 0\np 0 0\nr 0 0\ns 1e-30 1e-30\nf 45 8 8\n' > tiny.txt
expect_status "orbiter s 1e-30: refused" 2 r --spp 1 --orbiter tiny.txt -o v.pfm
expect_err "orbiter s 1e-30: says eye and target are too close" "too close for float arithmetic"
expect_status "--alpha nan: refused" 2 $P grade stu/a.pfm --ref teacher/ref.pfm --alpha nan
expect_err "--alpha nan: says what a level is" "a level in \(0, 0.5\)"
if [ "$LIMIT" != : ]; then
    expect_status "render out of memory: exit 2" 2 bash -c "ulimit -v 1000000; exec $P render $S --size 31622x31622 --spp 1 --quiet -o big.pfm"
    expect_err "render out of memory: says so" "out of memory for a 31622x31622 image"
fi
# a full disk (root only: a 64 KiB tmpfs): every failed write names the file asked for and the reason, exit 2
mkdir full
if mount -t tmpfs -o size=64k tmpfs full 2> /dev/null; then
    head -c 60000 /dev/zero > full/filler
    expect_status "full disk: view exits 2" 2 $P view stu/a.pfm -o full/page.html
    expect_err "full disk: view names the page and the reason" "full/page.html: cannot write: No space left on device"
    expect_status "full disk: render exits 2" 2 $P render "$S" --size 64x64 --spp 1 --quiet -o full/x.pfm
    expect_err "full disk: render names the image, not its temporary name" "^full/x.pfm: cannot write: No space left on device"
    expect_status "full disk: grade exits 2" 2 $P grade stu/a.pfm --ref teacher/ref.pfm --report full/g.md
    grep -Eq "not written: .*No space left on device" full/g.md "$TMP/out" "$TMP/err" 2> /dev/null \
        && pass "full disk: grade's row says why" || fail "full disk: grade's row does not say why"
    expect_status "full disk: convert exits 2" 2 $P convert stu/a.pfm full/c.png
    umount full
else skip "full disk: cannot mount a tmpfs (not root)"; fi
# a file name or header line with terminal escapes in a decoder's message (a Radiance HDR graded, a
# PNG texture named by an MTL): shown escaped (\x1b), never raw
ESCN=$(printf 'e\e[8mx')
printf '#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +Z \e[31m\n' > "$ESCN.hdr"
printf 'not an image' > "$ESCN.png"
printf 'mtllib esc.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl a\nf 1/1 2/2 3/3\n' > esc.obj
printf 'newmtl a\nKd 1 1 1\nmap_Kd %s.png\n' "$ESCN" > esc.mtl
for what in hdr png; do
    if [ $what = hdr ]; then $P grade "$ESCN.hdr" --ref teacher/ref.pfm > "$TMP/out" 2> "$TMP/err"
    else $P render esc.obj --size 8x8 --spp 1 -o esc.pfm > "$TMP/out" 2> "$TMP/err"; fi
    if grep -q $'\e' "$TMP/out" "$TMP/err"; then fail "a bad $what named with ESC[8m: a raw ESC in: $(head -c 300 "$TMP/err" | cat -v)"
    elif grep -q 'e\\x1b\[8mx' "$TMP/err"; then pass "a bad $what named with ESC[8m: its messages show \\x1b, no raw escape"
    else fail "a bad $what named with ESC[8m: $(head -c 300 "$TMP/err" | cat -v)"; fi
done
exit 0
