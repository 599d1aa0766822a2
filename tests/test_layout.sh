#!/usr/bin/env bash
# The layout by layer (docs/architecture.md), checked on the sources themselves:
#  - every source file sits in one of the layer folders, and every #include "..." names its module
#    (folder/file.h) and exists;
#  - includes go only where docs/architecture.md's arrows allow (e.g. tracer/ never includes cmd/,
#    util/, check/ or stats/), and there is no include circle (tsort) even counting a module as its
#    header and its .c together (a.c includes b.h and b.c includes a.h is a circle);
#  - no function in src/ is over 60 lines; one C dialect (no declaration in a for statement);
#  - no atoi/atof (they cannot report a bad number) and no exit() outside cmd/main.c;
#  - the default build is portable (no -march=native), and the docs name every folder.
. "$(dirname "$0")/lib.sh"
LAYERS="sys math geometry scene image sampler tracer render stats util files grade compare check cmd"
# allowed LAYER: the layers its files may include (besides its own)
allowed() {
    case $1 in
        sys) echo "" ;;
        math) echo "sys" ;;
        geometry) echo "sys math" ;;
        scene) echo "sys math geometry image" ;;
        image) echo "sys math" ;;
        sampler) echo "sys math" ;;
        tracer) echo "sys math geometry scene image sampler" ;;
        render) echo "sys math geometry scene image sampler tracer" ;;
        stats) echo "sys math image" ;;
        util) echo "sys math" ;;
        files) echo "sys math geometry scene image sampler tracer render stats util" ;;
        grade) echo "sys math image stats util files" ;;
        compare) echo "sys math geometry scene image sampler tracer render stats util files grade" ;;
        check) echo "sys math geometry scene sampler tracer stats" ;;
        cmd) echo "$LAYERS" ;;
    esac
}
SRC=${LAYOUT_SRC:-src}   # another tree to check (tests/test_layout.sh's own negative checks use it)
# the tests' and benchmarks' C files follow the same dialect (the compiler's
# -Wdeclaration-after-statement sees the rest of it: declarations after statements)
C_ELSEWHERE=""; [ -z "${LAYOUT_SRC:-}" ] && C_ELSEWHERE="tests/*.c tests/fuzz/*.c bench/*.c"

stray=$(find "$SRC" -type f \( -name '*.c' -o -name '*.h' \) | while read -r f; do
    d=${f#"$SRC"/}; d=${d%%/*}
    case " $LAYERS " in *" $d "*) ;; *) echo "$f" ;; esac
done)
if [ -z "$stray" ]; then pass "every source file is in a layer folder ($LAYERS)"
else fail "files outside the layer folders: $stray"; fi

# one awk over every file (a fork per file and per include took 51 s of make test with the
# planted copies): the includes that name no module, those against the arrows, and the module
# pairs for tsort; the existing files of $SRC are read first
pairs=$TMP/pairs
for l in $LAYERS; do echo "$l $(allowed "$l")"; done > "$TMP/arrows"
(cd "$SRC" && find . -type f -name '*.[ch]' | sed 's|^\./||') > "$TMP/files"
awk -v src="$SRC/" -v pairs="$pairs" -v out="$TMP/bad" '
    FILENAME == ARGV[1] { for (i = 2; i <= NF; i++) ok[$1 " " $i] = 1; ok[$1 " " $1] = 1; next }
    FILENAME == ARGV[2] { exists[$0] = 1; next }
    FNR == 1 { f = FILENAME; rel = substr(f, length(src) + 1); split(rel, parts, "/"); layer = parts[1]
               from = rel; sub(/\.[ch]$/, "", from) }
    /^[[:space:]]*#[[:space:]]*include[[:space:]]*"/ {
        inc = $0; sub(/^[^"]*"/, "", inc); sub(/".*/, "", inc)
        if (inc == "") next
        if (!(inc in exists) || index(inc, "/") == 0) { printf " %s:%s", f, inc > (out ".inc"); next }
        split(inc, q, "/")
        if (!((layer " " q[1]) in ok)) printf " %s->%s", f, inc > (out ".arrow")
        to = inc; sub(/\.h$/, "", to)
        if (from != to) print from, to > pairs
    }' "$TMP/arrows" "$TMP/files" "$SRC"/*/*.[ch]
touch "$pairs" "$TMP/bad.inc" "$TMP/bad.arrow"
bad_inc=$(cat "$TMP/bad.inc"); bad_arrow=$(cat "$TMP/bad.arrow")
if [ -z "$bad_inc" ]; then pass "every #include \"...\" names an existing folder/file.h"
else fail "includes that name no module of src/:$bad_inc"; fi
if [ -z "$bad_arrow" ]; then pass "includes follow the arrows of docs/architecture.md"
else fail "includes against the arrows:$bad_arrow"; fi
if tsort "$pairs" > /dev/null 2> "$TMP/tsort"; then pass "no include circle among modules (X.h with X.c; $(wc -l < "$pairs") includes)"
else fail "include circle: $(tr '\n' ' ' < "$TMP/tsort" | head -c 400)"; fi

# functions: their body, from '{' at column 0 to '}' at column 0 (named by the last line that
# started at column 0 before it: the signature, or its first line)
long=$(awk 'FNR == 1 { infn = 0 }
    /^\{/ { start = FNR; name = last; infn = 1; next }
    /^\}/ && infn { n = FNR - start + 1; if (n > 60) printf "%s:%d %s (%d lines)\n", FILENAME, start, name, n; infn = 0; next }
    /^[A-Za-z_]/ && !infn { last = $0 }' "$SRC"/*/*.c)
nfn=$(cat "$SRC"/*/*.c | grep -c '^{')
if [ -z "$long" ]; then pass "no function over 60 lines ($nfn functions)"
else fail "functions over 60 lines: $(echo "$long" | tr '\n' ';')"; fi

mixed=$(grep -nE '(^|[^A-Za-z0-9_])for[[:space:]]*\([[:space:]]*(const[[:space:]]+)?(int|long|size_t|unsigned|float|double|char|uint[0-9]+_t|int[0-9]+_t)[[:space:]]' "$SRC"/*/*.c $C_ELSEWHERE || true)
if [ -z "$mixed" ]; then pass "one C dialect in src/, tests/ and bench/: declarations at the top of a block, none in a for statement"
else fail "declarations in for statements: $(echo "$mixed" | tr '\n' ';')"; fi

calls=$(grep -nwE 'atoi|atof|atol' "$SRC"/*/*.c || true)
calls="$calls
$(grep -nE '(^|[^_a-z])exit[[:space:]]*\(' "$SRC"/*/*.c | grep -v "^$SRC/cmd/main.c:" || true)"
calls=$(echo "$calls" | sed '/^$/d')
if [ -z "$calls" ]; then pass "no atoi/atof, no exit() outside cmd/main.c"
else fail "atoi/atof or exit() where they must not be: $(echo "$calls" | tr '\n' ';')"; fi

if [ -z "${LAYOUT_SRC:-}" ]; then
    # the default build as a newcomer's `make` runs it: without the variables of a calling make
    # (`make test SAN=1` passes SAN=1 down through MAKEFLAGS)
    opt=$(env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL -u SAN -u NATIVE make -n -B build/sys/parallel.o 2>/dev/null | grep -- '-c -o' | head -n 1)
    case $opt in *-march=native*) fail "the default build uses -march=native: $opt" ;;
                 "") fail "could not see the default build's compile line (make -n)" ;;
                 *) pass "the default build is portable (no -march=native)" ;; esac
    for doc in docs/architecture.md README.md; do
        missing=""
        for l in $LAYERS; do grep -q "$l/" "$doc" 2>/dev/null || missing="$missing $l/"; done
        if [ -z "$missing" ]; then pass "$doc names every folder"; else fail "$doc does not name:$missing"; fi
    done
    # negative checks: the same rules on a copy of src/ with one planted violation each must fail
    # (each must make its own check fail, named by what the FAIL line says)
    for plant in "missing:math/planted.h" "arrow:includes against the arrows" "circle:include circle" "long:planted_long" \
                 "exit:planted_exit" "dialect:planted_for"; do
        want=${plant#*:}; plant=${plant%%:*}
        rm -rf "$TMP/src" && cp -r "$SRC" "$TMP/src"
        case $plant in
            missing) sed -i '0,/#include "/s//#include "math\/planted.h"\n#include "/' "$TMP/src/tracer/integrator.c" ;;
            arrow) sed -i '0,/#include "/s//#include "cmd\/diff.h"\n#include "/' "$TMP/src/tracer/integrator.c" ;;
            circle) sed -i '0,/#include "/s//#include "tracer\/integrator.h"\n#include "/' "$TMP/src/tracer/scene.c" ;;
            long) { echo "int planted_long(void)"; echo "{"; for i in $(seq 60); do echo "    (void)$i;"; done; echo "    return 0;"; echo "}"; } >> "$TMP/src/math/dvec.c" ;;
            exit) echo "void planted_exit(void) { exit(1); }" >> "$TMP/src/tracer/scene.c" ;;
            dialect) echo "void planted_for(void) { for (int i = 0; i < 2; i++) ; }" >> "$TMP/src/math/dvec.c" ;;
        esac
        if LAYOUT_SRC="$TMP/src" bash "$0" 2>&1 | grep '^FAIL' | grep -q "$want"; then pass "a planted violation ($plant) is caught"
        else fail "a planted violation ($plant) was not caught"; fi
    done
fi
