#!/bin/sh
# fuzz.sh: the fuzz campaigns' regression corpus, replayed under the sanitizers.
#
# Every input in tests/fuzz/regress/ once crashed vroc or hung it without
# legitimately large work (tools/fuzz.sh says how they are found).  Each is run
# as the campaign ran it, `vroc -b -q INPUT` in a scratch folder with
# VROC_SANDBOX=1, under a time limit: it must end by itself with status 0 or 1
# (an error is fine), with no signal and no sanitizer report.  Only the sanitizer
# build (BUILD=build-san) replays them; with the normal build this prints
# nothing.  First the replay itself is checked on inputs made to fail it.
. "$(dirname "$0")/lib.sh"
R=$(cd "$(dirname "$0")/fuzz/regress" && pwd)
[ "${BUILD:-build}" = build-san ] || exit 0
limit=${FUZZ_REPLAY_TIME:-60}

# replay FILE SECONDS: prints "ok", "timeout", "report" or "status N" and keeps
# vroc's error output in $TMP/replay.err (called with its own standard error
# sent away, where the shell says "Killed" of a timeout)
replay() {
    rm -rf "$TMP/work"
    mkdir -p "$TMP/work"
    (cd "$TMP/work" && VROC_SANDBOX=1 timeout -s KILL "$2" "$VROC" -b -q "$1" > /dev/null 2> "$TMP/replay.err")
    status=$?
    case "$status" in
        0 | 1) if grep -qE 'Sanitizer|runtime error' "$TMP/replay.err"; then echo report; else echo ok; fi ;;
        137) echo timeout ;;
        *) echo "status $status" ;;
    esac
}

# the replay catches what it is for: an input that runs past the limit, and an
# error that is not a sanitizer report passes
printf 'sphere a\nrun 1000000000\n' > "$TMP/slow.vroc"
got=$(replay "$TMP/slow.vroc" 2 2> /dev/null)
[ "$got" = timeout ] && ok "the replay stops an input at its time limit and says so" ||
    notok "the replay stops an input at its time limit and says so" "got: $got"
printf 'sphere a\nradius = 1e77\n' > "$TMP/error.vroc"
got=$(replay "$TMP/error.vroc" 20 2> /dev/null)
[ "$got" = ok ] && ok "the replay lets an input end with an error (status 1)" ||
    notok "the replay lets an input end with an error (status 1)" "got: $got"

for f in "$R"/*; do
    [ -f "$f" ] || continue
    name=$(basename "$f")
    [ "$name" = README ] && continue
    got=$(replay "$f" "$limit" 2> /dev/null)
    [ "$got" = ok ] && ok "fuzz regression $name ends by itself with status 0 or 1, no report" ||
        notok "fuzz regression $name ends by itself with status 0 or 1, no report" "$got" "$(head -5 "$TMP/replay.err")"
done
exit 0
