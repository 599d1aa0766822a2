#!/usr/bin/env bash
# bench/texture.sh — what a texture costs (`make bench`): ns per lookup (bench/texture_lookup.c), and
# the render time of a textured wall (map_Kd, a 1024 x 1024 texture of random texels, nearest and
# bilinear) against the same wall with a plain Kd, 256x256 x 64 spp, 2 threads, alternated, 3 rounds,
# median of each. Scenes from tests/materials/gen.py.
# Environment: PATHLAB (default ./pathlab), BUILD (where bench-texture is, default build).
set -eu
cd "$(dirname "$0")/.."
PATHLAB=${PATHLAB:-./pathlab}
BUILD=${BUILD:-build}
TMP=$(mktemp -d); trap 'rm -rf "$TMP"' EXIT
"$BUILD/bench-texture"
python3 tests/materials/gen.py "$TMP"
python3 - "$TMP/half.pfm" <<'PY'
import random, struct, sys
r = random.Random(1)
with open(sys.argv[1], "wb") as f:
    f.write(b"PF\n1024 1024\n-1\n")
    f.write(struct.pack("<%df" % (3 * 1024 * 1024), *(r.random() for _ in range(3 * 1024 * 1024))))
PY
F="--eye 0,0,2.9 --target 0,0,0 --fov 40 --size 256x256 --spp 64 --threads 2 --quiet"
time_of() { local t0 t1; t0=$(date +%s.%N); "$PATHLAB" render "$@" $F -o "$TMP/x.pfm"; t1=$(date +%s.%N); echo "$t1 - $t0" | bc; }
: > "$TMP/times"
for round in 1 2 3; do
    echo "plain $(time_of "$TMP/wall-plain.obj")" >> "$TMP/times"
    echo "nearest $(time_of "$TMP/wall.obj")" >> "$TMP/times"
    echo "bilinear $(time_of "$TMP/wall.obj" --texture-filter bilinear)" >> "$TMP/times"
done
for k in plain nearest bilinear; do
    echo "$k $(grep "^$k " "$TMP/times" | awk '{print $2}' | sort -n | sed -n 2p)"
done | awk '{ t[$1] = $2; print } END { printf "textured wall, 256x256 x 64 spp, 2 threads: nearest %.3f x, bilinear %.3f x the plain wall'"'"'s time\n", t["nearest"] / t["plain"], t["bilinear"] / t["plain"] }'
