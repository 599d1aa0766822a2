#!/usr/bin/env bash
# tests/slurm/run.sh — `make test-slurm`: the Slurm recipe of docs/distributed.md, run for real on a
# one-node Slurm started here, then stopped.
#
#  1. installs Debian's slurm-wlm and munge (and openimageio-tools for idiff) if missing;
#  2. in a temporary folder: a munge key and munged on its own socket, a slurm.conf for this machine
#     alone (its real hostname, the CPUs slurmd -C finds, ports 16817/16818 or SLURM_TEST_PORT and
#     +1, proctrack/linuxproc, task/none: no cgroups), slurmctld and slurmd, all as the current user
#     (root) with every file in the temporary folder; nothing in /etc, /var or /run is touched;
#  3. scripts/slurm/submit.sh: the Cornell box at 64x64, 64 spp in 4 tasks of 16 (seed 7); waits for
#     the merge job; checks that every task and the merge succeeded, the pieces are deleted, and the
#     merged image and variance equal a one-process render of the same 64 samples within float
#     rounding (idiff, relative 1e-5 on the image, 1e-4 on the variance);
#  4. stopping early: 2 tasks of a long render, scancel of the array while they run: each task writes
#     the samples it reached (pathlab's SIGTERM), the afterany merge job merges them, says which
#     ranges are missing and exits 1;
#  5. stops the daemons (by the pids they wrote) and deletes the folder, also on failure or Ctrl-C.
# Prints PASS/FAIL lines and "N passed, N failed". Exit 0 all passed, 1 a check failed, 2 Slurm could
# not be started here (the daemons' own error lines are printed; docs/distributed.md).
# Environment: PATHLAB (./pathlab), SLURM_TEST_PORT (16817), KEEP=1 keeps the folder for a look.
set -eu
cd "$(dirname "$0")/../.."
PATHLAB=${PATHLAB:-./pathlab}
port=${SLURM_TEST_PORT:-16817}
passed=0 failed=0
pass() { echo "PASS $*"; passed=$((passed + 1)); }
fail() { echo "FAIL $*"; failed=$((failed + 1)); }

# --- 1. the packages -----------------------------------------------------------------------------
need=()
command -v slurmctld >/dev/null 2>&1 || need+=(slurm-wlm)
command -v munged >/dev/null 2>&1 || need+=(munge)
command -v idiff >/dev/null 2>&1 || need+=(openimageio-tools)
if [ ${#need[@]} -gt 0 ]; then
    echo "test-slurm: installing ${need[*]} (Debian packages; needs root or sudo)"
    SUDO=; [ "$(id -u)" = 0 ] || SUDO=sudo
    $SUDO apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${need[@]}" >/dev/null
fi
[ -x "$PATHLAB" ] || { echo "test-slurm: no pathlab program at $PATHLAB (make first)" >&2; exit 2; }

# --- 2. a one-node Slurm in a temporary folder ------------------------------------------------------
T=$(mktemp -d /tmp/pathlab-slurm.XXXXXX)
chmod 711 "$T"            # munged wants every folder above its socket searchable by all
stop_all() {
    local f
    for f in "$T/slurmd.pid" "$T/slurmctld.pid"; do
        [ -s "$f" ] && kill "$(cat "$f")" 2>/dev/null
    done
    # wait up to 10 s for both to exit before stopping munge (they talk to it while shutting down)
    for _ in $(seq 20); do
        alive=0
        for f in "$T/slurmd.pid" "$T/slurmctld.pid"; do
            [ -s "$f" ] && kill -0 "$(cat "$f" 2>/dev/null)" 2>/dev/null && alive=1
        done
        [ $alive = 0 ] && break
        sleep 0.5
    done
    [ -S "$T/munge/socket" ] && munged --stop --socket="$T/munge/socket" >/dev/null 2>&1
    if [ "${KEEP:-0}" = 1 ]; then echo "test-slurm: the folder is kept: $T"; else rm -rf "$T"; fi
}
trap 'stop_all' EXIT
trap 'exit 130' INT TERM
# cannot_run WHAT LOG...: Slurm could not be started here; print the daemons' errors and stop (exit 2)
cannot_run() {
    local what=$1 f; shift
    echo "test-slurm: SLURM COULD NOT RUN HERE: $what"
    for f in "$@"; do
        [ -f "$f" ] || continue
        echo "  --- the last lines of $(basename "$f"):"
        tail -n 15 "$f" | sed 's/^/    /'
    done
    echo "(see docs/distributed.md, 'Slurm in a container')"
    exit 2
}

mkdir -m 711 "$T/munge"
dd if=/dev/urandom of="$T/munge/munge.key" bs=1024 count=1 2>/dev/null
chmod 400 "$T/munge/munge.key"
munged --socket="$T/munge/socket" --key-file="$T/munge/munge.key" --pid-file="$T/munge/munged.pid" \
    --log-file="$T/munge/munged.log" --seed-file="$T/munge/munged.seed" 2> "$T/munge/start.err" \
    || cannot_run "munged did not start" "$T/munge/start.err" "$T/munge/munged.log"
munge --socket="$T/munge/socket" -n | unmunge --socket="$T/munge/socket" >/dev/null 2>&1 \
    || cannot_run "munge cannot encode and decode a credential" "$T/munge/munged.log"

host=$(hostname -s)
node=$(slurmd -C 2>/dev/null | head -n 1 | sed -e 's/ *UpTime=.*//' -e 's/RealMemory=[0-9]*/RealMemory=1000/')
case $node in NodeName=*) ;; *) node="NodeName=$host CPUs=$(nproc) RealMemory=1000" ;; esac
mkdir "$T/state" "$T/spool" "$T/log"
cat > "$T/slurm.conf" <<EOF
# a one-node Slurm for tests/slurm/run.sh; every file in $T
ClusterName=pathlab-test
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=$(id -un)
SlurmdUser=$(id -un)
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$T/munge/socket
StateSaveLocation=$T/state
SlurmdSpoolDir=$T/spool
SlurmctldPidFile=$T/slurmctld.pid
SlurmdPidFile=$T/slurmd.pid
SlurmctldLogFile=$T/log/slurmctld.log
SlurmdLogFile=$T/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
SchedulerParameters=sched_interval=2
MinJobAge=600
KillWait=30
$node NodeAddr=127.0.0.1 State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF=$T/slurm.conf
echo "test-slurm: a one-node Slurm on $host ($node), files in $T"
slurmctld -f "$SLURM_CONF" 2> "$T/log/slurmctld.err" || cannot_run "slurmctld did not start" "$T/log/slurmctld.err" "$T/log/slurmctld.log"
slurmd -f "$SLURM_CONF" 2> "$T/log/slurmd.err" || cannot_run "slurmd did not start" "$T/log/slurmd.err" "$T/log/slurmd.log"
state=
for _ in $(seq 60); do
    state=$(sinfo -h -n "$host" -o %t 2>/dev/null || true)
    [ "$state" = idle ] && break
    sleep 0.5
done
[ "$state" = idle ] || cannot_run "the node is not idle after 30 s (sinfo: '${state:-no answer}')" \
    "$T/log/slurmctld.err" "$T/log/slurmctld.log" "$T/log/slurmd.err" "$T/log/slurmd.log"
pass "a one-node Slurm runs here ($(sinfo -V), node $host idle)"

# job_state ID: the state of a job (COMPLETED, FAILED, CANCELLED, PENDING, ...)
job_state() { scontrol show job "$1" -o 2>/dev/null | grep -o 'JobState=[A-Z_]*' | head -n 1 | cut -d= -f2; }
# wait_done ID SECONDS: wait until the job has ended; prints its state
wait_done() {
    local s i
    for ((i = 0; i < $2 * 2; i++)); do
        s=$(job_state "$1")
        case $s in COMPLETED|FAILED|CANCELLED|TIMEOUT|NODE_FAIL|OUT_OF_MEMORY|BOOT_FAIL|DEADLINE|PREEMPTED) echo "$s"; return ;; esac
        sleep 0.5
    done
    echo "STILL-${s:-UNKNOWN}"
}
# exit code of a job (e.g. 0:0, 1:0)
job_exit() { scontrol show job "$1" -o 2>/dev/null | grep -o ' ExitCode=[0-9:]*' | cut -d= -f2; }

# --- 3. the recipe: 4 tasks of 16 spp, merged, against one render of 64 spp --------------------------
mkdir "$T/run"
args=(scenes/cornell.obj "$T/run/cornell.pfm" --spp 64 --pieces 4 --pathlab "$PATHLAB" --size 64x64 --seed 7)
echo "test-slurm: scripts/slurm/submit.sh ${args[*]}"
if ! scripts/slurm/submit.sh "${args[@]}" > "$T/submit.out" 2>&1; then
    sed 's/^/    /' "$T/submit.out"
    fail "submit.sh refused the job"
    echo "$passed passed, $failed failed"; exit 1
fi
sed 's/^/    /' "$T/submit.out"
read -r array merge < <(tail -n 1 "$T/submit.out")
st=$(wait_done "$merge" 180)
if [ "$st" = COMPLETED ] && [ "$(job_exit "$merge")" = 0:0 ]; then pass "the merge job ran after the array and succeeded"
else fail "the merge job: state $st, exit $(job_exit "$merge"); its log: $(tail -n 5 "$T/run/cornell.pfm.slurm/merge.log" 2>&1)"; fi
ok=1
for k in 0 1 2 3; do
    s=$(job_state "${array}_$k")
    [ "$s" = COMPLETED ] || { ok=0; fail "task ${array}_$k: $s; its log: $(cat "$T/run/cornell.pfm.slurm/task-$k.log" 2>&1)"; }
done
[ $ok = 1 ] && pass "the 4 tasks of the array completed"
n=$(grep -c ': complete$' "$T/run/cornell.pfm.slurm/merge.log" 2>/dev/null || true)
if [ "$n" = 4 ]; then pass "the merge job found the 4 pieces complete"; else fail "the merge job found $n complete pieces, not 4"; fi
left=$(find "$T/run/cornell.pfm.slurm" -type f ! -name '*.log')
if [ -z "$left" ]; then pass "the pieces are deleted after the merge (only the logs stay)"; else fail "left in the folder: $left"; fi

"$PATHLAB" render scenes/cornell.obj --spp 64 --size 64x64 --seed 7 --quiet -o "$T/one.pfm" --variance "$T/one_var.pfm"
if [ -f "$T/run/cornell.pfm" ] && [ -f "$T/run/cornell_var.pfm" ]; then
    if idiff -fail 0 -failrelative 1e-5 -warn 0 -warnrelative 1e-5 "$T/run/cornell.pfm" "$T/one.pfm" > "$T/idiff.out" 2>&1; then
        pass "the merged image equals one render of the 64 samples (idiff: every pixel within 1e-5 relative)"
    else fail "the merged image differs from one render of the 64 samples: $(tail -n 6 "$T/idiff.out")"; fi
    if idiff -fail 0 -failrelative 1e-4 -warn 0 -warnrelative 1e-4 "$T/run/cornell_var.pfm" "$T/one_var.pfm" > "$T/idiff.out" 2>&1; then
        pass "the merged variance equals the one render's (every pixel within 1e-4 relative)"
    else fail "the merged variance differs from the one render's: $(tail -n 6 "$T/idiff.out")"; fi
    s=$(awk '$1 == "samples" { print $2 }' "$T/run/cornell.pfm.meta" 2>/dev/null || true)
    if [ "$s" = "$(awk '$1 == "samples" { print $2 }' "$T/one.pfm.meta")" ]; then pass "the merged .meta gives the samples of the one render ($s)"
    else fail "the merged .meta gives samples '$s'"; fi
else
    fail "no merged image in $T/run: $(ls "$T/run")"
fi

# --- 4. stopping early: scancel while the tasks run; afterany merges what they wrote -----------------
args=(scenes/cornell.obj "$T/run/long.pfm" --spp 100000 --pieces 2 --pathlab "$PATHLAB" --size 64x64 --seed 7)
echo "test-slurm: scripts/slurm/submit.sh ${args[*]}, then scancel while the tasks run"
scripts/slurm/submit.sh "${args[@]}" > "$T/submit.out" 2>&1 || { sed 's/^/    /' "$T/submit.out"; fail "submit.sh refused the long job"; }
read -r array merge < <(tail -n 1 "$T/submit.out")
for _ in $(seq 60); do    # both tasks running, then a few seconds of samples
    [ "$(job_state "${array}_0")" = RUNNING ] && [ "$(job_state "${array}_1")" = RUNNING ] && break
    sleep 0.5
done
sleep 4
scancel "$array"
st=$(wait_done "$merge" 120)
log=$T/run/long.pfm.slurm/merge.log
sed 's/^/    /' "$log" 2>/dev/null || true
if [ "$st" = FAILED ] && [ "$(job_exit "$merge")" = 1:0 ]; then pass "after scancel, the afterany merge job ran and exited 1 (incomplete)"
else fail "after scancel, the merge job: state $st, exit $(job_exit "$merge")"; fi
n=$(grep -c 'stopped early' "$log" 2>/dev/null || true)
if [ "$n" = 2 ]; then pass "each cancelled task wrote the samples it had reached (2 pieces 'stopped early')"
else fail "$n pieces stopped early, not 2; the task logs: $(cat "$T"/run/long.pfm.slurm/task-*.log 2>&1 | tail -n 8)"; fi
if [ -f "$T/run/long.pfm" ] && grep -q 'WITHOUT the samples' "$log"; then pass "the partial merge is written and names the missing ranges"
else fail "no partial merge, or the missing ranges not named"; fi

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
