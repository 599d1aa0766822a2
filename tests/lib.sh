# tests/lib.sh — helpers for the shell tests: pass/fail lines in the format tests/run.sh counts.
PATHLAB=${PATHLAB:-./pathlab}
BUILD=${BUILD:-build}
TMP=$(mktemp -d); trap 'rm -rf "$TMP"' EXIT
pass() { echo "PASS $*"; }
fail() { echo "FAIL $*"; }
# expect NAME STATUS COMMAND...: runs COMMAND, checks its exit status, keeps stderr in $TMP/err
expect_status() {
    local name=$1 want=$2; shift 2
    "$@" > "$TMP/out" 2> "$TMP/err"; local got=$?
    if [ "$got" -eq "$want" ]; then pass "$name"; else fail "$name: exit status $got, expected $want; stderr: $(head -c 300 "$TMP/err")"; fi
}
# expect_err NAME PATTERN: the last command's stderr matches PATTERN (grep -E)
expect_err() {
    if grep -qE -- "$2" "$TMP/err"; then pass "$1"; else fail "$1: stderr does not match '$2': $(head -c 300 "$TMP/err")"; fi
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
