#!/usr/bin/env bash
# scripts/readme-figures.sh [--run-only] — measures the figures the README quotes about the build and
# the tests, and writes them into README.md, each on its line (the one ending with its marker):
#   <!-- scripts/readme-figures.sh make run -->   `make run` in a fresh clone of HEAD, build included
#   <!-- scripts/readme-figures.sh make test -->  then `make clean` and `make test` in that clone, build
#                                                 included: its time and its checks (the "N passed,
#                                                 N failed" of its last line); EST_ALL=1 is passed on and
#                                                 writes the line "... make test EST_ALL=1" instead
# --run-only measures and writes make run's line alone (a minute or so; make test takes 5 to 30).
# Run it from the top folder after committing; the README is changed in place: commit it.
# tests/test_readme.sh checks that the lines are in the form written here, and tests/run.sh that a
# whole run has at least the checks the README says.
set -u
cd "$(dirname "$0")/.."
clone=$(mktemp -d)
trap 'rm -rf "$clone"' EXIT
git clone -q . "$clone/pathlab" || exit 2
# the shared data beside the clone, as beside this checkout (tests read ../shared/data)
[ -d ../shared ] && ln -s "$(cd ../shared && pwd)" "$clone/shared"
rev=$(git rev-parse --short HEAD)
cores=$(nproc 2> /dev/null || echo 2)
now() { date +%s.%N; }
secs() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f", b - a }'; }
mmss() { awk -v s="$1" 'BEGIN { printf "%d min %02d s", int(s / 60), int(s % 60 + 0.5) }'; }
load() { cut -d' ' -f1 /proc/loadavg 2> /dev/null || echo '?'; }
when() { date -u '+%Y-%m-%d %H:%M UTC'; }
# write KEY LINE: LINE (ending with KEY) in place of README.md's line ending with KEY
write() {
    awk -v key="$1" -v line="$2" 'substr($0, length($0) - length(key) + 1) == key && !done { print line; done = 1; next } { print }
        END { if (!done) exit 3 }' README.md > README.md.new && mv README.md.new README.md && echo "README.md: $2" && return 0
    rm -f README.md.new; echo "README.md has no line ending '$1': add one where the figure goes" >&2; exit 2
}
# make run: the build and the render of the Cornell box, 512x512 at 64 spp; then the render alone
l0=$(load); t0=$(now)
(cd "$clone/pathlab" && make run > "$clone/run.log" 2>&1) || { echo "make run failed: $(tail -3 "$clone/run.log")" >&2; exit 1; }
t1=$(now); l1=$(load)
s=$(now); (cd "$clone/pathlab" && ./pathlab render scenes/cornell.obj --spp 64 --quiet -o "$clone/c.png") || exit 1; render_s=$(secs "$s" "$(now)")
key="<!-- scripts/readme-figures.sh make run -->"
write "$key" "\`make run\` in a fresh clone, its build included, on $cores cores: **$(secs "$t0" "$t1") s** (the render alone, 512x512 at 64 spp: $render_s s), at $rev on $(when), load average $l0 to $l1. $key"
[ "${1:-}" = --run-only ] && exit 0
# make test, build included
(cd "$clone/pathlab" && make clean > /dev/null 2>&1)
l0=$(load); t0=$(now)
(cd "$clone/pathlab" && make test > "$clone/test.log" 2>&1)
t1=$(now); l1=$(load)
last=$(tail -n 1 "$clone/test.log")
case $last in *" passed, "*" failed") ;; *) echo "make test did not end with 'N passed, N failed': $last" >&2
    grep -E 'FAIL|Error|error:' "$clone/test.log" | head -20 >&2; exit 1 ;; esac
passed=${last%% passed*}; failed=${last#*passed, }; failed=${failed%% failed}
key="<!-- scripts/readme-figures.sh make test${EST_ALL:+ EST_ALL=$EST_ALL} -->"
write "$key" "${EST_ALL:+EST_ALL=$EST_ALL }\`make test\` in a fresh clone, its build included, on $cores cores: **$(mmss "$(secs "$t0" "$t1")")**, $((passed + failed)) checks ($passed passed), at $rev on $(when), load average $l0 to $l1. $key"
