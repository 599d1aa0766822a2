#!/usr/bin/env bash
# Inputs that are not regular files (a FIFO, a device, a folder) are refused at once, naming the file
# and what it is, exit 2: a FIFO with no writer in a class folder used to hang grade for ever, and
# /dev/zero was read without end (sys/input_file.h). Each command runs under `timeout 10`: 124 is a hang.
. "$(dirname "$0")/lib.sh"
mkfifo "$TMP/f.pfm" "$TMP/o.txt" || { skip "input kinds: mkfifo failed"; exit 0; }
mkdir "$TMP/d.pfm"
R=ref/cornell.pfm
for input in "$TMP/f.pfm:not a regular file" "/dev/zero:not a regular file" "$TMP/d.pfm:a folder"; do
    f=${input%%:*}; why=${input#*:}; k=$(basename "$f")
    expect_status "diff $k: exit 2, no hang" 2 timeout 10 $PATHLAB diff "$f" $R
    expect_err "diff $k: says it is $why" "$f: cannot open: $why"
    expect_status "convert $k: exit 2, no hang" 2 timeout 10 $PATHLAB convert "$f" "$TMP/x.png"
    expect_status "grade $k: exit 2, no hang" 2 timeout 10 $PATHLAB grade "$f" --ref $R
    expect_status "grade against $k as the reference: exit 2, no hang" 2 timeout 10 $PATHLAB grade $R --ref "$f"
done
expect_status "render --orbiter FIFO: exit 2, no hang" 2 timeout 10 $PATHLAB render scenes/cornell.obj --size 8x8 --spp 1 --orbiter "$TMP/o.txt" -o "$TMP/x.pfm"
expect_err "render --orbiter FIFO: says it is no regular file" "o.txt: cannot open the orbiter file: not a regular file"
expect_no_file "render --orbiter FIFO: nothing written" "$TMP/x.pfm"
# every other reader: the scene (a FIFO, a folder, a device), a FIFO named SCENE.view beside a
# scene (found, not named: it read as empty, a default camera without a word), a student's sample
# file for check-sampler (it hung), a FIFO named IMAGE.pfm.meta (grade and view hung)
mkfifo "$TMP/s.obj" "$TMP/samples.txt" "$TMP/g.pfm.meta" && mkdir "$TMP/sd.obj" "$TMP/sc" && cp scenes/cornell.obj scenes/cornell.mtl "$TMP/sc/" && mkfifo "$TMP/sc/cornell.view"
for f in "$TMP/s.obj:not a regular file" "$TMP/sd.obj:a folder" "/dev/zero:not a regular file" "$TMP/sc/cornell.obj:cornell.view: cannot open: not a regular file"; do
    s=${f%%:*}; why=${f#*:}; k=$(basename "$s")
    expect_status "render $k: exit 2, no hang" 2 timeout 10 $PATHLAB render "$s" --size 8x8 --spp 1 --quiet -o "$TMP/x.pfm"
    expect_err "render $k: says why" "$why"
done
expect_status "check-sampler FIFO: exit 2, no hang" 2 timeout 10 $PATHLAB check-sampler "$TMP/samples.txt" --pdf uniform
expect_err "check-sampler FIFO: says it is no regular file" "samples.txt: cannot open it: not a regular file"
cp $R "$TMP/g.pfm"
expect_status "view: a FIFO as the image's sidecar: exit 2, no hang" 2 timeout 10 $PATHLAB view "$TMP/g.pfm" -o "$TMP/g.html"
expect_err "view: says the sidecar is no regular file" "g.pfm.meta: cannot read: not a regular file"
expect_status "grade: a FIFO as the image's sidecar: no hang" 0 timeout 10 $PATHLAB grade "$TMP/g.pfm" --ref $R
exit 0
