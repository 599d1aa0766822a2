#!/usr/bin/env bash
# The scene files are what scenes/gen_scenes.py writes (hand edits would go unnoticed otherwise),
# and every scene loads.
. "$(dirname "$0")/lib.sh"
if command -v python3 >/dev/null 2>&1; then
    if out=$(python3 scenes/gen_scenes.py --check 2>&1); then pass "scenes/ match gen_scenes.py"
    else fail "scenes/ differ from gen_scenes.py: $out"; fi
else pass "scenes/ match gen_scenes.py (skipped: no python3)"; fi
for s in scenes/*.obj; do
    expect_status "$s renders" 0 $PATHLAB render "$s" --quiet --size 16x16 --spp 1 -o "$TMP/s.pfm"
done
exit 0
