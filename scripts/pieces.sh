# scripts/pieces.sh — sourced by parallel-render.sh and slurm/submit.sh: the checks on --spp and
# --pieces, and the sample range of piece k. Piece k of J renders samples k*N/J to (k+1)*N/J - 1
# (rounded down: sizes differ by at most one); the callers define die().

# pieces_check N J: both whole numbers, 1 <= J <= N (no empty piece)
pieces_check() {
    case $1 in ''|*[!0-9]*) die "--spp must be a positive whole number, not '$1'" ;; esac
    case $2 in ''|*[!0-9]*) die "--pieces must be a positive whole number, not '$2'" ;; esac
    [ "$1" -ge 1 ] || die "--spp must be at least 1"
    [ "$2" -ge 1 ] || die "--pieces must be at least 1"
    [ "$2" -le "$1" ] || die "$2 pieces of $1 samples: some would be empty; use at most --pieces $1"
}

# piece_first K N J, piece_end K N J: the first sample of piece K, and the one after its last
piece_first() { echo $(($1 * $2 / $3)); }
piece_end() { echo $((($1 + 1) * $2 / $3)); }

# The callers' option loops share their words and their end: the first two words that are not flags
# are SCENE and OUT (into pos[]), every other word or unknown flag is a render flag (into flags[]).
pieces_word() { if [ ${#pos[@]} -lt 2 ] && [ ${#flags[@]} -eq 0 ]; then pos+=("$1"); else flags+=("$1"); fi; }
pieces_words_done() {
    [ ${#pos[@]} -eq 2 ] || usage
    scene=${pos[0]} out=${pos[1]}
    [ -n "$spp" ] || die "give the samples per pixel: --spp N"
    pieces_check "$spp" "$pieces"
}
