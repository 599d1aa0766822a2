# tests/lib.sh — helpers for the shell tests: pass/fail lines in the format tests/run.sh counts.
PATHLAB=${PATHLAB:-./pathlab}
BUILD=${BUILD:-build}
TMP=$(mktemp -d); trap 'rm -rf "$TMP"' EXIT
pass() { echo "PASS $*"; }
fail() { echo "FAIL $*"; }
# What a failing command did, for a FAIL line that shows its cause rather than a line of its output.
# status_text RC: "exit 2", or "exit 130 (SIGINT: killed by a signal, or stopped by it)" for 128 + N
status_text() {
    local rc=$1 sig
    if [ "$rc" -gt 128 ] && [ "$rc" -lt 192 ] && sig=$(kill -l $((rc - 128)) 2> /dev/null); then
        echo "exit $rc (SIG${sig#SIG}: killed by a signal, or stopped by it)"
    else echo "exit $rc"; fi
}
# err_tail FILE [N]: the last N lines (default 4) of FILE on one line, joined by ' | ', at most 500 characters
err_tail() {
    local t; t=$(tail -n "${2:-4}" "$1" 2> /dev/null | tr -d '\r' | paste -sd '|' - | sed 's/|/ | /g' | cut -c1-500)
    echo "${t:-(nothing on stderr)}"
}
# ran RC ERRFILE COMMAND...: "`COMMAND` exit RC (signal); stderr ends: LAST LINES", the whole story of a failure
ran() {
    local rc=$1 err=$2; shift 2
    echo "\`$(echo "$*" | cut -c1-300)\` $(status_text "$rc"); stderr ends: $(err_tail "$err")"
}
# expect NAME STATUS COMMAND...: runs COMMAND, checks its exit status, keeps stderr in $TMP/err
expect_status() {
    local name=$1 want=$2; shift 2
    "$@" > "$TMP/out" 2> "$TMP/err"; local got=$?
    if [ "$got" -eq "$want" ]; then pass "$name"; else fail "$name: wanted exit $want: $(ran "$got" "$TMP/err" "$@")"; fi
    return 0
}
# expect_err NAME PATTERN: the last command's stderr matches PATTERN (grep -E)
expect_err() {
    if grep -qE -- "$2" "$TMP/err"; then pass "$1"; else fail "$1: stderr does not match '$2'; stderr ends: $(err_tail "$TMP/err")"; fi
}
# run_ok NAME COMMAND...: runs COMMAND (stderr in $TMP/run.err); nothing if it succeeds, else a FAIL
# line with the command, its status and its stderr's last lines; returns its status
run_ok() {
    local name=$1 rc; shift
    "$@" 2> "$TMP/run.err"; rc=$?
    [ "$rc" -eq 0 ] || fail "$name: $(ran "$rc" "$TMP/run.err" "$@")"
    return "$rc"
}
# expect_no_file NAME PATH...: none of the files exist, and no temporary file is left beside them
expect_no_file() {
    local name=$1; shift
    local f
    for f in "$@"; do
        if [ -e "$f" ] || ls "$f".tmp.* >/dev/null 2>&1; then fail "$name: $f (or a temporary file) was written"; return; fi
    done
    pass "$name"
}
# zcheck_expect NAME WANT A VA B VB: runs tests/zcheck and wants exit status WANT (0: same up to
# noise, 1: told apart); a bad input (status 2) always fails the test instead of passing for nothing.
zcheck_expect() {
    local name=$1 want=$2; shift 2
    local msg rc
    msg=$("$BUILD/tests/zcheck" "$@" 2>&1); rc=$?
    if [ "$rc" -eq "$want" ]; then pass "$name ($msg)"; else fail "$name: zcheck exit $rc, wanted $want: $msg"; fi
}
PFMTOOL=$BUILD/tests/pfmtool
# skip NAME WHY: a check that cannot run here (a tool missing), counted apart by tests/run.sh
skip() { echo "SKIP $*"; }
# have_oiio: 0 if OpenImageIO's idiff and oiiotool are installed (make test-deps installs them when it
# can); PATHLAB_NO_OIIO=1 pretends they are not, to try the skips
have_oiio() { [ -z "${PATHLAB_NO_OIIO:-}" ] && command -v idiff > /dev/null 2>&1 && command -v oiiotool > /dev/null 2>&1; }
