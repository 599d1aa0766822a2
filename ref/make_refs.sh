#!/usr/bin/env bash
# ref/make_refs.sh — regenerates the reference images of ref/ and ref/MANIFEST.md (`make refs`).
# A reference made by pathlab guards against regressions only; correctness rests on the tests with
# known answers and on unbiased estimators agreeing.
#
#   ref/make_refs.sh              # every group (what `make refs` runs)
#   ref/make_refs.sh scenes       # only the named groups: est, scenes, big (or REF_GROUPS="est scenes")
#
# Groups: `est` = cornell_L01 (tests/test_render.sh) and the 24x24 references of
# tests/test_estimators.sh; `scenes` = every scene of scenes/ at 64x64, full transport and L0..L3
# (SCENE.pfm, SCENE_split_L0.pfm .. SCENE_split_L3.pfm)
# (tests/test_refs.sh, `make bench`); `big` = the Cornell box at 128x128, full transport and L0..L3
# (cornell-128.pfm, cornell-128_split_L0.pfm .. _L3.pfm; tests/grade_calibration.sh,
# tests/test_grade_mistakes.sh). The manifest keeps the rows of the groups not regenerated, so
# it always lists every file; each row names the revision that made it.
set -euo pipefail
cd "$(dirname "$0")/.."
PATHLAB=${PATHLAB:-./pathlab}
groups=${*:-${REF_GROUPS:-est scenes big}}
for g in $groups; do case $g in est|scenes|big) ;; *) echo "make_refs.sh: unknown group '$g' (est, scenes, big)" >&2; exit 2 ;; esac; done
wants() { case " $groups " in *" $1 "*) return 0 ;; *) return 1 ;; esac; }
rev=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
[ -z "$(git status --porcelain src 2>/dev/null)" ] || rev="$rev+changes"
manifest=ref/MANIFEST.md
rows=$(mktemp); work=$(mktemp -d ref/.tmp.XXXXXX); trap 'rm -rf "$rows" "$work"' EXIT
order=()     # every file of every group, in this order in the manifest
row() {      # file scene spp seed time command
    echo "| $1 | $2 | $3 | $4 | $5 | \`$6\` | $rev |" >> "$rows"
    echo "ref/$1: $5"
}
elapsed() { awk -v a="$1" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f s", b - a }'; }
# name scene spp seed flags...: one image and its variance
ref() {
    local name=$1 scene=$2 spp=$3 seed=$4; shift 4
    order+=("$name.pfm" "${name}_var.pfm")
    wants "$group" || return 0
    local cmd="pathlab render $scene --spp $spp --seed $seed $* -o ref/$name.pfm --variance ref/${name}_var.pfm"
    local t0; t0=$(date +%s.%N)
    $PATHLAB render "$scene" --quiet --spp "$spp" --seed "$seed" "$@" -o "ref/$name.pfm" --variance "ref/${name}_var.pfm"
    local secs; secs=$(elapsed "$t0")
    row "$name.pfm" "$scene" "$spp" "$seed" "$secs" "$cmd"
    row "${name}_var.pfm" "$scene" "$spp" "$seed" "$secs" "$cmd"
}
# name scene spp seed flags...: one render of --bounces 0:3 --split gives name_split_L0 .. _L3 and
# their variances. pathlab names them OUT_Lk.pfm and VAR_Lk.pfm, with OUT = name_split and VAR =
# name_split_var: the variances are renamed to name_split_Lk_var.pfm. The L0..L3 total it also writes
# is their sum and is not kept. (`_split_` because ref/cornell_L1.pfm and cornell_L2.pfm are taken by
# the 24x24 references of group est.)
split_ref() {
    local name=$1 scene=$2 spp=$3 seed=$4 k; shift 4
    local out=${name}_split
    for k in 0 1 2 3; do order+=("${out}_L$k.pfm" "${out}_L${k}_var.pfm"); done
    wants "$group" || return 0
    local cmd="pathlab render $scene --spp $spp --seed $seed $* --bounces 0:3 --split -o $out.pfm --variance ${out}_var.pfm"
    local t0; t0=$(date +%s.%N)
    $PATHLAB render "$scene" --quiet --spp "$spp" --seed "$seed" "$@" --bounces 0:3 --split \
        -o "$work/$out.pfm" --variance "$work/${out}_var.pfm"
    local secs; secs=$(elapsed "$t0")
    for k in 0 1 2 3; do
        mv "$work/${out}_L$k.pfm" "ref/${out}_L$k.pfm"
        mv "$work/${out}_var_L$k.pfm" "ref/${out}_L${k}_var.pfm"
        row "${out}_L$k.pfm" "$scene" "$spp" "$seed" "$secs (all four)" "$cmd"
        row "${out}_L${k}_var.pfm" "$scene" "$spp" "$seed" "$secs (all four)" "$cmd; ${out}_var_L$k.pfm renamed"
    done
}

group=est
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

# Every scene at 64x64 as students render it: jittered pixels, full transport (default --bounces
# 0:inf, Russian roulette after 3 bounces) in SCENE.pfm, L0..L3 in SCENE_split_L0.pfm .. _L3.pfm.
# Default estimators, but --light solid-angle where it converged faster at equal time (measured at
# 128 spp: quad-light 2.7x lower mean relative variance in 1.7x the time, mis-plates 6.7x in 1.5x;
# on the others it changed nothing but the time). spp: about a minute each on 2 cores, and >= 16 times
# the 256 spp `make bench` compares against them (sphere-furnace, ~8x slower per sample: 2048).
group=scenes
seed=3000
for s in cornell:4096: cornell-glossy:4096: furnace:4096: quad-light:8192:solid-angle \
         sphere-furnace:2048: mis-plates:8192:solid-angle; do
    IFS=: read -r name spp light <<< "$s"
    flags="--size 64x64${light:+ --light $light}"
    seed=$((seed + 10))
    # shellcheck disable=SC2086
    ref "$name" "scenes/$name.obj" "$spp" "$seed" $flags
    # shellcheck disable=SC2086
    split_ref "$name" "scenes/$name.obj" "$spp" $((seed + 1)) $flags
done

# The Cornell box at 128x128 as students render it (default estimators, full transport), for grading
# at a second size: the same samples per pixel as the 64x64 one, 4 times the pixels (about a minute
# on 2 cores each). 4096 spp is >= 4 times the 1024 spp that tests/grade_calibration.sh grades.
group=big
ref cornell-128 scenes/cornell.obj 4096 3100 --size 128x128
split_ref cornell-128 scenes/cornell.obj 4096 3101 --size 128x128

# The manifest: every file of every group, its new row if just made, else its old row.
{
    echo "# Reference images"
    echo
    echo "Made by \`make refs\` (ref/make_refs.sh; \`ref/make_refs.sh GROUP\` remakes one group and keeps"
    echo "the other rows), last run at revision $rev on $(date -u +%Y-%m-%d),"
    echo "$(nproc) cores ($(lscpu 2>/dev/null | sed -n 's/^Model name: *//p' | head -1))."
    echo "Each image has its variance of the pixel mean beside it (\`_var.pfm\`)."
    echo
    echo "| file | scene | spp | seed | time | command | revision |"
    echo "|---|---|---|---|---|---|---|"
    for f in "${order[@]}"; do
        line=$(grep -F "| $f |" "$rows" | head -1 || true)
        if [ -z "$line" ] && [ -f "$manifest" ]; then
            line=$(grep -F "| $f |" "$manifest" | head -1 || true)
            # the older format listed only the image: its variance shares the image's row
            if [ -z "$line" ] && [ "${f%_var.pfm}" != "$f" ]; then
                line=$(grep -F "| ${f%_var.pfm}.pfm |" "$manifest" | head -1 | sed "s/^| [^ ]* |/| $f |/" || true)
            fi
            # rows of the older format (no revision column) get the revision of their header
            if [ -n "$line" ] && [ "$(tr -cd '|' <<< "$line" | wc -c)" -eq 7 ]; then
                old=$(sed -n 's/.*at revision \([^ ]*\) on.*/\1/p' "$manifest" | head -1)
                line="$line ${old:-unknown} |"
            fi
        fi
        if [ -z "$line" ]; then echo "make_refs.sh: no manifest row for ref/$f (run its group)" >&2; exit 1; fi
        echo "$line"
    done
} > "$manifest.tmp"
mv "$manifest.tmp" "$manifest"
