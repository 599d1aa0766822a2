#!/usr/bin/env bash
# bench/sweep.sh — RMSE against render time for every estimator on every scene (the last step of
# `make bench`).
#
# For each scene of SCENES (default: every scenes/*.obj), full transport (pathlab's defaults apart
# from the estimator flags), the scene's own camera at the reference's size, 1 thread, seed 1:
#  1. the reference is REF_DIR/SCENE.pfm with its variance REF_DIR/SCENE_var.pfm (error, naming
#     the file, if either is missing: make them with `make refs`); the renders take its size;
#  2. every estimator below at spp 1, 2, 4, ... round robin over estimators and scenes at each spp
#     level (so that machine noise hits them all alike); a curve stops when its next point would
#     take more than BUDGET seconds (twice its last render time) or pass MAX_SPP;
#  3. each render's time is its own, from its stats line (loading excluded; of "X.XX s" and
#     "spp x pixels / (M Msamples/s)", whichever is printed with the smaller relative rounding);
#     its error is `bench-plot error` against the reference, the reference's own noise removed
#     (see bench/plot.c);
#  4. `bench-plot report` writes the SVG (log-log RMSE against time, one panel per scene, one curve
#     per estimator) and prints each curve's slopes and the ranking by efficiency 1/(MSE x time);
#     then the same with the relative MSE (sqrt(relMSE) against time), which bright pixels (the
#     light's jittered edges, the same for every estimator) weigh less.
# Writes CSV (bench/results.csv), SVG (docs/bench.svg) and SVG_REL (docs/bench-relmse.svg), each
# complete or not at all, and both reports to OUT/sweep.md.
#
# Usage (from the project's root, after make): bench/sweep.sh     or: make bench
# Environment: PATHLAB (./pathlab), BUILD (build), PLOT ($BUILD/bench-plot), OUT ($BUILD/bench),
#   REF_DIR (ref), SCENES (every scenes/*.obj), ESTIMATORS (all labels below), BUDGET (2, seconds
#   per point), MAX_SPP (4096), THREADS (1), SEED (1), FIT_MIN (4), CSV, SVG, SVG_REL.
set -eu
PATHLAB=${PATHLAB:-./pathlab}
BUILD=${BUILD:-build}
PLOT=${PLOT:-$BUILD/bench-plot}
OUT=${OUT:-$BUILD/bench}
REF_DIR=${REF_DIR:-ref}
BUDGET=${BUDGET:-2}
MAX_SPP=${MAX_SPP:-4096}
THREADS=${THREADS:-1}
SEED=${SEED:-1}
FIT_MIN=${FIT_MIN:-4}
CSV=${CSV:-bench/results.csv}
SVG=${SVG:-docs/bench.svg}
SVG_REL=${SVG_REL:-docs/bench-relmse.svg}
if [ -z "${SCENES:-}" ]; then
    SCENES=$(for f in scenes/*.obj; do basename "$f" .obj; done)
fi
# label|flags. Every --direct choice with --light area and --dir brdf (light sampling and MIS also
# with --light solid-angle), then every --dir choice with --direct mis-power; mis-power with --dir
# brdf is in both families and is run once. --direct brdf never samples a light, so no --light.
ALL_EST=("light|--direct light --light area --dir brdf"
         "light-sa|--direct light --light solid-angle --dir brdf"
         "brdf|--direct brdf --dir brdf"
         "mis-balance|--direct mis-balance --light area --dir brdf"
         "mis-power|--direct mis-power --light area --dir brdf"
         "mis-power-sa|--direct mis-power --light solid-angle --dir brdf"
         "dir-cosine|--direct mis-power --light area --dir cosine"
         "dir-uniform|--direct mis-power --light area --dir uniform")
EST=()
for e in "${ALL_EST[@]}"; do
    if [ -z "${ESTIMATORS:-}" ] || [[ " $ESTIMATORS " == *" ${e%%|*} "* ]]; then EST+=("$e"); fi
done
[ ${#EST[@]} -gt 0 ] || { echo "sweep.sh: ESTIMATORS='$ESTIMATORS' names none of: ${ALL_EST[*]%%|*}" >&2; exit 2; }

for f in "$PATHLAB" "$PLOT"; do
    [ -x "$f" ] || { echo "sweep.sh: $f missing: run make first" >&2; exit 2; }
done
# pfm_size FILE: "W H" from the PFM header (3 whitespace-separated tokens: magic, width, height)
pfm_size() { head -c 64 "$1" | tr -s ' \t\r\n' '\n' | sed -n '2p;3p' | tr '\n' ' '; }
declare -A SIZE
for sc in $SCENES; do
    [ -f "scenes/$sc.obj" ] || { echo "sweep.sh: scenes/$sc.obj: no such scene" >&2; exit 2; }
    for f in "$REF_DIR/$sc.pfm" "$REF_DIR/${sc}_var.pfm"; do
        [ -f "$f" ] || { echo "sweep.sh: $f: missing (the reference of scenes/$sc.obj; make it with make refs)" >&2; exit 2; }
    done
    read -r w h <<< "$(pfm_size "$REF_DIR/$sc.pfm")"
    [[ "$w" =~ ^[0-9]+$ && "$h" =~ ^[0-9]+$ ]] || { echo "sweep.sh: $REF_DIR/$sc.pfm: not a PFM file" >&2; exit 2; }
    SIZE[$sc]=${w}x$h
done
mkdir -p "$OUT"
IMG=$OUT/sweep.tmp.pfm LOG=$OUT/sweep.log CPULOG=$OUT/sweep.cpu ROWS=$OUT/sweep.rows
loadavg() { cut -d' ' -f1-3 /proc/loadavg; }
# render_time LOG NPIX WALL: the render's seconds from its stats line "X.XX s, N spp, M Msamples/s, ..."
# (exit 1 without one); the process's wall time WALL if both print as 0 (a tiny test render)
render_time() {
    awk -v npix="$2" -v wall="$3" '/ spp, .* Msamples\/s/ { t = $1; spp = $3; ms = $5; found = 1 }
        END { if (!found) exit 1
              # both printed with 2 decimals: keep the one whose rounding is the smaller fraction
              if (t >= ms && t > 0) printf "%.5f", t
              else if (ms > 0) printf "%.5f", spp * npix / (ms * 1e6)
              else printf "%.5f", (wall > 0 ? wall : 0.001) }' "$1"
}

START=$(date +%s) LOAD_START=$(loadavg) DATE_START=$(date -u '+%Y-%m-%d %H:%M')
LOAD_MIN=${LOAD_START%% *} LOAD_MAX=$LOAD_MIN
echo "sweep: scenes ${SCENES//$'\n'/ }, ${#EST[@]} estimators, budget $BUDGET s per point, $THREADS thread(s); load average $LOAD_START"
: > "$ROWS"
TIMEFORMAT='%3R %3U %3S'   # bash's time: wall, user and system seconds of the whole process
declare -A ACTIVE
for sc in $SCENES; do for e in "${EST[@]}"; do ACTIVE["$sc|${e%%|*}"]=1; done; done
spp=1
while [ ${#ACTIVE[@]} -gt 0 ]; do
    for sc in $SCENES; do
        ref=$REF_DIR/$sc.pfm size=${SIZE[$sc]}
        npix=$(( ${size%x*} * ${size#*x} ))
        for e in "${EST[@]}"; do
            label=${e%%|*} flags=${e#*|}
            [ -n "${ACTIVE["$sc|$label"]:-}" ] || continue
            # shellcheck disable=SC2086
            # independent samples: the estimators' RMSE against time is the slides' Monte Carlo lesson
            if ! { time "$PATHLAB" render "scenes/$sc.obj" --sampler independent $flags --size "$size" --spp "$spp" --seed "$SEED" \
                       --threads "$THREADS" -o "$IMG" 2> "$LOG"; } 2> "$CPULOG"; then
                cat "$LOG" >&2; exit 1
            fi
            read -r wall user sys < "$CPULOG"
            t=$(render_time "$LOG" "$npix" "$wall") || { echo "sweep.sh: no stats line from pathlab:" >&2; cat "$LOG" >&2; exit 1; }
            err=$("$PLOT" error "$IMG" "$ref" "${ref%.pfm}_var.pfm") || exit 1
            # rmse R rmse_raw R0 relmse X mae M ...
            read -r _ rmse _ raw _ relmse _ mae _ <<< "$err"
            echo "$sc,$label,$flags,$spp,$t,$wall,$(awk -v u="$user" -v s="$sys" 'BEGIN { print u + s }'),$rmse,$raw,$relmse,$mae" >> "$ROWS"
            if awk -v t="$t" -v b="$BUDGET" 'BEGIN { exit !(2 * t > b) }' || [ $((2 * spp)) -gt "$MAX_SPP" ]; then
                unset "ACTIVE[$sc|$label]"
            fi
        done
    done
    l=$(loadavg); l1=${l%% *}
    LOAD_MIN=$(awk -v a="$LOAD_MIN" -v b="$l1" 'BEGIN { print (b < a ? b : a) }')
    LOAD_MAX=$(awk -v a="$LOAD_MAX" -v b="$l1" 'BEGIN { print (b > a ? b : a) }')
    echo "spp $spp done, $(( $(date +%s) - START )) s, load average $l, ${#ACTIVE[@]} curves go on"
    spp=$((spp * 2))
done
rm -f "$IMG"
LOAD_END=$(loadavg) DATE_END=$(date -u '+%H:%M') SECS=$(( $(date +%s) - START ))
CPU=$(lscpu 2>/dev/null | sed -n 's/^Model name:[[:space:]]*//p' | head -n 1)
REV="$(git rev-parse --short HEAD 2>/dev/null || echo '?')$(git diff --quiet HEAD -- src 2>/dev/null || echo '+changes')"
MACHINE="${CPU:-unknown CPU}, $(nproc) cores; load average (1, 5, 15 min) $LOAD_START at the start, $LOAD_END at the end, 1-minute load $LOAD_MIN to $LOAD_MAX"
RUN="$DATE_START–$DATE_END UTC, bench/sweep.sh ($SECS s), pathlab $REV, $THREADS thread(s), seed $SEED, budget $BUDGET s per point"

tmp=$(mktemp "$CSV.tmp.XXXXXX")
{
    echo "# bench/results.csv — written by bench/sweep.sh: RMSE against render time, every estimator on every scene."
    echo "# $RUN"
    echo "# $MACHINE"
    echo "# Renders: full transport, the scene's camera at the reference's size, reference REF_DIR/SCENE.pfm ($REF_DIR)."
    echo "# seconds: the render's own time from its stats line (loading excluded); wall_seconds, cpu_seconds: the whole"
    echo "# process (wall; user + system). rmse: against the reference, its own noise removed (sqrt(max(0, MSE - mean"
    echo "# reference variance))); rmse_raw: without that; relmse: mean((a-b)^2 - var_ref)/(ref^2 + 0.01); mae: mean |a-b|, raw."
    echo "scene,estimator,flags,spp,seconds,wall_seconds,cpu_seconds,rmse,rmse_raw,relmse,mae"
    cat "$ROWS"
} > "$tmp"
chmod "$(printf '%o' $((0666 & ~$(umask))))" "$tmp"    # mktemp makes 0600
mv "$tmp" "$CSV"
"$PLOT" report "$CSV" "$SVG" --fit-min "$FIT_MIN" --caption "$RUN" --caption "$MACHINE" > "$OUT/sweep.md.tmp"
"$PLOT" report "$CSV" "$SVG_REL" --metric relmse --fit-min "$FIT_MIN" --caption "$RUN" --caption "$MACHINE" \
    | awk 'n >= 2; /^$/ { n++ }' > "$OUT/sweep_rel.md.tmp"    # without its estimator list (the same)
{ echo "$RUN."; echo "$MACHINE."; echo; cat "$OUT/sweep.md.tmp"; echo; echo "The same ranked by relative MSE:"; cat "$OUT/sweep_rel.md.tmp"; } > "$OUT/sweep.md"
rm -f "$OUT/sweep.md.tmp" "$OUT/sweep_rel.md.tmp" "$ROWS"
echo
cat "$OUT/sweep.md"
echo
echo "written: $CSV, $SVG, $SVG_REL, $OUT/sweep.md ($SECS s)"
