#!/usr/bin/env bash
# scripts/slurm/submit.sh — submits a render split into pieces to Slurm: a job array (one task per
# sample range, scripts/slurm/render-piece.sbatch) and a merge job that runs after it
# (scripts/slurm/merge.sbatch). See docs/distributed.md.
#
#   scripts/slurm/submit.sh SCENE.obj OUT.pfm --spp N [options] [render flags]
#
# Options:
#   --pieces J      number of tasks, each one sample range (default: 8)
#   --cpus C        CPUs (pathlab threads) per task (default: 1)
#   --time-limit T  time limit of each task, in sbatch's format: 30, 2:00:00, 1-00:00:00 (default: the
#                   partition's). A task that reaches it writes the samples it has reached.
#   --pathlab PROG  the pathlab program (default: ./pathlab)
#   --afterok       run the merge only if every task succeeded (default: afterany, merge what was written)
#   --keep          keep the pieces after a complete merge
#   --dry-run       print the two sbatch commands, submit nothing
# Any other sbatch setting comes from sbatch's environment variables, e.g.
#   SBATCH_PARTITION=short SBATCH_ACCOUNT=course42 scripts/slurm/submit.sh ...
# Render flags (after SCENE and OUT) go to every task (--size, --seed, --bounces, --direct, ...).
#
# The cluster's nodes must see the same files at the same paths (the usual shared home or project file
# system): the tasks start in the folder you submit from; the program and OUT are given to them as
# absolute paths. Everything the jobs
# write goes into OUT.slurm/ (the pieces, task-K.log, merge.log) and OUT.pfm, OUT_var.pfm (+ .meta).
# Prints the two job ids and how to follow them; the last line is "ARRAY_ID MERGE_ID".
set -eu
here=$(cd "$(dirname "$0")" && pwd)

die() { echo "submit: $*" >&2; exit 2; }
. "$here/../pieces.sh"

pieces=8 cpus=1 time='' pathlab=./pathlab dep=afterany keep=0 dry=0 spp=''
pos=() flags=()
# This script's options may come anywhere; --spp N too; the first two words that are not flags are
# SCENE and OUT; everything else is a render flag given to every task.
while [ $# -gt 0 ]; do
    case $1 in
        --pieces) [ $# -ge 2 ] || usage; pieces=$2; shift 2 ;;
        --cpus) [ $# -ge 2 ] || usage; cpus=$2; shift 2 ;;
        --time-limit) [ $# -ge 2 ] || usage; time=$2; shift 2 ;;
        --afterok) dep=afterok; shift ;;
        *) pieces_option "$@"; shift "$used" ;;
    esac
done
pieces_words_done
case $cpus in ''|*[!0-9]*) die "--cpus must be a positive whole number, not '$cpus'" ;; esac
[ "$cpus" -ge 1 ] || die "--cpus must be at least 1"
case $out in *.pfm) ;; *) die "the output must be a .pfm file (linear float, what merge writes), not '$out'" ;; esac
for f in "${flags[@]+"${flags[@]}"}"; do
    case $f in
        --threads) die "--threads is set from --cpus (Slurm's --cpus-per-task); leave it out" ;;
        --spp|--samples|-o|--variance|--resume) die "$f is set for each task; leave it out of the render flags" ;;
    esac
done
[ $dry = 1 ] || command -v sbatch >/dev/null 2>&1 || die "sbatch not found: run this on a Slurm login node"
pieces_inputs_check

# the tasks start in this folder (--chdir), so the scene keeps the name given (it goes into the sidecars)
prog=$(abs "$pathlab") scn=$scene aout=$(abs "$out")
dir=$aout.slurm
[ -e "$dir" ] && die "$dir already exists (an earlier run?): look at it, then delete it or choose another output name"

array_cmd=(sbatch --parsable --array="0-$((pieces - 1))" --cpus-per-task="$cpus" ${time:+--time="$time"}
    --output="$dir/task-%a.log" --chdir="$PWD"
    "$here/render-piece.sbatch" "$prog" "$scn" "$dir" "$spp" "$pieces" "${flags[@]+"${flags[@]}"}")
merge_cmd=(sbatch --parsable --dependency="$dep:ARRAY_ID" --kill-on-invalid-dep=yes --time=15
    --output="$dir/merge.log" --chdir="$PWD" --export="ALL,KEEP_PIECES=$keep"
    "$here/merge.sbatch" "$prog" "$scn" "$dir" "$spp" "$pieces" "$aout" "${flags[@]+"${flags[@]}"}")

echo "submit: $scene, $spp samples per pixel in $pieces tasks of $cpus CPU(s), merged into $out (files in $dir/)"
for ((k = 0; k < pieces; k++)); do
    printf '  task %d: samples %d:%d\n' "$k" "$(piece_first "$k" "$spp" "$pieces")" "$(piece_end "$k" "$spp" "$pieces")"
done
if [ $dry = 1 ]; then
    echo "  ${array_cmd[*]}"
    echo "  ${merge_cmd[*]}"
    echo "(dry run: nothing submitted)"
    exit 0
fi

mkdir -p "$dir"
array=$("${array_cmd[@]}") || { rmdir "$dir"; die "sbatch refused the job array (message above)"; }
array=${array%%;*}
merge_cmd[3]=--dependency=$dep:$array
if ! merge=$("${merge_cmd[@]}"); then
    scancel "$array" || true
    die "sbatch refused the merge job (message above); the array $array is cancelled; delete $dir"
fi
merge=${merge%%;*}
echo "submit: job array $array (tasks ${array}_0 .. ${array}_$((pieces - 1))), merge job $merge ($dep:$array)"
echo "  follow:  squeue -j $array,$merge     logs: $dir/task-K.log, $dir/merge.log"
echo "  stop early and keep what is done: scancel $array   (each task writes the samples it reached; the merge merges them)"
echo "  cancel everything:                scancel $array $merge"
echo "$array $merge"
