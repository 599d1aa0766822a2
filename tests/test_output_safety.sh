#!/usr/bin/env bash
# Outputs cannot be diverted by what lies in their folder:
#  - links planted under the temporary names pathlab once used (NAME.tmp, NAME.meta.pending.tmp)
#    or under the output's own name are never followed: their targets stay as they were, and the
#    output is a regular file (every write goes through one temporary file of a random name,
#    created exclusively, then renamed: sys/atomic_file.h);
#  - a rewrite keeps the old file's mode (a private 600 report stays private);
#  - a read-only output (mode 444: a teacher's reference) is refused before any work, exit 2, and
#    left as it was.
. "$(dirname "$0")/lib.sh"
S=$PWD/scenes/cornell.obj
D=$TMP/w; mkdir -p "$D"; cd "$D" || exit 0
P=$PATHLAB; case $P in /*) ;; *) P=$OLDPWD/$PATHLAB ;; esac
REF=$OLDPWD/ref/cornell.pfm
$P render "$S" --size 64x64 --spp 4 --sampler independent --seed 3 --quiet -o g.pfm || { fail "output safety: the first render failed"; exit 0; }
for v in 1 2 3 4 5; do echo precious > victim$v.txt; done
ln -s victim1.txt class.md.tmp
ln -s victim2.txt out.pfm.meta.pending.tmp
ln -s victim3.txt cam.view.tmp
ln -s victim4.txt linked.pfm
ln -s victim5.txt report.csv
$P grade g.pfm --ref "$REF" --report class.md > /dev/null
$P render "$S" --size 8x8 --spp 1 -o out.pfm --quiet
$P render "$S" --size 8x8 --spp 1 -o o2.pfm --write-view cam.view --quiet
$P render "$S" --size 8x8 --spp 1 -o linked.pfm --quiet
$P grade g.pfm --ref "$REF" --report report.csv > /dev/null
changed=""
for v in 1 2 3 4 5; do [ "$(cat victim$v.txt)" = precious ] || changed="$changed victim$v.txt"; done
notreg=""
for f in class.md out.pfm.meta cam.view linked.pfm report.csv; do [ -f "$f" ] && [ ! -L "$f" ] || notreg="$notreg $f"; done
if [ -z "$changed" ] && [ -z "$notreg" ]; then pass "5 planted links (old temporary names, the outputs' own names): none followed, every output a regular file"
else fail "planted links: targets changed:${changed:- none}; outputs not regular files:${notreg:- none}"; fi
left=$(ls | grep -E '\.tmp\.|\.pending$' || true)
if [ -z "$left" ]; then pass "no temporary file left"; else fail "temporary files left: $left"; fi

echo secret > private.md; chmod 600 private.md
$P grade g.pfm --ref "$REF" --report private.md > /dev/null
m=$(stat -c %a private.md)
if [ "$m" = 600 ] && ! grep -q secret private.md; then pass "a rewritten private report keeps its mode 600"
else fail "a rewritten private report: mode $m (want 600), $(head -c 80 private.md)"; fi

cp g.pfm ro.pfm; chmod 444 ro.pfm; sum=$(cksum < ro.pfm)
expect_status "a read-only output (444) is refused, exit 2" 2 $P render "$S" --size 8x8 --spp 1 -o ro.pfm --quiet
expect_err "the refusal says it is read-only" "ro.pfm: is read-only"
if [ "$(cksum < ro.pfm)" = "$sum" ] && [ "$(stat -c %a ro.pfm)" = 444 ]; then pass "the read-only file is left as it was"
else fail "the read-only file changed: mode $(stat -c %a ro.pfm)"; fi
$P render "$S" --size 8x8 --spp 1 --bounces 0:2 --split -o pv.pfm --quiet && chmod 600 pv.pfm pv_L1.pfm
$P render "$S" --size 8x8 --spp 2 --bounces 0:2 --split -o pv.pfm --quiet
if [ "$(stat -c %a pv.pfm)" = 600 ] && [ "$(stat -c %a pv_L1.pfm)" = 600 ] && [ "$(stat -c %a pv_L0.pfm)" != 600 ]; then
    pass "a rewritten render keeps each file's mode (600 stays 600, the others as they were)"
else fail "a rewritten render's modes: pv.pfm $(stat -c %a pv.pfm), pv_L1.pfm $(stat -c %a pv_L1.pfm), pv_L0.pfm $(stat -c %a pv_L0.pfm)"; fi
chmod 444 pv_L1.pfm; before=$(cat pv.pfm pv_L0.pfm pv_L1.pfm pv_L2.pfm | cksum)
expect_status "a read-only layer of a --split set: exit 2" 2 $P render "$S" --size 8x8 --spp 3 --bounces 0:2 --split -o pv.pfm --quiet
expect_err "the refusal names the read-only layer" "pv_L1.pfm: is read-only"
if [ "$(cat pv.pfm pv_L0.pfm pv_L1.pfm pv_L2.pfm | cksum)" = "$before" ]; then pass "none of the set's files was replaced"
else fail "files of the set were replaced despite the read-only layer"; fi
exit 0
