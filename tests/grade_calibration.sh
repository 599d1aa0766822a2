#!/usr/bin/env bash
# tests/grade_calibration.sh [OUT.md] — how far `pathlab grade` can be trusted (`make grade-calibration`;
# not part of `make test`). Prints a Markdown report and, given OUT.md, writes it there too.
#
# (a) False alarms: honest images (pathlab's estimators standing in for different students'
#     renderers: --direct, --light, --dir and --rr varied; 1 to 1024 spp, powers of 2; 64x64 against
#     ref/cornell.pfm and 128x128 against ref/cornell-128.pfm; full transport as the references;
#     distinct seeds), each graded at the default alpha 0.01. Failures per spp, per estimator and
#     overall, with the one-sided 95% Clopper-Pearson upper bound of the rate.
# (b) Power: for sizes 64 and 128, spp 4, 64 and 1024 and four regions -- whole (every pixel),
#     quarter (the top-left quarter), bright (the 1% of pixels where the reference is brightest: the
#     emitter seen directly), sparse (one pixel in 16, a thin spread over the image) -- the smallest
#     relative bias b of 0.2% 0.5% 1% 2% 5% 10% 20% 50% for which >= 90% of the images fail. The bias
#     is put on honest renders (default estimators) by tests/mistakes.py regions: the region's pixels
#     times 1 + b on even images and 1 - b on odd ones (brighter and darker both).
# (c) Other scenes: false alarms, as (a), on every other scene with a full-transport 64x64 reference
#     (cornell-glossy, quad-light, mis-plates, furnace, sphere-furnace: ref/NAME.pfm): 1, 4, 16 and 64
#     spp, estimators default, brdf, light and cosine, 2 seeds each (160 images); graded against
#     ref/NAME.pfm. They count in the overall false-alarm line and the exit status.
#
# (d) Penumbrae and small lights: the box of tests/student/ (a block's penumbrae, the light hung under
#     the ceiling) with its light (130 x 105 mm) and with a 20 mm one, 64x48, against pathlab references
#     rendered here (--bounces 0:1 --pixel-center, 4096 spp, --variance: black pixels with rare light
#     around them): honest images of the student renderer (tests/student/student_render.c: pixel
#     centres, direct light) at 16, 64 and 256 spp and of pathlab --direct brdf (light found by chance)
#     at 16 and 64 spp; and a real 1024x768 case, the box against a 1024-spp reference, the student's
#     images at 128 spp (4 seeds). They count in the overall line and the exit status.
#     CALIB_PARTS=d runs (d) alone (any of a b c d; default all): measured on 2 cores shared with
#     other work, about 25 minutes with an empty cache, most of it the 1024x768 reference.
# Honest renders are cached in $CALIB_DIR (default /tmp/pathlab-calib), named by size, spp,
# estimator and seed: a rerun after a change to grade only re-grades. CALIB_FAST=1: a smoke test
# (fewer spp, estimators and images; 40 + 40 images; about 1.5 minutes on 2 cores with an empty cache,
# 30 s cached). Full run with an empty cache, measured on 2 shared cores: about 13 minutes (of it
# ~12 rendering; 128x128 at 1024 spp, 13-30 s an image, is over a third of it) before (c), whose
# 160 renders add well under a minute; cached: ~14 minutes on 2 cores shared with other work (the
# power part grades every failing image's likely mistakes), 13 of them at 128x128.
# FA_NEST_BIG and PW_N_BIG below set the images at 128x128 and 1024 spp if that is too slow.
set -uo pipefail
cd "$(dirname "$0")/.."
PATHLAB=${PATHLAB:-./pathlab}
DIR=${CALIB_DIR:-/tmp/pathlab-calib}
FAST=${CALIB_FAST:-0}
OUT=${1:-}
MISTAKES="python3 tests/mistakes.py"
mkdir -p "$DIR/honest" || exit 2
WORK=$(mktemp -d); trap 'rm -rf "$WORK"' EXIT
OTHER_SCENES="cornell-glossy quad-light mis-plates furnace sphere-furnace"
for r in ref/cornell.pfm ref/cornell-128.pfm; do
    [ -f "$r" ] || { echo "grade_calibration.sh: $r missing (ref/make_refs.sh scenes big)" >&2; exit 2; }
done
for s in $OTHER_SCENES; do
    [ -f "ref/$s.pfm" ] || { echo "grade_calibration.sh: ref/$s.pfm missing (ref/make_refs.sh scenes)" >&2; exit 2; }
done
[ -x "$PATHLAB" ] || { echo "grade_calibration.sh: $PATHLAB missing (make)" >&2; exit 2; }
t_start=$(date +%s)
: > "$WORK/render_times"
# part X: 0 if section X runs (CALIB_PARTS, default abcd); a skipped section leaves its table empty
part() { case "${CALIB_PARTS:-abcd}" in *"$1"*) return 0 ;; esac; return 1; }

# Estimators, label=flags (the label names the cache files)
ESTIMATORS=(
    "default="
    "light=--direct light"
    "brdf=--direct brdf"
    "mis-balance=--direct mis-balance"
    "light-sa=--direct light --light solid-angle"
    "solid-angle=--light solid-angle"
    "triangle=--light triangle"
    "power=--light power"
    "cosine=--dir cosine"
    "uniform=--dir uniform"
    "rr-off=--rr off"
    "rr1-light-sa-cos=--rr 1 --direct light --light solid-angle --dir cosine"
)
if [ "$FAST" != 0 ]; then
    FA_SPP="1 4 16 64 256"; FA_NEST=4; FA_NEST_BIG=4
    PW_SPP="4 64"; PW_N=6; PW_N_BIG=6
    OT_SPP="1 16"; OT_SEEDS=1
else
    FA_SPP="1 2 4 8 16 32 64 128 256 512 1024"; FA_NEST=12; FA_NEST_BIG=12  # 264 images
    PW_SPP="4 64 1024"; PW_N=10; PW_N_BIG=10
    OT_SPP="1 4 16 64"; OT_SEEDS=2                                         # 160 images
fi
OT_ESTIMATORS=("default=" "brdf=--direct brdf" "light=--direct light" "cosine=--dir cosine")
BIASES="0.002 0.005 0.01 0.02 0.05 0.1 0.2 0.5"

ref_of() { if [ "$1" = 64 ]; then echo ref/cornell.pfm; else echo ref/cornell-128.pfm; fi; }

# honest SIZE SPP LABEL SEED FLAGS...: the cached render's path on stdout (rendered if missing);
# the scene is $SCENE (default cornell; other scenes' files are named NAME_s...)
SCENE=cornell
honest() {
    local size=$1 spp=$2 label=$3 seed=$4; shift 4
    local f="$DIR/honest/s${size}_spp${spp}_${label}_seed${seed}.pfm"
    [ "$SCENE" != cornell ] && f="$DIR/honest/${SCENE}_s${size}_spp${spp}_${label}_seed${seed}.pfm"
    if [ ! -s "$f" ]; then
        local t0; t0=$(date +%s.%N)
        # shellcheck disable=SC2068
        # --sampler independent: the calibration (and the cached images) are of independent samples
        if ! $PATHLAB render "scenes/$SCENE.obj" --quiet --size "${size}x${size}" --spp "$spp" --seed "$seed" --sampler independent $@ -o "$f" >&2; then
            echo "grade_calibration.sh: render failed: $SCENE $size $spp $label $seed $*" >&2; exit 2
        fi
        awk -v t0="$t0" -v t1="$(date +%s.%N)" 'BEGIN { print t1 - t0 }' >> "$WORK/render_times"
    fi
    echo "$f"
}

# grade IMAGE REF: "rc<TAB>verdict" (the verdict line and the reason lines, joined with ;; not the
# exact pixels' summary line, "... 0 differ", printed for every image)
grade() {
    local out rc
    out=$($PATHLAB grade "$1" --ref "$2" 2>&1); rc=$?
    printf '%s\t%s\n' "$rc" "$(echo "$out" | grep -E '^(PASS|FAIL)|^  |rror|has a|differ' | grep -v '^exact pixels' | sed 's/^ *//' | paste -sd ';' - | cut -c1-200)"
}

# ---- (a) false alarms -------------------------------------------------------------------------
FA="$WORK/fa.tsv"     # size spp label seed rc verdict
: > "$FA"
seed=200000
for size in $(part a && echo 64 128); do
    ref=$(ref_of $size)
    for spp in $FA_SPP; do
        nest=$FA_NEST
        [ "$size" = 128 ] && [ "$spp" -ge 1024 ] && nest=$FA_NEST_BIG
        for ((e = 0; e < nest; e++)); do
            label=${ESTIMATORS[$e]%%=*} flags=${ESTIMATORS[$e]#*=}
            seed=$((seed + 1))
            # shellcheck disable=SC2086
            img=$(honest "$size" "$spp" "$label" "$seed" $flags) || exit 2
            printf '%s\t%s\t%s\t%s\t%s\n' "$size" "$spp" "$label" "$seed" "$(grade "$img" "$ref")" >> "$FA"
        done
    done
    echo "false alarms: ${size}x$size graded ($(($(date +%s) - t_start)) s so far)" >&2
done

# ---- (b) power --------------------------------------------------------------------------------
PW="$WORK/power.tsv"  # size spp region bias fails n
PWSUM="$WORK/power_summary.tsv"   # size spp region smallest-bias n
: > "$PW"; : > "$PWSUM"
seed=300000
for size in $(part b && echo 64 128); do
    ref=$(ref_of $size)
    for spp in $PW_SPP; do
        n=$PW_N
        [ "$size" = 128 ] && [ "$spp" -ge 1024 ] && n=$PW_N_BIG
        need=$(( (9 * n + 9) / 10 ))     # >= 90% of n
        seed=$((seed + 100))              # distinct seeds per size and spp
        imgs=()
        for ((i = 0; i < n; i++)); do
            img=$(honest "$size" "$spp" power "$((seed + i))") || exit 2
            imgs+=("$img")
        done
        rm -f "$WORK"/b/*.pfm; mkdir -p "$WORK/b"
        $MISTAKES regions "$ref" "$WORK/b" whole,quarter,bright,sparse "${BIASES// /,}" "${imgs[@]}" || exit 2
        for region in whole quarter bright sparse; do
            found=""
            for b in $BIASES; do
                fails=0
                for ((i = 0; i < n; i++)); do
                    rc=$($PATHLAB grade "$WORK/b/${region}_${b}_$i.pfm" --ref "$ref" > /dev/null 2>&1; echo $?)
                    [ "$rc" != 0 ] && fails=$((fails + 1))
                done
                printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$size" "$spp" "$region" "$b" "$fails" "$n" >> "$PW"
                [ -z "$found" ] && [ "$fails" -ge "$need" ] && found=$b
            done
            printf '%s\t%s\t%s\t%s\t%s\n' "$size" "$spp" "$region" "${found:-none}" "$n" >> "$PWSUM"
        done
        echo "power: ${size}x$size at $spp spp done ($(($(date +%s) - t_start)) s so far)" >&2
    done
done

# ---- (c) other scenes -------------------------------------------------------------------------
OT="$WORK/other.tsv"  # scene spp label seed rc verdict
: > "$OT"
seed=400000
for SCENE in $(part c && echo $OTHER_SCENES); do
    for spp in $OT_SPP; do
        for ((e = 0; e < ${#OT_ESTIMATORS[@]}; e++)); do
            label=${OT_ESTIMATORS[$e]%%=*} flags=${OT_ESTIMATORS[$e]#*=}
            for ((i = 0; i < OT_SEEDS; i++)); do
                seed=$((seed + 1))
                # shellcheck disable=SC2086
                img=$(honest 64 "$spp" "$label" "$seed" $flags) || exit 2
                printf '%s\t%s\t%s\t%s\t%s\n' "$SCENE" "$spp" "$label" "$seed" "$(grade "$img" "ref/$SCENE.pfm")" >> "$OT"
            done
        done
    done
    echo "other scenes: $SCENE graded ($(($(date +%s) - t_start)) s so far)" >&2
done
SCENE=cornell

# ---- (d) penumbrae and small lights: the student renderer's box --------------------------------
ST="$DIR/student"
mkdir -p "$ST"
# box_ref NAME W H SPP: the reference NAME-WxH-SPPspp.pfm of the box NAME (its variance beside it), cached
box_ref() {
    local f="$ST/$1-$2x$3-$4spp.pfm"   # the spp in the name: CALIB_FAST's and the full run's share a cache
    printf 'c 278 274.4 279.6\np 0 0\nr 0 180\ns 1079.6 600\nf 39.3 %s %s\n' "$2" "$3" > "$ST/orbiter-$2x$3.txt"
    [ -s "$f" ] || $PATHLAB render "$ST/$1.obj" --orbiter "$ST/orbiter-$2x$3.txt" --bounces 0:1 --pixel-center --sampler independent \
        --spp "$4" --seed 99 --quiet -o "$f" --variance "${f%.pfm}_var.pfm" >&2 || exit 2
    echo "$f"
}
# box_honest NAME W H SPP KIND SEED: an honest image of the box, cached (student: tests/student/student_render.c;
# brdf: pathlab --direct brdf)
box_honest() {
    local f="$ST/$1-$2x$3-$5-spp$4-seed$6.pfm"
    if [ ! -s "$f" ]; then
        if [ "$5" = student ]; then "$ST/render" "$ST/$1.obj" "$ST/orbiter-$2x$3.txt" "$4" "$6" "$f" >&2 || exit 2
        else $PATHLAB render "$ST/$1.obj" --orbiter "$ST/orbiter-$2x$3.txt" --bounces 0:1 --pixel-center --sampler independent \
                 --direct brdf --spp "$4" --seed "$6" --quiet -o "$f" >&2 || exit 2; fi
    fi
    echo "$f"
}
if part d; then
    ${CC:-cc} -std=c99 -D_DEFAULT_SOURCE -O2 -o "$ST/render" tests/student/student_render.c -lm || exit 2
    python3 tests/student/box_scene.py "$ST/box" && python3 tests/student/box_scene.py "$ST/small" 20 || exit 2
    # CALIB_FAST: the 1024x768 reference at 256 spp (its variance says how noisy it is; 1024 spp took
    # 128 s of CI's smoke test)
    if [ "$FAST" != 0 ]; then ST_SEEDS=2; ST_BIG_SEEDS=1; BIG_REF_SPP=256; else ST_SEEDS=10; ST_BIG_SEEDS=4; BIG_REF_SPP=1024; fi
    seed=500000
    for box in box small; do
        ref=$(box_ref "$box" 64 48 4096) || exit 2
        for kind_spp in student:16 student:64 student:256 brdf:16 brdf:64; do
            for ((i = 0; i < ST_SEEDS; i++)); do
                seed=$((seed + 1))
                img=$(box_honest "$box" 64 48 "${kind_spp#*:}" "${kind_spp%%:*}" "$seed") || exit 2
                printf '%s\t%s\t%s\t%s\t%s\n' "$box-64x48" "${kind_spp#*:}" "${kind_spp%%:*}" "$seed" "$(grade "$img" "$ref")" >> "$OT"
            done
        done
        echo "penumbrae: $box graded ($(($(date +%s) - t_start)) s so far)" >&2
    done
    t_big=$(date +%s)
    ref=$(box_ref box 1024 768 $BIG_REF_SPP) || exit 2
    for ((i = 0; i < ST_BIG_SEEDS; i++)); do
        img=$(box_honest box 1024 768 128 student $((600000 + i))) || exit 2
        printf '%s\t%s\t%s\t%s\t%s\n' "box-1024x768" 128 student $((600000 + i)) "$(grade "$img" "$ref")" >> "$OT"
    done
    echo "penumbrae: 1024x768 graded in $(($(date +%s) - t_big)) s ($(($(date +%s) - t_start)) s so far)" >&2
fi
t_total=$(($(date +%s) - t_start))
t_render=$(awk '{ s += $1 } END { printf "%.0f", s }' "$WORK/render_times")

# ---- the report -------------------------------------------------------------------------------
python3 - "$FA" "$PW" "$PWSUM" "$t_total" "$t_render" "$FAST" "$(git describe --always --dirty 2>/dev/null || echo unknown)" \
    "$(nproc)" "$OT" "$(date -u +%Y-%m-%d)" > "$WORK/report.md" <<'EOF'
import math, sys, collections
fa_path, pw_path, sum_path, t_total, t_render, fast, rev, cores, ot_path, day = sys.argv[1:11]

def binom_cdf(k, n, p):
    if p <= 0.0: return 1.0
    if p >= 1.0: return 1.0 if k >= n else 0.0
    return sum(math.exp(math.lgamma(n + 1) - math.lgamma(i + 1) - math.lgamma(n - i + 1)
                        + i * math.log(p) + (n - i) * math.log1p(-p)) for i in range(k + 1))

def upper95(k, n):
    """One-sided 95% Clopper-Pearson upper bound of a binomial rate, k of n."""
    if k >= n: return 1.0
    lo, hi = 0.0, 1.0
    for _ in range(60):
        mid = (lo + hi) / 2
        if binom_cdf(k, n, mid) > 0.05: lo = mid
        else: hi = mid
    return hi

rows = [l.rstrip("\n").split("\t") for l in open(fa_path) if l.strip()]
orows = [l.rstrip("\n").split("\t") for l in open(ot_path) if l.strip()]   # scene spp label seed rc verdict
print("# pathlab grade: calibration%s" % (" (CALIB_FAST=1: smoke test, few images)" if fast != "0" else ""))
print()
print("tests/grade_calibration.sh at revision %s, %s, %s cores; %s s in all, %.0f s of it rendering (cached renders"
      " are not re-rendered). Default alpha 0.01: an honest image should fail at most 1%% of the time."
      % (rev + (" (uncommitted changes)" if rev.endswith("-dirty") else ""), day, cores, t_total, float(t_render)))
print()
print("## False alarms (honest images, full transport)")
print()
allrc = [r[4] for r in rows] + [r[4] for r in orows]
n = len(allrc); k = sum(1 for rc in allrc if rc != "0"); bad = sum(1 for rc in allrc if rc == "2")
print("**Overall: %d of %d honest images failed (%.1f%%); 95%% upper bound %.1f%%.**%s"
      % (k, n, 100.0 * k / max(n, 1), 100.0 * upper95(k, n), " (%d of them exit 2: bad input)" % bad if bad else ""))
print()
kc = sum(1 for r in rows if r[4] != "0"); ko = sum(1 for r in orows if r[4] != "0")
print("Of them: Cornell box (64x64 and 128x128, below) %d of %d; other scenes (64x64, further below) %d of %d."
      % (kc, len(rows), ko, len(orows)))
print()
print("### Cornell box")
print()
def table(key, title):
    groups = collections.OrderedDict()
    for r in rows:
        groups.setdefault(key(r), []).append(r)
    print("| %s | 64x64 failed | 128x128 failed | both | rate | 95%% upper |" % title)
    print("|---|---|---|---|---|---|")
    for g, rs in groups.items():
        cell = []
        for size in ("64", "128"):
            s = [r for r in rs if r[0] == size]
            cell.append("%d / %d" % (sum(1 for r in s if r[4] != "0"), len(s)))
        kk = sum(1 for r in rs if r[4] != "0")
        print("| %s | %s | %s | %d / %d | %.1f%% | %.1f%% |" % (g, cell[0], cell[1], kk, len(rs), 100.0 * kk / len(rs), 100.0 * upper95(kk, len(rs))))
    print()
table(lambda r: r[1], "spp")
table(lambda r: r[2], "estimator")
fails = [r for r in rows if r[4] != "0"]
if fails:
    print("Failed honest images:")
    print()
    for r in fails:
        print("- %sx%s, %s spp, %s, seed %s: exit %s: %s" % (r[0], r[0], r[1], r[2], r[3], r[4], r[5]))
    print()
print("Estimators: default = --direct mis-power --light area --dir brdf --rr 3; light, brdf, mis-balance = --direct X;"
      " light-sa = --direct light --light solid-angle; solid-angle, triangle, power = --light X; cosine, uniform = --dir X;"
      " rr-off = --rr off; rr1-light-sa-cos = --rr 1 --direct light --light solid-angle --dir cosine.")
print()
print("### Other scenes (64x64 against ref/NAME.pfm; box, small: the student renderer's box, its light and a 20 mm one, against references rendered here)")
print()
ospp = sorted(set(r[1] for r in orows), key=int)
oscenes = list(collections.OrderedDict.fromkeys(r[0] for r in orows))
print("| scene | %s | all | rate |" % " | ".join("%s spp" % s for s in ospp))
print("|---|%s---|---|" % ("---|" * len(ospp)))
for sc in oscenes:
    cell = []
    for sp in ospp:
        s = [r for r in orows if r[0] == sc and r[1] == sp]
        cell.append("%d / %d" % (sum(1 for r in s if r[4] != "0"), len(s)))
    s = [r for r in orows if r[0] == sc]; kk = sum(1 for r in s if r[4] != "0")
    print("| %s | %s | %d / %d | %.1f%% |" % (sc, " | ".join(cell), kk, len(s), 100.0 * kk / max(len(s), 1)))
if orows:
    cell = []
    for sp in ospp:
        s = [r for r in orows if r[1] == sp]
        cell.append("%d / %d" % (sum(1 for r in s if r[4] != "0"), len(s)))
    print("| all | %s | %d / %d | %.1f%% |" % (" | ".join(cell), ko, len(orows), 100.0 * ko / len(orows)))
print()
ofails = [r for r in orows if r[4] != "0"]
if ofails:
    print("Failed honest images (other scenes):")
    print()
    for r in ofails:
        print("- %s 64x64, %s spp, %s, seed %s: exit %s: %s" % (r[0], r[1], r[2], r[3], r[4], r[5]))
    print()
print("Estimators: default, brdf = --direct brdf, light = --direct light, cosine = --dir cosine; student = tests/student/student_render.c"
      " (pixel centres, direct light); the box's references: --bounces 0:1 --pixel-center, 4096 spp at 64x48, 1024 spp at 1024x768.")
print()
print("## Power: the smallest relative bias that >= 90% of the images fail")
print()
summ = [l.rstrip("\n").split("\t") for l in open(sum_path) if l.strip()]
pw = [l.rstrip("\n").split("\t") for l in open(pw_path) if l.strip()]
regions = ["whole", "quarter", "bright", "sparse"]
print("| size | spp | images | whole | quarter | bright (top 1%) | sparse (1 px in 16) |")
print("|---|---|---|---|---|---|---|")
cells = collections.OrderedDict()
for size, spp, region, b, nimg in summ:
    cells.setdefault((size, spp, nimg), {})[region] = b
def pct(b):
    return "not found (> 50%)" if b == "none" else "%g%%" % (100 * float(b))
for (size, spp, nimg), c in cells.items():
    print("| %sx%s | %s | %s | %s |" % (size, size, spp, nimg, " | ".join(pct(c.get(r, "none")) for r in regions)))
print()
print("Biases tried: 0.2% 0.5% 1% 2% 5% 10% 20% 50%, all of them (a larger bias is not always found more often); the region's"
      " pixels times 1 + b on even images, 1 - b on odd ones. Failures per bias tried (size spp region: bias fails/n):")
print()
per = collections.OrderedDict()
for size, spp, region, b, f, nimg in pw:
    per.setdefault((size, spp, region), []).append("%g%% %s/%s" % (100 * float(b), f, nimg))
for (size, spp, region), l in per.items():
    print("- %sx%s %s spp %s: %s" % (size, size, spp, region, ", ".join(l)))
EOF
cat "$WORK/report.md"
[ -n "$OUT" ] && cp "$WORK/report.md" "$OUT"
# The verdict of the run: more false alarms than alpha 0.01 allows fails it (exit 1): k of n honest
# images with P(Binomial(n, 0.01) >= k) < 0.001, a rate no correct grade reaches but once in 1000 runs.
python3 - "$WORK/report.md" <<'EOF2'
import math, re, sys
m = re.search(r"\*\*Overall: (\d+) of (\d+) honest images failed", open(sys.argv[1]).read())
k, n = int(m.group(1)), int(m.group(2))
tail = sum(math.comb(n, j) * 0.01 ** j * 0.99 ** (n - j) for j in range(k, n + 1))
print("calibration: %d false alarms of %d honest images: P(>= %d | alpha 0.01) = %.3g: %s"
      % (k, n, k, tail, "too many (exit 1)" if tail < 0.001 else "as alpha allows"))
sys.exit(1 if tail < 0.001 else 0)
EOF2
