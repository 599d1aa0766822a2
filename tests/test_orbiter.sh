#!/usr/bin/env bash
# gKit cameras end to end: --orbiter (its f line gives the size), --view, --write-view read back bit for
# bit, --pixel-offset, and the input errors (exit 2, FILE:LINE). Tiny images, a few spp: a few seconds.
. "$(dirname "$0")/lib.sh"
R="$PATHLAB render scenes/cornell.obj --quiet --spp 2 --threads 2"
# the published Cornell camera of scenes/cornell.view as gKit's orbiter writes it (lookat's r 0 180
# looks along +z): eye = c + Ry(-180) (0, 0, 1080) = (278, 273, -800)
ORB=$TMP/orbiter.txt
printf 'c 278.000000 273.000000 280.000000\np 0.000000 0.000000\nr 0.000000 180.000000\ns 1080.000000 800.000000\nf 39.3076481 48.000000 32.000000\n' > "$ORB"
size() { sed -n 2p "$1" | tr -d '\n'; }

# 1. the orbiter renders at the size of its f line, and sees what scenes/cornell.view sees
expect_status "--orbiter: renders" 0 $R --orbiter "$ORB" -o "$TMP/orb.pfm"
if [ "$(size "$TMP/orb.pfm")" = "48 32" ]; then pass "--orbiter: the image size comes from the f line (48x32)"
else fail "--orbiter: image size '$(size "$TMP/orb.pfm")', expected the f line's 48 32"; fi
$R --size 48x32 -o "$TMP/view.pfm"
if cmp -s "$TMP/orb.pfm" "$TMP/view.pfm"; then pass "--orbiter of the published camera = scenes/cornell.view at 48x32, bit for bit"
else fail "--orbiter of the published camera differs from scenes/cornell.view at 48x32"; fi
$R --orbiter "$ORB" --size 20x10 -o "$TMP/orb2.pfm"
if [ "$(size "$TMP/orb2.pfm")" = "20 10" ]; then pass "--orbiter: --size wins over the f line"
else fail "--orbiter --size 20x10 gave '$(size "$TMP/orb2.pfm")'"; fi

# 2. --write-view, then --view of that file: the same image, bit for bit (here the auto-framed
# camera of a scene without a view file, the hardest case: every float comes from a computation)
cp scenes/cornell.obj scenes/cornell.mtl "$TMP/"
$PATHLAB render "$TMP/cornell.obj" --quiet --spp 2 --threads 2 --size 24x16 --eye 100.3,200.7,-613.1 -o "$TMP/w1.pfm" --write-view "$TMP/w.view"
$PATHLAB render "$TMP/cornell.obj" --quiet --spp 2 --threads 2 --view "$TMP/w.view" -o "$TMP/w2.pfm"
if [ -s "$TMP/w.view" ] && cmp -s "$TMP/w1.pfm" "$TMP/w2.pfm"; then pass "--write-view then --view: the same image, bit for bit"
else fail "--write-view then --view: the images differ ($(tr '\n' ' ' < "$TMP/w.view" 2>/dev/null))"; fi
expect_no_file "--write-view: no temporary file left" "$TMP/w.view.tmp"
$R --orbiter "$ORB" -o "$TMP/o1.pfm" --write-view "$TMP/o.view"
$R --view "$TMP/o.view" -o "$TMP/o2.pfm"
if cmp -s "$TMP/o1.pfm" "$TMP/o2.pfm" && grep -q '^size 48 32$' "$TMP/o.view"; then pass "--orbiter --write-view then --view: the same image"
else fail "--orbiter --write-view then --view differ: $(tr '\n' ' ' < "$TMP/o.view")"; fi

# 3. --pixel-offset: 0 and 0.5 shoot through other points; outside [0, 1) refused
$R --orbiter "$ORB" --pixel-center --pixel-offset 0 -o "$TMP/p0.pfm"
$R --orbiter "$ORB" --pixel-center --pixel-offset 0.5 -o "$TMP/p5.pfm"
$R --orbiter "$ORB" --pixel-center -o "$TMP/pd.pfm"
if ! cmp -s "$TMP/p0.pfm" "$TMP/p5.pfm"; then pass "--pixel-offset 0 and 0.5 give different images"
else fail "--pixel-offset has no effect"; fi
if cmp -s "$TMP/pd.pfm" "$TMP/p5.pfm"; then pass "--pixel-offset 0.5 is the default"; else fail "the default is not --pixel-offset 0.5"; fi
expect_status "--pixel-offset 2: refused (exit 2)" 2 $R --pixel-offset 2 -o "$TMP/x.pfm"
expect_err "--pixel-offset 2: the message says the range" "--pixel-offset expects a number from 0 .* got '2'"
expect_status "--pixel-offset 1: refused" 2 $R --pixel-offset 1 -o "$TMP/x.pfm"

# 4. input errors: exit 2, FILE:LINE and what is wrong; nothing written
printf 'c 0 1 0\nr 0 0\ns 4 2\n' > "$TMP/nop.txt"
expect_status "--orbiter without a p line: exit 2" 2 $R --orbiter "$TMP/nop.txt" -o "$TMP/x.pfm"
expect_err "--orbiter without a p line: FILE:LINE names it" "nop.txt:3: .*'p px py"
printf 'c 0 1 0\np 0 0\nr 0 1O\ns 4 2\n' > "$TMP/bad.txt"
expect_status "--orbiter with a bad number: exit 2" 2 $R --orbiter "$TMP/bad.txt" -o "$TMP/x.pfm"
expect_err "--orbiter with a bad number: FILE:LINE and the line" "bad.txt:3: expected 'r rx ry .*got 'r 0 1O'"
expect_status "--orbiter and --view together: exit 2" 2 $R --orbiter "$ORB" --view "$TMP/o.view" -o "$TMP/x.pfm"
expect_err "--orbiter and --view together: the message" "--orbiter and --view both give the camera"
expect_status "--view of a missing file: exit 2" 2 $R --view "$TMP/none.view" -o "$TMP/x.pfm"
expect_err "--view of a missing file: the message" "none.view: no such file"
expect_status "--orbiter of a missing file: exit 2" 2 $R --orbiter "$TMP/none.txt" -o "$TMP/x.pfm"
expect_no_file "failed renders write no image" "$TMP/x.pfm"

# 5. an older gKit file (no f line, "s size" alone): renders, with a note on fov and size
printf 'c 278 273 280\np 0 0\nr 0 180\ns 1080\n' > "$TMP/old.txt"
expect_status "an older orbiter file (no f line) renders" 0 $R --orbiter "$TMP/old.txt" --size 16x16 -o "$TMP/old.pfm"
expect_err "an older orbiter file: a note says fov and size are not in it" "has no 'f fov width height' line"

# 6. compare reuses render's flags: --orbiter works there too
expect_status "compare --orbiter: runs" 0 $PATHLAB compare scenes/cornell.obj --estimators "light,brdf" --spp 1 --threads 2 \
    --orbiter "$ORB" -o "$TMP/cmp"
if [ "$(size "$TMP/cmp/light.pfm")" = "48 32" ]; then pass "compare --orbiter: the f line's size"
else fail "compare --orbiter: light.pfm is '$(size "$TMP/cmp/light.pfm")'"; fi

# 7. (a hostile review, 2026-12-08) an f line beyond a view file's bounds is refused with its line, not
# later by the camera without a file; a SCENE.view beside a student's scene that is a link out of its
# folder is not read (a teacher's view file was used silently)
printf 'c 278 273 280\np 0 0\nr 0 180\ns 1080 1080\nf 0.001 16 16\n' > "$TMP/tinyfov.txt"
expect_status "an f line with a fov of 0.001 degree: exit 2" 2 $R --orbiter "$TMP/tinyfov.txt" -o "$TMP/x.pfm"
expect_err "an f line with a fov of 0.001 degree: the file and line named" "tinyfov.txt:5: expected 'f fov width height"
printf 'c 278 273 280\np 0 0\nr 0 180\ns 1080 1080\nf 40 65536 65536\n' > "$TMP/huge.txt"
expect_status "an f line of 65536x65536 pixels: exit 2" 2 $R --orbiter "$TMP/huge.txt" -o "$TMP/x.pfm"
expect_err "an f line of 65536x65536 pixels: the file and line named" "huge.txt:5: expected 'f fov width height"
mkdir -p "$TMP/stu" "$TMP/teacher"; cp scenes/cornell.obj scenes/cornell.mtl "$TMP/stu/"
printf 'eye 0 0 0\ntarget 0 0 1\nup 0 1 0\nfov 40\nsize 8 8\n' > "$TMP/teacher/secret.view"; ln -s ../teacher/secret.view "$TMP/stu/cornell.view"
expect_status "a SCENE.view linked out of the scene's folder: exit 2" 2 $PATHLAB render "$TMP/stu/cornell.obj" --quiet --spp 1 -o "$TMP/x.pfm"
expect_err "a SCENE.view linked out: said" "cornell.view: a symbolic link leading out of its folder"
expect_no_file "a SCENE.view linked out: no image" "$TMP/x.pfm"
exit 0
