#!/usr/bin/env bash
# ref/make_refs.sh — regenerates the reference images of ref/ and ref/MANIFEST.md (`make refs`).
# A reference made by pathlab guards against regressions only; correctness rests on the tests with
# known answers and on unbiased estimators agreeing.
set -euo pipefail
cd "$(dirname "$0")/.."
PATHLAB=${PATHLAB:-./pathlab}
rev=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
[ -z "$(git status --porcelain src 2>/dev/null)" ] || rev="$rev+changes"
manifest=ref/MANIFEST.md
{
    echo "# Reference images"
    echo
    echo "Made by \`make refs\` (ref/make_refs.sh) at revision $rev on $(date -u +%Y-%m-%d),"
    echo "$(nproc) cores ($(lscpu 2>/dev/null | sed -n 's/^Model name: *//p' | head -1))."
    echo "Each image has its variance of the pixel mean beside it (\`_var.pfm\`)."
    echo
    echo "| file | scene | spp | seed | time | command |"
    echo "|---|---|---|---|---|---|"
} > "$manifest.tmp"
# name scene spp seed flags...
ref() {
    local name=$1 scene=$2 spp=$3 seed=$4; shift 4
    local cmd="pathlab render $scene --spp $spp --seed $seed $* -o ref/$name.pfm --variance ref/${name}_var.pfm"
    local t0; t0=$(date +%s.%N)
    # shellcheck disable=SC2086
    $PATHLAB render "$scene" --quiet --spp "$spp" --seed "$seed" "$@" -o "ref/$name.pfm" --variance "ref/${name}_var.pfm"
    local secs; secs=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f s", b - a }')
    echo "| $name.pfm | $scene | $spp | $seed | $secs | \`$cmd\` |" >> "$manifest.tmp"
    echo "ref/$name.pfm: $secs"
}
ref cornell_L01 scenes/cornell.obj 8192 12345 --bounces 0:1 --direct light --light area --size 128x128
# For tests/test_estimators.sh: L1 alone, L2 alone and L0..L4 of the Cornell box and of its glossy
# variant at the tests' size and camera (24x24, pixel centres), with MIS (power heuristic),
# solid-angle light sampling and BRDF directions, at 32 times the samples of the tests' renders
# (16 times for --direct brdf's): the reference adds 3% (6%) to the variance of a comparison.
EST="--size 24x24 --pixel-center --direct mis-power --light solid-angle --dir brdf"
for s in cornell:cornell cornell-glossy:glossy; do
    scene=scenes/${s%%:*}.obj name=${s##*:}
    # shellcheck disable=SC2086
    ref "${name}_L1" "$scene" 131072 2001 --bounce 1 $EST
    # shellcheck disable=SC2086
    ref "${name}_L2" "$scene" 131072 2002 --bounce 2 $EST
    # shellcheck disable=SC2086
    ref "${name}_L0-4" "$scene" 131072 2003 --bounces 0:4 $EST
done
mv "$manifest.tmp" "$manifest"
