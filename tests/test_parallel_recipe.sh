#!/usr/bin/env bash
# The GNU parallel recipe of docs/distributed.md, run as documented on this machine: the Cornell box,
# 64 spp in 4 pieces merged, against one render of the same 64 samples (same seed): equal within float
# rounding (idiff: 1e-5 relative on the image, 1e-4 on the variance; docs/references.md measures
# 1.2e-7 and 4.6e-6); the merged sidecar names all the samples; the pieces are deleted. Then the
# failures a teacher meets: a bad render flag (every piece fails: nothing merged, nothing left), and
# Ctrl-C (each piece writes the samples it reached; the pieces are kept and merge as they are).
# Installs Debian's parallel if missing (as make test installs idiff). About 10 s.
cd "$(dirname "$0")/.."
. tests/lib.sh
export PARALLEL_HOME=$TMP/parallel-home     # GNU parallel's own files, deleted with $TMP
# make test-deps installs GNU parallel when it can (root or a password-less sudo); else skipped
if ! command -v parallel >/dev/null 2>&1 || [ -n "${PATHLAB_NO_PARALLEL:-}" ]; then
    skip "the GNU parallel recipe (parallel is not installed: make test-deps installs it as root or with sudo)"; exit 0
fi
R=scripts/parallel-render.sh

# 1. the recipe
expect_status "the recipe: 64 spp in 4 pieces, merged (exit 0)" 0 \
    $R scenes/cornell.obj "$TMP/merged.pfm" --spp 64 --pieces 4 --pathlab "$PATHLAB" --size 64x64 --seed 7
grep -q 'piece 3: samples 48:64' "$TMP/out" && pass "it prints each piece's sample range" || fail "no 'piece 3: samples 48:64' in: $(head -c 400 "$TMP/out")"
"$PATHLAB" render scenes/cornell.obj --spp 64 --size 64x64 --seed 7 --quiet -o "$TMP/one.pfm" --variance "$TMP/one_var.pfm"
if ! have_oiio; then skip "merged == one render (needs OpenImageIO's idiff)"
elif idiff -fail 0 -failrelative 1e-5 -warn 0 -warnrelative 1e-5 "$TMP/merged.pfm" "$TMP/one.pfm" > "$TMP/idiff" 2>&1; then
    pass "merged == one render of the 64 samples (every pixel-channel within 1e-5 relative)"
else fail "merged != one render: $(tail -n 5 "$TMP/idiff")"; fi
if ! have_oiio; then skip "the merged variance == the one render's (needs OpenImageIO's idiff)"
elif idiff -fail 0 -failrelative 1e-4 -warn 0 -warnrelative 1e-4 "$TMP/merged_var.pfm" "$TMP/one_var.pfm" > "$TMP/idiff" 2>&1; then
    pass "the merged variance == the one render's (1e-4 relative)"
else fail "merged variance != one render's: $(tail -n 5 "$TMP/idiff")"; fi
s=$(awk '$1 == "samples" { print $2 }' "$TMP/merged.pfm.meta" 2>/dev/null)
[ "$s" = 0:64 ] && pass "the merged sidecar: samples 0:64" || fail "the merged sidecar says samples '$s'"
expect_no_file "the pieces are deleted after the merge" "$TMP/merged.pfm.pieces"

# 2. a bad render flag: every piece fails, nothing merged, nothing left
expect_status "a bad render flag: exit 1" 1 \
    $R scenes/cornell.obj "$TMP/bad.pfm" --spp 8 --pieces 2 --pathlab "$PATHLAB" --size 64x64 --direct nonsense
expect_err "and it says no piece was written" 'no piece was written'
expect_no_file "no image and no pieces folder after a failure with nothing written" "$TMP/bad.pfm" "$TMP/bad.pfm.pieces"
expect_status "a render flag the script sets itself (--spp) is refused: exit 2" 2 \
    $R scenes/cornell.obj "$TMP/bad.pfm" --spp 8 --pathlab "$PATHLAB" --samples 0:4

# 3. Ctrl-C: the whole process group gets SIGINT, as from a terminal
setsid $R scenes/cornell.obj "$TMP/long.pfm" --spp 1000000 --pieces 2 --pathlab "$PATHLAB" --size 32x32 --seed 3 \
    > "$TMP/long.out" 2> "$TMP/long.err" &
pid=$!
for _ in $(seq 100); do    # until GNU parallel has started the pieces (each in its own process group)
    [ "$(pgrep -c -f "$TMP/long.pfm.pieces/piece-" 2>/dev/null)" = 2 ] && break
    sleep 0.1
done
sleep 2
kill -INT -- -"$pid"
wait "$pid"; rc=$?
[ $rc = 1 ] && pass "Ctrl-C: exit 1, nothing merged" || fail "Ctrl-C: exit $rc, expected 1; $(tail -n 5 "$TMP/long.err")"
grep -q 'pieces are kept' "$TMP/long.err" && pass "Ctrl-C: it says the pieces are kept and how to merge them" || fail "Ctrl-C: $(tail -n 5 "$TMP/long.err")"
n=0
for k in 0 1; do
    grep -q '^stopped SIGINT' "$TMP/long.pfm.pieces/piece-$k.pfm.meta" 2>/dev/null && n=$((n + 1))
done
[ $n = 2 ] && pass "Ctrl-C: each piece wrote the samples it reached (stopped SIGINT)" || fail "Ctrl-C: $n pieces say 'stopped SIGINT', not 2"
expect_status "the kept pieces merge as they are" 0 \
    "$PATHLAB" merge "$TMP/long.pfm" "$TMP/long.pfm.pieces/piece-0.pfm" "$TMP/long.pfm.pieces/piece-1.pfm" --variance "$TMP/long_var.pfm"
left=$(pgrep -f "$TMP/long.pfm" 2>/dev/null)
if [ -z "$left" ]; then pass "no process left after Ctrl-C"; else fail "processes of the interrupted run are left: $left"; kill -KILL $left; fi
