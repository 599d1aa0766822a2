#!/usr/bin/env bash
# tests/same_renders.sh OLD_PATHLAB NEW_PATHLAB — a refactoring must not change a single bit:
# renders every scene of scenes/ with both programs under five flag sets that together use every
# estimator choice (each --light, --dir and --direct, --split, --variance, --rr off, --pixel-center,
# one and two threads) at 40x40, 8 spp, and compares the PFMs byte for byte (cmp).
# Prints one line per render and "N identical, N different"; exits 1 if any differs.
# Used before and after each step of a refactoring, e.g.:
#   git stash; make; cp pathlab /tmp/old; git stash pop; make; tests/same_renders.sh /tmp/old ./pathlab
set -u
cd "$(dirname "$0")/.."
[ $# -eq 2 ] || { echo "usage: tests/same_renders.sh OLD_PATHLAB NEW_PATHLAB" >&2; exit 2; }
old=$(realpath "$1") new=$(realpath "$2") root=$PWD
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
FLAGS=(
    ""
    "--direct light --light solid-angle --bounces 0:4 --split --variance V.pfm --threads 1"
    "--direct brdf --dir cosine --threads 2"
    "--direct mis-balance --light power --dir uniform --rr off --bounces 1:3 --split"
    "--light triangle --pixel-center --rr 1 --seed 7 --variance V.pfm"
)
same=0; differ=0
for scene in scenes/*.obj; do
    for i in "${!FLAGS[@]}"; do
        for side in old new; do
            mkdir -p "$T/$side"
            prog=$old; [ $side = new ] && prog=$new
            # shellcheck disable=SC2086
            (cd "$T/$side" && rm -f ./*.pfm && "$prog" render "$root/$scene" --size 40x40 --spp 8 --quiet ${FLAGS[i]} -o out.pfm) \
                || echo "  $side program failed on $scene ${FLAGS[i]}"
        done
        ok=1
        for f in "$T"/old/*.pfm; do cmp -s "$f" "$T/new/$(basename "$f")" || ok=0; done
        [ "$(ls "$T/old" | wc -l)" = "$(ls "$T/new" | wc -l)" ] || ok=0
        n=$(ls "$T/old" | wc -l)
        if [ $ok = 1 ]; then same=$((same + 1)); echo "identical  $scene  [${FLAGS[i]:-defaults}]  ($n PFMs)"
        else differ=$((differ + 1)); echo "DIFFERENT  $scene  [${FLAGS[i]:-defaults}]"; fi
    done
done
echo "$same identical, $differ different"
[ $differ -eq 0 ]
