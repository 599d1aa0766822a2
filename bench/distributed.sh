#!/usr/bin/env bash
# bench/distributed.sh — how long a 1024x640 Cornell reference takes to reach 1% relative error per
# pixel on average, in one process and split in N pieces with GNU parallel (docs/distributed.md).
#
# At SPP samples per pixel (default 128), seed 1, ROUNDS times in turn (so that other work on the
# machine hits every configuration alike):
#   one process:  pathlab render scenes/cornell.obj --size SIZE --spp SPP --threads THREADS --variance
#   N pieces:     scripts/parallel-render.sh ... --pieces N -j THREADS (each piece --threads 1), N in PIECES
# Each run's wall time (the whole command: loading, every piece, the merge) and CPU time (user + system
# of every process). The relative error is bench/relerr.py on the image and its variance (the mean
# over pixel-channels with a mean above 0 of sqrt(variance of the mean) / mean); every configuration
# renders the same samples, so the images must agree (checked with idiff, 1e-5 relative). The time to
# 1% is extrapolated along 1/sqrt(spp): spp_1% = SPP * (relerr / 0.01)^2, time_1% = time * spp_1% / SPP.
# Prints the table (also written to OUT/distributed.md).
#
# Usage (from the project's root, after make): bench/distributed.sh
# Environment: PATHLAB (./pathlab), SPP (128), SIZE (1024x640), THREADS (2), PIECES ("4 8"),
#   ROUNDS (2), TARGET (0.01), OUT (a temporary folder, deleted at the end unless given).
set -eu
cd "$(dirname "$0")/.."
PATHLAB=${PATHLAB:-./pathlab}
SPP=${SPP:-128} SIZE=${SIZE:-1024x640} THREADS=${THREADS:-2} PIECES=${PIECES:-4 8} ROUNDS=${ROUNDS:-2}
TARGET=${TARGET:-0.01}
if [ -n "${OUT:-}" ]; then mkdir -p "$OUT"; else OUT=$(mktemp -d); trap 'rm -rf "$OUT"' EXIT; fi
scene=scenes/cornell.obj

echo "bench/distributed: $scene at $SIZE, $SPP spp, seed 1; one process of $THREADS threads, and $PIECES pieces by GNU parallel ($THREADS at a time, 1 thread each); $ROUNDS rounds"
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'); load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "pathlab $("$PATHLAB" --version 2>&1 | head -n 1)"

# run NAME COMMAND...: times COMMAND, appends "NAME wall cpu" to OUT/times
run() {
    local name=$1; shift
    /usr/bin/time -f "%e %U %S" -o "$OUT/time.txt" "$@" > "$OUT/run.log" 2>&1 || { cat "$OUT/run.log"; echo "bench/distributed: $name failed" >&2; exit 1; }
    read -r wall user sys < "$OUT/time.txt"
    echo "$name $wall $(echo "$user + $sys" | bc)" >> "$OUT/times"
    printf '  %-10s %8.1f s wall  %8.1f s CPU\n' "$name" "$wall" "$(echo "$user + $sys" | bc)"
}

: > "$OUT/times"
for ((r = 1; r <= ROUNDS; r++)); do
    echo "round $r (load average $(cut -d' ' -f1-3 /proc/loadavg)):"
    rm -f "$OUT"/one*.pfm*
    run one "$PATHLAB" render "$scene" --size "$SIZE" --spp "$SPP" --seed 1 --threads "$THREADS" --quiet \
        -o "$OUT/one.pfm" --variance "$OUT/one_var.pfm"
    for n in $PIECES; do
        rm -f "$OUT/p$n".pfm* "$OUT/p${n}_var".pfm*
        run "$n-pieces" scripts/parallel-render.sh "$scene" "$OUT/p$n.pfm" --spp "$SPP" --pieces "$n" -j "$THREADS" \
            --pathlab "$PATHLAB" --size "$SIZE" --seed 1
        idiff -fail 0 -failrelative 1e-5 -warn 0 -warnrelative 1e-5 "$OUT/p$n.pfm" "$OUT/one.pfm" > "$OUT/idiff.txt" 2>&1 \
            || { tail -n 5 "$OUT/idiff.txt"; echo "bench/distributed: $n pieces merged differ from the one render" >&2; exit 1; }
    done
done
rel=$(bench/relerr.py "$OUT/one.pfm" "$OUT/one_var.pfm" | awk '{ print $2 }')
echo "relative error at $SPP spp: $rel (bench/relerr.py); the merged images equal the one render (idiff, 1e-5)"
echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"

{
    echo "| configuration | wall s at $SPP spp (each round) | mean | ratio to one process | CPU s (mean) | time to $TARGET (extrapolated) |"
    echo "|---|---|---|---|---|---|"
    for name in one $(for n in $PIECES; do echo "$n-pieces"; done); do
        awk -v n="$name" -v spp="$SPP" -v rel="$rel" -v t="$TARGET" '
            $1 == "one" { one += $2; k1++ }
            $1 == n { w = w (w ? ", " : "") sprintf("%.1f", $2); s += $2; c += $3; k++ }
            END { m = s / k; need = spp * (rel / t) ^ 2; tt = m * need / spp
                  printf "| %s | %s | %.1f | %.3f | %.1f | %.0f spp: %dh%02dm |\n", n, w, m, m / (one / k1), c / k, need,
                         int(tt / 3600), int(tt % 3600 / 60 + 0.5) }' "$OUT/times"
    done
} | tee "$OUT/distributed.md"
