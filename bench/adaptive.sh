#!/usr/bin/env bash
# bench/adaptive.sh — error at equal time, uniform against adaptive sampling (docs/adaptive.md).
# For each scene: a reference (1024 spp, kept in OUT), then for each time T, REPS rounds of, in turn,
# `render --time T` (uniform) and `render --adaptive --time T` (pilot included in T), each with its
# own seed; bench/adaptive_error.py gives RMSE and relMSE with the reference's noise taken out.
# With TARGETS="0.1 ...": also at equal samples, --target-error E against uniform --spp (mean + 16).
# Environment: PATHLAB (default ./pathlab), SCENES ("cornell mis-plates"), SIZE (200x200), THREADS (2),
# TIMES ("5 20"), REPS (2), TARGETS (""), OUT (a temporary folder). Prints one line per render.
set -eu
cd "$(dirname "$0")/.."
P=${PATHLAB:-./pathlab}; SIZE=${SIZE:-200x200}; THREADS=${THREADS:-2}
OUT=${OUT:-$(mktemp -d)}; mkdir -p "$OUT"
for s in ${SCENES:-cornell mis-plates}; do
    ref=$OUT/ref_$s.pfm
    [ -f "$ref" ] || $P render "scenes/$s.obj" --quiet --size "$SIZE" --threads "$THREADS" --spp 1024 --seed 777 -o "$ref" --variance "$OUT/ref_${s}_var.pfm"
    for t in ${TIMES:-5 20}; do
        for r in $(seq 1 "${REPS:-2}"); do
            for mode in uniform adaptive; do
                f=$OUT/${s}_${t}_${mode}_$r.pfm
                flags=$([ $mode = adaptive ] && echo "--adaptive --sample-count $OUT/${s}_${t}_${mode}_${r}_n.pfm" || true)
                # shellcheck disable=SC2086
                # independent samples for both, as adaptive sampling uses: the allocation is what is compared
                $P render "scenes/$s.obj" --sampler independent --quiet --size "$SIZE" --threads "$THREADS" --time "$t" --seed $((1000 * r + t)) $flags -o "$f"
                spp=$(sed -n 's/^spp-mean //p; s/^spp \([0-9]*\)$/\1/p' "$f.meta")
                echo "$s T=$t $mode rep $r: $(python3 bench/adaptive_error.py "$ref" "$OUT/ref_${s}_var.pfm" "$f" | cut -d' ' -f2-) spp $spp"
            done
        done
    done
    # equal samples (no clock involved): --target-error E, then uniform with as many samples in all
    # (the mean count plus the pilot's 16)
    for e in ${TARGETS:-}; do
        f=$OUT/${s}_e${e}_adaptive.pfm
        $P render "scenes/$s.obj" --quiet --size "$SIZE" --threads "$THREADS" --target-error "$e" --seed 4242 -o "$f" --sample-count "${f%.pfm}_n.pfm"
        m=$(sed -n 's/^spp-mean //p' "$f.meta")
        n=$(awk -v m="$m" 'BEGIN { printf "%d", m + 16 + 0.5 }')
        $P render "scenes/$s.obj" --sampler independent --quiet --size "$SIZE" --threads "$THREADS" --spp "$n" --seed 4242 -o "$OUT/${s}_e${e}_uniform.pfm"
        echo "$s --target-error $e (mean $m spp + 16 pilot): $(python3 bench/adaptive_error.py "$ref" "$OUT/ref_${s}_var.pfm" "$f" | cut -d' ' -f2-)"
        echo "$s uniform --spp $n: $(python3 bench/adaptive_error.py "$ref" "$OUT/ref_${s}_var.pfm" "$OUT/${s}_e${e}_uniform.pfm" | cut -d' ' -f2-)"
    done
done
