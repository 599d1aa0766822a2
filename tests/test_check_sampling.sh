#!/usr/bin/env bash
# pathlab check-sampling: one row per sampling routine (routine, chi2, dof, p-value, integral, want,
# pdf err, verdict), the Sidak level and a summary line; exit status 0 when every sampler matches its
# pdf; the same rows whatever the thread count; --quiet; bad flags. The statistics themselves are
# tests/test_sampling.c's (the same cases with 1e6 samples), and the power to catch a broken sampler
# tests/test_chi2_power.c's: here a small sample count is enough.
. "$(dirname "$0")/lib.sh"
if [ "${PATHLAB_FAST:-0}" != 0 ]; then N=20000; else N=100000; fi
C="$PATHLAB check-sampling --samples $N"

$C --threads 2 > "$TMP/t2" 2> "$TMP/err"; rc=$?
if [ $rc -eq 0 ]; then pass "check-sampling --samples $N: exit status 0"
else fail "check-sampling --samples $N: exit status $rc: $(grep -E 'FAIL|error' "$TMP/t2" "$TMP/err" | head -5)"; fi

# the header, then rows ending in: chi2 dof p-value integral want pdf-err verdict
if grep -qE '^  routine +chi2 +dof +p-value +integral +want +pdf err +verdict$' "$TMP/t2"; then pass "table header"
else fail "table header missing: $(head -3 "$TMP/t2")"; fi
grep -E '^  ' "$TMP/t2" | grep -vE '^  routine ' > "$TMP/rows"
bad=$(awk '{ num = "^[0-9]+(\\.[0-9]+)?(e[-+][0-9]+)?$"; v = $NF; o = 0
             if (v != "pass") next
             if ($(NF-6) !~ num || $(NF-5) !~ /^[0-9]+$/ || $(NF-4) !~ num || $(NF-4) + 0 > 1) o = 1
             if (($(NF-3) !~ num && $(NF-3) != "-") || ($(NF-2) !~ num && $(NF-2) != "-") || ($(NF-1) !~ num && $(NF-1) != "-")) o = 1
             if (o) print }' "$TMP/rows")
rows=$(wc -l < "$TMP/rows"); passed=$(awk '$NF == "pass"' "$TMP/rows" | wc -l)
if [ -z "$bad" ] && [ "$rows" -ge 50 ] && [ "$passed" -eq "$rows" ]; then pass "$rows rows, all 'pass', each with chi2, dof, p in [0, 1], integral, want, pdf err"
else fail "rows: $rows, $passed pass; malformed: $(echo "$bad" | head -3)"; fi

# a row for every sampling routine of the course: warps, Blinn, BRDF mixture, triangles, spherical triangle, light choice
missing=""
for r in uniform_hemisphere cosine_hemisphere "cos_power m=1 " "cos_power m=10000" "brdf_sample diffuse" \
         "brdf_sample glossy Ns=10, wo 89 deg" "brdf_sample mixed Kd .5 Ks .3 Ns=10, wo 60 deg" sample_uniform_triangle \
         "light choice area" "light choice power" "light choice triangle" "light_sample_point uniform on its triangle" \
         "solid-angle, Omega = 0.5 sr" "floor 3e-4" "ceiling 6" "by area" "tree, 40 emitters, far" "tree points" "tree joint"; do
    grep -qF -- "$r" "$TMP/rows" || missing="$missing '$r'"
done
if [ -z "$missing" ]; then pass "a row for every sampling routine"; else fail "no row for:$missing"; fi

# the level and the summary
if grep -qE "^$rows passed, 0 failed \([0-9.]+ s\)$" "$TMP/t2"; then pass "summary line: $rows passed, 0 failed"
else fail "summary line: $(tail -1 "$TMP/t2")"; fi
if grep -qE "FAIL below 0\.000[0-9]+, so that all$" "$TMP/t2" && grep -qE "^$rows cases together .*Sidak" "$TMP/t2"; then pass "Sidak level printed"
else fail "no Sidak level in the legend"; fi

# reproducible: one thread, the same rows; another seed, other rows
$C --threads 1 | grep -E '^  ' > "$TMP/t1"
if grep -E '^  ' "$TMP/t2" | cmp -s - "$TMP/t1"; then pass "1 thread and 2 threads: the same rows"; else fail "the rows depend on the thread count"; fi
$C --seed 2 --quiet > "$TMP/q"; rc=$?
if [ $rc -eq 0 ] && [ "$(wc -l < "$TMP/q")" -eq 1 ] && grep -qE '^[0-9]+ passed, 0 failed' "$TMP/q"; then pass "--quiet --seed 2: only the summary line"
else fail "--quiet --seed 2 (status $rc): $(head -3 "$TMP/q")"; fi

for bad in "--samples abc" "--samples 10" "--threads 0" "--seed -1" "--samples"; do
    # shellcheck disable=SC2086
    expect_status "check-sampling $bad: status 2" 2 $PATHLAB check-sampling $bad
    expect_err "check-sampling $bad: the flag named" "${bad%% *}"
done
expect_status "check-sampling --help: status 0" 0 $PATHLAB check-sampling --help
if grep -q -- "--samples N" "$TMP/out"; then pass "check-sampling --help: the flags"; else fail "check-sampling --help: no usage"; fi
expect_status "check-sampling --frobnicate: status 2" 2 $PATHLAB check-sampling --frobnicate
expect_err "unknown flag named" "check-sampling: unknown flag '--frobnicate'"
if grep -q "^usage: pathlab check-sampling" "$TMP/err"; then pass "a usage line on error"; else fail "no usage line on error"; fi

# src/check's layering and include circles: tests/test_layout.sh, for every folder of src/
exit 0
