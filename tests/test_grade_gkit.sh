#!/usr/bin/env bash
# pathlab grade on scenes of the kinds gKit's students render (docs/gkit.md): textures, glossy walls
# read under --material diffuse, a smooth mesh, an image sky. Honest renders must pass; the mistakes
# a student makes with those features must fail (exit 1).
#
# Scenes: tests/materials/gen.py's texroom.obj (floor and back wall textured with the 8-bit
# tex8.ppm, side walls with Ks, a smooth sphere, a lamp), under --material diffuse as gKit's Monte
# Carlo tutorials, and skysphere.obj (a smooth sphere on a floor) under the image sky sky.pfm.
# References: pathlab, 48x48 at 1024 spp (a reference made by pathlab: what this tests is grade's
# verdict on these features, not the renderer; the renderer's answer on them is anchored against
# Cycles in docs/gkit.md). Honest: --sampler independent, 16 and 64 spp, 2 seeds, on both scenes:
# 8 images graded at alpha 0.01 each; at most one may fail (P(>= 2 of 8) ~ 0.27%).
# Mistakes, at 64 spp (each renders what a student's renderer would):
#   texture upside down     texroom-flipv.obj: texcoord v read as 1 - v (gKit's images start at the bottom row)
#   texture sRGB-decoded    --texture-decode srgb (gKit divides the bytes by 255, no curve)
#   texture ignored         texroom-notex.obj: map_Kd dropped, Kd the texture's mean
#   glossy model            --material blinn where the reference is --material diffuse
#   faceted                 --normals geometric: the vn ignored
#   sky upside down         sky-flipped.pfm (the image's rows reversed)
#   sky turned              sky-turned.pfm (half a turn about +Y: u read from the wrong origin)
# About 10 s on 2 cores.
. "$(dirname "$0")/lib.sh"
S=$TMP/scenes
python3 tests/materials/gen.py "$S" || fail "tests/materials/gen.py failed"
SIZE=48x48
ROOM=(--eye 0,1,3.6 --target 0,0.9,0 --fov 40 --material diffuse)
SKY=(--eye 0,1,4 --target 0,-0.2,0 --fov 40)
room() { $PATHLAB render "$S/$1" --quiet --size $SIZE "${ROOM[@]}" "${@:2}"; }
sky() { $PATHLAB render "$S/skysphere.obj" --quiet --size $SIZE "${SKY[@]}" --sky "$S/$1" "${@:2}"; }

run_ok "texroom reference, 1024 spp" room texroom.obj --spp 1024 --seed 1 -o "$TMP/room_ref.pfm"
run_ok "skysphere reference, 1024 spp" sky sky.pfm --spp 1024 --seed 1 -o "$TMP/sky_ref.pfm"

grade_case() { $PATHLAB grade "$1" --ref "$2" > "$TMP/g.out" 2> "$TMP/g.err"; rc=$?; }
verdict() { { grep -E '^(PASS|FAIL)|^likely' "$TMP/g.out"; head -1 "$TMP/g.err"; } | sed 's/^ *//' | paste -sd ';' - | cut -c1-200; }

# 1. honest renders
false_alarms=0 n=0
for spp in 16 64; do
    for seed in 11 12; do
        s=$((seed + 100 * spp))
        run_ok "texroom, honest" room texroom.obj --sampler independent --spp $spp --seed $s -o "$TMP/hr_${spp}_$seed.pfm"
        run_ok "skysphere, honest" sky sky.pfm --sampler independent --spp $spp --seed $s -o "$TMP/hs_${spp}_$seed.pfm"
        for pair in "hr room_ref texroom" "hs sky_ref skysphere"; do
            set -- $pair
            grade_case "$TMP/$1_${spp}_$seed.pfm" "$TMP/$2.pfm"; n=$((n + 1))
            if [ "$rc" = 0 ]; then echo "ok   honest $3 $spp spp seed $seed: [$(verdict)]"
            else false_alarms=$((false_alarms + 1)); echo "note honest $3 $spp spp seed $seed: exit $rc [$(verdict)]"; fi
        done
    done
done
if [ "$false_alarms" -le 1 ]; then pass "honest renders of texroom and skysphere: $false_alarms false alarm(s) of $n (at most 1)"
else fail "honest renders of texroom and skysphere: $false_alarms false alarms of $n (at most 1)"; fi

# 2. the mistakes: each must fail
mistake() {   # mistake LABEL REF IMAGE
    grade_case "$3" "$TMP/$2.pfm"
    if [ "$rc" = 1 ]; then pass "$1: fails [$(verdict)]"
    else fail "$1: exit $rc, wanted 1 (fail) [$(verdict)]"; fi
}
M=(--sampler independent --spp 64 --seed 77)
room texroom-flipv.obj "${M[@]}" -o "$TMP/m_flipv.pfm" && mistake "texture upside down (v read as 1 - v)" room_ref "$TMP/m_flipv.pfm"
room texroom.obj --texture-decode srgb "${M[@]}" -o "$TMP/m_srgb.pfm" && mistake "texture decoded as sRGB" room_ref "$TMP/m_srgb.pfm"
room texroom-notex.obj "${M[@]}" -o "$TMP/m_notex.pfm" && mistake "texture ignored (Kd its mean)" room_ref "$TMP/m_notex.pfm"
room texroom.obj --material blinn "${M[@]}" -o "$TMP/m_blinn.pfm" && mistake "glossy model (--material blinn) against diffuse" room_ref "$TMP/m_blinn.pfm"
sky sky.pfm --normals geometric "${M[@]}" -o "$TMP/m_facet.pfm" && mistake "faceted sphere (vn ignored)" sky_ref "$TMP/m_facet.pfm"
sky sky-flipped.pfm "${M[@]}" -o "$TMP/m_skyflip.pfm" && mistake "sky upside down" sky_ref "$TMP/m_skyflip.pfm"
sky sky-turned.pfm "${M[@]}" -o "$TMP/m_skyturn.pfm" && mistake "sky turned half a turn" sky_ref "$TMP/m_skyturn.pfm"
