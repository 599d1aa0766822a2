#!/usr/bin/env bash
# Reports as pages: compare's DIR/index.html (the table's rows, the plot as inline
# SVG, links to DIR's files), grade's page per image (the verdict, the likely mistake, the failing
# blocks as marks by their labels "too bright: ...", none for an honest image) and the class reports
# (Markdown, CSV, HTML) whose links reach the pages. Checks only what compare and grade put into the
# page (title, before/after HTML, mark labels), which html_page.c carries whatever its viewer, so it
# holds with the stand-in writer and the real one. Deterministic (fixed seeds): the honest image passes
# at alpha 0.01 and the biased one (a 16x16 block 5% too bright, about 7 sigma) fails. About 11 s.
. "$(dirname "$0")/lib.sh"
S=scenes/cornell.obj
# resolve FILE LINK: the path LINK names from the folder of FILE (absolute links kept)
resolve() { case $2 in /*) echo "$2" ;; *) echo "$(dirname "$1")/$2" ;; esac; }
# links_ok FILE LINK...: every link reaches a file; prints the missing ones
links_missing() { local f=$1 l; shift; for l in "$@"; do [ -f "$(resolve "$f" "$l")" ] || echo "$l"; done; }

# ---- compare: DIR/index.html ----
D=$TMP/cmp
expect_status "compare: two estimators, exit 0" 0 $PATHLAB compare $S --size 16x16 --threads 2 --quiet --spp 4 --ref-spp 16 \
    --estimators "light,A&B <x>=--direct brdf" -o "$D"
P=$D/index.html
if [ -s "$P" ] && grep -qF "pathlab compare: $S" "$P"; then pass "compare: index.html written, its title names the scene"
else fail "compare: no index.html or no title: $(ls "$D"; head -c 300 "$P" 2>/dev/null)"; fi
rows=$(grep -c '^<tr><td>' "$P")
if [ "$rows" = 2 ] && grep -q '^<tr><td>light</td><td><code>--direct light</code></td><td>4</td>' "$P" \
   && grep -q '^<tr><td>A&amp;B &lt;x&gt;</td><td><code>--direct brdf</code></td><td>4</td>' "$P"; then
    pass "compare: the table's rows in the page, labels escaped"
else fail "compare: $rows table rows: $(grep '<tr>' "$P" | head -c 600)"; fi
rmse=$(awk -F, 'NR == 2 { printf "%.4g", $5 }' "$D/table.csv")
if grep -q "^<tr><td>light</td>.*<td>$rmse</td>" "$P"; then pass "compare: the page's RMSE is table.csv's ($rmse)"
else fail "compare: RMSE $rmse of table.csv not in the page's row"; fi
if grep -q '<svg xmlns="http://www.w3.org/2000/svg" class="plot"' "$P" && grep -q '</svg>' "$P" \
   && [ "$(grep -c '<polyline' "$P")" = 2 ] && grep -q 'render time (s)' "$P"; then
    pass "compare: the error against time as inline SVG, one curve per estimator"
else fail "compare: no inline SVG plot with 2 curves ($(grep -c '<polyline' "$P") polylines)"; fi
# shellcheck disable=SC2046  # one word per link (the files' paragraph is compare's own HTML)
missing=$(links_missing "$P" $(grep '^<p>Files: ' "$P" | grep -o 'href="[^"]*"' | sed 's/^href="//; s/"$//'))
if [ -z "$missing" ] && grep -q 'href="heat-light.png"' "$P"; then pass "compare: the page's links reach DIR's files"
else fail "compare: links to missing files: $missing"; fi

# ---- grade: a page per image, marks, the class reports' links ----
G=$TMP/g; mkdir -p "$G/class" "$G/out"
R="$PATHLAB render $S --quiet --size 32x32 --bounces 0:1 --threads 2 --sampler independent"   # grade's test assumes independent samples
$R --spp 1024 --seed 1000 -o "$G/ref.pfm" --variance "$G/ref_var.pfm"
$R --spp 256 --seed 1 -o "$G/class/alice.pfm"
$R --spp 256 --seed 2 -o "$G/h2.pfm"
# bruno: the pixels x, y in 16..31 times 1.05; chloe: flipped upside down
python3 - "$G/h2.pfm" "$G/class/bruno.pfm" <<'PY'
import sys
sys.path.insert(0, "tests")
import mistakes as m
img = m.read_pfm(sys.argv[1])
for y in range(16, 32):
    for x in range(16, 32):
        for c in range(3):
            img.px[3 * (y * img.w + x) + c] *= 1.05
m.write(sys.argv[2], m.pfm_bytes(img))
PY
python3 tests/mistakes.py flip-v "$G/h2.pfm" "$G/class/chloe.pfm"
$PATHLAB grade "$G/class" --ref "$G/ref.pfm" --report "$G/out/class.md" > "$TMP/g.out" 2> "$TMP/err"; rc=$?
pages=$(cd "$G/out/class-pages" 2>/dev/null && ls | paste -sd ' ' -)
if [ $rc = 1 ] && [ "$pages" = "alice.html bruno.html chloe.html" ]; then pass "grade: exit 1, a page per student in class-pages/ beside the report"
else fail "grade: exit $rc, pages '$pages': $(cat "$TMP/g.out" "$TMP/err" | head -c 400)"; fi
A=$G/out/class-pages/alice.html B=$G/out/class-pages/bruno.html C=$G/out/class-pages/chloe.html
if grep -q '<b>PASS</b>' "$A" && ! grep -qE 'too (bright|dark): [+-][0-9]' "$A"; then pass "grade: the honest image's page: PASS, no mark"
else fail "grade: alice's page: $(grep -E 'verdict|too ' "$A" | head -c 300)"; fi
mark=$(grep -oE 'too bright: \+[0-9.]+ sigma, \+[0-9.]+% in [a-z]+' "$B" | head -1)
if grep -q '<b>FAIL</b>' "$B" && [ -n "$mark" ] && ! grep -qE 'too dark: [+-][0-9]' "$B"; then pass "grade: the biased image's page: FAIL, marked '$mark'"
else fail "grade: bruno's page has no 'too bright' mark: $(grep -E 'verdict|too ' "$B" | head -c 300)"; fi
if grep -q '<li>flipped vertically' "$C"; then pass "grade: the likely mistake on the page (flipped vertically)"
else fail "grade: chloe's page: $(grep -A2 'Likely' "$C" | head -c 300)"; fi
# shellcheck disable=SC2046
links=$(grep -oE '\]\([^)]*\.html\)' "$G/out/class.md" | sed 's/^](//; s/)$//')
missing=$(links_missing "$G/out/class.md" $links)
if [ "$(echo "$links" | wc -w)" = 3 ] && [ -z "$missing" ] && ! echo "$links" | grep -q '^/'; then
    pass "grade: class.md links each row to its page, relatively, and the links resolve"
else fail "grade: class.md links '$links', missing '$missing'"; fi
if grep -q 'href="../class.md"' "$A" && [ -f "$(resolve "$A" ../class.md)" ]; then pass "grade: a page links back to the class report"
else fail "grade: alice's page has no link back to ../class.md"; fi
# the HTML and CSV class reports, pages in a folder given with --pages
mkdir -p "$G/html"
$PATHLAB grade "$G/class" --ref "$G/ref.pfm" --report "$G/html/class.html" --pages "$G/pg" > "$TMP/g.out" 2> "$TMP/err"; rc=$?
H=$G/html/class.html
hrefs=$(grep -oE '<td><a href="[^"]*"' "$H" 2>/dev/null | sed 's/^<td><a href="//; s/"$//')
# shellcheck disable=SC2086
missing=$(links_missing "$H" $hrefs)
if [ $rc = 1 ] && grep -qF "Grades against $G/ref.pfm" "$H" && [ "$(echo "$hrefs" | wc -w)" = 3 ] && [ -z "$missing" ] \
   && grep -q '<td>FAIL</td>' "$H"; then pass "grade: --report class.html with --pages elsewhere: the table, its links resolve"
else fail "grade: class.html: exit $rc, links '$hrefs', missing '$missing': $(head -c 300 "$TMP/err")"; fi
$PATHLAB grade "$G/class" --ref "$G/ref.pfm" --report "$G/out/c.csv" > /dev/null 2>&1
page=$(awk -F, '/bruno/ { gsub(/"/, "", $(NF - 1)); print $(NF - 1) }' "$G/out/c.csv")
if head -1 "$G/out/c.csv" | grep -q ',page,flagged$' && [ -f "$(resolve "$G/out/c.csv" "$page")" ]; then pass "grade: the CSV's page column reaches bruno's page"
else fail "grade: c.csv page '$page'"; fi
# one image, --pages: its page, and nothing when the folder cannot be made
expect_status "grade: one image with --pages, exit 0" 0 $PATHLAB grade "$G/class/alice.pfm" --ref "$G/ref.pfm" --pages "$G/one"
if [ -s "$G/one/alice.html" ] && grep -q "^page: $G/one/alice.html" "$TMP/out"; then pass "grade: one image's page written and named"
else fail "grade: no $G/one/alice.html: $(cat "$TMP/out" | tail -3)"; fi
expect_status "grade: --pages in a missing folder, exit 2" 2 $PATHLAB grade "$G/class/alice.pfm" --ref "$G/ref.pfm" --pages "$G/no/such"
expect_err "grade: the pages' folder named" "--pages .*no/such: the folder .*/no does not exist"
expect_status "grade: a missing reference with --pages, exit 2" 2 $PATHLAB grade "$G/class/alice.pfm" --ref "$G/none.pfm" --pages "$G/never"
expect_no_file "grade: bad input makes no pages' folder" "$G/never"
# students' folders holding files of one name: one page each, named by the path
mkdir -p "$G/st/ana" "$G/st/ben"
cp "$G/class/alice.pfm" "$G/st/ana/render.pfm"; cp "$G/class/bruno.pfm" "$G/st/ben/render.pfm"
$PATHLAB grade "$G/st/ana/render.pfm" "$G/st/ben/render.pfm" --ref "$G/ref.pfm" --report "$G/st/c.md" > /dev/null 2>&1
links=$(grep -oE '\]\([^)]*\.html\)' "$G/st/c.md" | sed 's/^](//; s/)$//' | sort -u)
# shellcheck disable=SC2086
missing=$(links_missing "$G/st/c.md" $links)
if [ "$links" = "$(printf 'c-pages/ana_2frender.html\nc-pages/ben_2frender.html')" ] && [ -z "$missing" ] && grep -q '<b>FAIL</b>' "$(resolve "$G/st/c.md" "$(echo "$links" | grep ben)")"; then
    pass "grade: two images named render.pfm get two pages ($(echo $links))"
else fail "grade: same file names: links '$links', missing '$missing'"; fi
# students of one file name in their own folders (st/ana/render.pfm, st/ben/render.pfm): the class
# page's viewer names each by its path, not both "render.pfm"
mkdir -p "$TMP/st/ana" "$TMP/st/ben"
for s in ana ben; do $PATHLAB render scenes/cornell.obj --quiet --spp 16 --seed 3 --bounce 1 --size 24x24 --pixel-center -o "$TMP/st/$s/render.pfm"; done
$PATHLAB grade "$TMP/st/ana/render.pfm" "$TMP/st/ben/render.pfm" --ref ref/cornell_L1.pfm --report "$TMP/st.html" > /dev/null 2>&1
names=$(python3 - "$TMP/st.html" <<'PYEND'
import re, json, sys
t = open(sys.argv[1]).read()
d = json.loads(re.search(r'id="pathlab-settings">(.*?)</script>', t, re.S).group(1))
print(' '.join(i['name'].split('/st/')[-1] for i in d['images']))
PYEND
)
[ "$names" = "ana/render.pfm ben/render.pfm" ] && pass "class page: the viewer names students of one file name by their paths ($names)" || fail "class page: viewer names '$names'"
