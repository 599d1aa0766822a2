#!/usr/bin/env bash
# tests/test_exports.sh — no exported function that nobody calls. Every global function defined in
# src/ (the "T" symbols of $BUILD/LAYER/NAME.o, listed by nm) must be referenced (a "U" symbol) by
# another object: another file of src/, a test or tool of tests/ (tests/*.c, tests/fuzz/*.c) or
# bench/plot.c. A function nobody calls is dead code (remove it); one called only inside its own
# file must be static (then the compiler warns if it becomes unused). main is the one exception.
# The test and bench sources are compiled here at -O0 (objects in a temporary folder, a few
# seconds), so the check needs nothing beyond the build of make test, in any build folder
# (BUILD=build-san works: the sanitizers only add references to their own functions).
# A negative self-check plants an unused function, a function called only by its own file and a
# function called by another object, and wants the first two reported and the third not.
. "$(dirname "$0")/lib.sh"
cd "$(dirname "$0")/.."
CC=${CC:-cc}
CFLAGS_T="-std=c99 -D_POSIX_C_SOURCE=200809L -O0 -w -Isrc -Itests/fuzz"

# unused_exports DEFS REFS: prints, sorted, the global functions defined (T) in the objects listed in
# the file DEFS and referenced (U) by none of the objects of DEFS and REFS (one path a line each)
unused_exports() {
    local defs=$1 refs=$2
    # shellcheck disable=SC2046
    nm -A --defined-only $(cat "$defs") 2> /dev/null | awk '$2 == "T" { print $3 }' | sort -u > "$TMP/defined"
    # shellcheck disable=SC2046
    nm -A --undefined-only $(cat "$defs" "$refs") 2> /dev/null | awk '{ print $NF }' | sort -u > "$TMP/used"
    comm -23 "$TMP/defined" "$TMP/used" | grep -vx 'main'
}

command -v nm > /dev/null 2>&1 || { fail "exports: nm (binutils) is missing: cannot list the symbols"; exit 0; }
# the objects of src/ in this build, and the callers outside src/ compiled here
# (an object whose source is gone, left in an old build folder, is not read: it would define
# functions nothing calls any more)
for o in "$BUILD"/*/*.o; do
    c=src/${o#"$BUILD"/}; c=${c%.o}.c
    [ -f "$c" ] && echo "$o"
done > "$TMP/defs"
if [ ! -s "$TMP/defs" ]; then fail "exports: no objects in $BUILD/*/ (run make first)"; exit 0; fi
mkdir -p "$TMP/obj"; : > "$TMP/refs"; bad=
for c in tests/*.c tests/fuzz/*.c bench/plot.c; do
    o=$TMP/obj/$(echo "$c" | tr / _).o
    # shellcheck disable=SC2086
    $CC $CFLAGS_T -c -o "$o" "$c" 2> "$TMP/cc.err" || { bad="$bad $c"; continue; }
    echo "$o" >> "$TMP/refs"
done
if [ -n "$bad" ]; then fail "exports: could not compile$bad to read what they call: $(head -c 300 "$TMP/cc.err")"; exit 0; fi

# negative self-check: the analysis must see a planted unused export and a file-only one, and must
# not report a function that another object calls
cat > "$TMP/planted.c" << 'EOF'
int planted_unused_export(void);
int planted_file_only(void);
int planted_called(void);
int planted_unused_export(void) { return 1; }
int planted_file_only(void) { return 2; }
int planted_called(void) { return planted_file_only(); }
EOF
printf 'int planted_called(void);\nint planted_caller(void);\nint planted_caller(void) { return planted_called(); }\n' > "$TMP/caller.c"
if $CC $CFLAGS_T -c -o "$TMP/planted.o" "$TMP/planted.c" && $CC $CFLAGS_T -c -o "$TMP/caller.o" "$TMP/caller.c"; then
    { cat "$TMP/defs"; echo "$TMP/planted.o"; } > "$TMP/defs_planted"
    { cat "$TMP/refs"; echo "$TMP/caller.o"; } > "$TMP/refs_planted"
    got=$(unused_exports "$TMP/defs_planted" "$TMP/refs_planted" | grep '^planted_' | tr '\n' ' ')
    # planted_file_only is called, but only inside planted.o: nm shows no U for it anywhere
    if [ "$got" = "planted_file_only planted_unused_export " ]; then
        pass "exports: the check finds a planted unused function and a file-only one, not a called one"
    else
        fail "exports: the self-check is broken: planted functions reported: '$got' (wanted planted_file_only planted_unused_export)"
    fi
else
    fail "exports: could not compile the self-check's planted files"
fi

n_def=$(nm --defined-only $(cat "$TMP/defs") 2> /dev/null | awk '$2 == "T"' | wc -l)
unused=$(unused_exports "$TMP/defs" "$TMP/refs")
if [ -z "$unused" ]; then
    pass "exports: each of the $n_def global functions of src/ is called from another file"
else
    for f in $unused; do
        where=$(nm -A --defined-only $(cat "$TMP/defs") 2> /dev/null | awk -v f="$f" '$2 == "T" && $3 == f { sub(/:.*/, "", $1); print $1 }' |
            sed "s|^$BUILD/|src/|; s|\.o$|.c|")
        if [ "$(cat $where 2> /dev/null | grep -cw -- "$f")" -gt 1 ]; then
            fail "exports: $f ($where) is used only inside its own file: make it static (and drop it from the header)"
        else
            fail "exports: $f ($where) is called by nothing: remove it (and its declaration)"
        fi
    done
fi
