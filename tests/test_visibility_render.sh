#!/usr/bin/env bash
# The shadow rays not traced (src/geometry/visibility.h) change no pixel: McGuire's empty white box
# (CornellBox-Empty-White.obj's 12 triangles, ../shared/data/cornell-mcguire) is rendered as it is,
# where every wall sees the light wholly and no shadow ray is traced, and with a 13th triangle, a
# needle 1e-20 wide standing in the middle of the room from near the floor to near the ceiling: it
# comes between every wall and the light, so that every shadow ray is traced, but no ray comes
# within 1e-20 of it. The two PFM files must be the same bytes, and the stats lines must say which
# rays were traced. And a light under a huge ground lights nothing (a known answer at mixed scales).
. "$(dirname "$0")/lib.sh"
cat > "$TMP/box.mtl" << 'EOF'
newmtl wall
Kd 1 1 1
newmtl light
Kd 0.78 0.78 0.78
Ke 10 10 10
EOF
cat > "$TMP/box.obj" << 'EOF'
mtllib box.mtl
usemtl wall
v -1.01 0.00 0.99
v 1.00 0.00 0.99
v 1.00 0.00 -1.04
v -0.99 0.00 -1.04
f -4 -3 -2 -1
v -1.02 1.99 0.99
v -1.02 1.99 -1.04
v 1.00 1.99 -1.04
v 1.00 1.99 0.99
f -4 -3 -2 -1
v -0.99 0.00 -1.04
v 1.00 0.00 -1.04
v 1.00 1.99 -1.04
v -1.02 1.99 -1.04
f -4 -3 -2 -1
v 1.00 0.00 -1.04
v 1.00 0.00 0.99
v 1.00 1.99 0.99
v 1.00 1.99 -1.04
f -4 -3 -2 -1
v -1.01 0.00 0.99
v -0.99 0.00 -1.04
v -1.02 1.99 -1.04
v -1.02 1.99 0.99
f -4 -3 -2 -1
usemtl light
v -0.24 1.98 0.16
v -0.24 1.98 -0.22
v 0.23 1.98 -0.22
v 0.23 1.98 0.16
f -4 -3 -2 -1
EOF
{ cat "$TMP/box.obj"; printf 'usemtl wall\nv 0 0.2 0\nv 0 1.8 0\nv 1e-20 1.0 0\nf -3 -2 -1\n'; } > "$TMP/hidden.obj"
cp "$TMP/box.mtl" "$TMP/hidden.mtl"; sed -i 's/box\.mtl/hidden.mtl/' "$TMP/hidden.obj"
cam="--eye 0,1,3.9 --target 0,1,0 --up 0,1,0 --fov 40 --size 48x48 --spp 32 --threads 2"
for s in box hidden; do
    # shellcheck disable=SC2086
    run_ok "visibility_render_$s" "$PATHLAB" render "$TMP/$s.obj" $cam -o "$TMP/$s.pfm"
    cp "$TMP/run.err" "$TMP/$s.err"
done
if grep -q "22 of 24 triangle-emitter pairs need no shadow ray" "$TMP/box.err" && grep -q "shadow 0; [1-9][0-9]* shadow rays not traced" "$TMP/box.err"; then
    pass "visibility_render_box_traces_none ($(grep -o 'shadow 0; [0-9]* shadow rays not traced' "$TMP/box.err"))"
else fail "visibility_render_box_traces_none: the empty box should trace no shadow ray: $(err_tail "$TMP/box.err")"; fi
traced=$(sed -n 's/.*shadow \([0-9]*\); \([0-9]*\) shadow rays not traced.*/\1 \2/p' "$TMP/hidden.err")
if [ -n "$traced" ] && [ "${traced% *}" -gt "${traced#* }" ]; then
    pass "visibility_render_hidden_traces ($traced: shadow rays traced, not traced)"
else fail "visibility_render_hidden_traces: with the hidden triangle most shadow rays should be traced: $(err_tail "$TMP/hidden.err")"; fi
if cmp -s "$TMP/box.pfm" "$TMP/hidden.pfm"; then pass "visibility_render_same_image (48x48, 32 spp: the same bytes)"
else fail "visibility_render_same_image: the images differ: $("$PATHLAB" diff "$TMP/box.pfm" "$TMP/hidden.pfm" 2>&1 | head -3 | tr '\n' ' ')"; fi

# A known answer at mixed scales: a light 5e-6 under a ground 1e4 wide, facing up into it, a panel over
# the ground. Nothing the camera sees gets any light: every pixel is 0. (The pairs' tolerance was once
# 2^-30 of the largest coordinate, 9.3e-6 here: the light counted as in the ground's plane, its pairs
# with the panel were cleared and the panel was lit.)
printf 'newmtl white\nKd 0.8 0.8 0.8\nnewmtl light\nKd 0.5 0.5 0.5\nKe 20 20 20\n' > "$TMP/under.mtl"
cat > "$TMP/under.obj" << 'EOF'
mtllib under.mtl
usemtl white
v -1e4 0 -1e4
v -1e4 0 1e4
v 1e4 0 1e4
v 1e4 0 -1e4
f 1 2 3 4
v -0.5 1 -0.5
v 0.5 1 -0.5
v 0.5 1 0.5
v -0.5 1 0.5
f 5 6 7 8
usemtl light
v -0.25 -5e-6 0.25
v -0.25 -5e-6 -0.25
v 0.25 -5e-6 -0.25
v 0.25 -5e-6 0.25
f 12 11 10 9
EOF
run_ok "visibility_render_under_ground" "$PATHLAB" render "$TMP/under.obj" --eye 0,0.3,2.5 --target 0,1,0 --up 0,1,0 \
    --fov 40 --size 32x32 --spp 8 --threads 2 -o "$TMP/under.pfm"
header=$(head -n 3 "$TMP/under.pfm" | wc -c)
lit=$(tail -c +$((header + 1)) "$TMP/under.pfm" | tr -d '\000' | wc -c)
if [ "$lit" -eq 0 ] && [ "$(wc -c < "$TMP/under.pfm")" -eq $((header + 32 * 32 * 12)) ]; then
    pass "visibility_render_under_ground_black (32x32: every pixel 0)"
else fail "visibility_render_under_ground_black: $lit nonzero bytes; $(grep -o '[0-9]* of [0-9]* triangle-emitter pairs' "$TMP/run.err")"; fi
