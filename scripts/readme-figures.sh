#!/usr/bin/env bash
# scripts/readme-figures.sh — measures the figures the README quotes about the build and the tests
# and writes them into README.md (the line ending <!-- scripts/readme-figures.sh -->):
#   make run   in a fresh clone of HEAD (build included): its time on this machine
#   make test  in the same clone, after that: its time, its checks (the "N passed" of its last line)
# Takes 5 to 20 minutes (the whole test suite, on a loaded machine more). Run it from the top folder
# after committing; the README is changed in place, commit it. tests/test_readme.sh checks that the
# figures are in the form this script writes, and tests/run.sh that a whole run has at least the
# README's number of checks. EST_ALL=1 is passed on (CI's variant: all 48 estimator combinations).
set -u
cd "$(dirname "$0")/.."
clone=$(mktemp -d)
trap 'rm -rf "$clone"' EXIT
git clone -q . "$clone/pathlab" || exit 2
rev=$(git rev-parse --short HEAD)
cores=$(nproc 2> /dev/null || echo 2)
secs() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f", b - a }'; }
now() { date +%s.%N; }
load() { cut -d' ' -f1 /proc/loadavg 2> /dev/null || echo '?'; }
# make run (the build and the render), then make test
l0=$(load); t0=$(now)
(cd "$clone/pathlab" && make run > "$clone/run.log" 2>&1) || { echo "make run failed: $(tail -3 "$clone/run.log")" >&2; exit 1; }
t1=$(now)
render_s=$(cd "$clone/pathlab" && s=$(now) && ./pathlab render scenes/cornell.obj --spp 64 --quiet -o "$clone/c.png" && secs "$s" "$(now)")
(cd "$clone/pathlab" && make test > "$clone/test.log" 2>&1); t2=$(now); l1=$(load)
last=$(tail -n 1 "$clone/test.log")
case $last in *" passed, "*" failed") ;; *) echo "make test did not end with 'N passed, N failed': $last" >&2; exit 1 ;; esac
passed=${last%% passed*}; failed=${last#*passed, }; failed=${failed%% failed}
checks=$((passed + failed))
run_s=$(secs "$t0" "$t1"); test_s=$(secs "$t1" "$t2")
mmss() { awk -v s="$1" 'BEGIN { printf "%d min %02d s", int(s / 60), int(s % 60 + 0.5) }'; }
when=$(date -u '+%Y-%m-%d %H:%M UTC')
echo "make run: $run_s s (the render alone $render_s s); make test: $(mmss "$test_s"), $checks checks ($failed failed); load $l0 to $l1"
tag=${EST_ALL:+ EST_ALL=1}
key="<!-- scripts/readme-figures.sh$tag -->"
line="${tag:+\`EST_ALL=1 make test\` (every estimator combination, as CI runs it)}${tag:-\`make test\`} in a fresh clone, after \`make run\`, on $cores cores: **$(mmss "$test_s")**, $checks checks ($passed passed), at $rev on $when, load average $l0 to $l1; \`make run\` (its build and a 512x512 render at 64 spp): $run_s s, the render alone $render_s s. $key"
awk -v key="$key" -v line="$line" 'substr($0, length($0) - length(key) + 1) == key && !done { print line; done = 1; next } { print }
    END { if (!done) exit 3 }' README.md > README.md.new
case $? in
0) mv README.md.new README.md; echo "README.md: $line" ;;
*) rm -f README.md.new; echo "README.md has no line ending '$key': add one where the figures go" >&2; exit 2 ;;
esac
