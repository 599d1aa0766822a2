#!/usr/bin/env bash
# The docs say what is true now, checked on README.md and docs/*.md:
#  - no doc names an issue ("issue 12", "Issue 12, item 4") or a branch (branch `bvh4`, the hostile
#    branch, "main's binary"): a reader has neither; the history of experiments is in bench/log.md;
#  - docs/performance.md is at most 400 lines (current figures, how to reproduce them, what each option buys);
#  - the "Print this" list of docs/architecture.md names every file of src/tracer/ with its line count
#    as `wc -l` gives it (the failure says the right count), and its total;
#  - every file path a doc names (src/..., tests/..., bench/..., docs/..., a layer's file such as
#    tracer/integrator.c, a Markdown link) exists;
#  - architecture.md's arrows are exactly test_layout.sh's allowed(), and every function its "Where to
#    find" table names is in a file that row names;
#  - every section a doc names by title ("docs/sampler.md, \"Which default\"") exists;
#  - README's flag table gives each value list of `pathlab render --help` (--light a|b|...) as it is.
# Each check is shown to fail on a copy of the docs with one planted violation (as test_layout.sh does).
. "$(dirname "$0")/lib.sh"
ROOT=${DOCS_ROOT:-.}   # another tree to check (this file's own negative checks use it)
LAYER_RE='sys|math|geometry|scene|image|sampler|tracer|render|stats|util|files|grade|compare|check|cmd'
docs() { echo "$ROOT/README.md"; ls "$ROOT"/docs/*.md; }
# DOCS_ONLY=N runs check N alone (the negative checks below run only the check each plant breaks)
want() { [ -z "${DOCS_ONLY:-}" ] || [ "$DOCS_ONLY" = "$1" ]; }

# 1. issues and branches (grep -n: file:line: text)
if want 1; then
issue=$(docs | xargs grep -niE '\bissues? #?[0-9]+' || true)
if [ -z "$issue" ]; then pass "no doc names an issue number"
else fail "docs name an issue (say what is true now instead): $(echo "$issue" | cut -c1-160 | head -n 8 | tr '\n' ';')"; fi
BRANCH_RE='branch(es)? [`'"'"'"]|[`'"'"'"] branch\b|\b(feature|helper'"'"'s|main|master|hostile|fuzz|white|bvh[0-9]*) branch\b|\bbranch (main|master|hostile|fuzz|white|bvh[0-9]*|h[0-9])\b'
MAIN_RE='\bmain('"'"'s)? (at [0-9a-f]{6,}|binary|build|before|after)\b|\b(of|against|than|on|from|with) main\b([^.(_]|$)|\bmain'"'"'s\b'
branch=$(docs | xargs grep -nE "$BRANCH_RE|$MAIN_RE" || true)
if [ -z "$branch" ]; then pass "no doc names a branch"
else fail "docs name a branch (say what is true now instead): $(echo "$branch" | cut -c1-160 | head -n 8 | tr '\n' ';')"; fi

fi

# 2. performance.md's length
if want 2; then
n=$(wc -l < "$ROOT/docs/performance.md")
if [ "$n" -le 400 ]; then pass "docs/performance.md is $n lines (at most 400)"
else fail "docs/performance.md is $n lines, over 400: its history belongs in bench/log.md"; fi

fi

# 3. architecture.md's print list: rows "| N | `src/tracer/FILE` | LINES | ..." of the section whose
# heading says "Print this", and a row "| | total | LINES |"
if want 3; then
list=$(awk '/^#+ .*[Pp]rint this/ { on = 1; next } on && /^#/ { on = 0 } on' "$ROOT/docs/architecture.md")
stale="" listed="" sum=0
while IFS='|' read -r _ _ file count _; do
    file=$(echo "$file" | tr -d ' `'); count=$(echo "$count" | tr -d ' ')
    case $file in src/*) ;; *) continue ;; esac
    listed="$listed $file"
    if [ ! -f "$ROOT/$file" ]; then stale="$stale $file does not exist;"; continue; fi
    real=$(wc -l < "$ROOT/$file"); sum=$((sum + real))
    [ "$count" = "$real" ] || stale="$stale $file is listed with $count lines, wc -l says $real: write $real;"
done <<< "$list"
for f in "$ROOT"/src/tracer/*.[ch]; do
    f=${f#"$ROOT"/}
    case " $listed " in *" $f "*) ;; *) stale="$stale $f is missing from the list ($(wc -l < "$ROOT/$f") lines);" ;; esac
done
total=$(echo "$list" | sed -n 's/^|[^|]*| *total *| *\([0-9]*\) *|.*/\1/p')
[ "$total" = "$sum" ] || stale="$stale the total says '$total', the files listed add up to $sum: write $sum;"
if [ -z "$listed" ]; then fail "docs/architecture.md has no \"Print this\" list of src/tracer/'s files"
elif [ -z "$stale" ]; then pass "docs/architecture.md's print list: every file of src/tracer/, line counts as wc -l ($sum lines)"
else fail "docs/architecture.md's print list is stale:$stale"; fi

fi

# 4. every path a doc names exists: words starting src/ tests/ bench/ docs/ (from the project's
# root), a layer's file (tracer/integrator.c: under src/), a Markdown link (from the doc's folder).
# A path with a placeholder in capitals (tests/mutants/NAME.patch) or a glob (tests/*.sh) is
# checked as a pattern: something must match it.
if want 4; then
missing=""
exists() {   # PATH: 0 if the path (or, with * or a placeholder, anything matching it) exists
    local p=$1
    [ -e "$p" ] || [ -e "$p.c" ] && return 0   # tests/zcheck: built from tests/zcheck.c
    while [[ $p =~ [A-Z][A-Z0-9_]*[A-Z0-9] ]]; do p=${p/"${BASH_REMATCH[0]}"/*}; done   # NAME, SCENE... match anything
    compgen -G "$p" > /dev/null
}
# prose FILE: the lines outside code blocks (fenced or indented by 4), where a Markdown link is a link
prose() { awk '/^ *```/ { code = !code; next } !code && !/^(    |\t)/' "$1"; }
for d in $(docs); do
    dir=$(dirname "$d"); rel=${d#"$ROOT"/}
    while read -r p; do
        [ -z "$p" ] && continue
        exists "$ROOT/$p" || missing="$missing $rel: $p;"
    done < <(grep -oE '(^|[^A-Za-z0-9_./$-])(src|tests|bench|docs)/[A-Za-z0-9_.*/-]*[A-Za-z0-9_*/]' "$d" |
             sed -E 's/^[^a-z]//' | sort -u)
    while read -r p; do
        [ -z "$p" ] && continue
        exists "$ROOT/src/$p" || missing="$missing $rel: $p (src/$p);"
    done < <(grep -oE "(^|[^A-Za-z0-9_./\$-])($LAYER_RE)/[a-z0-9_]+\.[ch]\b" "$d" | sed -E 's/^[^a-z]//' | sort -u)
    while read -r p; do
        [ -z "$p" ] && continue
        exists "$dir/$p" || missing="$missing $rel: ($p);"
    done < <(prose "$d" | grep -oE '\]\([^)# ]+' | sed 's/^](//' | grep -vE '^[a-z]+:' | sort -u)
done
if [ -z "$missing" ]; then pass "every file path named in README.md and docs/*.md exists"
else fail "docs name paths that do not exist:$missing"; fi

fi

# 5. architecture.md's arrows are tests/test_layout.sh's: the last column of each layer's row of the
# folders table (`sys/` `math/` ..., "nothing", "every layer") is that layer's allowed() there
if want 5; then
eval "$(sed -n -e '/^LAYERS=/p' -e '/^allowed() {/,/^}/p' tests/test_layout.sh)"
arrows=""
for l in $LAYERS; do
    row=$(grep -E "^\| \`$l/\` \|" "$ROOT/docs/architecture.md" | head -n 1)
    if [ -z "$row" ]; then arrows="$arrows $l/ has no row;"; continue; fi
    last=$(echo "$row" | awk -F'|' '{ print $(NF - 1) }')
    case $last in *"every layer"*) got="$LAYERS" ;; *) got=$(echo "$last" | grep -oE '[a-z]+/' | tr -d '/' | tr '\n' ' ') ;; esac
    want=$(allowed "$l")
    [ "$(echo $got | tr ' ' '\n' | sort | tr '\n' ' ')" = "$(echo $want | tr ' ' '\n' | sort | tr '\n' ' ')" ] ||
        arrows="$arrows $l/ may include '$(echo $want)' in test_layout.sh, the doc says '$(echo $got)';"
done
if [ -z "$arrows" ]; then pass "docs/architecture.md's arrows are those of tests/test_layout.sh"
else fail "docs/architecture.md's arrows differ from tests/test_layout.sh's allowed():$arrows"; fi

fi

# 6. "Where to find": every function() a row names is defined in a file that row names
if want 6; then
where=$(awk '/^#+ Where to find/ { on = 1; next } on && /^#/ { on = 0 } on && /^\|/' "$ROOT/docs/architecture.md")
gone=""
while read -r row; do
    files=$(echo "$row" | grep -oE "($LAYER_RE)/[a-z0-9_]+\.[ch]" | sort -u)
    where_said=$(echo $files)
    [ -z "$files" ] && files=$(cd "$ROOT/src" && ls */*.[ch]) && where_said="src/"   # a row naming no file: anywhere in src/
    for fn in $(echo "$row" | grep -oE '`[a-z_0-9]+\(\)`' | tr -d '`()' | sort -u); do
        (cd "$ROOT/src" && grep -qE "(^|[^a-z_0-9])$fn\(" $files 2>/dev/null) || gone="$gone $fn() is not in $where_said;"
    done
done <<< "$where"
if [ -z "$where" ]; then fail "docs/architecture.md has no \"Where to find\" table"
elif [ -z "$gone" ]; then pass "docs/architecture.md's \"Where to find\": every function named is in a file its row names"
else fail "docs/architecture.md's \"Where to find\" names functions not there:$gone"; fi

fi

# 8. a section named by title ("docs/sampler.md, \"Which default\"", "README, \"Polygons\"") exists there:
# a heading, or a paragraph's bold lead, that contains the title
if want 8; then
sections=""
for d in $(docs); do
    while IFS= read -r m; do
        [ -z "$m" ] && continue
        target=${m%%[,:]*}; title=${m#*\"}; title=${title%\"}
        case $target in README|README.md) tf=$ROOT/README.md ;; *) tf=$ROOT/docs/${target##*/} ;; esac
        [ -f "$tf" ] || continue   # a missing file is check 4's
        grep -F -- "$title" "$tf" | grep -qE '^#+ |^- \*\*|^\*\*' ||
            sections="$sections ${d#"$ROOT"/} names \"$title\" in ${tf#"$ROOT"/}, which has no such section;"
    done < <(grep -oE '(README|[a-z-]+\.md)[,:] "[^"]+"' "$d")
done
if [ -z "$sections" ]; then pass "every section a doc names by its title exists"
else fail "docs name sections that do not exist:$sections"; fi

fi

# 7. README's flag table gives every value list of `pathlab render --help` (--light a|b|c ...) as it is
if want 7; then
help=$("$PATHLAB" render --help 2>&1)
flags=""
if [ -z "$help" ]; then fail "could not read $PATHLAB render --help (build it first)"
else
    while read -r m; do
        [ -z "$m" ] && continue
        flag=${m%% *}
        row=$(grep -oE "^\| \`$flag [^\`]*\`" "$ROOT/README.md" | head -n 1 | sed -E 's/^\| `//; s/`$//; s/\\\|/|/g')
        [ "$row" = "$m" ] || flags="$flags render --help says '$m', README's table '${row:-nothing}';"
    done < <(echo "$help" | grep -oE -- '--[a-z-]+ [a-zA-Z0-9-]+(\|[a-zA-Z0-9-]+)+')
    if [ -z "$flags" ]; then pass "README's flag table lists the values of every flag as render --help does"
    else fail "README's flag table differs from render --help:$flags"; fi
fi

fi

# negative checks: the same checks on a copy of the docs with one planted violation each must fail
# (each its own check, named by what the FAIL line says)
if [ -z "${DOCS_ROOT:-}" ]; then
    # the tree: links to the project's files, copies of the docs that the plants edit
    R=$TMP/root; mkdir -p "$R/docs"
    for f in * .[!.]*; do case $f in docs|README.md) ;; *) ln -s "$PWD/$f" "$R/$f" ;; esac; done
    for f in docs/*; do case $f in *.md) ;; *) ln -s "$PWD/$f" "$R/$f" ;; esac; done
    for plant in "1:issue:name an issue" "1:branch:name a branch" "1:main:name a branch" "2:length:over 400" \
                 "3:count:print list is stale" "4:path:paths that do not exist" "4:link:paths that do not exist" \
                 "5:arrow:arrows differ" "6:where:names functions not there" "7:values:differs from render --help" \
                 "8:section:sections that do not exist"; do
        only=${plant%%:*}; plant=${plant#*:}; want=${plant#*:}; plant=${plant%%:*}
        cp README.md "$R/README.md"; cp docs/*.md "$R/docs/"   # fresh copies, then one violation
        case $plant in
            issue) echo "As issue 7 asks, the image is brighter." >> "$R/docs/guide.md" ;;
            branch) echo "Measured on branch \`bvh4\`." >> "$R/README.md" ;;
            main) echo "The images are byte for byte those of main's binary." >> "$R/docs/sampler.md" ;;
            length) seq 401 >> "$R/docs/performance.md" ;;
            count) sed -i -E '/^#+ .*[Pp]rint this/,/^#/ s/^(\| *[0-9]+ *\| *`src\/tracer\/[a-z_]+\.[ch]` *\| *)[0-9]+/\10/' "$R/docs/architecture.md" ;;
            path) echo "See src/tracer/render.c." >> "$R/docs/estimators.md" ;;
            link) echo "[the log](../bench/no_such_log.md)" >> "$R/docs/sampler.md" ;;
            arrow) sed -i -E 's/^(\| `tracer\/` .*\| )`sys\/` /\1`sys\/` `render\/` /' "$R/docs/architecture.md" ;;
            where) sed -i 's/`survives_roulette()`/`survives_the_roulette()`/' "$R/docs/architecture.md" ;;
            values) sed -i 's/\\|tree`/`/' "$R/README.md" ;;
            section) echo "See docs/sampler.md, \"Which sampler to pick\"." >> "$R/docs/guide.md" ;;
        esac
        if DOCS_ONLY=$only DOCS_ROOT="$R" bash "$0" 2>&1 | grep '^FAIL' | grep -q "$want"; then pass "a planted violation ($plant) is caught"
        else fail "a planted violation ($plant) was not caught"; fi
    done
fi
