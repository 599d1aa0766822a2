#!/usr/bin/env bash
# tests/mutants/lib.sh — helpers shared by tests/mutants/run.sh, bug_images.sh and remake.sh: a
# private copy of the working tree (never the repository itself: src/ is not touched) and the
# mutants of tests/mutants/list.sh (each a patch, tests/mutants/NAME.patch) applied to copies of it.
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
MDIR=$ROOT/tests/mutants
MUT_N=0
# shellcheck disable=SC2034  # the arrays are read by run.sh and bug_images.sh
M_NAME=(); M_TEST=(); M_ENV=(); M_WHAT=()
# mutant NAME TEST ENV: records one mutant (called by list.sh); WHAT is the first line of its patch
mutant() {
    M_NAME[MUT_N]=$1; M_TEST[MUT_N]=$2; M_ENV[MUT_N]=$3
    M_WHAT[MUT_N]=$(patch_what "$1")
    MUT_N=$((MUT_N + 1))
}
# patch_file NAME: the patch of mutant NAME
patch_file() { echo "$MDIR/$1.patch"; }
# patch_what NAME: what the mutant breaks (its patch's first line, "Mutant NAME: " removed)
patch_what() { [ -f "$(patch_file "$1")" ] && sed -n '1s/^Mutant [^:]*: *//p' "$(patch_file "$1")"; }
# patch_field NAME FIELD: the value of the header line "FIELD: value" (Test, Env) of its patch
patch_field() { sed -n "/^--- /q; s/^$2: *//p" "$(patch_file "$1")" | head -n 1; }
# patch_src NAME: the files (src/...) the patch edits, one a line
patch_src() { sed -n 's|^+++ b/\([^[:space:]]*\).*|\1|p' "$(patch_file "$1")"; }
# shellcheck source=list.sh
. "$MDIR/list.sh"

# mutant_index NAME: prints the index of mutant NAME, or fails
mutant_index() {
    local i
    for ((i = 0; i < MUT_N; i++)); do [ "${M_NAME[i]}" = "$1" ] && { echo "$i"; return 0; }; done
    return 1
}

# list_problems: prints one line per disagreement between list.sh and the patches (a listed mutant
# without a patch or whose header's Test/Env differ, a patch that list.sh does not run); none: fine
list_problems() {
    local i n p
    for ((i = 0; i < MUT_N; i++)); do
        n=${M_NAME[i]}
        if [ ! -f "$(patch_file "$n")" ]; then echo "mutant $n: tests/mutants/$n.patch is missing"; continue; fi
        [ -n "${M_WHAT[i]}" ] || echo "mutant $n: its patch's first line is not 'Mutant $n: what it breaks'"
        [ "$(patch_field "$n" Test)" = "${M_TEST[i]}" ] ||
            echo "mutant $n: its patch says 'Test: $(patch_field "$n" Test)', list.sh says ${M_TEST[i]}"
        [ "$(patch_field "$n" Env)" = "${M_ENV[i]}" ] ||
            echo "mutant $n: its patch says 'Env: $(patch_field "$n" Env)', list.sh says ${M_ENV[i]}"
    done
    for p in "$MDIR"/*.patch; do
        [ -e "$p" ] || continue
        n=$(basename "$p" .patch)
        mutant_index "$n" > /dev/null || echo "tests/mutants/$n.patch is not in tests/mutants/list.sh: it would never run"
    done
}

# copy_tree DEST: copies the working tree's src/ tests/ scenes/ ref/ web/ tools/ Makefile (uncommitted
# work included, which `git archive` would miss) into the new folder DEST, and its default build
# build/ and ./pathlab if there are any, timestamps kept (cp -a): make then rebuilds only what is out
# of date there (what changed since that build) instead of everything
copy_tree() {
    mkdir -p "$1" && (cd "$ROOT" && cp -a src tests scenes ref web tools Makefile "$1/") || return 1
    if [ -d "$ROOT/build" ]; then cp -a "$ROOT/build" "$1/" || return 1; fi
    if [ -f "$ROOT/pathlab" ]; then cp -a "$ROOT/pathlab" "$1/" || return 1; fi
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

# patch_applies NAME DIR: 0 if NAME.patch applies cleanly to the tree in DIR (a dry run: DIR is not
# changed; no fuzz, so a hunk whose context has changed fails rather than landing elsewhere);
# otherwise prints patch's complaint
patch_applies() {
    local out
    out=$(cd "$2" && patch -p1 --dry-run --batch --fuzz=0 < "$(patch_file "$1")" 2>&1) && return 0
    echo "$out" | grep -v '^checking file' | sed 's/^/      /'
    return 1
}

# apply_mutant I BASE DEST: copies BASE (with its build, timestamps kept so that make rebuilds
# only what the mutation touches) to DEST and applies the patch of mutant I there; fails if it
# does not apply cleanly (the code it edits has changed: the patch is stale, remake.sh remakes it)
apply_mutant() {
    local n=${M_NAME[$1]} base=$2 dest=$3
    rm -rf "$dest" && cp -a "$base" "$dest" || return 1
    (cd "$dest" && patch -p1 --batch --fuzz=0 --no-backup-if-mismatch -s < "$(patch_file "$n")") > /dev/null
}

# stale_hint NAME: how to remake a patch that no longer applies
stale_hint() {
    echo "      the code it edits has changed; remake the patch: tests/mutants/remake.sh $1  (it says what to do)"
}

# test_targets TEST: the make targets a tests/run.sh filter needs (the program, the test tools,
# and the C test of that name if there is one)
test_targets() {
    local t="pathlab build/tests/zcheck build/tests/pfmtool"
    [ -f "$ROOT/tests/$1.c" ] && t="$t build/tests/$1"
    echo "$t"
}
