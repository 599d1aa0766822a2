#!/bin/sh
# tools/man.sh PATHLAB — pathlab's man page (roff, on stdout), made from `PATHLAB help`: the overview
# is the synopsis, each "==== pathlab NAME ====" section of the help a subsection, as printed
# (no-fill). `make install` installs it as man1/pathlab.1; `man pathlab` shows the same text as
# `pathlab help`.
set -e
prog=${1:-./pathlab}
help=$("$prog" help)
rev=$("$prog" --version | sed -n '1s/^pathlab //p')
printf '.TH PATHLAB 1 "" "pathlab %s" "User Commands"\n' "$rev"
printf '.SH NAME\npathlab \\- a teaching path tracer: render, compare estimators, grade images against references\n'
# roff: a backslash is \e; a line starting with . or ' is protected by \&
printf '%s\n' "$help" | awk '
    function out(s) { gsub(/\\/, "\\e", s); if (s ~ /^[.'"'"']/) s = "\\&" s; print s }
    NR == 1 { next }
    /^==== pathlab / { if (!sub_open) { print ".fi" } sub(/^==== /, ""); sub(/ ====$/, ""); print ".SS \"" $0 "\""; print ".nf"; sub_open = 1; next }
    !started { print ".SH SYNOPSIS"; print ".nf"; started = 1 }
    started && !sub_open && !sect && /^$/ && seen_usage { print ".fi"; print ".SH COMMANDS"; print ".nf"; sect = 1; next }
    /^usage:$/ && !seen_usage { seen_usage = 1; next }
    { out($0) }
    END { print ".fi" }'
printf '.SH SEE ALSO\nREADME.md and docs/ of pathlab'"'"'s sources: docs/guide.md (a student'"'"'s walk through the bounces),\ndocs/grading.md (grading a class), docs/references.md (references).\n'
