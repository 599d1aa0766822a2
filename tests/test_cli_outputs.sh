#!/usr/bin/env bash
# Outputs checked before any work: a missing folder, a folder given as a file, an
# unknown extension, for every file a command writes, is refused with status 2 and a message naming
# the flag and the path, before the scene is read or a pixel rendered (the scene here is missing or
# the render is big: a check done after the work would show in the message or the time); and a
# --variance or --split set that cannot be written whole is not written at all.
. "$(dirname "$0")/lib.sh"
S=scenes/cornell.obj
big="--size 2048x2048 --spp 4096"   # minutes of work: these runs must stop before rendering
refuse() {   # NAME PATTERN COMMAND...: status 2 at once, stderr matching PATTERN
    local name=$1 pat=$2 t0 t1; shift 2
    t0=$(date +%s%N)
    expect_status "$name: status 2" 2 timeout -k 5 20 "$@"   # a check after the work: killed, status 124
    t1=$(date +%s%N)
    expect_err "$name: named" "$pat"
    if [ $(( (t1 - t0) / 1000000 )) -lt 5000 ]; then pass "$name: before the work ($(( (t1 - t0) / 1000000 )) ms)"
    else fail "$name: took $(( (t1 - t0) / 1000000 )) ms: the check came after the work"; fi
}
mkdir -p "$TMP/dir.pfm"
# shellcheck disable=SC2086
{
refuse "render -o in a missing folder" "^pathlab render: -o $TMP/no/x.pfm: the folder $TMP/no does not exist" $PATHLAB render $S $big -o "$TMP/no/x.pfm"
refuse "render -o a folder" "-o $TMP/dir.pfm: is a folder" $PATHLAB render $S $big -o "$TMP/dir.pfm"
refuse "render -o .jpg" "unknown image format \(use .pfm, .ppm or .png\)" $PATHLAB render $S $big -o "$TMP/x.jpg"
refuse "render --variance in a missing folder" "^pathlab render: --variance $TMP/no/v.pfm: the folder" $PATHLAB render $S $big -o "$TMP/x.pfm" --variance "$TMP/no/v.pfm"
refuse "render --variance = -o" "-o and --variance are the same file" $PATHLAB render $S $big -o "$TMP/x.pfm" --variance "$TMP/x.pfm"
# one file under two spellings, a --split layer as the variance, the view over the scene or a sidecar:
# each was written, then the render failed or the file was lost (found by fuzzing)
refuse "render --variance = -o spelled ./" "-o and --variance are the same file" $PATHLAB render $S $big -o "$TMP/x.pfm" --variance "$TMP/./x.pfm"
refuse "render --variance = a --split layer of -o" "a layer of -o \(--split\) and --variance are the same file" \
    $PATHLAB render $S $big --split --bounces 0:2 -o "$TMP/x.pfm" --variance "$TMP/x_L1.pfm"
cp scenes/cornell.obj scenes/cornell.mtl "$TMP/"
refuse "render --write-view = the scene" "--write-view .*cornell.obj: a view file is text|--write-view and the scene are the same file" $PATHLAB render "$TMP/cornell.obj" $big -o "$TMP/x.pfm" --write-view "$TMP/cornell.obj"
refuse "render --write-view = -o's sidecar" "-o's sidecar and --write-view are the same file" $PATHLAB render $S $big -o "$TMP/x.pfm" --write-view "$TMP/x.pfm.meta"
# the other inputs a command line names (a hostile review, 2026-12-08): --write-view over the student's
# orbiter file or the MTL, -o or --variance over the sky image, each was written
printf 'c 0 0 0\np 0 0 -2\nr 0 0 0\ns 1 1\n' > "$TMP/orbiter.txt"; "$PFMTOOL" const 8 4 1 1 1 "$TMP/sky.pfm"
refuse "render --write-view = --orbiter" "--write-view and --orbiter are the same file" $PATHLAB render $S $big -o "$TMP/x.pfm" --orbiter "$TMP/orbiter.txt" --write-view "$TMP/./orbiter.txt"
refuse "render --write-view = --mtl" "--write-view .*cornell.mtl: a view file is text|--write-view and --mtl are the same file" $PATHLAB render $S $big -o "$TMP/x.pfm" --mtl "$TMP/cornell.mtl" --write-view "$TMP/cornell.mtl"
refuse "render -o = --sky" "-o and --sky are the same file" $PATHLAB render $S $big -o "$TMP/sky.pfm" --sky "$TMP/sky.pfm"
refuse "render --variance = --sky" "--variance and --sky are the same file" $PATHLAB render $S $big -o "$TMP/x.pfm" --variance "$TMP/sky.pfm" --sky "$TMP/sky.pfm"
refuse "render --sample-count in a missing folder" "^pathlab render: --sample-count $TMP/no/c.pfm" \
    $PATHLAB render $S --size 2048x2048 --target-error 0.001 -o "$TMP/x.pfm" --sample-count "$TMP/no/c.pfm"
refuse "render --sample-count .png" "--sample-count .*c.png.*pfm" \
    $PATHLAB render $S --size 2048x2048 --target-error 0.001 -o "$TMP/x.pfm" --sample-count "$TMP/c.png"
refuse "render --write-view in a missing folder" "^pathlab render: --write-view $TMP/no/v.view" $PATHLAB render $S $big -o "$TMP/x.pfm" --write-view "$TMP/no/v.view"
mkdir -p "$TMP/x_L2.pfm"
refuse "render --split: a layer's name taken by a folder" "--split $TMP/x_L2.pfm: is a folder" $PATHLAB render $S $big --bounces 0:3 --split -o "$TMP/x.pfm"
refuse "render: a missing scene and a bad output: the output named first" "^pathlab render: -o $TMP/no/x.png" $PATHLAB render "$TMP/none.obj" -o "$TMP/no/x.png"
refuse "diff --heatmap in a missing folder" "^pathlab diff: --heatmap $TMP/no/h.png" $PATHLAB diff ref/cornell.pfm ref/cornell.pfm --heatmap "$TMP/no/h.png"
refuse "convert to a missing folder" "^pathlab convert: output $TMP/no/x.png" $PATHLAB convert ref/cornell.pfm "$TMP/no/x.png"
refuse "convert to .tif" "unknown" $PATHLAB convert ref/cornell.pfm "$TMP/x.tif"
refuse "merge to a missing folder" "^pathlab merge: output $TMP/no/m.pfm" $PATHLAB merge "$TMP/no/m.pfm" ref/cornell.pfm
refuse "merge --variance in a missing folder" "^pathlab merge: --variance $TMP/no/v.pfm" $PATHLAB merge "$TMP/m.pfm" ref/cornell.pfm --variance "$TMP/no/v.pfm"
refuse "grade --report in a missing folder" "^pathlab grade: --report $TMP/no/r.md" $PATHLAB grade ref/cornell_L1.pfm --ref ref/cornell.pfm --report "$TMP/no/r.md"
refuse "grade --report .txt" "--report .*r.txt: use a name ending in .md" $PATHLAB grade ref/cornell_L1.pfm --ref ref/cornell.pfm --report "$TMP/r.txt"
refuse "grade --heatmap in a missing folder" "^pathlab grade: --heatmap $TMP/no/h.png" $PATHLAB grade ref/cornell_L1.pfm --ref ref/cornell.pfm --heatmap "$TMP/no/h.png"
refuse "compare -o under a missing folder" "^pathlab compare: -o $TMP/no/cmp" $PATHLAB compare $S --estimators light $big -o "$TMP/no/cmp"
touch "$TMP/afile"
refuse "compare -o a file" "exists and is not a folder" $PATHLAB compare $S --estimators light $big -o "$TMP/afile"
}
ls "$TMP"/no > /dev/null 2>&1 && fail "a refused run created $TMP/no" || pass "no refused run created a folder or file"

# a --split/--variance set that fails at the end is not written at all: the folder named like
# a layer's variance appears while the render runs (after the checks), so the rename would fail.
# --time 1.5, not a number of spp: the render outlasts the 0.3 s before the mkdir on any machine
# (2000 spp took 1.1 s on a loaded one, and a faster build or machine would have beaten it).
mkdir -p "$TMP/set"
$PATHLAB render $S --size 32x32 --time 1.5 --bounces 0:3 --split --quiet -o "$TMP/set/b.pfm" --variance "$TMP/set/b_var.pfm" &
pid=$!
sleep 0.3; mkdir "$TMP/set/b_var_L2.pfm"
wait $pid; rc=$?
left=$(cd "$TMP/set" && ls | grep -v '^b_var_L2.pfm$' | tr '\n' ' ')
if [ "$rc" -eq 2 ] && [ -z "$left" ]; then pass "a layer that cannot be written: status 2 and none of the 20 files written"
else fail "a layer that cannot be written: status $rc, written: $left"; fi
# --write-view was written with the camera, before --resume's checks: a render that failed left it
$PATHLAB render $S --quiet --size 8x8 --spp 2 -o "$TMP/rs.pfm"
expect_status "--resume with a clashing --size, --write-view: exit 2" 2 $PATHLAB render --resume -o "$TMP/rs.pfm" --spp 4 --size 16x16 --write-view "$TMP/rs.view"
expect_no_file "--resume refused: no view file left" "$TMP/rs.view"
expect_status "a render with --write-view: exit 0" 0 $PATHLAB render $S --quiet --size 8x8 --spp 1 -o "$TMP/rv.pfm" --write-view "$TMP/rv.view"
if grep -q "^size 8 8" "$TMP/rv.view" 2>/dev/null; then pass "--write-view written with the image"; else fail "--write-view: $(cat "$TMP/rv.view" 2>&1 | head -3)"; fi
# a resume with nothing to add still writes the --write-view asked (it wrote none); a view file named
# like a scene's file or an image is refused (--write-view cornell.mtl replaced the MTL its mtllib names);
# -o over a texture of the scene is refused once the scene is read
$PATHLAB render $S --quiet --size 8x8 --spp 2 --sampler independent -o "$TMP/rs_ind.pfm"
expect_status "--resume with nothing to add, --write-view: exit 0" 0 $PATHLAB render --resume -o "$TMP/rs_ind.pfm" --spp 2 --quiet --write-view "$TMP/rs2.view"
if [ -s "$TMP/rs2.view" ]; then pass "--resume with nothing to add: the view written"; else fail "--resume with nothing to add: no view file"; fi
refuse "render --write-view x.mtl" "--write-view .*x.mtl: a view file is text" $PATHLAB render $S $big -o "$TMP/x.pfm" --write-view "$TMP/x.mtl"
mkdir -p "$TMP/tex"; printf 'P3\n2 2\n255\n255 0 0 0 255 0 0 0 255 255 255 255\n' > "$TMP/tex/t.ppm"
printf 'newmtl m\nKd 1 1 1\nKe 1 1 1\nmap_Kd t.ppm\n' > "$TMP/tex/t.mtl"
printf 'mtllib t.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl m\nf 1/1 2/2 3/3\n' > "$TMP/tex/t.obj"
refuse "render -o the scene's texture" "is the texture .*t.ppm of the scene" $PATHLAB render "$TMP/tex/t.obj" $big -o "$TMP/tex/./t.ppm"
# mtllib T.MTL (any case) and a .jpg texture are no view files; an MTL the OBJ names is an input
refuse "render --write-view T.MTL" "--write-view .*T.MTL: a view file is text" $PATHLAB render $S $big -o "$TMP/x.pfm" --write-view "$TMP/T.MTL"
refuse "render --write-view wood.jpg" "--write-view .*wood.jpg: a view file is text" $PATHLAB render $S $big -o "$TMP/x.pfm" --write-view "$TMP/wood.jpg"
printf 'newmtl m\nKd 1 1 1\nKe 1 1 1\n' > "$TMP/tex/lib.txt"; printf 'mtllib lib.txt\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n' > "$TMP/tex/u.obj"
refuse "render --write-view = the MTL an mtllib names (lib.txt)" "is the MTL file .*lib.txt of the scene" $PATHLAB render "$TMP/tex/u.obj" $big -o "$TMP/x.pfm" --write-view "$TMP/tex/lib.txt"
exit 0
