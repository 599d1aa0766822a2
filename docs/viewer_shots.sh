#!/usr/bin/env bash
# docs/viewer_shots.sh — the screenshots of pathlab's viewer in docs/guide.md (docs/img/viewer-*.png):
# the Cornell box at 16 spp against a 256-spp reference (split view, zoomed), and direct light only
# (--bounces 0:1) against it (the signed difference). Needs ./pathlab and Chromium (Debian: chromium).
# About a minute on the 2-core machine.
set -euo pipefail
cd "$(dirname "$0")/.."
P=${PATHLAB:-./pathlab}
W=$(mktemp -d); trap 'rm -rf "$W"' EXIT
R=(--threads 2 --quiet --size 256x256)
"$P" render scenes/cornell.obj "${R[@]}" --spp 16 --bounces 0:3 --split --variance "$W/mine_var.pfm" -o "$W/mine.pfm"
"$P" render scenes/cornell.obj "${R[@]}" --spp 256 --seed 9 --variance "$W/ref_var.pfm" -o "$W/ref.pfm"
"$P" render scenes/cornell.obj "${R[@]}" --spp 64 --bounces 0:1 -o "$W/direct.pfm"
"$P" view "$W/mine.pfm" "$W/direct.pfm" --ref "$W/ref.pfm" -o "$W/page.html"
# shot NAME JS: a screenshot of the page after the script JS (window.pathlabViewer is V)
shot() {
    { sed '$d' "$W/page.html"; echo "<script>var V = window.pathlabViewer; $2</script></body></html>"; } > "$W/$1.html"
    chromium --headless --no-sandbox --disable-gpu --no-first-run --disable-extensions --disable-background-networking \
        --user-data-dir="$W/profile-$1" --window-size=1100,1100 --hide-scrollbars --screenshot="docs/img/viewer-$1.png" \
        "file://$W/$1.html" > /dev/null 2>&1
}
shot image "V.setView(2.2, 128, 128); V.setRow(150); V.showProbe(150, 150);" &
shot split "V.setMode('split'); V.setSplit(0.55); V.setView(6, 141, 150); V.setRow(150); V.showProbe(150, 150);" &
shot diff "V.setImage(1); V.setMode('diff'); V.setView(2.2, 128, 128); V.setRow(200); V.showProbe(128, 200);" &
wait
ls -l docs/img/viewer-*.png
