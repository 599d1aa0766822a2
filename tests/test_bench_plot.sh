#!/usr/bin/env bash
# bench-plot (bench/plot.c) and bench/sweep.sh: the error against a noisy reference, slopes and
# ranking on exact power laws, interpolation at T*, a valid SVG, bad input; a tiny sweep end to end.
. "$(dirname "$0")/lib.sh"
PLOT=$BUILD/bench-plot
near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { exit !(a - b <= t && b - a <= t) }'; }

# 1. error: a = 1.5, ref = 1 with variance 0.09: raw MSE 0.25, less the reference's noise 0.16
$PFMTOOL const 8 4 1.5 1.5 1.5 "$TMP/a.pfm"
$PFMTOOL const 8 4 1 1 1 "$TMP/b.pfm"
$PFMTOOL const 8 4 0.09 0.09 0.09 "$TMP/v.pfm"
$PFMTOOL const 4 4 1 1 1 "$TMP/small.pfm"
out=$("$PLOT" error "$TMP/a.pfm" "$TMP/b.pfm" "$TMP/v.pfm")
val() { echo "$out" | awk -v k="$1" '{ for (i = 1; i < NF; i++) if ($i == k) print $(i + 1) }'; }
for kvt in "rmse 0.4" "rmse_raw 0.5" "mae 0.5" "relmse 0.158416" "var_ref 0.09"; do
    # shellcheck disable=SC2086  # split into metric and value on purpose
    set -- $kvt
    if near "$(val "$1")" "$2" 1e-5; then pass "error: $1 = $2"; else fail "error: $1 is '$(val "$1")', expected $2 ($out)"; fi
done
out=$("$PLOT" error "$TMP/a.pfm" "$TMP/b.pfm")
if near "$(val rmse)" 0.5 1e-6; then pass "error: no variance, rmse = raw"; else fail "error without variance: $out"; fi
expect_status "error: sizes differ, status 2" 2 "$PLOT" error "$TMP/a.pfm" "$TMP/small.pfm"
expect_err "error: sizes named" "small.pfm.*4x4"

# 2. report on exact power laws. Scene s1, T* = 0.64 s (A's last point, B and C go further):
#    A: rmse 0.1 t^-1/2, t = 0.01 spp   -> RMSE(T*) 0.125,  efficiency 1/(0.015625 x 0.64) = 100
#    B: rmse 0.2 t^-1/2, t = 0.02 spp   -> RMSE(T*) 0.25,   efficiency 25  (4x A's time)
#    C: rmse 0.05 t^-1/4, t = 0.005 spp -> RMSE(T*) 0.0559, efficiency 500 (the best; A 5x, B 20x)
#    Scene s2, T* = 0.48 s (F's last point), between E's points 0.32 and 0.64: E's RMSE there is
#    0.1 x 0.48^-1/2 = 0.1443 only if interpolated in log-log; D: rmse 3/spp (slope -1), one zero point.
{
    echo "# a comment"
    echo "scene,estimator,flags,spp,seconds,rmse"
    awk 'BEGIN { for (s = 1; s <= 64; s *= 2) {
        t = 0.01 * s; printf "s1,A,--a,%d,%.10g,%.10g\n", s, t, 0.1 * t ^ -0.5
        t = 0.02 * s; printf "s1,B,--b,%d,%.10g,%.10g\n", s, t, 0.2 * t ^ -0.5
        t = 0.005 * s * 2; printf "s1,C,--c,%d,%.10g,%.10g\n", 2 * s, t, 0.05 * t ^ -0.25
        t = 0.01 * s; printf "s2,E,--e,%d,%.10g,%.10g\n", s, t, 0.1 * t ^ -0.5
        if (s <= 16) { t = 0.03 * s; printf "s2,F,--f,%d,%.10g,%.10g\n", s, t, 0.3 * t ^ -0.5 }
        t = 0.01 * s; printf "s2,D,--d,%d,%.10g,%.10g\n", s, t, 3 / s }
        print "s2,D,--d,128,1.28,0" }'
} > "$TMP/r.csv"
if "$PLOT" report "$TMP/r.csv" "$TMP/r.svg" --caption 'a <caption> & more' > "$TMP/rep" 2> "$TMP/err"; then
    pass "report: runs"
else
    fail "report: exit status $?: $(cat "$TMP/err")"
fi
# row SCENE EST COLUMN: a cell of the Markdown table (columns: scene, T*, rank, estimator, RMSE at
# T*, efficiency, x the best, slope vs time, slope vs spp, spp)
row() { awk -F'|' -v s="$1" -v e="$2" -v c="$3" '{ for (i = 2; i < NF; i++) gsub(/^ +| +$/, "", $i) } $2 == s && $5 == e { print $(c + 1) }' "$TMP/rep"; }
check_cell() {   # name scene est column want tolerance
    local got; got=$(row "$2" "$3" "$4")
    if near "${got%% *}" "$5" "$6"; then pass "report: $1 = $5"; else fail "report: $1 is '$got', expected $5"; fi
}
check_cell "A slope vs time" s1 A 8 -0.5 0.005
check_cell "A slope vs spp" s1 A 9 -0.5 0.005
check_cell "C slope vs time" s1 C 8 -0.25 0.005
check_cell "D slope vs spp (zero RMSE point skipped)" s2 D 9 -1 0.005
check_cell "s1 T*" s1 A 2 0.64 0.001
check_cell "A RMSE at T*" s1 A 5 0.125 0.0005
check_cell "A efficiency" s1 A 6 100 0.5
check_cell "B x the best's time" s1 B 7 20 0.5
check_cell "A x the best's time" s1 A 7 5 0.005
check_cell "s2 T*" s2 E 2 0.48 0.001
check_cell "E RMSE at T*, interpolated in log-log" s2 E 5 0.144 0.0005
ranks="$(row s1 C 3) $(row s1 A 3) $(row s1 B 3)"
if [ "$ranks" = "1 2 3" ]; then pass "report: ranking C, A, B"; else fail "report: ranks of C, A, B are '$ranks', expected 1 2 3"; fi
order=$(awk -F'|' '$2 ~ /s1/ { gsub(/ /, "", $5); printf "%s", $5 }' "$TMP/rep")
if [ "$order" = "CAB" ]; then pass "report: rows in rank order"; else fail "report: row order $order, expected CAB"; fi
if command -v python3 > /dev/null 2>&1; then
    if python3 -c "import xml.dom.minidom,sys; xml.dom.minidom.parse(sys.argv[1])" "$TMP/r.svg" 2> "$TMP/err"; then
        pass "report: the SVG is well-formed XML (with '<' and '&' in a caption)"
    else
        fail "report: the SVG is not well-formed: $(tail -n 1 "$TMP/err")"
    fi
fi
n=$(grep -c '<polyline' "$TMP/r.svg")
if [ "$n" -eq 6 ]; then pass "report: one polyline per curve (6)"; else fail "report: $n polylines, expected 6"; fi
# every plotted coordinate inside the figure
bad=$(grep -o 'points="[^"]*"' "$TMP/r.svg" | sed 's/points=//; s/"//g' | tr ' ' '\n' | awk -F, -v W="$(sed -n 's/.*<svg[^>]* width="\([0-9.]*\)".*/\1/p' "$TMP/r.svg")" '$1 < 0 || $1 > W || $2 < 0 { n++ } END { print n + 0 }')
if [ "$bad" -eq 0 ]; then pass "report: every point inside the figure"; else fail "report: $bad points outside the figure"; fi

# 3. bad input: status 2, the file and line named, no SVG written
sed '5s/,[^,]*$//' "$TMP/r.csv" > "$TMP/short.csv"
expect_status "report: a short row, status 2" 2 "$PLOT" report "$TMP/short.csv" "$TMP/bad.svg"
expect_err "report: file and line named" "short.csv:5:"
expect_no_file "report: no SVG after a bad row" "$TMP/bad.svg"
sed 's/^scene,estimator,flags,spp,seconds,rmse$/scene,estimator,flags,spp,secs,rmse/' "$TMP/r.csv" > "$TMP/nocol.csv"
expect_status "report: no seconds column, status 2" 2 "$PLOT" report "$TMP/nocol.csv" "$TMP/bad.svg"
expect_err "report: missing column named" "nocol.csv:2: no column 'seconds'"
expect_status "report: missing file, status 2" 2 "$PLOT" report "$TMP/none.csv" "$TMP/bad.svg"
expect_err "report: missing file named" "none.csv"

# 4. bench/sweep.sh: a missing reference is named; a tiny sweep (quad-light, 8x8, 2 estimators,
#    spp 1 to 4) writes one CSV row per render and two well-formed SVGs
expect_status "sweep: missing reference, status 2" 2 env PATHLAB="$PATHLAB" BUILD="$BUILD" REF_DIR="$TMP" SCENES=quad-light OUT="$TMP" bench/sweep.sh
expect_err "sweep: missing reference named" "$TMP/quad-light.pfm: missing"
"$PATHLAB" render scenes/quad-light.obj --size 8x8 --spp 64 --seed 4242 --quiet -o "$TMP/quad-light.pfm" --variance "$TMP/quad-light_var.pfm"
if env PATHLAB="$PATHLAB" BUILD="$BUILD" REF_DIR="$TMP" SCENES=quad-light ESTIMATORS="light brdf" MAX_SPP=4 OUT="$TMP" \
       CSV="$TMP/s.csv" SVG="$TMP/s.svg" SVG_REL="$TMP/s2.svg" bench/sweep.sh > "$TMP/out" 2> "$TMP/err"; then
    n=$(grep -c '^quad-light,' "$TMP/s.csv")
    sizes=$(awk -F, '$1 == "quad-light" { printf "%s ", $4 }' "$TMP/s.csv")
    if [ "$n" -eq 6 ] && [ "$sizes" = "1 1 2 2 4 4 " ]; then pass "sweep: 2 estimators x spp 1, 2, 4 in the CSV, round robin"; else fail "sweep: rows $n, spp '$sizes'"; fi
    if [ -s "$TMP/s.svg" ] && [ -s "$TMP/s2.svg" ]; then pass "sweep: both SVGs written"; else fail "sweep: an SVG is missing"; fi
else
    fail "sweep: exit status $?: $(tail -n 3 "$TMP/err")"
fi
exit 0
