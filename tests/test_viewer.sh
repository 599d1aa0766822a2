#!/usr/bin/env bash
# pathlab view in a real browser (headless Chromium, Debian's `chromium`, installed here if missing
# and possible; without it the browser checks are skipped and say so). Pages written by pathlab view
# (and by build/tests/test_html_page for the marks) are copied with tests/viewer/test.js appended;
# the test script drives window.pathlabViewer and writes PASS/FAIL lines into the page, read back
# from --dump-dom. Checked: the probe's values against the PFM files' bytes (at 10 pixels, relative
# 1e-3), exposure, split, difference, keys, the layers' strip, marks and links, no network request
# (the page's CSP, a blocked control request, no resource loaded, no http(s) URL in the page), and a
# page of a 2048x1024 image decoded and drawn within LOAD_BOUND ms (8000; measured 1.6-5.3 s with the
# machine's two cores shared by 12-18 processes). Two Chromium runs side by side; 25 s in all at load 12-14.
# Also the command's errors (no browser needed): a missing file named, two sizes refused naming both.
. "$(dirname "$0")/lib.sh"
LOAD_BOUND=${LOAD_BOUND:-8000}

# --- the command's errors ---
$PATHLAB render scenes/cornell.obj --size 96x64 --spp 8 --bounces 0:2 --split --variance "$TMP/c_var.pfm" -o "$TMP/c.pfm" --quiet
$PATHLAB render scenes/cornell.obj --size 96x64 --spp 32 --seed 7 --variance "$TMP/r_var.pfm" -o "$TMP/r.pfm" --quiet
$PFMTOOL scale "$TMP/c.pfm" 1e-3 "$TMP/small.pfm"
$PFMTOOL const 64 64 1 1 1 "$TMP/sq.pfm"
expect_status "view: a missing image, exit 2" 2 $PATHLAB view "$TMP/c.pfm" "$TMP/none.pfm" -o "$TMP/x.html"
expect_err "view: the missing file named" "none.pfm"
expect_status "view: two sizes, exit 2" 2 $PATHLAB view "$TMP/c.pfm" --ref "$TMP/sq.pfm" -o "$TMP/x.html"
expect_err "view: two sizes, both files and sizes named" "sq.pfm is 64x64, .*c.pfm is 96x64"
expect_status "view: no -o, exit 2" 2 $PATHLAB view "$TMP/c.pfm"
expect_no_file "view: no page written after an error" "$TMP/x.html"
expect_status "view: images, reference, variances, layers: exit 0" 0 \
    $PATHLAB view "$TMP/c.pfm" "$TMP/small.pfm" --ref "$TMP/r.pfm" -o "$TMP/main.html"
$PATHLAB view "$TMP/r.pfm" --layers "$TMP/c" -o "$TMP/layers.html" 2> "$TMP/err"
n=$(grep -o '"name":"L[0-9]"' "$TMP/layers.html" 2>/dev/null | tr '\n' ' ')
if [ "$n" = '"name":"L0" "name":"L1" "name":"L2" ' ]; then pass "view: --layers PREFIX finds PREFIX_L0.pfm .. L2"
else fail "view: --layers found '$n'; $(head -c 200 "$TMP/err")"; fi
expect_status "view: --layers with no layer, exit 2" 2 $PATHLAB view "$TMP/r.pfm" --layers "$TMP/none" -o "$TMP/x.html"
expect_err "view: --layers with no layer, the prefix named" "no layer .*none_L0.pfm"
if grep -q "Content-Security-Policy\" content=\"default-src 'none'" "$TMP/main.html" && ! grep -qE 'https?://' "$TMP/main.html"
then pass "view: the page's CSP forbids requests, no http(s) URL in it"
else fail "view: CSP missing or a URL in the page: $(grep -oE 'https?://[^"]*' "$TMP/main.html" | head -3)"; fi

# script_hashes FILE: 'sha256-BASE64' of each inline script (no type, no src) of FILE, as a CSP lists them
script_hashes() {
    python3 -c 'import base64, hashlib, re, sys
t = open(sys.argv[1], encoding="utf-8").read()
print(" ".join("'"'"'sha256-%s'"'"'" % base64.b64encode(hashlib.sha256(s.encode()).digest()).decode()
               for s in re.findall(r"<script>(.*?)</script>", t, re.S)))' "$1"
}
# allow_test_scripts FILE: the test's own scripts allowed by their hashes beside the viewer's, in the
# page's CSP (which allows no inline script but by hash)
allow_test_scripts() {
    local h; h=$(script_hashes "$1")
    sed -i "s#script-src [^;]*;#script-src $h;#" "$1"
}
csp=$(grep -o 'Content-Security-Policy" content="[^"]*' "$TMP/main.html")
hash=$(command -v python3 >/dev/null && script_hashes "$TMP/main.html")
case $csp in
*"script-src $hash;"*"base-uri 'none'; form-action 'none'"*)
    if [ -n "$hash" ] && [ "$(echo "$hash" | wc -w)" = 1 ] && ! echo "$csp" | grep -q "script-src[^;]*unsafe-inline"
    then pass "view: the CSP allows the page's one script by its SHA-256 ($hash), no 'unsafe-inline' script, base-uri and form-action 'none'"
    else fail "view: the CSP's script-src: $csp (the script's hash: $hash)"; fi ;;
*) fail "view: the CSP does not list the script's hash $hash with base-uri and form-action 'none': $csp" ;;
esac

# --- the browser ---
find_chromium() { command -v chromium || command -v chromium-browser || command -v google-chrome || true; }
CHROME=${CHROMIUM-$(find_chromium)}   # CHROMIUM=PROGRAM chooses the browser (CHROMIUM= : none, to see the skip)
if [ -z "${CHROMIUM+set}" ] && [ -z "$CHROME" ] && command -v apt-get >/dev/null 2>&1 && { [ "$(id -u)" = 0 ] || sudo -n true 2>/dev/null; }; then
    SUDO=$( [ "$(id -u)" = 0 ] || echo sudo )
    echo "installing chromium for the viewer's browser tests"
    $SUDO apt-get update -qq >/dev/null 2>&1
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq chromium >/dev/null 2>&1
    CHROME=$(find_chromium)
fi
if [ -z "$CHROME" ] || ! command -v "$CHROME" >/dev/null 2>&1; then
    echo "SKIP viewer: no Chromium (Debian: apt-get install chromium); the browser checks did not run"
    exit 0
fi

# the exposure convert --exposure auto picks for the first image: the viewer's automatic one must agree
AUTO=$($PATHLAB convert "$TMP/c.pfm" "$TMP/c_auto.png" --exposure auto 2> /dev/null | sed -n 's/^exposure auto: \([-+][0-9.]*\) stops.*/\1/p')
# test_page PAGE KIND OUT [NAME FILE.pfm]...: PAGE with a listener of blocked requests first in its
# head, and at its end the PFM files' bytes (base64) and tests/viewer/test.js.
test_page() {
    local page=$1 kind=$2 out=$3; shift 3
    {
        sed -e '$d' -e 's#<head>#<head><script>window.__pathlabBlocked = []; document.addEventListener("securitypolicyviolation", function (e) { __pathlabBlocked.push(e.blockedURI); });</script>#' "$page"
        echo "<script>var TEST = {kind: '$kind', bound: $LOAD_BOUND, convertAuto: ${AUTO:-0}}, PFM = {"
        while [ $# -gt 0 ]; do echo "$1: '$(base64 -w0 "$2")',"; shift 2; done
        echo "};</script><script>"
        cat tests/viewer/test.js
        echo "</script></body></html>"
    } > "$out"
    allow_test_scripts "$out"
}
# run_page KIND FILE: Chromium's DOM of FILE once loaded (and 200 ms of the page's timers) in $TMP/KIND.dom
run_page() {
    timeout 90 "$CHROME" --headless --no-sandbox --disable-gpu --no-first-run --disable-extensions --disable-dev-shm-usage \
        --disable-background-networking --disable-component-update --disable-sync \
        --user-data-dir="$TMP/profile-$1" --virtual-time-budget=3000 --dump-dom "file://$2" > "$TMP/$1.dom" 2> "$TMP/$1.err"
}
"$BUILD/tests/test_html_page" "$TMP" > /dev/null 2>&1 || fail "viewer: build/tests/test_html_page could not write the marks page"
test_page "$TMP/main.html" main "$TMP/t-main.html" image "$TMP/c.pfm" ref "$TMP/r.pfm" small "$TMP/small.pfm" \
    image_var "$TMP/c_var.pfm" ref_var "$TMP/r_var.pfm" layer1 "$TMP/c_L1.pfm"
test_page "$TMP/marks.html" marks "$TMP/t-marks.html"
start=$(date +%s%N)
for k in main marks; do run_page $k "$TMP/t-$k.html" & done
wait
echo "note: two Chromium runs side by side took $(( ($(date +%s%N) - start) / 1000000 )) ms; pages: $(stat -c %s "$TMP/main.html") bytes (96x64, 2 images, a reference, 2 variances, 3 layers), $(stat -c %s "$TMP/marks.html") bytes (2048x1024)"
for k in main marks; do
    lines=$(sed -n '/<pre id="pathlab-test">/,/<\/pre>/p' "$TMP/$k.dom" | grep -E '^(PASS|FAIL) ')
    if [ -n "$lines" ]; then echo "$lines" | sed 's/&lt;/</g; s/&gt;/>/g; s/&amp;/\&/g'
    else fail "viewer: the $k page wrote no result (Chromium: $(grep -v -e dbus -e 'unexpected operator' "$TMP/$k.err" | head -c 300))"; fi
done
