# scripts/pieces.sh — sourced by parallel-render.sh and slurm/submit.sh: their usage, the options
# they share, the checks on --spp, --pieces and the inputs, and the sample range of piece k. Piece k
# of J renders samples k*N/J to (k+1)*N/J - 1 (rounded down: sizes differ by at most one); the
# callers define die().

# usage: the caller's help, its comment block from line 2 to `set -eu`; exit 2
usage() {
    sed -n '2,/^set -eu/p' "$0" | sed -e '/^set -eu/d' -e 's/^# \{0,1\}//' >&2
    exit 2
}

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

# The callers' option loops end alike. pieces_option ARGS... takes the options both have (--spp N,
# --pathlab PROG, --keep, --dry-run, -h/--help) and what is not an option of theirs: the first two
# words that are not flags are SCENE and OUT (into pos[]), every other word or unknown flag is a
# render flag (into flags[]). It sets used to the number of words taken, for the caller's shift.
pieces_option() {
    used=1
    case $1 in
        --spp) [ $# -ge 2 ] || usage; spp=$2; used=2 ;;
        --pathlab) [ $# -ge 2 ] || usage; pathlab=$2; used=2 ;;
        --keep) keep=1 ;;
        --dry-run) dry=1 ;;
        -h|--help) usage ;;
        -*) flags+=("$1") ;;
        *) if [ ${#pos[@]} -lt 2 ] && [ ${#flags[@]} -eq 0 ]; then pos+=("$1"); else flags+=("$1"); fi ;;
    esac
}
pieces_words_done() {
    [ ${#pos[@]} -eq 2 ] || usage
    scene=${pos[0]} out=${pos[1]}
    [ -n "$spp" ] || die "give the samples per pixel: --spp N"
    pieces_check "$spp" "$pieces"
}

# pieces_inputs_check: the program runs and the scene is there
pieces_inputs_check() {
    [ -x "$pathlab" ] || die "no pathlab program at '$pathlab' (run make, or give --pathlab PROG)"
    [ -f "$scene" ] || die "no scene '$scene'"
}

# abs PATH: PATH from /, for a machine or a job that does not start in this folder
abs() { case $1 in /*) printf '%s\n' "$1" ;; *) printf '%s\n' "$PWD/${1#./}" ;; esac; }
