#!/usr/bin/env bash
# bench/portable.sh PORTABLE NATIVE MESH... — what -march=native buys: the default build (its
# traversal compiled for SSE2, AVX2 and AVX-512 and chosen at start; asserts on) against the NATIVE=1
# build (-march=native, -DNDEBUG) on the same work, run alternately (3 rounds, median) so that the
# shared machine's load hits both alike, both on one CPU (taskset -c 0, when there is taskset):
#   bench-rays on each mesh (primary, diffuse and shadow rays, 1 thread): Mrays/s ratio;
#   a render (Cornell box, 128x128, 64 spp, 1 thread): time ratio.
# Prints native/portable speed ratios (above 1: native is faster). Used by `make bench-portable`.
set -eu
[ $# -ge 3 ] || { echo "usage: bench/portable.sh PORTABLE NATIVE MESH..." >&2; exit 2; }
port=$1 nat=$2; shift 2
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
median() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
pin=(); command -v taskset > /dev/null && pin=(taskset -c 0)
for mesh in "$@"; do
    for r in 1 2 3; do
        "${pin[@]}" "$port" bench-rays "$mesh" -t 1 > "$T/p$r"
        "${pin[@]}" "$nat" bench-rays "$mesh" -t 1 > "$T/n$r"
    done
    for kind in primary diffuse shadow; do
        p=$(for r in 1 2 3; do sed -n "s/^$kind: .* \([0-9.]*\) Mrays\/s.*/\1/p" "$T/p$r"; done | median)
        n=$(for r in 1 2 3; do sed -n "s/^$kind: .* \([0-9.]*\) Mrays\/s.*/\1/p" "$T/n$r"; done | median)
        awk -v m="$(basename "$mesh")" -v k=$kind -v p="$p" -v n="$n" \
            'BEGIN { printf "%-12s %-8s portable %7.2f  native %7.2f Mrays/s  native/portable %.3f\n", m, k, p, n, n / p }'
    done
done
for r in 1 2 3; do
    for b in port nat; do
        prog=$port; [ $b = nat ] && prog=$nat
        s=$(date +%s%N)
        "${pin[@]}" "$prog" render scenes/cornell.obj --size 128x128 --spp 64 --threads 1 --quiet -o "$T/$b.pfm"
        echo $(( ($(date +%s%N) - s) / 1000000 )) >> "$T/time_$b"
    done
done
p=$(median < "$T/time_port"); n=$(median < "$T/time_nat")
awk -v p="$p" -v n="$n" 'BEGIN { printf "%-12s %-8s portable %7d  native %7d ms        native/portable speed %.3f\n", "cornell", "render", p, n, p / n }'
cmp -s "$T/port.pfm" "$T/nat.pfm" && echo "the two builds rendered the same image, bit for bit" \
    || echo "the two builds' images differ in their last bits (different instructions, same estimator)"
