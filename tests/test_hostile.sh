#!/usr/bin/env bash
# Hostile inputs (../shared/data/hostile/README.md: fuzzed and hand-made files): each one found a bug by fuzzing or by
# hand. Whatever the input, pathlab ends in bounded time and memory with either a correct render or
# a clear error naming the file and line (exit 2), and writes no partial output.
# The small inputs are in tests/hostile/; the big ones (4096- and 100000-corner faces, a 100 MB face line, a
# 100 MB keyword) are made here at run time. The libFuzzer inputs (*.bin) hold an OBJ, an MTL and a
# view file between the markers @@MTL@@ and @@VIEW@@; split_bin cuts them as the fuzz harness does.
. "$(dirname "$0")/lib.sh"
D=tests/hostile
OUT=$TMP/out.pfm
# Sanitizer builds are slow and reserve terabytes of virtual memory: no ulimit -v there.
case "$PATHLAB" in *san*) SAN=1 ;; *) SAN=0 ;; esac
# PATHLAB_FAST=1 (make test SAN=1): the big inputs are 20 MB instead of 100 MB.
if [ "${PATHLAB_FAST:-0}" = 1 ]; then MB=20; else MB=100; fi

# render_t NAME SECONDS STATUS ARGS...: pathlab render ARGS within SECONDS (else FAIL), exit STATUS
render_t() {
    local name=$1 secs=$2 want=$3; shift 3
    rm -f "$OUT"
    timeout "$secs" "$PATHLAB" render "$@" > "$TMP/out" 2> "$TMP/err"; local got=$?
    if [ "$got" -eq 124 ]; then fail "$name: still running after $secs s"; return 1; fi
    if [ "$got" -ne "$want" ]; then fail "$name: wanted exit $want: $(ran "$got" "$TMP/err" "$PATHLAB" render "$@")"; return 1; fi
    if [ "$want" -ne 0 ] && [ -e "$OUT" ]; then fail "$name: an output was written despite the error"; return 1; fi
    pass "$name (exit $got)"
}
# split_bin FILE DIR: DIR/s.obj, DIR/m.mtl, DIR/s.view (the OBJ names m.mtl)
split_bin() {
    mkdir -p "$2"
    awk -v d="$2" 'BEGIN { f = d "/s.obj" } !mtl && index($0, "@@MTL@@") == 1 { f = d "/m.mtl"; mtl = 1; next }
        mtl && !view && index($0, "@@VIEW@@") == 1 { f = d "/s.view"; view = 1; next } { print > f }' "$1"
}
# stat_field NAME: the number after NAME in the stats line ("continuation 123", "123 paths cut")
stat_field() { sed -n "s/.*$1 \([0-9]*\).*/\1/p" "$TMP/err" | tail -n 1; }

# ---- view files ----
# a comment longer than the old 1023-character buffer: its tail ("size 2 2") was read as a line
render_t "view: a 1032-character comment ending in 'size 2 2' is a comment" 60 0 $D/quad-light.obj \
    --view $D/longline-comment.view --spp 1 -o "$OUT" --write-view "$TMP/w.view"
grep -q '^size 512 512$' "$TMP/w.view" && pass "view: the long comment's 'size 2 2' is not applied (512x512)" \
    || fail "view: long comment: the view used was $(grep size "$TMP/w.view")"
render_t "view: a valid file with a long comment is accepted (was 'unknown key')" 60 0 $D/quad-light.obj \
    --view $D/longline-rejected.view --spp 1 -o "$OUT" --write-view "$TMP/w.view"
grep -q '^size 16 16$' "$TMP/w.view" && grep -q '^eye 0 0.949999988 -1.60000002$' "$TMP/w.view" \
    && pass "view: the line after the long comment is read as line 5 (size 16 16, eye of line 1)" \
    || fail "view: long comment: the view used was $(tr '\n' ' ' < "$TMP/w.view")"
render_t "view: size 2521474836477 256 refused before the float-to-int cast" 10 2 $D/quad-light.obj --view $D/size-huge.view -o "$OUT"
expect_err "view: size 2521474836477 256: file:line and the values" "size-huge.view:1: size 2521474836477 256: out of range"
render_t "view: size 1e10 16 refused" 10 2 $D/quad-light.obj --view $D/size-1e10.view -o "$OUT"
expect_err "view: size 1e10 16: file:line" "size-1e10.view:1: size 1e10 16: out of range"
split_bin $D/fuzz-crash-view-size.bin "$TMP/crash"
render_t "view: fuzz-crash-view-size.bin" 10 2 "$TMP/crash/s.obj" -o "$OUT"
expect_err "view: fuzz-crash-view-size.bin: the size line named" "s.view:8: size 2521474836477 256: out of range"
printf 'size 8 %s\n' "$(printf '3%.0s' $(seq 120))" > "$TMP/v0.view"   # found by make fuzz: finite in double, inf in float
render_t "view: a 120-digit size (inf as a float) refused" 10 2 $D/quad-light.obj --view "$TMP/v0.view" -o "$OUT"
expect_err "view: a 120-digit size: out of range at its line" "v0.view:1: size 8 3333.*\\.\\.\\.: out of range"
printf 'eye 1e39 0 0\n' > "$TMP/v1.view"
render_t "view: eye 1e39 (finite double, beyond float) refused" 10 2 $D/quad-light.obj --view "$TMP/v1.view" -o "$OUT"
expect_err "view: eye 1e39: 'too large for a float', not 'up is parallel'" "v1.view:1: a number too large for a float"
printf 'eye 0 1 -3\nfov 40\0 size 2 2\n' > "$TMP/v2.view"
render_t "view: a NUL byte in a line is an error" 10 2 $D/quad-light.obj --view "$TMP/v2.view" -o "$OUT"
expect_err "view: NUL byte: file:line" "v2.view:2: a NUL byte"
render_t "view: /dev/zero as a view file ends at once" 10 2 $D/quad-light.obj --view /dev/zero -o "$OUT"
render_t "view: /dev/null as --view refused (it was read as an empty view: the default framing, exit 0)" 10 2 $D/quad-light.obj \
    --view /dev/null -o "$OUT"
expect_err "view: /dev/null: says there is no camera in it" "/dev/null: no camera in it"
F=$TMP/fifo; mkdir -p "$F"; cp $D/quad-light.obj $D/quad-light.mtl "$F/"
if mkfifo "$F/quad-light.view" 2>/dev/null; then
    render_t "view: a FIFO named SCENE.view (no writer) refused at once, not read as an empty view" 10 2 "$F/quad-light.obj" \
        --size 4x4 --spp 1 -o "$OUT"
    expect_err "view: a FIFO named SCENE.view: says it is no regular file" "quad-light.view: cannot open: not a regular file"
fi
printf 'size 6 6\n' | render_t "view: --view reads a pipe" 30 0 $D/quad-light.obj --view /dev/stdin --spp 1 -o "$OUT" \
    --write-view "$TMP/w.view"
grep -q '^size 6 6$' "$TMP/w.view" && pass "view: the pipe's size 6 6 was read" || fail "view: pipe: $(grep size "$TMP/w.view")"
printf '# eye and target\neye 0 1 0\n\ntarget 0 1 0\n' > "$TMP/v3.view"
render_t "view: eye == target refused" 10 2 $D/quad-light.obj --view "$TMP/v3.view" -o "$OUT"
expect_err "view: eye == target: the view file and both lines named" "v3.view:4: eye \(line 2\) and target \(line 4\) are the same point"
printf 'eye 0 5 0\ntarget 0 0 0\nup 0 2 0\n' > "$TMP/v4.view"
render_t "view: up parallel to the view direction refused" 10 2 $D/quad-light.obj --view "$TMP/v4.view" -o "$OUT"
expect_err "view: up parallel: file:line" "v4.view:3: up 0 2 0 \(line 3\) is parallel"
render_t "view: a flag overriding a bad key: the flag's value is used" 30 0 $D/quad-light.obj --view "$TMP/v4.view" \
    --up 0,0,1 --size 8x8 --spp 1 -o "$OUT"
printf 'eye 1e30 0 0\ntarget -1e30 0 0\n' > "$TMP/v5.view"
render_t "view: eye/target overflowing float arithmetic refused" 10 2 $D/quad-light.obj --view "$TMP/v5.view" -o "$OUT"
expect_err "view: float overflow: file:line" "v5.view:2: eye, target or up too large"

# gKit orbiter files share the view files' line reader (they had the same 1023-character buffer)
{ printf 'c 0 0.5 0\np 0 0\nr 10 0\n#'; head -c 1100 /dev/zero | tr '\0' a; printf 's 3 3\ns 4 4\n'; } > "$TMP/long.orbiter"
render_t "orbiter: a 1101-character comment ending in 's 3 3' is a comment" 30 0 $D/quad-light.obj --orbiter "$TMP/long.orbiter" \
    --size 8x8 --spp 1 -o "$OUT"
printf 'c 0 0.5 0\np 0 0\nr 10 0\ns 3\0 3\n' > "$TMP/nul.orbiter"
render_t "orbiter: a NUL byte is an error" 10 2 $D/quad-light.obj --orbiter "$TMP/nul.orbiter" -o "$OUT"
expect_err "orbiter: NUL byte: file:line" "nul.orbiter:4: a NUL byte"

# ---- termination whatever the materials ----
# A closed box, Kd 1: with q = min(1, max beta) = 1 every path ran to the 10^6-bounce cap (0.8 s per
# sample). Now q <= 0.95 from bounce 32 on (RR_CAP_FROM in integrator.c): 32 bounces, then about
# 20 more, so 40 to 70 continuation rays per path.
render_t "roulette: closed box with Kd 1 ends" 60 0 $D/kd1/furnace.obj --size 16x16 --spp 4 -o "$OUT"
n=$(stat_field continuation); per=$(( ${n:-999999999} / 1024 ))
if [ "$per" -ge 40 ] && [ "$per" -le 70 ]; then pass "roulette: Kd 1: $per continuation rays per path (expected 32 + 1/(1-0.95) = 52)"
else fail "roulette: Kd 1: $per continuation rays per path, expected 40 to 70: $(tail -n 1 "$TMP/err")"; fi
grep -q ' 0 paths cut at 1000 bounces' "$TMP/err" \
    && pass "roulette: Kd 1: no path cut by the bounce cap" || fail "roulette: Kd 1: $(tail -n 1 "$TMP/err")"
render_t "roulette off: Kd 1 ends at the hard bounce cap" 60 0 $D/kd1/furnace.obj --size 4x4 --spp 1 --rr off -o "$OUT"
grep -q ' 16 paths cut at 1000 bounces' "$TMP/err" && pass "roulette off: the 16 paths cut at 1000 bounces are counted" \
    || fail "roulette off: stats line: $(tail -n 1 "$TMP/err")"
render_t "roulette off, light sampling only: Kd 1 ends at the hard bounce cap" 60 0 $D/kd1/furnace.obj --size 4x4 --spp 1 \
    --rr off --direct light -o "$OUT"
grep -q ' 16 paths cut at 1000 bounces' "$TMP/err" && pass "roulette off, light sampling only: the 16 paths cut are counted" \
    || fail "roulette off, light sampling only: stats line: $(tail -n 1 "$TMP/err")"
split_bin $D/fuzz-timeout-kd15.bin "$TMP/kd15"
render_t "roulette: fuzz-timeout-kd15.bin (Kd 1.5, closed box) ends" 60 0 "$TMP/kd15/s.obj" --size 16x16 --spp 4 -o "$OUT"
expect_err "roulette: Kd 1.5 warned at load, MTL file:line" "m.mtl:3: material 'furnace' has Kd \+ Ks = 1.5 > 1: it creates energy"

# ---- polygons ----
face() {   # N: one convex N-gon (a circle) under quad-light's light, as slow_face/gen.py
    awk -v n="$1" 'BEGIN { print "mtllib quad-light.mtl\nv -0.5 1 -0.5\nv 0.5 1 -0.5\nv 0.5 1 0.5\nv -0.5 1 0.5";
        print "usemtl light\nf 1 2 3\nf 1 3 4\nusemtl plane"; pi = atan2(0, -1)
        for (i = 0; i < n; i++) printf "v %.6f 0.5 %.6f\n", cos(2 * pi * i / n), -sin(2 * pi * i / n)
        printf "f"; for (i = 0; i < n; i++) printf " %d", 5 + i; print "" }'
}
cp $D/quad-light.mtl "$TMP/"
face 4096 > "$TMP/f4096.obj"; face 100000 > "$TMP/f100k.obj"
render_t "polygon: a 4096-corner face loads" 30 0 "$TMP/f4096.obj" --size 8x8 --spp 1 -o "$OUT"
render_t "polygon: a 100000-corner face is refused at once (50 s of ear clipping before)" 10 2 "$TMP/f100k.obj" -o "$OUT"
expect_err "polygon: the cap named with file:line" "f100k.obj:100010: face with more than 4096 corners"
# a 100 MB face line repeating "2 3 4 " (slow_face/gen_repeat.py): 1.5 GB and no end before
{ printf 'mtllib quad-light.mtl\nv 0 0 0\nv 1 0 0\nv 0 0 1\nv 1 1 1\nf 1 2 3\nf '
  yes '2 3 4' | head -n $((MB * 1024 * 1024 / 6)) | tr '\n' ' '; } > "$TMP/rep.obj"
if [ "$SAN" = 1 ]; then render_t "polygon: a $MB MB face line is refused" 60 2 "$TMP/rep.obj" -o "$OUT"
else (ulimit -v 1000000; render_t "polygon: a $MB MB face line is refused within 1 GB of memory" 60 2 "$TMP/rep.obj" -o "$OUT"); fi
expect_err "polygon: $MB MB face line: file:line" "rep.obj:7: face with more than 4096 corners"
rm -f "$TMP/rep.obj" "$TMP/f100k.obj"

# ---- long tokens in messages ----
{ printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n'; head -c $((MB * 1024 * 1024)) /dev/zero | tr '\0' x; } > "$TMP/long.obj"
render_t "message: a $MB MB unknown keyword" 60 0 "$TMP/long.obj" --size 4x4 --spp 1 -o "$OUT"
size=$(wc -c < "$TMP/err")
if [ "$size" -lt 2000 ] && grep -q "long.obj:5: ignoring unknown keyword 'x\{40\}\.\.\.'" "$TMP/err"; then
    pass "message: the keyword is cut to 40 characters + '...' ($size bytes of stderr)"
else fail "message: $size bytes of stderr: $(head -c 300 "$TMP/err")"; fi
rm -f "$TMP/long.obj"
{ printf 'v '; head -c 100000 /dev/zero | tr '\0' 3; printf ' 0 0\n'; } > "$TMP/num.obj"
render_t "message: a 100000-digit number" 10 2 "$TMP/num.obj" -o "$OUT"
grep -q "num.obj:1: '3\{40\}\.\.\.' is not a finite float" "$TMP/err" && [ "$(wc -c < "$TMP/err")" -lt 500 ] \
    && pass "message: the number is cut to 40 characters + '...'" || fail "message: $(head -c 300 "$TMP/err")"

# ---- files a scene names stay in its folder ----
S=$TMP/scene; mkdir -p "$S/sub" "$S/folder.mtl"
cp $D/quad-light.obj $D/quad-light.mtl "$S/"; cp $D/quad-light.mtl "$S/sub/"; cp $D/quad-light.mtl "$TMP/outside.mtl"
ln -s ../outside.mtl "$S/out.mtl"; ln -s quad-light.mtl "$S/in.mtl"
mkfifo "$S/fifo.mtl" 2>/dev/null
truncate -s $((65 * 1024 * 1024)) "$S/big.mtl"
mtllib() {   # NAME STATUS LIB [PATTERN]: a scene whose mtllib line (line 7) names LIB
    sed "s#^mtllib .*#mtllib $3#" $D/quad-light.obj > "$S/t.obj"
    render_t "mtllib $1" 10 "$2" "$S/t.obj" --size 4x4 --spp 1 -o "$OUT" && [ -n "${4:-}" ] && expect_err "mtllib $1: message" "$4"
}
mtllib "/etc/passwd refused" 2 /etc/passwd "t.obj:7: mtllib '/etc/passwd' is outside the scene's folder"
mtllib "/dev/zero refused" 2 /dev/zero "t.obj:7: mtllib '/dev/zero' is outside the scene's folder"
mtllib "../outside.mtl refused" 2 ../outside.mtl "t.obj:7: mtllib '../outside.mtl' is outside the scene's folder"
mtllib "a symlink leading out refused" 2 out.mtl "t.obj:7: mtllib 'out.mtl' is outside the scene's folder"
mtllib "a folder refused" 2 folder.mtl "t.obj:7: mtllib 'folder.mtl' is a folder"
[ -p "$S/fifo.mtl" ] && mtllib "a FIFO refused (it would block)" 2 fifo.mtl "t.obj:7: mtllib 'fifo.mtl' is not a regular file"
mtllib "a 65 MiB file refused" 2 big.mtl "t.obj:7: mtllib 'big.mtl' is larger than 64 MiB"
mtllib "sub/quad-light.mtl (below the folder) accepted" 0 sub/quad-light.mtl
mtllib "a symlink inside the folder accepted" 0 in.mtl
mtllib "an absolute path inside the folder accepted" 0 "$S/quad-light.mtl"
mtllib "sub/../quad-light.mtl accepted" 0 sub/../quad-light.mtl
render_t "OBJ: /dev/zero as the scene ends at once" 10 2 /dev/zero -o "$OUT"
expect_err "OBJ: /dev/zero: not a regular file" "/dev/zero: cannot open: not a regular file"

# ---- ignored MTL keys: one line per file ----
printf 'newmtl glass\nKd 0.1 0.1 0.1\nKa 0 0 0\nTf 1 1 1\nNi 1.5\nd 0.2\nillum 7\nnewmtl plane\nKd 0.5\nKa 0 0 0\nillum 2\nnewmtl light\nKe 10 10 10\n' > "$S/quad-light.mtl"
render_t "MTL: ignored keys" 10 0 "$S/quad-light.obj" --size 4x4 --spp 1 -o "$OUT"
if [ "$(grep -c 'quad-light.mtl' "$TMP/err")" = 1 ] && grep -q "quad-light.mtl: ignored keys: Ka (2), illum (2); not supported: transmission (Tf (1), Ni (1), d (1)): every surface is opaque" "$TMP/err"; then
    pass "MTL: one line sums up the ignored keys, transmission named as not supported"
else fail "MTL: $(head -c 400 "$TMP/err")"; fi
exit 0
