#!/usr/bin/env bash
# The fuzz seed corpus (tests/fuzz/corpus/TARGET/) replayed through each harness of tests/fuzz/,
# built by the build under test without libFuzzer (BUILD/fuzz/replay_TARGET, tests/fuzz/replay.c):
# every seed runs to its end (a crash, a sanitizer report in a SAN build or a hang fails), and the
# harness's private temporary folder is gone afterwards. A few seconds; `make fuzz` is the real fuzzing.
. "$(dirname "$0")/lib.sh"
mkdir -p "$TMP/t"
for t in scene mtl view orbiter pfm sidecar report hdr png tga ppm jpeg; do
    bin=$BUILD/fuzz/replay_$t
    n=$(ls tests/fuzz/corpus/$t | wc -l)
    if [ ! -x "$bin" ]; then fail "fuzz seeds $t: $bin is missing (make test builds it)"; continue; fi
    start=$(date +%s.%N)
    out=$(TMPDIR=$TMP/t timeout 60 "$bin" tests/fuzz/corpus/$t/* 2>"$TMP/err"); rc=$?
    secs=$(echo "$(date +%s.%N) - $start" | bc)
    if [ "$rc" = 0 ] && [ "$out" = "replayed $n inputs" ]; then pass "fuzz seeds $t: $n inputs replayed in ${secs} s"
    else fail "fuzz seeds $t: exit $rc, '$out' for $n inputs: $(grep -m 3 -E 'ERROR|runtime error|SUMMARY' "$TMP/err" | tr '\n' ' ')"; fi
    if [ "$rc" != 0 ]; then rm -rf "${TMP:?}"/t/*   # a crash leaves it: already counted
    elif [ -z "$(ls -A "$TMP/t")" ]; then pass "fuzz seeds $t: the harness removed its temporary folder"
    else fail "fuzz seeds $t: left in TMPDIR: $(ls "$TMP/t" | head -n 3 | tr '\n' ' ')"; rm -rf "${TMP:?}"/t/*; fi
done
