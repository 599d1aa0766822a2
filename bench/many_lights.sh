#!/usr/bin/env bash
# bench/many_lights.sh — --light tree against --light power and --light area on a scene of many
# lights (scenes/many-lights: 10560 emitting triangles), at equal time: MSE x time.
#
#  1. a reference: --light tree --direct mis-power at REF_SPP spp with its variance (all of THREADS),
#     seed 4242, cached in OUT while the pathlab binary is the same;
#  2. ROUNDS rounds; in each, every strategy renders the whole light transport (default flags but
#     --light) for SEC seconds (--time) on THREADS threads, seed = the round, one after the other so
#     that machine noise hits them alike; its time is the stats line's, its error the MSE against
#     the reference with the reference's own noise removed (pfmtool rmse's rmse_ref);
#  3. per strategy: spp reached, MSE, MSE x time, and that product relative to --light power's
#     (below 1: better; the mean over the rounds).
# Prints the table and writes it to OUT/many_lights.md (raw data: OUT/many_lights.tsv).
#
# Usage (from the project's root, after make and make test-build): bench/many_lights.sh
# Environment: PATHLAB (./pathlab), BUILD (build), OUT ($BUILD/bench), SIZE (160x120), REF_SPP (2048),
#   SEC (10), ROUNDS (2), THREADS (2), LIGHTS (tree power area).
set -eu
PATHLAB=${PATHLAB:-./pathlab}
BUILD=${BUILD:-build}
PFMTOOL=${PFMTOOL:-$BUILD/tests/pfmtool}
OUT=${OUT:-$BUILD/bench}
SIZE=${SIZE:-160x120}
REF_SPP=${REF_SPP:-2048}
SEC=${SEC:-10}
ROUNDS=${ROUNDS:-2}
THREADS=${THREADS:-2}
LIGHTS=${LIGHTS:-tree power area}
SCENE=scenes/many-lights.obj
for f in "$PATHLAB" "$PFMTOOL"; do
    [ -x "$f" ] || { echo "many_lights.sh: $f missing: run make (and make test-build) first" >&2; exit 2; }
done
mkdir -p "$OUT"
TSV=$OUT/many_lights.tsv MD=$OUT/many_lights.md IMG=$OUT/many_lights.tmp.pfm
ref=$OUT/ref_many_lights.pfm stamp=$OUT/ref_many_lights.stamp
REF_FLAGS="--size $SIZE --spp $REF_SPP --seed 4242 --light tree --direct mis-power --threads $THREADS"
want="$(cksum < "$PATHLAB" | cut -d' ' -f1) $REF_FLAGS"
if [ -f "$ref" ] && [ -f "${ref%.pfm}_var.pfm" ] && [ "$(cat "$stamp" 2>/dev/null)" = "$want" ]; then
    echo "reference $ref: reused (same pathlab binary and flags)"
else
    echo "reference: $REF_FLAGS"
    # shellcheck disable=SC2086
    "$PATHLAB" render "$SCENE" $REF_FLAGS -o "$ref" --variance "${ref%.pfm}_var.pfm" 2>&1 | grep ' spp, '
    echo "$want" > "$stamp"
fi
LOAD_START=$(cut -d' ' -f1-3 /proc/loadavg)
printf "round\tlight\tspp\tseconds\tmse\n" > "$TSV"
for round in $(seq 1 "$ROUNDS"); do
    for l in $LIGHTS; do
        "$PATHLAB" render "$SCENE" --size "$SIZE" --time "$SEC" --threads "$THREADS" --seed "$round" --light "$l" \
            -o "$IMG" 2> "$OUT/render.log"
        t=$(awk '/ spp, .* Msamples\/s/ { print $1 }' "$OUT/render.log")
        spp=$(awk '/ spp, .* Msamples\/s/ { print $3 }' "$OUT/render.log")
        mse=$("$PFMTOOL" rmse "$IMG" "$ref" "${ref%.pfm}_var.pfm" | awk '{ for (i = 1; i < NF; i++) if ($i == "rmse_ref") print $(i + 1) ^ 2 }')
        printf "%s\t%s\t%s\t%s\t%s\n" "$round" "$l" "$spp" "$t" "$mse" >> "$TSV"
        echo "round $round  --light $l: $spp spp in $t s, MSE $mse"
    done
done
LOAD_END=$(cut -d' ' -f1-3 /proc/loadavg)
{
    echo "# Many lights: MSE x time, scenes/many-lights, $SIZE, $SEC s per render, $THREADS threads"
    echo
    echo "$(date -u '+%Y-%m-%d %H:%M UTC'), $("$PATHLAB" --version | head -1), $ROUNDS rounds, reference $REF_FLAGS;"
    echo "load average $LOAD_START at the start, $LOAD_END at the end."
    echo
    echo "| --light | round | spp | seconds | MSE | MSE x time | / power's |"
    echo "|---|--:|--:|--:|--:|--:|--:|"
    awk -F'\t' 'NR > 1 { k = $1; p[k, $2] = $4 * $5; r[NR] = $0 }
        END { for (i = 2; i <= NR; i++) { split(r[i], f, "\t"); x = f[4] * f[5]
                  printf "| %s | %s | %s | %s | %.4g | %.4g | %.3f |\n", f[2], f[1], f[3], f[4], f[5], x, x / p[f[1], "power"] } }' "$TSV"
    echo
    awk -F'\t' 'NR > 1 { s[$2] += $4 * $5; n[$2]++; if ($2 == "power") sp += $4 * $5 }
        END { for (l in s) printf "mean MSE x time of --light %s / power'"'"'s: %.3f\n", l, s[l] / sp }' "$TSV" | sort
} > "$MD"
cat "$MD"
