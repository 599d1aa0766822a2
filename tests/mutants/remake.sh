#!/usr/bin/env bash
# tests/mutants/remake.sh — (re)writes a mutant's patch, tests/mutants/NAME.patch, from an edited copy
# of the source file; for a patch that no longer applies (the code it edits has changed), or a new one.
#
#   tests/mutants/remake.sh NAME                 step 1 for a stale patch: copies the file it edits to
#                                                /tmp/mutant-NAME/, tries the old patch there with
#                                                some fuzz, shows the old change and where its line
#                                                is now; check or edit that copy, then step 2
#   tests/mutants/remake.sh NAME COPY [SRCFILE]  step 2 (or a new mutant): writes NAME.patch, the
#                                                diff from SRCFILE (src/..., default: the file the old
#                                                patch edits; give it when the code moved to another
#                                                file) to COPY, keeping the old patch's header lines
#                                                (what it breaks, Test:, Env:), and checks that it
#                                                applies to the tree
#
# A new mutant: step 2 writes a header to fill in (its first line says what the bug breaks in a
# student's words; Test: and Env: as in its line of tests/mutants/list.sh, which you add). Then run
# it: tests/mutants/run.sh NAME must say "caught". The tree itself is never changed.
set -u
. "$(dirname "$0")/lib.sh"
[ $# -ge 1 ] && [ $# -le 3 ] || { sed -n '4,15s/^# \{0,1\}//p' "$0" >&2; exit 2; }
name=$1; pf=$(patch_file "$name")

if [ $# -eq 1 ]; then   # step 1
    [ -f "$pf" ] || { echo "no tests/mutants/$name.patch: for a new mutant, edit a copy of the file and run: $0 $name COPY SRCFILE" >&2; exit 2; }
    if why=$(patch_applies "$name" "$ROOT"); then echo "tests/mutants/$name.patch still applies cleanly: nothing to remake"; exit 0; fi
    echo "tests/mutants/$name.patch does not apply cleanly:"; echo "$why"
    src=$(patch_src "$name" | head -n 1)
    d=${TMPDIR:-/tmp}/mutant-$name; rm -rf "$d"; mkdir -p "$d"
    echo; echo "the old change (- the line it replaced, + the bug):"
    sed -n '/^@@/,$p' "$pf" | grep '^[-+]' | grep -v '^\(---\|+++\) ' | sed 's/^/    /'
    echo; echo "where the replaced line is now in src/ (fixed-string search, spaces trimmed):"
    sed -n '/^@@/,$p' "$pf" | grep '^-' | grep -v '^--- ' | sed 's/^-[[:space:]]*//' | while IFS= read -r l; do
        [ -n "$l" ] && (cd "$ROOT" && grep -rnF -- "$l" src/ | head -n 5 | sed 's/^/    /')
    done
    if [ ! -f "$ROOT/$src" ]; then
        echo; echo "$src is gone (moved?): copy the file that now holds that code, edit it, then run: $0 $name COPY SRCFILE"; exit 1
    fi
    copy=$d/$(basename "$src"); cp "$ROOT/$src" "$copy"
    echo
    if patch --batch --fuzz=3 --no-backup-if-mismatch -s "$copy" < "$pf" > "$d/patch.log" 2>&1; then
        echo "the old patch applies to a copy with fuzz; check that it breaks what it should:"
        diff -u "$ROOT/$src" "$copy" | sed 's/^/    /'
    else
        cp "$ROOT/$src" "$copy"
        echo "the old patch does not apply even with fuzz: make the same change by hand in $copy"
    fi
    rm -f "$copy.rej" "$copy.orig"
    echo; echo "then write the patch: $0 $name $copy${src:+ $src}"
    exit 1
fi

# step 2
copy=$2; src=${3:-}
if [ -z "$src" ]; then
    [ -f "$pf" ] || { echo "a new mutant needs SRCFILE: $0 $name COPY src/LAYER/FILE.c" >&2; exit 2; }
    src=$(patch_src "$name")
    [ "$(echo "$src" | wc -l)" -eq 1 ] || { echo "$name.patch edits several files; give SRCFILE and remake it per file by hand" >&2; exit 2; }
fi
src=${src#./}; src=${src#"$ROOT"/}
[ -f "$ROOT/$src" ] || { echo "no file $src in $ROOT" >&2; exit 2; }
[ -f "$copy" ] || { echo "no file $copy" >&2; exit 2; }
if cmp -s "$ROOT/$src" "$copy"; then echo "$copy is the same as $src: edit it first (put the bug in)" >&2; exit 1; fi
tmp=$(mktemp)
if [ -f "$pf" ]; then
    sed -n '/^--- /q; p' "$pf" > "$tmp"
else
    i=$(mutant_index "$name") && t=${M_TEST[i]} && e=${M_ENV[i]} || { t="TEST (a tests/run.sh filter)"; e="- (or VAR=value)"; }
    printf 'Mutant %s: WHAT IT BREAKS, in a student'"'"'s words.\nTest: %s\nEnv: %s\n\n' "$name" "$t" "$e" > "$tmp"
fi
diff -u --label "a/$src" --label "b/$src" "$ROOT/$src" "$copy" >> "$tmp"
mv "$tmp" "$pf"
echo "wrote tests/mutants/$name.patch:"; sed 's/^/    /' "$pf"
if ! why=$(patch_applies "$name" "$ROOT"); then echo "FAIL: it does not apply to the tree:"; echo "$why"; exit 1; fi
mutant_index "$name" > /dev/null || echo "now add its line to tests/mutants/list.sh and fill in its header"
echo "it applies; now check that a test catches it: tests/mutants/run.sh $name"
