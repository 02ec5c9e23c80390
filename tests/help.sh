#!/bin/sh
# help.sh: checks that the command reference is whole and in step everywhere.
#
# commands/ (one file per command) is built by tools/mkhelp.awk into the program's
# `help` and into the command list of man/vroc.1.  This script checks that every
# file parses and its C compiles, that man/vroc.1 is what the generator makes
# now and is lint-clean, that the generator rejects broken files, and that the
# binary ($VROC, default ./vroc) and the man page name exactly the commands of
# commands/.  Run from tests/run.sh, or alone: VROC=./vroc sh tests/help.sh.
# Prints one "ok - ..." or "not ok - ..." line per check, with "#" lines saying
# why; exits 0 once every check has run (the lines carry the results).
set -u
cd "$(dirname "$0")/.." || exit 1
VROC=${VROC:-./vroc}
AWK=${AWK:-awk}
LC_ALL=C
export LC_ALL

tmp=$(mktemp -d "${TMPDIR:-/tmp}/vroc-help.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
trap 'exit 1' HUP INT TERM

ok() { printf 'ok - %s\n' "$1"; }
not_ok() { # text, then optional file whose lines explain why
    printf 'not ok - %s\n' "$1"
    if [ $# -gt 1 ] && [ -s "$2" ]; then
        sed -n '1,20s/^/#   /p' "$2"
    fi
}

words=$(for f in commands/*; do [ -f "$f" ] && basename "$f"; done | sort)
nwords=$(printf '%s\n' "$words" | grep -c .)

# ---- (a) every file of commands/ parses, and the C it makes compiles ----
if [ "$nwords" -gt 0 ] &&
   $AWK -f tools/mkhelp.awk -v mode=c commands/* > "$tmp/help_data.c" 2> "$tmp/err"; then
    ok "all $nwords files of commands/ parse (mkhelp.awk mode=c)"
    cc=${CC:-cc}
    if command -v "$cc" > /dev/null 2>&1; then
        if "$cc" -std=c17 -Wall -Wextra -Wpedantic -Werror -Isrc \
               -c -o "$tmp/help_data.o" "$tmp/help_data.c" > "$tmp/err" 2>&1; then
            ok "the generated help_data.c compiles with -std=c17 -Wall -Wextra -Wpedantic -Werror"
        else
            not_ok "the generated help_data.c compiles with strict warnings" "$tmp/err"
        fi
    else
        ok "the generated help_data.c compiles # SKIP no C compiler"
    fi
else
    [ "$nwords" -gt 0 ] || echo "no files in commands/" > "$tmp/err"
    not_ok "all files of commands/ parse (mkhelp.awk mode=c)" "$tmp/err"
    not_ok "the generated help_data.c compiles (nothing was generated)"
fi

# ---- (b) man/vroc.1 is what the template and commands/ make now ----
if $AWK -f tools/mkhelp.awk -v mode=man -v template=man/vroc.1.in commands/* \
        > "$tmp/vroc.1" 2> "$tmp/err"; then
    if cmp -s "$tmp/vroc.1" man/vroc.1; then
        ok "man/vroc.1 is up to date with man/vroc.1.in and commands/"
    else
        diff man/vroc.1 "$tmp/vroc.1" > "$tmp/err" 2>&1
        not_ok "man/vroc.1 is up to date (run make man/vroc.1)" "$tmp/err"
    fi
else
    not_ok "man/vroc.1 is up to date (the generator failed)" "$tmp/err"
fi

# ---- (c) the man page is lint-clean ----
if command -v mandoc > /dev/null 2>&1; then
    mandoc -Tlint -W warning man/vroc.1 > "$tmp/err" 2>&1
    if [ ! -s "$tmp/err" ]; then
        ok "mandoc -Tlint -W warning man/vroc.1 prints nothing"
    else
        not_ok "mandoc -Tlint -W warning man/vroc.1 prints nothing" "$tmp/err"
    fi
else
    echo "mandoc is not installed (make deps)" > "$tmp/err"
    not_ok "mandoc -Tlint -W warning man/vroc.1 prints nothing" "$tmp/err"
fi

# ---- (d) the generator rejects broken files, naming them ----
# reject WHAT SED-SCRIPT: a copy of commands/radius edited by SED-SCRIPT must fail.
reject() {
    mkdir -p "$tmp/bad"
    rm -f "$tmp/bad/radius"
    sed "$2" commands/radius > "$tmp/bad/radius"
    if $AWK -f tools/mkhelp.awk -v mode=c commands/cube "$tmp/bad/radius" \
            > /dev/null 2> "$tmp/err"; then
        echo "the generator accepted it" > "$tmp/err"
        not_ok "the generator rejects a file with $1" "$tmp/err"
    elif grep -q "bad/radius" "$tmp/err"; then
        ok "the generator rejects a file with $1, naming it"
    else
        not_ok "the generator names the file with $1" "$tmp/err"
    fi
}
if [ -f commands/radius ] && [ -f commands/cube ]; then
    reject "no summary" '/^summary:/d'
    reject "fields out of order" '/^group:/{h;d;};/^usage:/G'
    reject "a field twice" '/^summary:/p'
    reject "an unknown group" 's/^group:.*/group: shapes/'
    reject "a summary ending with a period" 's/^\(summary:.*\)$/\1./'
    reject "a summary starting with a capital" 's/^summary: ./summary: S/'
    reject "a usage not starting with its name" 's/^usage:.*/usage: rad = r/'
    reject "no example" '/^example:/,$d'
    reject "nothing in it" 'd'
else
    echo "commands/radius or commands/cube is missing" > "$tmp/err"
    not_ok "the generator rejects broken files (no sample to break)" "$tmp/err"
fi

# ---- (f) the man page lists exactly the commands of commands/ ----
sed -n 's/^\.It Ic \([A-Za-z0-9_]*\).*/\1/p' man/vroc.1 | sort > "$tmp/man-words"
printf '%s\n' "$words" > "$tmp/words"
if cmp -s "$tmp/man-words" "$tmp/words"; then
    ok "man/vroc.1 lists exactly the $nwords commands of commands/"
else
    diff "$tmp/words" "$tmp/man-words" > "$tmp/err" 2>&1
    not_ok "man/vroc.1 lists exactly the commands of commands/ (< commands/, > man)" "$tmp/err"
fi

# ---- checks that run the binary ----
if [ ! -x "$VROC" ]; then
    echo "$VROC: no such executable (build it with make)" > "$tmp/err"
    not_ok "help lists every command of commands/" "$tmp/err"
    not_ok "help WORD prints the usage line of every command" "$tmp/err"
    not_ok "help nosuch fails with status 1 and names nosuch" "$tmp/err"
    exit 0
fi

# ---- (e) help lists every command; help WORD prints its usage ----
"$VROC" -b -c 'help' < /dev/null > "$tmp/help" 2>&1
status=$?
: > "$tmp/err"
[ $status -eq 0 ] || echo "help exited with status $status" >> "$tmp/err"
for w in $words; do
    grep -Eq "(^|[^A-Za-z0-9_.])$w([^A-Za-z0-9_]|\$)" "$tmp/help" ||
        echo "missing: $w" >> "$tmp/err"
done
if [ ! -s "$tmp/err" ]; then
    ok "help lists all $nwords commands of commands/"
else
    not_ok "help lists every command of commands/" "$tmp/err"
fi

: > "$tmp/err"
for w in $words; do
    usage=$(sed -n 's/^usage: //p' "commands/$w")
    if ! "$VROC" -b -c "help $w" < /dev/null > "$tmp/one" 2>&1; then
        echo "help $w: exit status not 0" >> "$tmp/err"
    elif ! grep -Fq -- "$usage" "$tmp/one"; then
        echo "help $w: no line with: $usage" >> "$tmp/err"
    fi
done
if [ ! -s "$tmp/err" ]; then
    ok "help WORD prints the usage line of each of the $nwords commands"
else
    not_ok "help WORD prints the usage line of every command" "$tmp/err"
fi

# ---- (g) an unknown word is an error that names it ----
"$VROC" -b -c 'help nosuch' < /dev/null > "$tmp/out" 2>&1
status=$?
if [ $status -eq 1 ] && grep -q nosuch "$tmp/out"; then
    ok "help nosuch fails with status 1 and names nosuch"
else
    { echo "exit status $status; output:"; cat "$tmp/out"; } > "$tmp/err"
    not_ok "help nosuch fails with status 1 and names nosuch" "$tmp/err"
fi
exit 0
