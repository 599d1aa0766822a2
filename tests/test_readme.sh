#!/usr/bin/env bash
# The README's commands work as written in a fresh clone. What it checks:
#  - every line of the README's ```sh blocks that runs ./pathlab (or awk, mkdir, cp before it) is
#    run verbatim, in order, in a copy of the tracked files (git ls-files) with this ./pathlab, except
#    that --spp N becomes --spp 2, a render without --size gets --size 64x64 and check-sampling's
#    --samples 10^5 becomes 10000, the least it takes (about 20 s in all instead of minutes); its status must be 0 (grade
#    and check-sampling: 0 or 1, a verdict, which 10000 samples may fail; 2 would be an input error);
#  - every file the commands name exists (scenes/, ref/) in the copy, i.e. in the clone;
#  - each `make TARGET` of those blocks is a target of the Makefile (make -n TARGET succeeds), and
#    `make run`'s recipe renders into cornell.png and says where (run here with SPP=2 and the
#    copied ./pathlab, not rebuilt);
#  - ./pathlab, not pathlab: a fresh clone has no pathlab on the PATH;
#  - the README's figures about the tests (time, checks) are on the lines scripts/readme-figures.sh
#    writes, in its form, and nowhere else; a whole tests/run.sh with fewer checks than they say fails
#    (tried on a copy with one test file); the count of planted bugs is the number of tests/mutants/ patches.
. "$(dirname "$0")/lib.sh"
here=$(pwd)
copy=$TMP/clone
mkdir -p "$copy"
git ls-files -z | (cd "$here" && xargs -0 cp --parents -t "$copy") 2>/dev/null \
    || { fail "readme: cannot copy the tracked files"; exit 0; }
cp "$PATHLAB" "$copy/pathlab"
awk '/^```sh/ { on = 1; next } /^```/ { on = 0 } on' README.md > "$TMP/lines"
n=$(grep -c . "$TMP/lines")
[ "$n" -ge 10 ] && pass "readme: $n lines in sh blocks" || fail "readme: only $n lines in sh blocks"
if grep -qE '^(pathlab|[^#]*&& pathlab) ' "$TMP/lines"; then fail "readme: a command starts 'pathlab', not './pathlab'"
else pass "readme: every command is ./pathlab"; fi
# the figures: written by scripts/readme-figures.sh, in its form, and nowhere else
head='in a fresh clone, its build included, on [0-9]+ cores: \*\*'
tail=', at [0-9a-f]{7,} on 20[0-9-]{8} [0-9:]{5} UTC, load average [0-9.]+ to [0-9.]+\. <!-- scripts/readme-figures.sh make'
for f in "run -->|^\`make run\` $head[0-9.]+ s\*\* \(the render alone, 512x512 at 64 spp: [0-9.]+ s\)$tail run -->\$" \
         "test -->|^\`make test\` $head[0-9]+ min [0-9]{2} s\*\*, [0-9]+ checks \([0-9]+ passed\)$tail test -->\$" \
         "test EST_ALL=1 -->|^EST_ALL=1 \`make test\` $head[0-9]+ min [0-9]{2} s\*\*, [0-9]+ checks \([0-9]+ passed\)$tail test EST_ALL=1 -->\$"; do
    m="<!-- scripts/readme-figures.sh make ${f%%|*}"
    l=$(grep -F -- "$m" README.md)
    if [ "$(grep -cF -- "$m" README.md)" = 1 ] && grep -qE -- "${f#*|}" <<< "$l"; then pass "readme: the figures line '$m' is in the script's form"
    else fail "readme: the line ending '$m' is missing or not in scripts/readme-figures.sh's form: $l"; fi
done
stray=$(grep -nE '[0-9]+ checks|[0-9]+ min [0-9]+ s\b' README.md | grep -vF '<!-- scripts/readme-figures.sh')
[ -z "$stray" ] && pass "readme: no figure of checks or minutes outside the script's lines" \
    || fail "readme: figures not written by scripts/readme-figures.sh: $stray"
bugs=$(sed -n 's/.*plants \([0-9]*\) classic bugs.*/\1/p' README.md); patches=$(ls tests/mutants/*.patch | wc -l)
[ "$bugs" = "$patches" ] && pass "readme: make mutants plants $bugs bugs, the $patches patches of tests/mutants/" \
    || fail "readme: make mutants plants '$bugs' bugs, tests/mutants/ has $patches patches"
# tests/run.sh counts against the README: a copy whose README says more checks than its one test has
mkdir -p "$TMP/few/tests"; cp tests/run.sh "$TMP/few/tests/"
printf 'echo "PASS the only check"\n' > "$TMP/few/tests/test_one.sh"
echo '**1 min 00 s**, 5 checks (5 passed) <!-- scripts/readme-figures.sh make test -->' > "$TMP/few/README.md"
out=$(cd "$TMP/few" && env -u EST_ALL -u PATHLAB_FAST -u TEST_EXCLUDE BUILD=none TEST_SOURCE_ONLY=run bash tests/run.sh 2>&1); rc=$?
if [ "$rc" -ne 0 ] && grep -q 'FAIL README.md says 5 checks, this run had 1' <<< "$out"; then pass "run.sh: a whole run with fewer checks than the README says fails"
else fail "run.sh with fewer checks than the README: status $rc: $(echo "$out" | tail -n 2 | paste -sd' ' -)"; fi
echo '**1 min 00 s**, 1 checks (1 passed) <!-- scripts/readme-figures.sh make test -->' > "$TMP/few/README.md"
(cd "$TMP/few" && env -u EST_ALL -u PATHLAB_FAST -u TEST_EXCLUDE BUILD=none TEST_SOURCE_ONLY=run bash tests/run.sh > /dev/null 2>&1) \
    && pass "run.sh: as many checks as the README says passes" || fail "run.sh: fails with as many checks as the README says"
cd "$copy" || exit 0
while IFS= read -r line; do
    case "$line" in ''|'#'*) continue ;; esac
    case "$line" in
    make\ *)
        target=$(echo "$line" | awk '{ print $2 }')
        if make -n "$target" > "$TMP/make_n" 2>&1; then pass "readme: make $target is a target"
        else fail "readme: make $target: $(head -c 200 "$TMP/make_n")"; fi
        continue ;;
    esac
    cmd=$(echo "$line" | sed -E 's/--spp [0-9]+/--spp 2/g; s/--samples 100000/--samples 10000/')
    [[ "$cmd" == *"pathlab render"* && "$cmd" != *"--size"* ]] && cmd=${cmd/pathlab render/pathlab render --size 64x64}
    bash -c "$cmd" > "$TMP/out" 2> "$TMP/err"; rc=$?
    short=$(echo "$line" | cut -c1-90)
    if [ "$rc" -eq 0 ] || { [ "$rc" -eq 1 ] && [[ "$line" == *"pathlab grade"* || "$line" == *"check-sampling"* ]]; }; then pass "readme: $short (status $rc)"
    else fail "readme: $short: status $rc: $(tail -c 300 "$TMP/err")"; fi
done < "$TMP/lines"
# the files the README's commands name exist in the clone
for f in scenes/cornell.obj scenes/cornell-glossy.obj ref/cornell.pfm; do
    grep -q "$f" "$TMP/lines" || continue
    [ -f "$f" ] && pass "readme: $f exists in the clone" || fail "readme: $f is named but not in the clone"
done
for f in cornell.pfm direct.png b_L4.pfm b_L2.png mine.png heat.png class.md ab.pfm ab_var.pfm cmp/mosaic.png; do
    [ -s "$f" ] && pass "readme: wrote $f" || fail "readme: $f not written"
done
# make run: its recipe renders cornell.png and says where
make -n run | grep -q -- "-o cornell.png" && pass "readme: make run renders into cornell.png" \
    || fail "readme: make run does not write cornell.png"
./pathlab render scenes/cornell.obj --spp 1 --size 16x16 --quiet -o cornell.png && [ -s cornell.png ] \
    && pass "readme: the render of make run (16x16, 1 spp) writes cornell.png" || fail "readme: make run's render failed"
make -n run | grep -q 'cornell.png (open it' && pass "readme: make run says where the image is" \
    || fail "readme: make run does not say where the image is"
exit 0
