#!/usr/bin/env bash
# scripts/parallel-render.sh — one render split into pieces run by GNU parallel, on this machine or
# on several machines over ssh, then merged into one image (docs/distributed.md).
#
#   scripts/parallel-render.sh SCENE.obj OUT.pfm --spp N [options] [render flags]
#
# The N samples per pixel are cut into PIECES disjoint ranges 0:a, a:b, ... :N; piece k renders
#   pathlab render SCENE.obj --samples A:B -o DIR/piece-k.pfm --variance DIR/var-k.pfm [render flags]
# GNU parallel runs the pieces, and `pathlab merge` combines them into OUT.pfm and OUT_var.pfm (the
# variance of each pixel's mean, which `pathlab grade` finds beside a reference). Since the random
# numbers of sample i of pixel p depend only on (seed, p, i), OUT.pfm equals, within float rounding,
# one render with --spp N and the same seed: the pieces are pieces of that render, not independent
# renders averaged.
#
# Options:
#   --pieces J       number of pieces (default: 4)
#   -j, --jobs P     pieces run at once on each machine (default: its number of cores)
#   -S, --sshlogin LOGINS   run on these machines (GNU parallel's syntax: "pc1,pc2,4/pc3,:" where
#                    ":" is this machine and "4/" caps a machine at 4 pieces at once); repeatable
#   --sshloginfile FILE     the same, one machine per line
#   --pathlab PROG   the pathlab program (default: ./pathlab)
#   --retries R      run a failed piece again up to R times, on any machine (default: 0)
#   --keep           keep the pieces folder (OUT.pfm.pieces/) after a successful merge
#   --dry-run        print the pieces and the commands, run nothing
# Render flags (after SCENE and OUT) are given to every piece (--size, --seed, --bounces, --direct, ...);
# each piece uses --threads 1 unless you give --threads.
#
# Several machines: this script assumes the SAME PATHS everywhere (the usual lab with the home folders
# on a shared file system, or a copy at the same path: see docs/distributed.md): the pathlab program,
# the scene (with its .mtl and .view) and the folder of OUT are read and written under the same names
# on every machine; nothing is transferred. Machines need ssh without a password (ssh-copy-id) and
# perl (GNU parallel runs a small perl program remotely). PARALLEL_SSH changes the ssh command, e.g.
# PARALLEL_SSH="ssh -p 2222 -i ~/.ssh/lab_key".
#
# If a piece fails, nothing is merged: the pieces folder is kept and the script prints how to render
# the missing range and merge by hand. Interrupting the script (Ctrl-C) stops the pieces, each of which
# writes what it has reached (pathlab's first SIGINT); they are kept too, to be merged as they are.
# Exit status: 0 merged; 1 a piece or the merge failed; 2 bad usage.
set -eu

die() { echo "parallel-render: $*" >&2; exit 2; }
. "$(dirname "$0")/pieces.sh"

pieces=4 jobs='' pathlab=./pathlab retries=0 keep=0 dry=0 spp=''
logins=() hosts=() pos=() flags=()
# This script's options may come anywhere; --spp N too; the first two words that are not flags are
# SCENE and OUT; everything else is a render flag given to every piece.
while [ $# -gt 0 ]; do
    case $1 in
        --pieces) [ $# -ge 2 ] || usage; pieces=$2; shift 2 ;;
        -j|--jobs) [ $# -ge 2 ] || usage; jobs=$2; shift 2 ;;
        -S|--sshlogin) [ $# -ge 2 ] || usage; logins+=(-S "$2"); hosts+=("$2"); shift 2 ;;
        --sshloginfile) [ $# -ge 2 ] || usage; logins+=(--sshloginfile "$2"); hosts+=("the machines of $2"); shift 2 ;;
        --retries) [ $# -ge 2 ] || usage; retries=$2; shift 2 ;;
        *) pieces_option "$@"; shift "$used" ;;
    esac
done
pieces_words_done
case $retries in ''|*[!0-9]*) die "--retries must be a whole number, not '$retries'" ;; esac
case $out in *.pfm) ;; *) die "the output must be a .pfm file (linear float, what merge writes), not '$out'" ;; esac
command -v parallel >/dev/null 2>&1 || die "GNU parallel is not installed: apt-get install parallel (Debian/Ubuntu)"
pieces_inputs_check
threads=(--threads 1)
for f in "${flags[@]+"${flags[@]}"}"; do
    case $f in
        --threads) threads=() ;;
        --spp|--samples|-o|--variance|--resume) die "$f is set by this script for each piece; leave it out of the render flags" ;;
    esac
done

outvar=${out%.pfm}_var.pfm
dir=$out.pieces
[ -e "$dir" ] && die "$dir already exists (pieces of an earlier run?): merge them with 'pathlab merge', or delete the folder"

# The pieces: k, first sample, end sample (k*N/J rounded down, so sizes differ by at most one).
ranges=()
for ((k = 0; k < pieces; k++)); do
    ranges+=("$k $(piece_first "$k" "$spp" "$pieces") $(piece_end "$k" "$spp" "$pieces")")
done

echo "parallel-render: $scene, $spp samples per pixel in $pieces pieces: ${flags[*]+${flags[*]}}"
for r in "${ranges[@]}"; do
    read -r k a b <<< "$r"
    echo "  piece $k: samples $a:$b -> $dir/piece-$k.pfm"
done
where="this machine"
[ ${#hosts[@]} -gt 0 ] && where=$(IFS=,; echo "${hosts[*]}")
echo "  run by GNU parallel on $where${jobs:+, $jobs at a time per machine}; then: $pathlab merge $out $dir/piece-*.pfm --variance $outvar"
if [ $dry = 1 ]; then echo "(dry run: nothing run)"; exit 0; fi

mkdir "$dir"
# On other machines, absolute paths: a remote shell starts in the home folder, not here. On this
# machine the names as given (the scene's name goes into each piece's sidecar and the merged one).
prog=$pathlab scn=$scene adir=$dir
if [ ${#logins[@]} -gt 0 ]; then
    prog=$(abs "$pathlab") scn=$(abs "$scene") adir=$(abs "$dir")
fi

# -q quotes every word of the command (paths with spaces stay whole, locally and over ssh);
# --colsep splits each input line "k A B" into {1} {2} {3}; --joblog records each piece's machine,
# time and exit status; --halt soon,fail=1 stops starting new pieces once one has failed for good.
# --termseq: on Ctrl-C, GNU parallel sends each running piece ONE SIGINT (pathlab then finishes its
# pass and writes the samples reached) and SIGKILL only 30 s later; its default (TERM twice within
# 200 ms) would make pathlab stop at once without writing anything. --retries only if asked: GNU
# parallel 20221122 (Debian 12) given "--retries 0" with --halt never ends once a piece has failed.
retry=()
[ "$retries" -gt 0 ] && retry=(--retries "$retries")
set +e
printf '%s\n' "${ranges[@]}" | parallel -q --colsep ' ' --joblog "$adir/joblog" --termseq INT,30000,KILL,25 \
    --halt soon,fail=1 "${retry[@]+"${retry[@]}"}" ${jobs:+--jobs "$jobs"} "${logins[@]+"${logins[@]}"}" \
    --tagstring 'piece {1}' \
    "$prog" render "$scn" --samples '{2}:{3}' -o "$adir/piece-{1}.pfm" --variance "$adir/var-{1}.pfm" \
    --quiet "${threads[@]+"${threads[@]}"}" "${flags[@]+"${flags[@]}"}"
rc=$?
set -e

echo "parallel-render: the pieces (GNU parallel's job log):"
awk -F'\t' 'NR > 1 { host = ($2 == ":" ? "this machine" : $2)
                     printf "  piece %d on %s: %.1f s, exit status %s%s\n", $1 - 1, host, $4, $7, ($8 ? ", signal " $8 : "") }' \
    "$adir/joblog" | sort -k2,2n || true
if [ "$rc" -ne 0 ] && ! ls "$dir"/piece-*.pfm >/dev/null 2>&1; then
    rm -r "$dir"
    echo "parallel-render: GNU parallel exit status $rc: no piece was written (the messages above say why); nothing merged." >&2
    exit 1
fi
if [ "$rc" -ne 0 ]; then
    echo "parallel-render: GNU parallel exit status $rc: a piece failed or was stopped; nothing merged. The pieces are kept in $dir/." >&2
    echo "  A piece stopped early wrote what it reached (its .meta has its sample range); a missing range can be" >&2
    echo "  rendered again with: $pathlab render $scene --samples A:B -o $dir/piece-K.pfm --variance $dir/var-K.pfm ${flags[*]+${flags[*]}}" >&2
    echo "  then merged with:    $pathlab merge $out $dir/piece-*.pfm --variance $outvar   (and: rm -r $dir)" >&2
    exit 1
fi

inputs=()
for ((k = 0; k < pieces; k++)); do inputs+=("$dir/piece-$k.pfm"); done
echo "parallel-render: merging: $pathlab merge $out ${inputs[*]} --variance $outvar"
if ! "$pathlab" merge "$out" "${inputs[@]}" --variance "$outvar"; then
    echo "parallel-render: the merge failed; the pieces are kept in $dir/" >&2
    exit 1
fi
if [ $keep = 1 ]; then
    echo "parallel-render: $out and $outvar written; the pieces are kept in $dir/"
else
    rm -r "$dir"
    echo "parallel-render: $out and $outvar written (the pieces are deleted; --keep keeps them)"
fi
