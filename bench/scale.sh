#!/usr/bin/env bash
# bench/scale.sh — `make bench-scale`: the BVH from 1M to 16M triangles, pathlab against Embree 3.
#
# For each size N in SCALE_SIZES (millions of triangles, default "1 2 4 8 16"), a field of copies of
# the bunny (build/bench-scale-mesh, bench/scale_mesh.c) is written once to SCALE_CACHE (default
# ~/.cache/pathlab-bench-scale: outside git, 0.04 GB of OBJ per million triangles).
# SCALE_KIND=subdivide: the bunny itself cut into 4^k times its triangles instead (at least N
# million: "1 4 16" gives 1.1M, 4.4M, 17.8M), the same surface and view at every size, so that
# only the tree grows. Then, for each thread count of SCALE_THREADS (default "1 2"), embree-rays
# and `pathlab bench-rays` run on it back to back (same rays, ../shared/tools/embree-rays/README.md),
# each under /usr/bin/time for its peak resident memory, SCALE_ROUNDS times (default 1),
# alternated. Embree's own BVH size comes from one more run with EMBREE_VERBOSE=1 (its statistics:
# "total ... #bytes/prim"), at 1 thread and 64x64 rays; pathlab prints its own (nodes and triangle
# blocks: all the tree keeps of the mesh).
# Writes one line per run to SCALE_OUT (default bench/scale.csv; with the load average; SCALE_APPEND=1
# adds to it instead), then draws docs/NAME.svg for bench/NAME.csv and prints the tables and slopes
# (bench/scale_plot.py). PATHLAB_FLAGS are passed to bench-rays (e.g. "--bvh-quality split");
# SCALE_TAG names them in the CSV (default: pathlab).
# With 1 thread both programs run on one CPU (taskset -c SCALE_CPU, default 0), as `make bench` does:
# a virtual machine's CPUs can differ in speed for minutes, and a pair split across two of them
# compares the CPUs, not the programs.
# SCALE_CLOCK=cpu times both with the process's CPU clock instead of the wall clock (bench-rays
# --cpu-time, and embree-rays built as build/embree-rays-cpu with bench/cpu_clock.h): on a machine
# loaded by other processes, wall seconds count their time slices too.
set -eu
PATHLAB=${PATHLAB:-./pathlab}
BUILD=${BUILD:-build}
SIZES=${SCALE_SIZES:-"1 2 4 8 16"}
THREADS=${SCALE_THREADS:-"1 2"}
ROUNDS=${SCALE_ROUNDS:-1}
CACHE=${SCALE_CACHE:-$HOME/.cache/pathlab-bench-scale}
OUT=${SCALE_OUT:-bench/scale.csv}
TAG=${SCALE_TAG:-pathlab}
KIND=${SCALE_KIND:-field}
case $KIND in field) SUB="" ;; subdivide) SUB=subdivide ;; *) echo "scale.sh: SCALE_KIND is field or subdivide" >&2; exit 2 ;; esac
FLAGS=${PATHLAB_FLAGS:-}
BASE=../shared/data/meshes/bunny.obj
CLOCK=${SCALE_CLOCK:-wall}
EMBREE=$BUILD/embree-rays
case $CLOCK in
  wall) CPU=() ;;
  cpu) EMBREE=$BUILD/embree-rays-cpu; CPU=(-include bench/cpu_clock.h); FLAGS="$FLAGS --cpu-time" ;;
  *) echo "scale.sh: SCALE_CLOCK is wall or cpu" >&2; exit 2 ;;
esac

[ -x "$PATHLAB" ] || { echo "scale.sh: no $PATHLAB (run make first)" >&2; exit 2; }
[ -x "$EMBREE" ] || cc -O2 -std=c99 "${CPU[@]}" -o "$EMBREE" ../shared/tools/embree-rays/embree_rays.c -lembree3 -lpthread -lm
mkdir -p "$CACHE"
[ -n "${SCALE_APPEND:-}" ] && [ -s "$OUT" ] || echo "tool,threads,triangles,load_ms,build_ms,bytes_per_tri,peak_rss_mb,primary,diffuse,shadow,primary_hits,loadavg,date,clock" > "$OUT"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

# run TOOL THREADS MESH CMD...: one line of the CSV from the command's output and peak memory.
run() {
  local tool=$1 t=$2 mesh=$3; shift 3
  /usr/bin/time -f "rss %M" -o "$tmp/time" "$@" > "$tmp/out" 2>/dev/null || { echo "scale.sh: $tool failed on $mesh" >&2; return 1; }
  python3 - "$tmp/out" "$tmp/time" "$tool" "$t" "$(cut -d' ' -f1 /proc/loadavg)" "${BPT:-}" "$CLOCK" >> "$OUT" <<'PY'
import re, sys, time
out, tm, tool, t, load = open(sys.argv[1]).read(), open(sys.argv[2]).read(), sys.argv[3], sys.argv[4], sys.argv[5]
g = lambda pat: re.search(pat, out).group(1)
rate = lambda k: g(k + r':\s*\d+ rays,\s*\d+ \w+,\s*([\d.]+) Mrays/s')
bpt = re.search(r'BVH and triangles ([\d.]+) bytes/triangle', out)
print(",".join([tool, t, g(r'(\d+) triangles'), g(r'load (\d+) ms'), g(r'build.*?: ([\d.]+) ms'),
                bpt.group(1) if bpt else sys.argv[6], "%.0f" % (int(re.search(r'rss (\d+)', tm).group(1)) / 1024),
                rate('primary'), rate('diffuse'), rate('shadow'), g(r'primary:\s*\d+ rays,\s*(\d+)'), load,
                time.strftime('%Y-%m-%d %H:%M', time.gmtime()), sys.argv[7]]))
PY
  tail -1 "$OUT"
}

for n in $SIZES; do
  mesh=$CACHE/bunny-${SUB:+sub-}${n}M.obj
  [ -s "$mesh" ] || "$BUILD/bench-scale-mesh" "$BASE" $((n * 1000000)) "$mesh" $SUB
  # Embree's BVH statistics: bytes per primitive of its nodes and leaves (the leaves hold the triangles)
  EMBREE_VERBOSE=1 "$EMBREE" "$mesh" -t 1 -r 64 > "$tmp/verbose" 2>&1 || true
  ebpt=$(sed -n 's/^ *total *: sah.*#bytes\/prim = *\([0-9.]*\).*/\1/p' "$tmp/verbose" | tail -1)
  echo "embree BVH bytes/triangle at ${n}M: ${ebpt:-?}"
  for t in $THREADS; do
    pin=; [ "$t" = 1 ] && command -v taskset > /dev/null && pin="taskset -c ${SCALE_CPU:-0}"
    for r in $(seq "$ROUNDS"); do
      # shellcheck disable=SC2086
      BPT=$ebpt run embree "$t" "$mesh" $pin "$EMBREE" "$mesh" -t "$t"
      # shellcheck disable=SC2086
      run "$TAG" "$t" "$mesh" $pin "$PATHLAB" bench-rays "$mesh" -t "$t" $FLAGS
    done
  done
done
python3 bench/scale_plot.py "$OUT" "docs/$(basename "$OUT" .csv).svg"
