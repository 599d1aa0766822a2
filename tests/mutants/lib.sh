#!/usr/bin/env bash
# tests/mutants/lib.sh — helpers shared by tests/mutants/run.sh and tests/mutants/bug_images.sh:
# a private copy of the working tree (never the repository itself: src/ is not touched) and the
# mutants of tests/mutants/list.sh applied to copies of that copy.
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
MUT_N=0
# shellcheck disable=SC2034  # the arrays are read by run.sh and bug_images.sh
M_NAME=(); M_FILE=(); M_SED=(); M_TEST=(); M_ENV=(); M_WHAT=()
# mutant NAME FILE SED TEST ENV WHAT: records one mutant (called by list.sh)
mutant() {
    M_NAME[MUT_N]=$1; M_FILE[MUT_N]=$2; M_SED[MUT_N]=$3; M_TEST[MUT_N]=$4; M_ENV[MUT_N]=$5; M_WHAT[MUT_N]=$6
    MUT_N=$((MUT_N + 1))
}
# shellcheck source=list.sh
. "$ROOT/tests/mutants/list.sh"

# mutant_index NAME: prints the index of mutant NAME, or fails
mutant_index() {
    local i
    for ((i = 0; i < MUT_N; i++)); do [ "${M_NAME[i]}" = "$1" ] && { echo "$i"; return 0; }; done
    return 1
}

# copy_tree DEST: copies the working tree's src/ tests/ scenes/ ref/ Makefile (uncommitted work
# included, which `git archive` would miss) into the new folder DEST
copy_tree() {
    mkdir -p "$1" && (cd "$ROOT" && cp -r src tests scenes ref web tools Makefile "$1/")
}

# build_in DIR TARGETS...: builds there quietly (warnings of a mutant are expected: an unused
# variable); prints the compiler's output and fails if the build fails
build_in() {
    local dir=$1; shift
    if ! (cd "$dir" && nice -n 10 make -s -j2 "$@" > .build.log 2>&1); then
        tail -n 20 "$dir/.build.log" >&2
        return 1
    fi
}

# apply_mutant I BASE DEST: copies BASE (with its build, timestamps kept so that make rebuilds
# only what the mutation touches) to DEST and applies mutant I there; fails if the sed script
# did not change the file (the code it targets has moved: the mutant is stale)
apply_mutant() {
    local i=$1 base=$2 dest=$3 f before after
    rm -rf "$dest" && cp -a "$base" "$dest" || return 1
    f="$dest/${M_FILE[i]}"
    [ -f "$f" ] || return 1
    before=$(cksum < "$f")
    sed -i -e "${M_SED[i]}" "$f" || return 1
    after=$(cksum < "$f")
    [ "$before" != "$after" ]
}

# test_targets TEST: the make targets a tests/run.sh filter needs (the program, the test tools,
# and the C test of that name if there is one)
test_targets() {
    local t="pathlab build/tests/zcheck build/tests/pfmtool"
    [ -f "$ROOT/tests/$1.c" ] && t="$t build/tests/$1"
    echo "$t"
}
