#!/bin/sh
# fuzz.sh: the fuzz campaigns' regression corpus, replayed under the sanitizers.
#
# Every input in tests/fuzz/regress/ once crashed vroc or hung it without
# legitimately large work (tools/fuzz.sh says how they are found).  Each is run
# as the campaign ran it, `vroc -b -q INPUT` in a scratch folder with
# VROC_SANDBOX=1, under a time limit: it must end by itself with status 0 or 1
# (an error is fine), with no signal and no sanitizer report.  Only the sanitizer
# build (BUILD=build-san) replays them; with the normal build this prints
# nothing.
. "$(dirname "$0")/lib.sh"
R=$(cd "$(dirname "$0")/fuzz/regress" && pwd)
[ "${BUILD:-build}" = build-san ] || exit 0
limit=${FUZZ_REPLAY_TIME:-60}
n=0
for f in "$R"/*; do
    [ -f "$f" ] || continue
    [ "$(basename "$f")" = README ] && continue
    n=$((n + 1))
    name=$(basename "$f")
    rm -rf "$TMP/work"
    mkdir -p "$TMP/work"
    out=$(cd "$TMP/work" && VROC_SANDBOX=1 timeout -s KILL "$limit" "$VROC" -b -q "$f" 2>&1 >/dev/null)
    status=$?
    case "$status" in
        0 | 1) if printf '%s' "$out" | grep -qE 'Sanitizer|runtime error|LeakSanitizer'; then
                   notok "fuzz regression $name: no sanitizer report" "$(printf '%s' "$out" | head -5)"
               else
                   ok "fuzz regression $name ends with status $status"
               fi ;;
        137) notok "fuzz regression $name ends within $limit s" ;;
        *) notok "fuzz regression $name ends with status 0 or 1" "status $status" "$(printf '%s' "$out" | head -5)" ;;
    esac
done
exit 0
