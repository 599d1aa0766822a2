#!/usr/bin/env bash
# grade's outputs against a class of hostile file names and copied images (16x16 renders, a few
# seconds): every name escaped on the terminal (no control character, no bidirectional override), in
# the Markdown report (one table row per image, no raw HTML, no link but the page's, no autolink) and
# in the CSV (one line per image, every field quoted, no cell a spreadsheet reads as a formula); one
# page and one heatmap per image (names one-to-one: "a b.pfm" and "a_b.pfm", st/*/render.pfm); a copy
# of the reference, of another student, and the reference scaled by 1.001 flagged in the verdict and
# every report; a page that cannot be written said in the row (exit 2, the verdict kept); a secondary
# guess of the diagnosis marked as such; the pages' CSP allows the one script by its hash.
# Needs python3 (the CSV and Markdown parsers of the checks).
. "$(dirname "$0")/lib.sh"
PATHLAB=$(cd "$(dirname "$PATHLAB")" && pwd)/$(basename "$PATHLAB"); PFMTOOL=$PWD/$PFMTOOL
command -v python3 > /dev/null || { skip "reports: no python3 for the structure checks"; exit 0; }
S=scenes/cornell.obj
r16() { "$PATHLAB" render $S --size 16x16 --sampler independent --quiet "$@"; }
r16 --spp 256 --seed 1 --variance "$TMP/ref_var.pfm" -o "$TMP/ref.pfm"
mkdir -p "$TMP/class"
r16 --spp 16 --seed 2 -o "$TMP/class/alice.pfm"
r16 --spp 16 --seed 3 --bounces 0:1 -o "$TMP/bad.pfm"
# the names: HTML, links, autolinks, rows forged with | and a newline, formulas, terminal escapes,
# a right-to-left override, a name that is itself a Markdown table row, backticks, a long name
LONG=$(printf 'x%.0s' $(seq 1 230))
NAMES=('<script>alert(1)<!--' '"><img src=x onerror=alert(2)>' '[x](javascript:alert(3))' "$(printf 'new\nline | x')"
       '=HYPERLINK("http:\\evil.example","click me")' "@SUM(1+1)*cmd|' -C calc'!A0" '+1' "$(printf '\tTAB')"
       'javascript:alert(4)' 'www.evil.org' 'mail@evil.org' "$(printf 'zed.pfm: PASS (+0.12%%)\e[8m')"
       "$(printf 'abc\xe2\x80\xaegpj.exe')" '| x | PASS | 0 | | | | |' '`code` *em* _u_ ~~s~~' "$LONG" "$(printf 'bad\xff\xfe')")
k=0
for n in "${NAMES[@]}"; do
    "$PFMTOOL" scale "$TMP/ref.pfm" 2.$((10 + k)) "$TMP/class/$n.pfm"   # failing, each its own pixels
    k=$((k + 1))
done
cp "$TMP/ref.pfm" "$TMP/class/copy.pfm"                         # the reference, byte for byte
cp "$TMP/class/alice.pfm" "$TMP/class/bob.pfm"                  # another student's
"$PFMTOOL" scale "$TMP/ref.pfm" 1.001 "$TMP/class/scaled.pfm"   # the reference times 1.001
N=$((${#NAMES[@]} + 4))

(cd "$TMP" && "$PATHLAB" grade class --ref ref.pfm --report class.md > out.txt 2> err.txt); rc=$?
if [ $rc = 1 ]; then pass "reports: a class of $N hostile names graded, exit 1 (fails, no input error)"
else fail "reports: grade exit $rc: $(head -c 300 "$TMP/err.txt")"; fi
(cd "$TMP/class" && "$PATHLAB" grade *.pfm --ref ../ref.pfm --report ../class.csv > /dev/null 2>&1)

# --- the terminal ---
python3 - "$TMP/out.txt" "$TMP/err.txt" <<'EOF' && pass "reports: stdout and stderr hold no control character (but newlines) and no bidirectional control; ESC shown as \\x1b" || fail "reports: the terminal output is not clean"
import sys
for p in sys.argv[1:]:
    b = open(p, 'rb').read()
    bad = [c for c in b if (c < 0x20 and c != 10) or c == 0x7f]
    t = b.decode('utf-8', 'replace')
    if bad or any(ch in t for ch in '\u202a\u202b\u202c\u202d\u202e\u2066\u2067\u2068\u2069\u200e\u200f\x85\x9b'):
        print("raw control in", p, bad[:5]); sys.exit(1)
    if '\ufffd' in t: print("not UTF-8 in", p); sys.exit(1)
o = open(sys.argv[1], encoding='utf-8').read()
sys.exit(0 if '\\x1b[8m' in o and '\\u202e' in o else 1)
EOF
if grep -q '^class/zed.pfm: PASS (+0.12%)\\x1b\[8m.pfm: FAIL' "$TMP/out.txt"; then pass "reports: the ESC[8m name's FAIL is visible"
else fail "reports: the ESC[8m name: $(grep -a zed "$TMP/out.txt" | head -c 200)"; fi

# --- Markdown: one row per image, 8 columns, nothing live ---
python3 - "$TMP/class.md" "$N" <<'EOF' && pass "reports: class.md has one table row per image, 7 cells each, no raw HTML, no link but the pages', no autolink, no control character" || fail "reports: class.md"
import re, sys
text = open(sys.argv[1], encoding='utf-8').read()
n = int(sys.argv[2])
rows = [l for l in text.split('\n') if l.startswith('| ') and not l.startswith('| image |')]
ok = True
def bad(why, l=''):
    global ok; ok = False; print(why, l[:200])
if len(rows) != n: bad("rows %d, images %d" % (len(rows), n))
for l in rows:
    cells = re.split(r'(?<!\\)\|', l)
    if len(cells) != 9: bad("cells %d" % (len(cells) - 2), l)
    live = re.sub(r'\[[^\[\]]*\]\(class-pages/[A-Za-z0-9._-]+\.html\)|`[@:.]`', '', l)
    if re.search(r'<|>|https?://|www\.|@|\]\(|\[', live): bad("live text", l)
    links = re.findall(r'\]\(', l)
    if len(links) > 1 or (links and not re.search(r'\| \[[^|\[\]]*\]\(class-pages/[A-Za-z0-9._-]+\.html\) \|', l)): bad("a link", l)
    if re.search(r'[\x00-\x1f\x7f\u202e]', l): bad("control", l)
sys.exit(0 if ok else 1)
EOF

# --- CSV: RFC 4180, one line per image, no formula ---
python3 - "$TMP/class.csv" "$N" <<'EOF' && pass "reports: class.csv has one line per image, 9 fields each, text fields quoted, none starting = + - @ tab or CR" || fail "reports: class.csv"
import csv, sys
raw = open(sys.argv[1], encoding='utf-8', newline='').read()
lines = raw.split('\n')
rows = list(csv.reader(raw.splitlines()))
n = int(sys.argv[2])
ok = len(lines) == n + 2 and lines[-1] == '' and len(rows) == n + 1 and all(len(r) == 9 for r in rows)
for r in rows[1:]:
    for i in (0, 5, 6, 7, 8):
        if r[i] and r[i][0] in '=+-@\t\r': ok = False; print("formula", r[i][:80])
    if '\r' in ''.join(r) or '\n' in ''.join(r): ok = False
for l in lines[1:-1]:
    if not l.startswith('"'): ok = False; print("unquoted", l[:80])
if not ok: print(len(lines), len(rows), [len(r) for r in rows][:5])
sys.exit(0 if ok else 1)
EOF
grep -q "^\"'=HYPERLINK(\"\"http:" "$TMP/class.csv" && pass "reports: class.csv: =HYPERLINK(...) written '=HYPERLINK(...), as text" \
    || fail "reports: class.csv: $(grep -a HYPERLINK "$TMP/class.csv" | head -c 200)"

# --- pages and heatmaps: one per image ---
npages=$(ls "$TMP/class-pages" | wc -l)
ngraded=$(grep -c '](class-pages/' "$TMP/class.md")
if [ "$npages" = "$ngraded" ] && [ "$npages" = "$N" ]; then pass "reports: $npages pages for $N images, each linked once"
else fail "reports: $npages pages, $ngraded links, $N images"; fi
# no name reorders or hides what a page shows: no control or bidirectional character in the HTML
# report or any page (as text or in the viewer's JSON), the override shown as \u202e
(cd "$TMP" && "$PATHLAB" grade class --ref ref.pfm --report class.html > /dev/null 2>&1)
python3 - "$TMP/class.html" "$TMP"/class-pages/*.html <<'EOF' && pass "reports: class.html and the pages hold no control or bidirectional character, the override shown as \\u202e" || fail "reports: a page holds a raw control or bidirectional character"
import re, sys
ok, seen = True, False
for p in sys.argv[1:]:
    t = open(p, encoding='utf-8', errors='replace').read()
    if re.search('[\x00-\x08\x0b-\x1f\x7f\x85\x9b\u061c\u200e\u200f\u202a-\u202e\u2066-\u2069]', t): ok = False; print("raw in", p)
    seen |= 'abc\\u202egpj.exe' in t
sys.exit(0 if ok and seen else 1)
EOF
mkdir -p "$TMP/two"; cp "$TMP/class/alice.pfm" "$TMP/two/a b.pfm"; cp "$TMP/bad.pfm" "$TMP/two/a_b.pfm"
(cd "$TMP" && "$PATHLAB" grade two --ref ref.pfm --report two.md > /dev/null 2>&1)
t1=$(grep -o '<title>[^<]*' "$TMP/two-pages/a_20b.html" 2>/dev/null); t2=$(grep -o '<title>[^<]*' "$TMP/two-pages/a_5fb.html" 2>/dev/null)
if [ "$t1" = "<title>two/a b.pfm" ] && [ "$t2" = "<title>two/a_b.pfm" ]; then pass "reports: 'a b.pfm' and 'a_b.pfm' get their own pages (a_20b.html, a_5fb.html)"
else fail "reports: pages of 'a b' and 'a_b': $(ls "$TMP/two-pages" | tr '\n' ' ')"; fi
mkdir -p "$TMP/case"; cp "$TMP/class/alice.pfm" "$TMP/case/Ana.pfm"; cp "$TMP/bad.pfm" "$TMP/case/ana.pfm"
(cd "$TMP" && "$PATHLAB" grade case --ref ref.pfm --report case.md > /dev/null 2>&1)
if [ "$(ls "$TMP/case-pages" | tr '\n' ' ')" = "_41na.html ana.html " ]; then pass "reports: 'Ana.pfm' and 'ana.pfm' get pages that differ in more than case (_41na.html, ana.html)"
else fail "reports: pages of 'Ana' and 'ana': $(ls "$TMP/case-pages" | tr '\n' ' ')"; fi
mkdir -p "$TMP/st/ana" "$TMP/st/ben" "$TMP/heat"; cp "$TMP/class/alice.pfm" "$TMP/st/ana/render.pfm"; cp "$TMP/bad.pfm" "$TMP/st/ben/render.pfm"
(cd "$TMP" && "$PATHLAB" grade st/*/render.pfm --ref ref.pfm --heatmap heat > /dev/null 2>&1)
if [ "$(ls "$TMP/heat" | tr "\n" " ")" = "ana_2frender.png ben_2frender.png " ]; then pass "reports: --heatmap of st/*/render.pfm writes one PNG per image"
else fail "reports: heatmaps: $(ls "$TMP/heat" | tr '\n' ' ')"; fi

# --- integrity flags ---
flagged() { grep -a "^$1: .*FLAGGED: $2" "$TMP/out.txt" > /dev/null && grep -a "^| $1 | [A-Z]* (FLAGGED) |.*$2" "$TMP/class.md" > /dev/null; }
flagged class/copy.pfm "identical to the reference" && pass "reports: a copy of the reference flagged (terminal, Markdown)" || fail "reports: the copy not flagged: $(grep -a copy "$TMP/out.txt")"
flagged class/bob.pfm "identical to class/alice.pfm" && grep -q "^| class/alice.pfm | PASS (FLAGGED) |.*identical to class/bob.pfm" "$TMP/class.md" \
    && pass "reports: a copy of another student flagged in both rows" || fail "reports: alice/bob: $(grep -a -e alice -e bob "$TMP/out.txt")"
flagged class/scaled.pfm "too close to the reference" && pass "reports: the reference times 1.001 flagged as too close to it" || fail "reports: scaled: $(grep -a scaled "$TMP/out.txt")"
if [ "$(grep -ac FLAGGED "$TMP/out.txt")" = 4 ] && grep -q '^"copy.pfm",PASS,.*"identical to the reference' "$TMP/class.csv" \
   && grep -q 'FLAGGED</b>: identical to the reference' "$TMP/class-pages/copy.html"; then
    pass "reports: 3 images and the summary flagged on the terminal, no other; the CSV's and the page's flag"
else fail "reports: flagged lines: $(grep -a FLAGGED "$TMP/out.txt")"; fi

# --- a page that cannot be written: the row says why, the verdict stays ---
mkdir -p "$TMP/w" "$TMP/w-pages/alice.html"
expect_status "reports: a page not written: exit 2" 2 "$PATHLAB" grade "$TMP/class/alice.pfm" "$TMP/two/a b.pfm" --ref "$TMP/ref.pfm" --report "$TMP/w.md"
grep -q '^| .*/alice.pfm | PASS (FLAGGED) |.*| its page .*alice.html was not written: exists and is not a regular file' "$TMP/w.md" \
    && pass "reports: its row keeps PASS and says why the page is missing" || fail "reports: $(grep alice "$TMP/w.md")"

# --- the diagnosis: one difference, one mistake and its secondary guesses ---
"$PATHLAB" render $S --size 64x64 --spp 64 --seed 101 --quiet -o "$TMP/good64.pfm"
# values clamped at 1: the lamp clamped, which "no L0" nearly explains too (a secondary guess)
python3 - "$TMP/good64.pfm" "$TMP/clamped.pfm" <<'EOF'
import sys, struct
f = open(sys.argv[1], 'rb'); head = [f.readline() for _ in range(3)]; d = f.read()
v = struct.unpack('<%df' % (len(d) // 4), d)
open(sys.argv[2], 'wb').write(b''.join(head) + struct.pack('<%df' % len(v), *(min(x, 1.0) for x in v)))
EOF
"$PATHLAB" grade "$TMP/clamped.pfm" --ref ref/cornell.pfm --report "$TMP/d.md" > /dev/null 2>&1
row=$(grep 'clamped.pfm' "$TMP/d.md")
case $row in
*"; or instead, a secondary guess: "*) pass "reports: a secondary guess marked as such in the class report" ;;
*) fail "reports: the row of an image with several guesses: $row" ;;
esac
