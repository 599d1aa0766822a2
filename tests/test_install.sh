#!/usr/bin/env bash
# make install PREFIX=... DESTDIR=... and make uninstall, in a temporary folder: the program, its man
# page (made from pathlab help: every command there) and the bash completion (which completes a
# flag); uninstall removes the three and nothing else. Runs the Makefile on a copy of it beside this
# build's program (nothing is rebuilt: the copy has no sources, OBJ= says so).
. "$(dirname "$0")/lib.sh"
src=$(pwd)
mkdir -p "$TMP/tree/tools" "$TMP/root/opt/pl/share/man/man1"
cp Makefile "$TMP/tree/"; cp tools/man.sh "$TMP/tree/tools/"; cp "$PATHLAB" "$TMP/tree/pathlab"
touch "$TMP/root/opt/pl/share/man/man1/other.1"   # someone else's file: uninstall leaves it
cd "$TMP/tree" || exit 0
# The copy's make sees neither this make's flags nor its build choice: `make test SAN=clang` puts SAN
# in the environment, and the copy would then look for build-clang-san/pathlab, which it has not.
mk() { env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL -u SAN -u FUZZ -u NATIVE make "$@"; }
D=$TMP/root P=/opt/pl
run_ok "make install" mk -s install OBJ= PREFIX=$P DESTDIR="$D" > "$TMP/inst.out"
for f in bin/pathlab share/man/man1/pathlab.1 share/bash-completion/completions/pathlab; do
    [ -s "$D$P/$f" ] && pass "install: $P/$f under DESTDIR" || fail "install: $P/$f not installed"
done
[ -x "$D$P/bin/pathlab" ] && "$D$P/bin/pathlab" --version > /dev/null && pass "install: the installed pathlab runs" || fail "install: the installed pathlab does not run"
missing=
for c in render grade compare merge convert view diff check-sampler; do grep -q "^\.SS \"pathlab $c\"" "$D$P/share/man/man1/pathlab.1" || missing="$missing $c"; done
[ -z "$missing" ] && pass "man page: a section per command" || fail "man page: no section for$missing"
grep -q -- '--target-error' "$D$P/share/man/man1/pathlab.1" && pass "man page: the flags of the help" || fail "man page: no --target-error"
if command -v man > /dev/null 2>&1; then
    MANWIDTH=100 man -l "$D$P/share/man/man1/pathlab.1" 2> "$TMP/man.err" | grep -q 'pathlab render SCENE.obj' && [ ! -s "$TMP/man.err" ] \
        && pass "man -l shows the page without a warning" || fail "man -l: $(head -c 300 "$TMP/man.err")"
else skip "man -l: man is not installed"; fi
got=$(bash -c '. "$1"; COMP_WORDS=(pathlab render --spl); COMP_CWORD=2; _pathlab; echo "${COMPREPLY[*]}"' _ "$D$P/share/bash-completion/completions/pathlab")
[ "$got" = "--split" ] && pass "the installed completion completes render --spl to --split" || fail "installed completion: '$got'"
run_ok "make uninstall" mk -s uninstall OBJ= PREFIX=$P DESTDIR="$D" > /dev/null
left=$(cd "$D" && find . -type f | sort | paste -sd' ' -)
[ "$left" = "./opt/pl/share/man/man1/other.1" ] && pass "uninstall: the three files gone, another's file kept" || fail "uninstall left: $left"
# the default PREFIX is /usr/local
mk -s -n install OBJ= DESTDIR=/x | grep -q "/x/usr/local/bin/pathlab" \
    && pass "install: PREFIX defaults to /usr/local" || fail "install: the default PREFIX is not /usr/local"
cd "$src" || exit 0
exit 0
