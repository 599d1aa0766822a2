#!/usr/bin/env bash
# pathlab check-sampler: a student's sample file (x y z [pdf] per line) against the pdf they claim.
# The files are drawn here by python3 (random.Random with fixed seeds), 40000 directions each
# (100000 for the exponent off by one), written with %.9g. The command's level is its default
# alpha = 0.01 for the whole check (Sidak: 0.005 for each of the chi-square and the column's
# normalisation), so each honest case below is a false alarm with probability about 0.01; they were
# also run with seeds 11 to 16 at 100000 (42 runs) and 21 to 24 at 40000 (24 runs): all passed.
# Each mistake must fail (exit 1) with its diagnosis named; bad files exit 2 with FILE:LINE.
. "$(dirname "$0")/lib.sh"
N=40000
cat > "$TMP/gen.py" <<'PY'
import math, random, sys
# gen.py MODE N SEED [M] [wox woy woz]: a student's sample file on stdout
mode, n, seed = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
M = float(sys.argv[4]) if len(sys.argv) > 4 else 1.0
wo = [float(x) for x in sys.argv[5:8]] if len(sys.argv) > 7 else [0.0, 0.0, 1.0]
l = math.sqrt(sum(x * x for x in wo)); wo = [x / l for x in wo]
rng = random.Random(seed)
def dirz(c, phi):
    s = math.sqrt(max(0.0, 1 - c * c)); return [math.cos(phi) * s, math.sin(phi) * s, c]
out = ["# %s n=%d seed=%d m=%g" % (mode, n, seed, M)]
for i in range(n):
    u1, u2 = rng.random(), 1.0 - rng.random()
    phi = 2 * math.pi * u1
    if mode in ("cosine", "cosine-nopi", "below"):          # cos theta = sqrt(u)
        w = dirz(math.sqrt(u2), phi); pdf = w[2] / math.pi
        if mode == "cosine-nopi": pdf = w[2]                # mistake: the 1/pi forgotten
        if mode == "below" and i % 100 == 7: w[2] = -w[2]  # mistake: 1 direction in 100 flipped below
    elif mode == "hemisphere":
        w = dirz(u2, phi); pdf = 1 / (2 * math.pi)
    elif mode == "uniform":
        w = dirz(1 - 2 * u2, phi); pdf = 1 / (4 * math.pi)
    elif mode == "theta":                                   # mistake: theta = (pi/2) u
        w = dirz(math.cos(0.5 * math.pi * u2), phi); pdf = 1 / (2 * math.pi)
    elif mode in ("cosm", "cosm-exp", "cosm-norm"):         # mistakes: u^(1/M); (M+2)/(2 pi)
        w = dirz(u2 ** (1 / M if mode == "cosm-exp" else 1 / (M + 1)), phi)
        pdf = (M + (2 if mode == "cosm-norm" else 1)) / (2 * math.pi) * w[2] ** M
    elif mode.startswith("blinn"):                          # h ~ cos^M, w = reflect(wo, h)
        h = dirz(u2 ** (1 / (M + 1)), phi)
        d = sum(a * b for a, b in zip(wo, h))
        w = [2 * d * b - a for a, b in zip(wo, h)]
        ph = (M + 1) / (2 * math.pi) * h[2] ** M
        pdf = ph / (4 * d)
        if mode == "blinn-nojac": pdf = ph                  # mistake: no 1/(4 wo.h)
        if mode == "blinn-cos": pdf = (M + 1) / (2 * math.pi) * max(w[2], 0) ** M / (4 * d)
        if w[2] <= 0: pdf = 0.0                             # below the surface: written, pdf 0
    else:
        sys.exit("unknown mode " + mode)
    out.append("%.9g %.9g %.9g %.9g" % (w[0], w[1], w[2], pdf))
print("\n".join(out))
PY
gen() { local f=$1; shift; python3 "$TMP/gen.py" "$@" > "$TMP/$f"; }
WO="0.5 0 0.866"
# run NAME FILE STATUS PATTERN FLAGS...: exit status STATUS and stdout matching PATTERN
run() {
    local name=$1 f=$2 want=$3 pat=$4; shift 4
    $PATHLAB check-sampler "$TMP/$f" "$@" > "$TMP/out" 2> "$TMP/err"; local rc=$?
    if [ $rc -ne "$want" ]; then fail "$name: wanted exit $want: $(grep -E 'FAIL|->' "$TMP/out" | head -4) $(ran "$rc" "$TMP/err" $PATHLAB check-sampler "$TMP/$f" "$@")"
    elif ! grep -qE -- "$pat" "$TMP/out"; then fail "$name: no '$pat' in: $(grep -E 'FAIL|->' "$TMP/out" | head -4)"
    else pass "$name"; fi
}

# honest samplers, each with its right pdf column: every check passes
gen cos.txt cosine $N 1;            run "cosine, right pdf: pass" cos.txt 0 '^pass: 0 checks failed' --pdf cosine
gen hemi.txt hemisphere $N 2;       run "uniform hemisphere: pass" hemi.txt 0 '^pass' --pdf hemisphere
gen sph.txt uniform $N 3;           run "uniform sphere: pass" sph.txt 0 '^pass' --pdf uniform
gen cosm.txt cosm $N 4 20;          run "cos^20: pass" cosm.txt 0 '^pass' --pdf cosm:20
gen blinn.txt blinn $N 5 20 $WO;    run "blinn:20, wo (0.5, 0, 0.866): pass" blinn.txt 0 '^pass' --pdf blinn:20 --wo 0.5,0,0.866
gen blinn1.txt blinn $N 6 1 0.9 0.3 0.1
run "blinn:1 at grazing wo (1/3 of the reflections below the surface): pass" blinn1.txt 0 '^pass' --pdf blinn:1 --wo 0.9,0.3,0.1
cut -d' ' -f1-3 "$TMP/cos.txt" > "$TMP/cos3.txt"
run "directions without a pdf column: the chi-square alone" cos3.txt 0 'no pdf column' --pdf cosine

# the mistakes, each caught and named
gen nojac.txt blinn-nojac $N 7 20 $WO
run "blinn pdf without the Jacobian 1/(4 wo.h): caught" nojac.txt 1 '-> .*Jacobian of the reflection' --pdf blinn:20 --wo 0.5,0,0.866
gen bcos.txt blinn-cos $N 8 20 $WO
run "blinn pdf with cos^m theta instead of theta_h: caught" bcos.txt 1 "-> .*cos\^m of the direction's angle" --pdf blinn:20 --wo 0.5,0,0.866
gen nopi.txt cosine-nopi $N 9;      run "cosine pdf without 1/pi: caught" nopi.txt 1 '-> your pdf is pi times too large: the 1/pi is missing' --pdf cosine
gen norm.txt cosm-norm $N 10 20;    run "cos^20 pdf with (m+2)/(2 pi): caught" norm.txt 1 '-> .*\(m\+2\)/\(2 pi\) instead of \(m\+1\)' --pdf cosm:20
gen theta.txt theta $N 11;          run "uniform in theta: caught" theta.txt 1 '-> your directions are uniform in theta, not in cos theta' --pdf hemisphere
gen exp.txt cosm-exp 100000 12 20;      run "cos theta = u^(1/M): caught, K fitted" exp.txt 1 '-> .*cos\^K with K = 1[89]\.[0-9]+.*u\^\(1/20\) instead' --pdf cosm:20
gen below.txt below $N 13;          run "directions below the surface: caught" below.txt 1 '-> [0-9]+ directions below the surface \(z < 0; the first on line 9\)' --pdf cosine
grep -v ' -' "$TMP/blinn.txt" | awk '$3 > 0' > "$TMP/above.txt"   # the reflections below left out
run "blinn file without the reflections below the surface: caught" above.txt 1 '-> no direction below the surface' --pdf blinn:20 --wo 0.5,0,0.866
run "cosine directions claimed as hemisphere: chi-square fails, K about 1" cos3.txt 1 'cos\^K with K = (0\.9|1\.0)' --pdf hemisphere

# a direction printed at the horizon (%f writes z < 5e-7 as 0.000000; 5% of honest 100000-line files
# had one) is on the surface, not below it; a pdf 1e156 times too small on one line made the
# normalisation's error infinite, and the check passed: now it fails
{ cat "$TMP/hemi.txt"; echo "-0.975083 -0.221841 0.000000 0.159155"; } > "$TMP/horizon.txt"
run "a direction at z = 0.000000: on the surface, pass" horizon.txt 0 '^pass: 0 checks failed' --pdf hemisphere
{ cat "$TMP/cos.txt"; echo "1 0 1e-9 3e-166"; } > "$TMP/tiny.txt"
run "one pdf 1e156 times too small: the normalisation fails" tiny.txt 1 'normalisation FAIL' --pdf cosine
# few samples: a warning, the chi-square not judged (a correct sampler would fail it: honest files of
# 700 to 1400 lines failed 20 of 20), exit 2 (neither pass nor fail); bad input: exit 2 and FILE:LINE
head -200 "$TMP/cos.txt" > "$TMP/few.txt"; run "199 samples: a warning" few.txt 2 '^warning: only 199 samples' --pdf cosine
run "199 samples: the chi-square not judged, the verdict says so" few.txt 2 '^NOT JUDGED: the other checks pass, but 199 samples are too few' --pdf cosine
head -1000 "$TMP/cos.txt" | sed 's/ [^ ]*$/ 0.5/' > "$TMP/few_bad.txt"; run "999 samples with a wrong pdf column: still a fail" few_bad.txt 1 '^FAIL' --pdf cosine
# a line over 4095 bytes (split by the reader, it read as two samples), a NUL byte (the rest of the
# line was dropped), a control character in the line: refused with FILE:LINE, shown escaped
{ head -3 "$TMP/cos.txt"; printf '0 0 1 0.3183099%4100s 0 0 1 0.3183099\n' ' '; } > "$TMP/long.txt"
expect_status "a line over 4095 bytes: exit 2" 2 $PATHLAB check-sampler "$TMP/long.txt" --pdf cosine
expect_err "a line over 4095 bytes: FILE:LINE" "long.txt:4: a line over 4095 bytes"
{ head -3 "$TMP/cos.txt"; printf '0 0 1 0.3183099\0 7 7 7\n'; } > "$TMP/nul.txt"
expect_status "a NUL byte: exit 2" 2 $PATHLAB check-sampler "$TMP/nul.txt" --pdf cosine
expect_err "a NUL byte: FILE:LINE" "nul.txt:4: a NUL byte: not a text file"
{ head -3 "$TMP/cos.txt"; printf '0 0 \033[2K\rpass\n'; } > "$TMP/esc.txt"
expect_status "an escape sequence in a line: exit 2" 2 $PATHLAB check-sampler "$TMP/esc.txt" --pdf cosine
if grep -q $'\033' "$TMP/err"; then fail "an escape sequence in a line: printed raw"; else pass "an escape sequence in a line: shown escaped"; fi
head -16 "$TMP/cos.txt" > "$TMP/bad.txt"; echo "nan 0 1" >> "$TMP/bad.txt"
expect_status "malformed line: exit 2" 2 $PATHLAB check-sampler "$TMP/bad.txt" --pdf cosine
expect_err "malformed line: FILE:17 and the line" "bad\.txt:17: expected 3 or 4 numbers \(x y z \[pdf\]\), got 'nan 0 1'"
printf '0 0 1 0.3\n0.5 0 0.5 0.3\n' > "$TMP/len.txt"
expect_status "direction not unit: exit 2" 2 $PATHLAB check-sampler "$TMP/len.txt" --pdf cosine
expect_err "direction not unit: FILE:2 and its length" "len\.txt:2: the direction \(0\.5, 0, 0\.5\) has length 0\.707107"
printf '0 0 1 0.3\n\n# c\n0 0 1\n' > "$TMP/mix.txt"
expect_status "a pdf on some lines only: exit 2" 2 $PATHLAB check-sampler "$TMP/mix.txt" --pdf cosine
expect_err "a pdf on some lines only: FILE:4" "mix\.txt:4: 3 numbers, but line 1 has 4"
expect_status "blinn without --wo: exit 2" 2 $PATHLAB check-sampler "$TMP/cos.txt" --pdf blinn:20
expect_status "unknown --pdf: exit 2" 2 $PATHLAB check-sampler "$TMP/cos.txt" --pdf phong
expect_err "unknown --pdf: the names" "one of uniform, hemisphere, cosine, cosm:M, blinn:M, got 'phong'"
expect_status "missing file: exit 2" 2 $PATHLAB check-sampler "$TMP/none.txt" --pdf cosine
