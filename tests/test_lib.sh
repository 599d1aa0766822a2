#!/usr/bin/env bash
# The test helpers of tests/lib.sh tell why a command failed: its FAIL line names the command, its
# exit status, the signal when one stopped it, and the last lines of its stderr (not its first line,
# which is often a render's harmless "38 triangles"). tests/run.sh names the signal of a test file
# that dies without a FAIL line.
. "$(dirname "$0")/lib.sh"
# a command that prints a harmless first line, its cause last, then dies of SIGTERM
cat > "$TMP/dies.sh" <<'SH'
echo "scenes/cornell.obj: 38 triangles" >&2
echo "pathlab render: the cause, last" >&2
kill -TERM $$
SH
line=$(expect_status "a killed command" 0 bash "$TMP/dies.sh")
for want in '^FAIL a killed command' "bash $TMP/dies.sh" 'exit 143' 'SIGTERM' 'the cause, last'; do
    if grep -qF -- "${want#^}" <<< "$line" && { [ "${want:0:1}" != '^' ] || grep -q -- "$want" <<< "$line"; }; then
        pass "expect_status on a killed command: its FAIL line has '$want'"
    else fail "expect_status on a killed command: no '$want' in: $line"; fi
done
line=$(run_ok "a failing render" bash -c 'echo first >&2; echo second >&2; exit 2')
[[ "$line" == *"exit 2;"*"first | second"* ]] && pass "run_ok: the status and the stderr's last lines ($line)" \
    || fail "run_ok: '$line'"
[ -z "$(run_ok "a good command" true)" ] && pass "run_ok: nothing for a command that succeeds" || fail "run_ok printed for a success"
# tests/run.sh on a test file killed by a signal without a FAIL line
mkdir -p "$TMP/t/tests" && cp tests/run.sh "$TMP/t/tests/"
printf 'echo "PASS one"\nkill -KILL $$\n' > "$TMP/t/tests/test_killed.sh"
out=$(cd "$TMP/t" && BUILD=none bash tests/run.sh 2>&1)
if grep -q 'FAIL test_killed.sh: exited with status 137 (SIGKILL' <<< "$out"; then pass "run.sh names the signal that killed a test file"
else fail "run.sh on a killed file: $(echo "$out" | head -3)"; fi
exit 0
