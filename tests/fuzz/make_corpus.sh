#!/usr/bin/env bash
# tests/fuzz/make_corpus.sh — (re)writes the seed corpus tests/fuzz/corpus/TARGET/ (committed; run
# it again after adding scenes): small valid and invalid inputs of each reader, from scenes/,
# tests/obj/ and, when present, ../shared/data/hostile/ (the inputs the first fuzzing found).
# The scene target's inputs are "OBJ @@MTL@@ MTL @@VIEW@@ view" (tests/fuzz/fuzz_scene.c).
set -eu
cd "$(dirname "$0")/../.."
C=tests/fuzz/corpus
H=../shared/data/hostile
rm -rf "$C"; mkdir -p "$C"/scene "$C"/mtl "$C"/view "$C"/orbiter "$C"/pfm "$C"/sidecar
combine() {   # OBJ MTL VIEW: the three as one input, the OBJ's mtllib renamed m.mtl
    sed 's/^mtllib .*/mtllib m.mtl/' "$1"
    if [ -n "$2" ]; then printf '\n@@MTL@@\n'; cat "$2"; fi
    if [ -n "$3" ]; then printf '\n@@VIEW@@\n'; cat "$3"; fi
}
for s in cornell cornell-glossy furnace mis-plates quad-light; do   # sphere-furnace: 180 kB, too big
    combine scenes/$s.obj scenes/$s.mtl scenes/$s.view > "$C/scene/$s"
    cp scenes/$s.mtl "$C/mtl/$s.mtl"; cp scenes/$s.view "$C/view/$s.view"
done
for o in tests/obj/*.obj; do   # the parser's edge cases, with their MTL if they name one
    lib=$(sed -n 's/^mtllib \([^ ]*\).*/\1/p' "$o" | head -n 1)
    m=""; [ -n "$lib" ] && [ -f "tests/obj/$lib" ] && m=tests/obj/$lib
    [ "$(wc -c < "$o")" -le 8192 ] && combine "$o" "$m" "" > "$C/scene/obj-$(basename "$o" .obj)"
done
for m in tests/obj/*.mtl; do cp "$m" "$C/mtl/obj-$(basename "$m")"; done
if [ -d "$H" ]; then
    cp "$H"/fuzz-crash-view-size.bin "$H"/fuzz-timeout-kd15.bin "$C/scene/"
    combine "$H"/hang_kd1/furnace.obj "$H"/hang_kd1/furnace.mtl "$H"/hang_kd1/furnace.view > "$C/scene/hostile-hang-kd1"
    combine "$H"/view_longline/quad-light.obj "$H"/view_longline/quad-light.mtl "$H"/view_longline/quad-light.view > "$C/scene/hostile-longline"
    cp "$H"/ubsan_view_size/min.view "$C/view/hostile-size.view"
    cp "$H"/view_longline/quad-light.view "$C/view/hostile-longline.view"
    cp "$H"/view_longline/rejected.view "$C/view/hostile-rejected.view"
fi
printf 'eye 0 0 5\ntarget 0 0 0\nup 0 1 0\nfov 45\nsize 8 6\n' > "$C/view/all-keys.view"
printf '# comment\n\n  eye 1e-3 -2 3.5 # tail\r\nsize 1 1\n' > "$C/view/comments.view"
# gKit orbiter files: as gKit writes them, an old one without f, comments and odd spacing, an error
printf 'c 278.000000 273.000000 280.000000\np 0.000000 0.000000\nr 0.000000 180.000000\ns 1080.000000 800.000000\nf 39.3076481 48.000000 32.000000\n' > "$C/orbiter/cornell"
printf 'c -0.01 0.995 -0.025\np 0.149664 -0.266665\nr 18 16\ns 2.450631 3.48732\nf 45 1024 640\n' > "$C/orbiter/issue"
printf 'c 0 0 0\np 0 0\nr 0 0\ns 5\n' > "$C/orbiter/old-no-f"
printf '# a comment\n\nf 60 32 16\ns 2 3\n  r 90 0\np 0 0\nc 1 2 3\n' > "$C/orbiter/any-order"
printf 'c 0 0 0\np 0 x\nr 0 0\ns 5 5\n' > "$C/orbiter/bad-number"
# the limits (libFuzzer's integer mutations square or double a number: from here one step goes past them)
printf 'c -1e30 1e30 0\np 1e30 -1e30\nr 360 -360\ns 1e30 1e-30\nf 179.999 65536 65536\n' > "$C/orbiter/limits"
printf 'size 65536 16384\nfov 179.999\neye 1e38 -1e38 0\n' > "$C/view/limits.view"
{ printf 'c 0 0 0\np 0 0\nr 0 0\ns 5 5\n#'; printf '%01022d' 0; printf 'c 9 9 9\n'; } > "$C/orbiter/long-comment"
# PFMs: colour and grey, both byte orders, a few pixels; a truncated one; a lying size
pfm() {   # HEADER-MAGIC W H SCALE PIXEL-BYTES
    printf '%s\n%s %s\n%s\n' "$1" "$2" "$3" "$4"; printf "$5"
}
pfm PF 2 1 -1.0 '\x00\x00\x80\x3f\x00\x00\x00\x3f\x00\x00\x00\x00\x00\x00\x80\x3f\x00\x00\x80\x3f\x00\x00\x80\x3f' > "$C/pfm/rgb-le.pfm"
pfm PF 1 1 1.0 '\x3f\x80\x00\x00\x3f\x00\x00\x00\x00\x00\x00\x00' > "$C/pfm/rgb-be.pfm"
pfm Pf 2 2 -1.0 '\x00\x00\x80\x3f\x00\x00\x00\x3f\x00\x00\x00\x00\x00\x00\x20\x41' > "$C/pfm/grey-le.pfm"
pfm PF 2 2 -1.0 '\x00\x00\x80\x3f' > "$C/pfm/truncated.pfm"
pfm PF 2147483647 2147483647 -1.0 '' > "$C/pfm/huge-size.pfm"
pfm PF 1 1 -1.0 '\x00\x00\xc0\x7f\x00\x00\x80\x7f\x00\x00\x80\xff' > "$C/pfm/nan-inf.pfm"
# sidecars: as render writes them (mean, variance, layers, adaptive, sobol), and hostile ones: ranges
# near INT64_MAX (they overflowed the resume's arithmetic), a variance named by an absolute path,
# through "..", or as a device
side() {   # NAME LINES...: a mean's sidecar of a 16x16 render with the lines given after it
    local n=$1; shift
    { printf 'kind mean\nlayer total\nseed 1\nscene scenes/cornell.obj\nscene-id fnv1a64:5df60ac8842923b7\n'
      printf 'flags --bounces 0:inf --light area --dir brdf --direct mis-power --rr 3 --pixel-offset 0.5\n'
      printf 'camera eye 278,273,-800 target 278,273,0 up 0,1,0 fov 39.3076477 size 1x1\nrevision 9d77892\n'
      printf '%s\n' "$@"; } > "$C/sidecar/$n"
}
side mean 'samples 0:4' 'spp 4' 'variance x_var.pfm'
side variance 'samples 0:4' 'spp 4' && sed -i 's/^kind mean/kind variance/' "$C/sidecar/variance"
side pieces 'samples 0:4,8:16,1000:1200' 'variance x_var.pfm' 'layers 0:3' 'stopped SIGINT'
side adaptive 'samples 0:64' 'spp-mean 12.5' 'spp-cap 64' 'adaptive --target-error 0.01 --pilot 16' 'pilot-seed 7' 'sample-count x_n.pfm'
side sobol 'samples 0:4' 'sampler sobol' 'variance-dof 3' 'variance x_var.pfm'
side near-int64-max 'samples 0:2,9223372036854775805:9223372036854775807' 'variance x_var.pfm'
side near-limit 'samples 0:2,4611686018427387000:4611686018427387904' 'variance x_var.pfm'
side absolute 'samples 0:4' 'variance /dev/zero'
side climbs 'samples 0:4' 'variance ../x_var.pfm'
side negative-seed 'samples 0:4' 'seed -1' 'spp-cap -5'
side adaptive-no-cap 'samples 0:64' 'spp-mean 12.5' 'adaptive --target-error 0.01 --pilot 16'   # found by make fuzz
for t in scene mtl view orbiter pfm sidecar; do echo "$t: $(ls "$C/$t" | wc -l) seeds, $(cat "$C/$t"/* | wc -c) bytes"; done
