#!/bin/sh
# fuzz.sh: the fuzz campaigns' regression corpus, replayed under the sanitizers.
#
# Every input in tests/fuzz/regress/ once crashed vroc or hung it without
# legitimately large work (tools/fuzz.sh says how they are found).  Each is run
# as the campaign ran it, `vroc -b -q INPUT` in a scratch folder with
# VROC_SANDBOX=1, or for a reader's finding (mesh-FORMAT-WHAT) `fuzz_mesh FORMAT
# INPUT`, under a time limit: it must end by itself with status 0 or 1
# (an error is fine), with no signal and no sanitizer report.  The readers' seeds
# (tests/fuzz/mesh-seeds/) are replayed too, each with every reader and with the
# content deciding: a seed is read by its own reader and refused by the others.  Only the sanitizer
# build (BUILD=build-san) replays them; with the normal build this prints
# nothing.  First the replay itself is checked on inputs made to fail it.
. "$(dirname "$0")/lib.sh"
R=$(cd "$(dirname "$0")/fuzz/regress" && pwd)
[ "${BUILD:-build}" = build-san ] || exit 0
limit=${FUZZ_REPLAY_TIME:-60}
MESH=$(cd "$(dirname "$0")/.." && pwd)/build-san/tests/fuzz_mesh

# replay FILE SECONDS: prints "ok", "timeout", "report" or "status N" and keeps
# vroc's error output in $TMP/replay.err (called with its own standard error
# sent away, where the shell says "Killed" of a timeout)
replay() {
    rm -rf "$TMP/work"
    mkdir -p "$TMP/work"
    case "$(basename "$1")" in
    mesh-*) # mesh-FORMAT-WHAT: that reader
        fmt=$(basename "$1" | cut -d- -f2)
        (cd "$TMP/work" && timeout -s KILL "$2" "$MESH" "$fmt" "$1" > /dev/null 2> "$TMP/replay.err") ;;
    *) (cd "$TMP/work" && VROC_SANDBOX=1 timeout -s KILL "$2" "$VROC" -b -q "$1" > /dev/null 2> "$TMP/replay.err") ;;
    esac
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

# the readers' seeds: each read by its own reader (and with the content
# deciding), refused by the others, never with a report
seeds=$(cd "$(dirname "$0")/fuzz/mesh-seeds" && pwd)
for f in "$seeds"/*; do
    name=$(basename "$f")
    case "$name" in *.obj) own=obj ;; *.stl) own=stl ;; *.ply) own=ply ;; *) own=off ;; esac
    fine=0
    for fmt in obj stl off ply any; do
        (cd "$TMP" && timeout -s KILL "$limit" "$MESH" "$fmt" "$f" > /dev/null 2> "$TMP/replay.err")
        status=$?
        want=1
        [ "$fmt" = "$own" ] || [ "$fmt" = any ] && want=0
        if [ "$status" -ne "$want" ] || grep -qE 'Sanitizer|runtime error' "$TMP/replay.err"; then
            notok "the readers' seed $name: $fmt ends with status $want, no report" "status $status" \
                "$(head -3 "$TMP/replay.err")"
            fine=1
        fi
    done
    [ $fine -eq 0 ] && ok "the readers' seed $name is read as $own and as its content says, and refused by the other readers"
done

for f in "$R"/*; do
    [ -f "$f" ] || continue
    name=$(basename "$f")
    [ "$name" = README ] && continue
    got=$(replay "$f" "$limit" 2> /dev/null)
    [ "$got" = ok ] && ok "fuzz regression $name ends by itself with status 0 or 1, no report" ||
        notok "fuzz regression $name ends by itself with status 0 or 1, no report" "$got" "$(head -5 "$TMP/replay.err")"
done
exit 0
