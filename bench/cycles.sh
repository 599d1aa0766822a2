#!/usr/bin/env bash
# bench/cycles.sh [--doc] — pathlab's efficiency against Blender Cycles 3.4 at equal time.
#
# On diffuse scenes (SCENES: scenes/cornell and McGuire's CornellBox-Original), SIZE pixels, THREADS
# threads, for each LEVEL of spp (64 256), in one run and back to back so that the shared machine's
# load hits both renderers alike:
#  1. Cycles (../shared/tools/cycles/cycles_ref.py: Lambert, one-sided emission, box filter 1 pixel,
#     no clamping, denoising or adaptive sampling) renders LEVEL spp; T = its CYCLES_DONE time (render
#     and scene sync, without Blender's start-up);
#  2. right after, each pathlab column renders with `--time T` (as many passes as fit in T: the
#     equal time is measured in the same minute, whatever the load, instead of predicting an spp from
#     an earlier timing run); its time is its stats line's (the render, no loading);
#  3. every image's MSE (mean over pixels and R, G, B) against two references of REF_SPP spp each, one
#     rendered by Cycles, one by pathlab (REF_PATHLAB, default flags); each reference is the average of
#     two halves with different seeds, so its own noise, mean (A - B)^2 / 4, is known and is taken off
#     every MSE. Against its own renderer's reference an MSE is that renderer's variance alone; against
#     the other's it also holds the systematic difference of the two renderers (bias^2).
#  4. efficiency = MSE x time; the ratio pathlab / Cycles (below 1: pathlab reaches the error sooner;
#     pathlab's target is at most 0.5), with both images measured against the same reference: the Cycles one
#     (charges pathlab with any difference from Cycles) and the pathlab one (the reverse).
# The scenes' exact duplicate faces (same corner positions; CornellBox-Original has two) are removed
# for both renderers (into a temporary copy): Cycles skips self-hits by primitive id and renders
# both twins black. Nothing is masked: the lamp seen directly and the open front's black pixels count.
# The references are checked against each other: mean difference per channel with its standard
# error, alignment (their MSE at every one-pixel shift and flipped: no shift must win), worst blocks.
#
# Columns: PATHLAB (default ./pathlab) with each flag set of PATHLAB_FLAGS, separated by ';' (e.g.
# PATHLAB_FLAGS="; --sampler sobol" gives two columns: default flags and sobol); a set whose first
# word is a path to an executable uses that program instead (e.g. "/tmp/sobolsnap/pathlab --sampler sobol").
# Prints the Markdown table; --doc also writes it into docs/performance.md under the heading
# "Efficiency against Blender Cycles" (replacing that section). Raw data: OUT/cycles.tsv; the last
# round's images: OUT/cycles_img/SCENE_LEVEL_cycles.exr, ..._columnN.pfm.
#
# Usage (from the project's root): make bench-cycles, or bench/cycles.sh [--doc]
# Environment: PATHLAB, PATHLAB_FLAGS, REF_PATHLAB (first column's program), REF_PATHLAB_FLAGS (""),
#   SIZE (200x200), THREADS (2), LEVELS (64 256), REF_SPP (2048, two halves), ROUNDS (1; round r uses
#   seed r for both renderers), SCENES (cornell mcguire; mcguire-NAME adds MCGUIRE/NAME.obj, e.g.
#   mcguire-CornellBox-Empty-RG, with CornellBox-Original's camera; NAME adds scenes/NAME.obj with
#   scenes/NAME.view, e.g. cornell-glossy with CYCLES_REF=tools/cycles_glossy.py), OUT (build-native/bench if it exists, else
#   build/bench), REF_DIR (${XDG_CACHE_HOME:-~/.cache}/pathlab-bench-cycles: cached references),
#   CYCLES_REF (../shared/tools/cycles/cycles_ref.py), MCGUIRE (../shared/data/cornell-mcguire),
#   CYCLES_PATTERN (Cycles' sampling pattern for every Cycles render, set through tools/cycles_pattern.py;
#   empty: Blender's default, progressive multi-jitter in 3.4, which renders scenes/many-lights 0.4 % to
#   1.7 % too bright; SOBOL agrees with pathlab there: bench/log.md, "the 0.4 % explained").
set -eu
DOC=0
[ "${1:-}" = --doc ] && { DOC=1; shift; }
[ $# -eq 0 ] || { echo "usage: bench/cycles.sh [--doc] (settings in the environment, see the script's head)" >&2; exit 2; }
PATHLAB=${PATHLAB:-./pathlab}
PATHLAB_FLAGS=${PATHLAB_FLAGS:-}
REF_PATHLAB=${REF_PATHLAB:-}
REF_PATHLAB_FLAGS=${REF_PATHLAB_FLAGS:-}
SIZE=${SIZE:-200x200} THREADS=${THREADS:-2} LEVELS=${LEVELS:-64 256} REF_SPP=${REF_SPP:-2048}
ROUNDS=${ROUNDS:-1} SCENES=${SCENES:-cornell mcguire}
OUT=${OUT:-$( [ -d build-native ] && echo build-native/bench || echo build/bench )}
REF_DIR=${REF_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/pathlab-bench-cycles}
CYCLES_REF=${CYCLES_REF:-../shared/tools/cycles/cycles_ref.py}
CYCLES_PATTERN=${CYCLES_PATTERN:-}
MCGUIRE=${MCGUIRE:-../shared/data/cornell-mcguire}
PY=/usr/bin/python3   # Debian's python3 (python3-openimageio), not a pyenv one
HELP="$PY bench/cycles_images.py"
die() { echo "bench/cycles.sh: $*" >&2; exit 1; }

# the columns: program and flags
COL_BIN=() COL_FLAGS=() COL_LABEL=()
IFS=';' read -r -a sets <<< "$PATHLAB_FLAGS;"
[ ${#sets[@]} -gt 0 ] || sets=("")
for s in "${sets[@]}"; do
    read -r first rest <<< "$s" || true
    if [ -n "${first:-}" ] && [ "${first#*/}" != "$first" ] && [ -x "$first" ]; then bin=$first flags=${rest:-}
    else bin=$PATHLAB flags=$(echo "$s" | sed 's/^ *//; s/ *$//'); fi
    COL_BIN+=("$bin") COL_FLAGS+=("$flags")
    COL_LABEL+=("${flags:-default flags}$( [ "$bin" = "$PATHLAB" ] || echo " ($bin)")")
done
[ -n "$REF_PATHLAB" ] || REF_PATHLAB=${COL_BIN[0]}
command -v blender >/dev/null || die "blender missing (make bench-cycles installs it)"
$PY -c 'import OpenImageIO' 2>/dev/null || die "python3-openimageio missing for $PY (make bench-cycles installs it)"
[ -f "$CYCLES_REF" ] || die "$CYCLES_REF missing"
for b in "${COL_BIN[@]}" "$REF_PATHLAB"; do [ -x "$b" ] || die "$b missing: build it first (make)"; done
mkdir -p "$OUT/cycles_img" "$REF_DIR"
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
W=${SIZE%x*} H=${SIZE#*x}
loadavg() { cut -d' ' -f1-3 /proc/loadavg; }
BLENDER_VERSION=$(blender -b --factory-startup --version 2>/dev/null | sed -n 's/^Blender \([0-9.]*\).*/\1/p' | head -n 1)

# scenes: a deduplicated copy (OBJ beside its MTL) and the camera, the same for both renderers
view_get() { sed -n "s/^$2[[:space:]]\+//p" "$1" | head -n 1 | tr -s ' \t' ','; }
declare -A OBJ CAM
for sc in $SCENES; do
    mkdir -p "$T/$sc"
    case $sc in
        cornell) src=scenes/cornell.obj
            CAM[$sc]="--eye $(view_get scenes/cornell.view eye) --target $(view_get scenes/cornell.view target) --up $(view_get scenes/cornell.view up) --fov $(view_get scenes/cornell.view fov)" ;;
        mcguire) src=$MCGUIRE/CornellBox-Original.obj
            # no camera comes with it; ../shared/data/README.md's suggestion
            CAM[$sc]="--eye 0,1,3.9 --target 0,1,0 --up 0,1,0 --fov 40" ;;
        mcguire-*) src=$MCGUIRE/${sc#mcguire-}.obj   # another of McGuire's boxes, the same camera
            CAM[$sc]="--eye 0,1,3.9 --target 0,1,0 --up 0,1,0 --fov 40" ;;
        *) src=scenes/$sc.obj   # another of pathlab's scenes, with its camera
            [ -f scenes/$sc.view ] || die "unknown scene $sc (cornell, mcguire, mcguire-NAME for MCGUIRE/NAME.obj, or NAME for scenes/NAME.obj and .view)"
            CAM[$sc]="--eye=$(view_get scenes/$sc.view eye) --target=$(view_get scenes/$sc.view target) --up=$(view_get scenes/$sc.view up) --fov=$(view_get scenes/$sc.view fov)" ;;
    esac
    [ -f "$src" ] || die "$src missing"
    for m in $(sed -n 's/^mtllib[[:space:]]*//p' "$src" | tr -d '\r'); do cp "$(dirname "$src")/$m" "$T/$sc/"; done
    OBJ[$sc]=$T/$sc/$(basename "$src")
    $HELP dedup "$src" "${OBJ[$sc]}"
done

cycles() {  # cycles SCENE SPP SEED OUT.exr: prints the CYCLES_DONE seconds
    # shellcheck disable=SC2086
    CYCLES_PATTERN=$CYCLES_PATTERN blender -b --factory-startup --python tools/cycles_pattern.py --python "$CYCLES_REF" -- \
        "${OBJ[$1]}" ${CAM[$1]} --size "$SIZE" --spp "$2" --threads "$THREADS" --seed "$3" --out "$4" > "$T/cycles.log" 2>&1 \
        || { cat "$T/cycles.log" >&2; die "blender failed"; }
    # the pattern asked for must be the one the render used (the handler ran, the name was valid)
    grep -q "^CYCLES_PATTERN ${CYCLES_PATTERN:-[A-Z_]*}\$" "$T/cycles.log" || { cat "$T/cycles.log" >&2; die "Cycles did not render with sampling pattern '${CYCLES_PATTERN:-its default}'"; }
    sed -n 's/^CYCLES_DONE \([0-9.]*\) s/\1/p' "$T/cycles.log" | tail -n 1 | grep . || { cat "$T/cycles.log" >&2; die "no CYCLES_DONE"; }
}
pathlab() {  # pathlab BIN "FLAGS" SCENE SEED OUT.pfm ARGS...: prints "seconds spp" from its stats line
    local bin=$1 flags=$2 sc=$3 seed=$4 out=$5; shift 5
    # shellcheck disable=SC2086
    "$bin" render "${OBJ[$sc]}" ${CAM[$sc]} --size "$SIZE" --threads "$THREADS" --seed "$seed" $flags "$@" -o "$out" \
        2> "$T/pathlab.log" || { cat "$T/pathlab.log" >&2; die "pathlab failed"; }
    awk '/ spp, .* Msamples\/s/ { s = $1; n = $3 } END { if (n == "") exit 1; print s, n }' "$T/pathlab.log" \
        || { cat "$T/pathlab.log" >&2; die "no stats line from $bin"; }
}

# 1. references, cached while the scene, camera, size, spp and programs are the same
LOAD_START=$(loadavg) DATE_START=$(date -u '+%Y-%m-%d %H:%M') SEC_START=$(date +%s)
declare -A CREF PREF CVAR PVAR
half=$((REF_SPP / 2))
for sc in $SCENES; do
    key="$(cat "$T/$sc"/* | cksum | cut -d' ' -f1) ${CAM[$sc]} $SIZE $REF_SPP $THREADS"
    CREF[$sc]=$REF_DIR/cycles_${sc}_$REF_SPP${CYCLES_PATTERN:+_$CYCLES_PATTERN}.exr
    want="$key blender $BLENDER_VERSION $(cksum < "$CYCLES_REF" | cut -d' ' -f1) pattern ${CYCLES_PATTERN:-default}"
    if [ -f "${CREF[$sc]}" ] && [ "$(cat "${CREF[$sc]%.exr}.stamp" 2>/dev/null)" = "$want" ]; then
        echo "Cycles reference ${CREF[$sc]}: reused"
    else
        echo "Cycles reference ${CREF[$sc]}: rendering 2 x $half spp ..."
        # (a failure inside $(...) ends only that subshell: each result is assigned first, so that it ends the script)
        for s in 101 102; do secs=$(cycles "$sc" $half $s "$T/ref_$s.exr"); echo "  seed $s: $secs s"; done
        $HELP avg "$T/ref_101.exr" "$T/ref_102.exr" "${CREF[$sc]}" > "${CREF[$sc]%.exr}.var"
        echo "$want" > "${CREF[$sc]%.exr}.stamp"
    fi
    PREF[$sc]=$REF_DIR/pathlab_${sc}_$REF_SPP.exr
    want="$key pathlab $(cksum < "$REF_PATHLAB" | cut -d' ' -f1) $REF_PATHLAB_FLAGS"
    if [ -f "${PREF[$sc]}" ] && [ "$(cat "${PREF[$sc]%.exr}.stamp" 2>/dev/null)" = "$want" ]; then
        echo "pathlab reference ${PREF[$sc]}: reused"
    else
        echo "pathlab reference ${PREF[$sc]}: rendering 2 x $half spp with $REF_PATHLAB $REF_PATHLAB_FLAGS ..."
        for s in 101 102; do got=$(pathlab "$REF_PATHLAB" "$REF_PATHLAB_FLAGS" "$sc" $s "$T/ref_$s.pfm" --spp $half); echo "  seed $s: $got"; done
        $HELP avg "$T/ref_101.pfm" "$T/ref_102.pfm" "${PREF[$sc]}" > "${PREF[$sc]%.exr}.var"
        echo "$want" > "${PREF[$sc]%.exr}.stamp"
    fi
    CVAR[$sc]=$(cat "${CREF[$sc]%.exr}.var") PVAR[$sc]=$(cat "${PREF[$sc]%.exr}.var")
done

# 2. the renders: per round, scene and level, Cycles then every pathlab column at Cycles' time
TSV=$OUT/cycles.tsv
printf 'round\tscene\tlevel\tcolumn\tseconds\tspp\tmse_cref\tmse_pref\n' > "$TSV"
LOAD_RENDERS=$(loadavg) LOADS=""
for r in $(seq 1 "$ROUNDS"); do
    for sc in $SCENES; do
        for lv in $LEVELS; do
            t=$(cycles "$sc" "$lv" "$r" "$T/c.exr")
            read -r _ mc <<< "$($HELP mse "$T/c.exr" "${CREF[$sc]}" "${CVAR[$sc]}")"
            read -r _ mp <<< "$($HELP mse "$T/c.exr" "${PREF[$sc]}" "${PVAR[$sc]}")"
            printf '%s\t%s\t%s\tCycles\t%s\t%s\t%s\t%s\n' "$r" "$sc" "$lv" "$t" "$lv" "$mc" "$mp" >> "$TSV"
            echo "round $r, $sc, $lv spp: Cycles $t s, MSE $mc (Cycles ref) $mp (pathlab ref)"
            cp "$T/c.exr" "$OUT/cycles_img/${sc}_${lv}_cycles.exr"
            for i in "${!COL_BIN[@]}"; do
                got=$(pathlab "${COL_BIN[$i]}" "${COL_FLAGS[$i]}" "$sc" "$r" "$T/p.pfm" --time "$t")
                read -r pt pn <<< "$got"
                read -r _ mc <<< "$($HELP mse "$T/p.pfm" "${CREF[$sc]}" "${CVAR[$sc]}")"
                read -r _ mp <<< "$($HELP mse "$T/p.pfm" "${PREF[$sc]}" "${PVAR[$sc]}")"
                printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$r" "$sc" "$lv" "$i" "$pt" "$pn" "$mc" "$mp" >> "$TSV"
                echo "  ${COL_LABEL[$i]}: $pt s, $pn spp, MSE $mc (Cycles ref) $mp (pathlab ref)"
                cp "$T/p.pfm" "$OUT/cycles_img/${sc}_${lv}_column$((i + 1)).pfm"
            done
            LOADS="$LOADS $(cut -d' ' -f1 /proc/loadavg)"
        done
    done
done
LOAD_END=$(loadavg) SEC_END=$(date +%s)

# 3. the table
MD=$OUT/cycles.md
rev() { "$1" --version 2>/dev/null | awk 'NR == 1 { print $2 }' | grep . || echo '?'; }  # the revision built into it
CPU=$(lscpu 2>/dev/null | sed -n 's/^Model name:[[:space:]]*//p' | head -n 1)
{
    echo "## Efficiency against Blender Cycles"
    echo
    echo "Written by \`bench/cycles.sh --doc\` (\`make bench-cycles\`), which replaces this section when rerun; how it"
    echo "measures: the script's head. What the figures show: the next section."
    echo
    echo "$DATE_START UTC, \`bench/cycles.sh\` ($((SEC_END - SEC_START)) s in all), ${CPU:-unknown CPU}, $(nproc) cores, Blender $BLENDER_VERSION, sampling pattern ${CYCLES_PATTERN:-the default of Blender}."
    echo "Load average (1, 5, 15 min): $LOAD_START at the start, $LOAD_RENDERS before the renders, $LOAD_END at the end;"
    echo "1-minute load after each level:$LOADS. $SIZE, $THREADS threads, $ROUNDS round(s) (seed = round)."
    echo "Each Cycles render (T = its CYCLES_DONE time) is followed at once by every pathlab column with \`--time T\`."
    echo "MSE: over pixels and RGB, the reference's own noise taken off (references: $REF_SPP spp each, two halves,"
    echo "pathlab's rendered by \`$REF_PATHLAB $REF_PATHLAB_FLAGS\` at $(rev "$REF_PATHLAB")). Efficiency ratio = (MSE x time of pathlab) / (MSE x time of Cycles),"
    echo "both against the Cycles reference (C) or both against the pathlab reference (P); below 1 pathlab is ahead; pathlab's target is at most 0.5 (the same error in at most half Cycles' time)."
    echo
    echo "Columns:"
    for i in "${!COL_BIN[@]}"; do echo "$((i + 1)). \`${COL_BIN[$i]} ${COL_FLAGS[$i]}\` (revision $(rev "${COL_BIN[$i]}"))"; done
    echo
    awk -F'\t' -v ncol=${#COL_BIN[@]} -f - "$TSV" <<'AWK'
NR == 1 { next }
{
    k = $2 SUBSEP $3 SUBSEP $4
    if (!(($2 SUBSEP $3) in seen)) { seen[$2 SUBSEP $3] = 1; order[++n] = $2 SUBSEP $3 }
    t[k] += $5; s[k] += $6; mc[k] += $7; mp[k] += $8; c[k]++
    # per-round ratios, for the spread over rounds
    if ($4 == "Cycles") { ct[$1, $2, $3] = $5; cc[$1, $2, $3] = $7; cp[$1, $2, $3] = $8 }
    else { rc = $5 * $7 / (ct[$1, $2, $3] * cc[$1, $2, $3]); rp = $5 * $8 / (ct[$1, $2, $3] * cp[$1, $2, $3])
           if (!(k in lo) || rc < lo[k]) lo[k] = rc; if (!(k in hi) || rc > hi[k]) hi[k] = rc }
}
END {
    printf "| scene | spp (Cycles) |"; for (i = 1; i <= ncol; i++) printf " column %d: ratio C / P |", i; print ""
    printf "|---|--:|"; for (i = 1; i <= ncol; i++) printf "--:|"; print ""
    for (j = 1; j <= n; j++) {
        split(order[j], p, SUBSEP); kc = order[j] SUBSEP "Cycles"
        printf "| %s | %s |", p[1], p[2]
        for (i = 0; i < ncol; i++) {
            k = order[j] SUBSEP i
            printf " **%.2f** / %.2f%s |", t[k] * mc[k] / (t[kc] * mc[kc]), t[k] * mp[k] / (t[kc] * mp[kc]),
                (c[k] > 1 ? sprintf(" (rounds %.2f–%.2f)", lo[k], hi[k]) : "")
        }
        print ""
    }
    print ""
    print "| scene | spp (Cycles) | renderer | time (s) | spp | MSE vs Cycles ref | MSE vs pathlab ref | MSE x time, C | ratio C | ratio P |"
    print "|---|--:|---|--:|--:|--:|--:|--:|--:|--:|"
    for (j = 1; j <= n; j++) {
        split(order[j], p, SUBSEP); kc = order[j] SUBSEP "Cycles"
        for (i = -1; i < ncol; i++) {
            k = order[j] SUBSEP (i < 0 ? "Cycles" : i); m = c[k]
            printf "| %s | %s | %s | %.2f | %.0f | %.3g | %.3g | %.3g | %.2f | %.2f |\n", p[1], p[2], i < 0 ? "Cycles" : "column " i + 1,
                t[k] / m, s[k] / m, mc[k] / m, mp[k] / m, t[k] * mc[k] / m / m, t[k] * mc[k] / (t[kc] * mc[kc]), t[k] * mp[k] / (t[kc] * mp[kc])
        }
    }
}
AWK
    echo
    echo "The two references against each other (bench/cycles_images.py refs):"
    echo
    for sc in $SCENES; do
        echo "$sc ($(basename "${OBJ[$sc]}"), \`${CAM[$sc]}\`):"
        echo; echo '```'; $HELP refs "${CREF[$sc]}" "${PREF[$sc]}" "${CVAR[$sc]}" "${PVAR[$sc]}"; echo '```'; echo
    done
} > "$MD"
echo
cat "$MD"
echo "written: $MD (raw data $TSV)"
if [ $DOC = 1 ]; then
    # replace the section (its heading to the next "## " heading) or append it
    awk -v md="$MD" '
        $0 == "## Efficiency against Blender Cycles" { skip = 1; while ((getline l < md) > 0) print l; done = 1; print ""; next }
        skip && /^## / { skip = 0 }
        !skip { print }
        END { if (!done) { print ""; while ((getline l < md) > 0) print l } }' docs/performance.md > "$T/perf.md"
    cp "$T/perf.md" docs/performance.md
    echo "docs/performance.md: section \"Efficiency against Blender Cycles\" written"
fi
