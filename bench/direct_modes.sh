#!/usr/bin/env bash
# bench/direct_modes.sh — how long each --direct mode takes to reach the same error on L1.
#
# For each scene, L1 alone (--bounce 1), SIZE pixels, 1 thread:
#  1. a reference: --direct mis-power --light solid-angle --dir brdf at REF_SPP spp with its
#     variance (all cores, seed 4242), cached in OUT and reused while the pathlab binary is the same;
#  2. every configuration below rendered at spp 1, 2, 4, ... MAX_SPP (seed 1), round robin over the
#     configurations and scenes at each spp level so that machine noise hits them all alike; each
#     render's time is its own (the stats line: spp x pixels / Msamples/s, which excludes loading);
#     its error is pfmtool rmse against the reference, with the reference's own noise removed;
#  3. per configuration, over spp >= FIT_MIN: the slopes of log RMSE against log spp and log time
#     (both expected -0.5) and the seconds per spp (total time / total spp, so that load noise is
#     averaged over the run); the spp to reach the target RMSE = TARGET x the reference's mean,
#     interpolated in log-log between the two measured points around it (outside the measured
#     range: extended from the nearest point along spp^-1/2, marked "(extrap.)"); the time to the
#     target = those spp x the seconds per spp; the same again with the process's CPU time (user +
#     system, loading included), less disturbed by other work on a shared machine.
# Prints the table and writes it to OUT/direct_modes.md (raw data: OUT/direct_modes.tsv).
#
# Usage (from the project's root, after make): bench/direct_modes.sh     or: make bench
# Environment: PATHLAB (./pathlab), BUILD (build), OUT ($BUILD/bench), SIZE (128x128),
#   REF_SPP (4096), MAX_SPP (512), FIT_MIN (8), TARGET (0.05), SCENES (cornell cornell-glossy).
set -eu
PATHLAB=${PATHLAB:-./pathlab}
BUILD=${BUILD:-build}
PFMTOOL=${PFMTOOL:-$BUILD/tests/pfmtool}
OUT=${OUT:-$BUILD/bench}
SIZE=${SIZE:-128x128}
REF_SPP=${REF_SPP:-4096}
MAX_SPP=${MAX_SPP:-512}
FIT_MIN=${FIT_MIN:-8}
TARGET=${TARGET:-0.05}
SCENES=${SCENES:-cornell cornell-glossy}
# direct light dir; --direct brdf does not use --light at all, so it is rendered once ("-")
CONFIGS=("light solid-angle brdf" "light area brdf" "brdf - brdf"
         "mis-balance solid-angle brdf" "mis-balance area brdf"
         "mis-power solid-angle brdf" "mis-power area brdf")
REF_FLAGS="--bounce 1 --direct mis-power --light solid-angle --dir brdf --size $SIZE --spp $REF_SPP --seed 4242"

for f in "$PATHLAB" "$PFMTOOL"; do
    [ -x "$f" ] || { echo "direct_modes.sh: $f missing: run make $f first" >&2; exit 2; }
done
mkdir -p "$OUT"
W=${SIZE%x*}; H=${SIZE#*x}
TSV=$OUT/direct_modes.tsv MD=$OUT/direct_modes.md IMG=$OUT/direct_modes.tmp.pfm
loadavg() { cut -d' ' -f1-3 /proc/loadavg; }
# render_time LOG: seconds of the render from its stats line "X.XX s, N spp, M Msamples/s, ..."
render_time() {
    awk -v npix=$((W * H)) '/ spp, .* Msamples\/s/ { spp = $3; ms = $5 } END { if (ms > 0) printf "%.5f", spp * npix / (ms * 1e6); else exit 1 }' "$1"
}

# 1. references
LOAD_START=$(loadavg)
BIN_SUM=$(cksum < "$PATHLAB" | cut -d' ' -f1)
for sc in $SCENES; do
    ref=$OUT/ref_${sc}_L1.pfm stamp=$OUT/ref_${sc}_L1.stamp
    want="$BIN_SUM $REF_FLAGS"
    if [ -f "$ref" ] && [ -f "${ref%.pfm}_var.pfm" ] && [ "$(cat "$stamp" 2>/dev/null)" = "$want" ]; then
        echo "reference $ref: reused (same pathlab binary and flags)"
    else
        echo "reference $ref: rendering ($REF_FLAGS, all cores) ..."
        # shellcheck disable=SC2086
        "$PATHLAB" render "scenes/$sc.obj" $REF_FLAGS -o "$ref" --variance "${ref%.pfm}_var.pfm" 2> "$OUT/ref.log" \
            || { cat "$OUT/ref.log" >&2; exit 1; }
        tail -n 1 "$OUT/ref.log"
        echo "$want" > "$stamp"
    fi
done

# 2. the renders, round robin
LOAD_RENDERS=$(loadavg) DATE_START=$(date -u '+%Y-%m-%d %H:%M')
LOAD_MIN=${LOAD_RENDERS%% *} LOAD_MAX=$LOAD_MIN
echo "load average at the start: $LOAD_START; before the renders: $LOAD_RENDERS"
printf 'scene\tdirect\tlight\tdir\tspp\tseconds\trmse\trmse_raw\tmean\tmean_ref\tvar_ref\tcpu_seconds\n' > "$TSV"
TIMEFORMAT='%3U %3S'   # bash's time: user and system CPU seconds of the whole process
spp=1
while [ "$spp" -le "$MAX_SPP" ]; do
    for sc in $SCENES; do
        ref=$OUT/ref_${sc}_L1.pfm
        for c in "${CONFIGS[@]}"; do
            read -r direct light dir <<< "$c"
            lflag=$light; [ "$lflag" = - ] && lflag=area
            # independent samples: the fitted slopes assume the error falls as 1/sqrt(N)
            if ! { time "$PATHLAB" render "scenes/$sc.obj" --sampler independent --bounce 1 --direct "$direct" --light "$lflag" --dir "$dir" \
                       --size "$SIZE" --spp "$spp" --seed 1 --threads 1 -o "$IMG" 2> "$OUT/render.log"; } 2> "$OUT/cpu.log"; then
                cat "$OUT/render.log" >&2; exit 1
            fi
            t=$(render_time "$OUT/render.log")
            cpu=$(awk '{ print $1 + $2 }' "$OUT/cpu.log")
            # rmse R relrmse _ relmse _ mean_a A mean_b B var_b V rmse_ref E
            read -r _ raw _ _ _ _ _ mean _ mref _ vref _ err <<< "$("$PFMTOOL" rmse "$IMG" "$ref" "${ref%.pfm}_var.pfm")"
            printf '%s\t%s\t%s\t%s\t%d\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$sc" "$direct" "$light" "$dir" "$spp" "$t" "$err" "$raw" "$mean" "$mref" "$vref" "$cpu" >> "$TSV"
        done
    done
    l=$(loadavg); l1=${l%% *}
    LOAD_MIN=$(awk -v a="$LOAD_MIN" -v b="$l1" 'BEGIN { print (b < a ? b : a) }')
    LOAD_MAX=$(awk -v a="$LOAD_MAX" -v b="$l1" 'BEGIN { print (b > a ? b : a) }')
    echo "spp $spp done, load average $l"
    spp=$((spp * 2))
done
rm -f "$IMG"
LOAD_END=$(loadavg) DATE_END=$(date -u '+%H:%M')
echo "load average after: $LOAD_END (1-minute load during the renders: $LOAD_MIN to $LOAD_MAX)"

# 3. fits, times to the target, the table
CPU=$(lscpu 2>/dev/null | sed -n 's/^Model name:[[:space:]]*//p' | head -n 1)
{
    echo "$DATE_START–$DATE_END UTC, \`bench/direct_modes.sh\`, pathlab revision $(git rev-parse --short HEAD 2>/dev/null || echo '?')$(git diff --quiet HEAD -- src 2>/dev/null || echo '+changes'),"
    echo "${CPU:-unknown CPU}, $(nproc) cores; renders with --threads 1; load average (1, 5, 15 min) $LOAD_START at the start,"
    echo "$LOAD_RENDERS before the renders, $LOAD_END after; 1-minute load $LOAD_MIN to $LOAD_MAX during the renders."
    echo "L1 only (\`--bounce 1\`), $SIZE, \`--dir brdf\`, spp 1 to $MAX_SPP (seed 1); reference: \`$REF_FLAGS\`."
    echo "Target: RMSE = $TARGET × the reference's mean (the reference's own noise removed from each RMSE). Slopes: log RMSE"
    echo "against log spp and log render time, spp ≥ $FIT_MIN. ms per spp: total render time / total spp over spp ≥ $FIT_MIN"
    echo "(the render's own time, no loading). spp to target: interpolated in log-log between measured points; \"extrap.\":"
    echo "outside spp 1 to $MAX_SPP, extended along spp^-1/2 from the nearest point. Time to target = spp to target × ms per spp."
    echo "× the fastest in CPU time: the same with the process's user + system CPU time instead (loading included), which"
    echo "other work on a shared machine disturbs less than wall time."
    echo "Mean error: (mean of the $MAX_SPP-spp image − reference mean) / reference mean, ± one standard error (RMSE/√pixels)."
    echo
} > "$MD"
awk -F'\t' -v target="$TARGET" -v fitmin="$FIT_MIN" -v maxspp="$MAX_SPP" -v npix=$((W * H)) '
NR == 1 { next }
{
    key = $1 SUBSEP $2 SUBSEP $3
    if (!(key in n)) { order[++nkeys] = key; n[key] = 0 }
    i = ++n[key]; S[key, i] = $5; T[key, i] = $6; E[key, i] = $7; C[key, i] = $12
    mref[$1] = $10
    if ($5 == maxspp) { last_mean[key] = $9; last_err[key] = $7 }
}
function fmt_t(t) { return t >= 100 ? sprintf("%.0f", t) : t >= 10 ? sprintf("%.1f", t) : sprintf("%.2f", t) }
# least squares slope of log E against log X[key, i] (X = "S" or "T"), over spp >= fitmin
function slope(key, X,    i, x, y, sx, sy, sxx, sxy, m) {
    for (i = 1; i <= n[key]; i++) if (S[key, i] >= fitmin && E[key, i] > 0) {
        x = log(X == "S" ? S[key, i] : T[key, i]); y = log(E[key, i])
        sx += x; sy += y; sxx += x * x; sxy += x * y; m++
    }
    return m >= 2 ? (m * sxy - sx * sy) / (m * sxx - sx * sx) : 0
}
END {
    for (k = 1; k <= nkeys; k++) {
        key = order[k]; split(key, p, SUBSEP); sc = p[1]
        goal = target * mref[sc]
        # seconds per spp: all renders of spp >= fitmin together (load noise averaged over the run)
        st = sc_ = ss = 0
        for (i = 1; i <= n[key]; i++) if (S[key, i] >= fitmin) { st += T[key, i]; sc_ += C[key, i]; ss += S[key, i] }
        cost[key] = st / ss; ccost[key] = sc_ / ss
        # spp to the goal: first downward crossing, interpolated in log-log
        need = ""; note[key] = ""
        for (i = 1; i < n[key]; i++) if (E[key, i] >= goal && E[key, i + 1] < goal && E[key, i + 1] > 0) {
            f = log(goal / E[key, i]) / log(E[key, i + 1] / E[key, i])
            need = exp(log(S[key, i]) + f * log(S[key, i + 1] / S[key, i])); break
        }
        if (need == "") {
            i = E[key, 1] < goal ? 1 : n[key]
            need = S[key, i] * (E[key, i] / goal) ^ 2; note[key] = " (extrap.)"
        }
        spp_need[key] = need; t_need[key] = need * cost[key]; c_need[key] = need * ccost[key]
        if (!(sc in best) || t_need[key] < best[sc]) best[sc] = t_need[key]
        if (!(sc in cbest) || c_need[key] < cbest[sc]) cbest[sc] = c_need[key]
    }
    printf "| scene | `--direct` | `--light` | slope vs spp | slope vs time | ms per spp | RMSE at %d spp | spp to target | time to target (s) | × the fastest | × the fastest in CPU time | mean error at %d spp |\n", maxspp, maxspp
    printf "|---|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n"
    for (k = 1; k <= nkeys; k++) {
        key = order[k]; split(key, p, SUBSEP); sc = p[1]
        printf "| %s | %s | %s | %.2f | %.2f | %.1f | %.3g | %s%s | %s | %.1f | %.1f | %+.2f%% ± %.2f%% |\n", sc, p[2], (p[3] == "-" ? "—" : p[3]),
            slope(key, "S"), slope(key, "T"), 1e3 * cost[key], last_err[key], (spp_need[key] >= 1e3 ? sprintf("%.3g", spp_need[key]) : sprintf("%.0f", spp_need[key])), note[key],
            fmt_t(t_need[key]), t_need[key] / best[sc], c_need[key] / cbest[sc], 100 * (last_mean[key] - mref[sc]) / mref[sc], 100 * last_err[key] / sqrt(npix) / mref[sc]
    }
    printf "\nTargets: "
    for (sc in mref) printf "%s %.3g; ", sc, target * mref[sc]
    printf "(%g × the mean of the reference).\n", target
}' "$TSV" >> "$MD"
echo
cat "$MD"
echo
echo "written: $MD (raw data $TSV)"
