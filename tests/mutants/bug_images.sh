#!/usr/bin/env bash
# tests/mutants/bug_images.sh — the pictures of docs/correctness.md: the Cornell box rendered by
# four classic bugs (mutants of tests/mutants/list.sh, built in a temporary copy of the tree) and by
# the correct program, 256x256 at 64 spp, full transport, seed 1, into docs/img/bug_NAME.png and
# docs/img/correct_cornell.png; then `pathlab grade` of each 64-spp image against a 1024-spp render
# of the correct program (prints the verdict lines). About 4 minutes on 2 cores.
# Usage: tests/mutants/bug_images.sh [OUTDIR]   (default docs/img)
set -u
. "$(dirname "$0")/lib.sh"
OUT=${1:-$ROOT/docs/img}
BUGS="no-cos-surface area-pdf emission-twice acne"
SIZE=256x256 SPP=64 REF_SPP=1024
FLAGS="--size $SIZE --seed 1 --quiet --sampler independent"   # graded: independent samples, as grade assumes
W=$(mktemp -d); trap 'rm -rf "$W"' EXIT
mkdir -p "$OUT"
copy_tree "$W/base" && build_in "$W/base" pathlab || { echo "the unbroken copy does not build" >&2; exit 1; }
# render BINARY NAME: NAME.pfm (for grade) and NAME.png (for the docs), the same image
render() {
    # shellcheck disable=SC2086
    nice -n 10 "$1" render "$ROOT/scenes/cornell.obj" $FLAGS --spp $SPP -o "$W/$2.pfm" &&
        nice -n 10 "$1" render "$ROOT/scenes/cornell.obj" $FLAGS --spp $SPP -o "$OUT/$2.png"
}
echo "reference: the correct program, $REF_SPP spp"
# shellcheck disable=SC2086
nice -n 10 "$W/base/pathlab" render "$ROOT/scenes/cornell.obj" --size $SIZE --seed 99 --quiet --sampler independent --spp $REF_SPP -o "$W/ref.pfm" || exit 1
render "$W/base/pathlab" correct_cornell || exit 1
for b in $BUGS; do
    i=$(mutant_index "$b") || { echo "no mutant $b" >&2; exit 1; }
    apply_mutant "$i" "$W/base" "$W/m_$b" || { echo "mutant $b did not apply" >&2; exit 1; }
    build_in "$W/m_$b" pathlab || exit 1
    render "$W/m_$b/pathlab" "bug_$b" || exit 1
done
for n in correct_cornell $(for b in $BUGS; do echo "bug_$b"; done); do
    echo "== pathlab grade $n.pfm --ref ref_${REF_SPP}spp.pfm"
    "$W/base/pathlab" grade "$W/$n.pfm" --ref "$W/ref.pfm"
    echo "(exit status $?)"
done
