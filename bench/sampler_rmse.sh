#!/usr/bin/env bash
# bench/sampler_rmse.sh — RMSE of --sampler independent and sobol against a committed reference
# (ref/cornell.pfm, ref/mis-plates.pfm: 64x64, independent, 4096 and 8192 spp), at 4, 16, 64 and 256
# spp, each averaged (as MSE) over SEEDS seeds; and the reference's own noise, the mean of its
# _var.pfm, subtracted from the MSE (E[(a - ref)^2] = MSE(a) + Var(ref) when the two are independent).
# Prints one table row per scene and spp: MSE of each sampler (corrected), and the RMSE ratio.
# Usage: bench/sampler_rmse.sh [PATHLAB] (default ./pathlab); THREADS (default 1), SEEDS (default 4).
set -eu
P=${1:-./pathlab}; THREADS=${THREADS:-1}; SEEDS=${SEEDS:-4}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
mse() { "$P" diff "$1" "$2" | awk '/^RMSE/ {print $2 * $2}'; }
varmean() { "$P" convert "$1" "$T/v.png" 2>&1 | awk '/mean/ {s += $3; n++} END {printf "%.6g", s / n}'; }
printf '| scene | spp | MSE independent | MSE sobol | RMSE ratio sobol/independent |\n|---|---|---|---|---|\n'
for case in "cornell|" "mis-plates|--light solid-angle"; do
    scene=${case%%|*}; extra=${case#*|}
    refvar=$(varmean "ref/${scene}_var.pfm")
    for spp in 4 16 64 256; do
        row=""
        for smp in independent sobol; do
            sum=0
            for seed in $(seq 1 "$SEEDS"); do
                # shellcheck disable=SC2086
                "$P" render "scenes/$scene.obj" --size 64x64 --spp "$spp" --seed "$seed" $extra --sampler "$smp" \
                    --threads "$THREADS" --quiet -o "$T/a.pfm"
                sum=$(awk -v s="$sum" -v m="$(mse "$T/a.pfm" "ref/$scene.pfm")" 'BEGIN {print s + m}')
            done
            row="$row $(awk -v s="$sum" -v n="$SEEDS" -v r="$refvar" 'BEGIN {printf "%.5g", s / n - r}')"
        done
        set -- $row
        printf '| %s | %d | %s | %s | %.3f |\n' "$scene" "$spp" "$1" "$2" "$(awk -v a="$1" -v b="$2" 'BEGIN {print (a > 0 && b > 0) ? sqrt(b / a) : 0}')"
    done
    echo "(reference noise subtracted for $scene: $refvar)"
done
