#!/usr/bin/env bash
# Signals at random moments leave no temporary file and no half-set of files.
# A render with --split and --variance writes 20 files (o.pfm, o_var.pfm, o_L0..3, o_var_L0..3 and
# a .meta sidecar each) over an older complete set; it is sent SIGINT, SIGTERM, SIGHUP, SIGQUIT or
# SIGPIPE (all handled alike) after a random
# delay of 0..300 ms (a third of the runs get a second signal 0..100 ms later: the render then
# quits at once), 30 times; then 6 more runs are hit while they write (two signals right after the
# stats line, 0..200 turns of a shell loop apart), and 6 runs of convert and merge after 0..30 ms. After each run:
#  - no *.tmp.* or *.pending file is left in the folder;
#  - the set is whole: all 20 files, each PFM the size of a complete 200x200 image, and all 10
#    sidecars name the same seed (each run has its own), i.e. the old set or the new one, never a mix;
#  - the exit status is 0 (finished) or 128 + the signal (129 HUP, 130 INT, 131 QUIT, 141 PIPE, 143
#    TERM), nothing else.
# SIGKILL cannot be caught: what it leaves is printed (not a test), see src/sys/interrupt.h.
# Random delays from $RANDOM, seeded by SIGNAL_SEED (default: the clock, printed, to replay a failure).
. "$(dirname "$0")/lib.sh"
seed=${SIGNAL_SEED:-$(date +%s)}
RANDOM=$seed
echo "signal delays seeded with SIGNAL_SEED=$seed"
D=$TMP/sig
mkdir -p "$D"
args=(render scenes/cornell.obj --size 96x96 --bounces 0:3 --split --threads 2 -o "$D/o.pfm" --variance "$D/o_var.pfm")
names="o o_var o_L0 o_L1 o_L2 o_L3 o_var_L0 o_var_L1 o_var_L2 o_var_L3"
$PATHLAB "${args[@]}" --spp 1 --seed 1000 --quiet || { fail "signals: the first render failed"; exit 0; }
size=$(stat -c %s "$D/o.pfm")

bad_runs=0
files=""; metas=""
for n in $names; do files="$files $D/$n.pfm"; metas="$metas $D/$n.pfm.meta"; done
shopt -s nullglob
check_set() {   # LABEL STATUS: the folder after a run (2 processes: the machine may be loaded)
    local label=$1 rc=$2 left sizes seeds z
    left=("$D"/*.tmp.* "$D"/*.pending)
    [ ${#left[@]} -eq 0 ] || { fail "$label: left behind: ${left[*]##*/}"; bad_runs=$((bad_runs + 1)); return; }
    # shellcheck disable=SC2086
    sizes=$(stat -c %s $files 2>&1)
    for z in $sizes; do
        [ "$z" = "$size" ] || { fail "$label: an image of $z bytes, a whole one is $size: $(echo $sizes)"; bad_runs=$((bad_runs + 1)); return; }
    done
    # shellcheck disable=SC2086
    seeds=$(awk '/^seed / { n++; s[$2] = 1 } END { for (k in s) d++; print n "/" d }' $metas 2>/dev/null)
    [ "$seeds" = "10/1" ] || { fail "$label: seed lines in the 10 sidecars (count/distinct): $seeds: a half-set"; bad_runs=$((bad_runs + 1)); return; }
    case $rc in 0|129|130|131|141|143) ;; *) fail "$label: exit status $rc"; bad_runs=$((bad_runs + 1)) ;; esac
}
SIGNALS=(INT TERM HUP QUIT PIPE)
sig_name() { echo "${SIGNALS[RANDOM % 5]}"; }

# 30 renders stopped at random moments (loading, rendering, writing)
stats=""
for i in $(seq 1 30); do
    $PATHLAB "${args[@]}" --spp 8 --seed "$i" --quiet 2> /dev/null &
    pid=$!
    sleep "0.$(printf '%03d' $((RANDOM % 301)))"
    s1=$(sig_name); kill -s "$s1" "$pid" 2> /dev/null
    second=""
    if [ $((RANDOM % 3)) -eq 0 ]; then
        sleep "0.$(printf '%03d' $((RANDOM % 101)))"; second=$(sig_name); kill -s "$second" "$pid" 2> /dev/null
    fi
    wait "$pid"; rc=$?
    stats="$stats $rc"
    check_set "render $i (SIG$s1${second:+ then SIG$second})" "$rc"
done
echo "exit statuses of the 30 renders:$stats"
[ "$bad_runs" -eq 0 ] && pass "30 renders stopped by SIGINT/TERM/HUP/QUIT/PIPE after 0..300 ms: no temporary file, the old set or the new one"

# 6 renders hit while writing: the first signal is taken after the render, the second quits mid-write
bad_runs=0; written=0
for i in $(seq 31 36); do
    $PATHLAB "${args[@]}" --spp 1 --seed "$i" 2> "$TMP/err.$i" &
    pid=$!
    for _ in $(seq 1 2000); do [[ "$(< "$TMP/err.$i")" == *NaN/Inf* ]] && break; sleep 0.01; done
    kill -INT "$pid" 2> /dev/null
    for _ in $(seq 1 $((RANDOM % 200))); do :; done   # 0..200 turns of the shell's loop, no process
    kill -TERM "$pid" 2> /dev/null
    wait "$pid"; rc=$?
    grep -q "^seed $i$" "$D/o.pfm.meta" && written=$((written + 1))
    check_set "render $i (SIGINT, SIGTERM while writing)" "$rc"
done
[ "$bad_runs" -eq 0 ] && pass "6 renders stopped while writing their 20 files: no temporary file, no half-set ($written of 6 wrote the new set)"

# other commands write through the same atomic files: convert (a PNG) and merge, stopped at random
bad_runs=0
for i in $(seq 1 6); do
    if [ $((i % 2)) -eq 0 ]; then $PATHLAB convert "$D/o.pfm" "$D/view.png" > /dev/null 2>&1 &
    else $PATHLAB merge "$D/m.pfm" "$D/o.pfm" > /dev/null 2>&1 & fi
    pid=$!
    sleep "0.0$(printf '%02d' $((RANDOM % 31)))"
    kill -s "$(sig_name)" "$pid" 2> /dev/null
    wait "$pid"; rc=$?
    left=("$D"/*.tmp.* "$D"/*.pending)
    [ ${#left[@]} -eq 0 ] || { fail "convert/merge $i: left behind: ${left[*]##*/}"; bad_runs=$((bad_runs + 1)); }
    case $rc in 0|2|129|130|131|141|143) ;; *) fail "convert/merge $i: exit status $rc"; bad_runs=$((bad_runs + 1)) ;; esac
done
[ "$bad_runs" -eq 0 ] && pass "6 runs of convert and merge stopped after 0..30 ms: no temporary file"

# SIGHUP (a closed terminal), SIGQUIT (Ctrl-\\) and SIGPIPE (a reader gone) stop a render as Ctrl-C
# does: the pass ends, the image reached is written, its sidecar says which signal; by default each
# would have killed pathlab at once, writing nothing.
for s in HUP QUIT PIPE; do
    rm -f "$D"/h.pfm*
    $PATHLAB render scenes/cornell.obj --size 32x32 --spp 1000000 --threads 2 -o "$D/h.pfm" 2> "$TMP/err.$s" &
    pid=$!
    for _ in $(seq 1 1000); do grep -q 'spp' "$TMP/err.$s" 2> /dev/null && break; sleep 0.01; done
    sleep 0.2; kill -s "$s" "$pid" 2> /dev/null; wait "$pid"; rc=$?
    want=$((128 + $(kill -l "$s")))
    left=("$D"/*.tmp.* "$D"/*.pending)
    if [ "$rc" = "$want" ] && grep -q "^stopped SIG$s$" "$D/h.pfm.meta" 2> /dev/null && [ ${#left[@]} -eq 0 ]; then
        pass "SIG$s stops a render after its pass: the image reached written, 'stopped SIG$s' in its sidecar, exit $rc"
    else fail "SIG$s during a render: exit $rc (want $want), sidecar: $(grep stopped "$D/h.pfm.meta" 2>&1), left: ${left[*]##*/}"; fi
done

# SIGKILL cannot be caught: shown, not tested (the outputs are still the old or the new ones, renamed
# whole; the temporary files of the moment stay)
$PATHLAB "${args[@]}" --spp 1 --seed 99 2> "$TMP/err.k" &
pid=$!
for _ in $(seq 1 2000); do [[ "$(< "$TMP/err.k")" == *NaN/Inf* ]] && break; sleep 0.01; done
kill -KILL "$pid" 2> /dev/null; wait "$pid" 2> /dev/null
echo "note: SIGKILL while writing left: $(cd "$D" && ls | grep -E '\.tmp\.|\.pending' | tr '\n' ' ')(nothing if it fell outside the write)"
exit 0
