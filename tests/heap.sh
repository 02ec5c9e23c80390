#!/bin/sh
# heap.sh: on every scene, the collision heap changes no trajectory (the traces with
# collision_heap on and off are the same, byte for byte), and neither does
# rendering (the traces with record on and off are the same); record writes the
# frames' files.
. "$(dirname "$0")/lib.sh"
S=$(cd "$(dirname "$0")/../scenes" && pwd)
frames=100
[ "${BUILD:-build}" = build-san ] && frames=15
for f in "$S"/*.vroc; do
    name=$(basename "$f" .vroc)
    "$VROC" -b -q "$f" -c "collision_heap = on; trace = $TMP/on.csv; run $frames" > "$TMP/out-on" 2>&1
    s1=$?
    "$VROC" -b -q "$f" -c "collision_heap = off; trace = $TMP/off.csv; run $frames" > "$TMP/out-off" 2>&1
    s2=$?
    if [ $s1 -ne 0 ] || [ $s2 -ne 0 ]; then
        notok "$name: runs with the heap on and off" "$(head -3 "$TMP/out-on" "$TMP/out-off")"
        continue
    fi
    same "$name: the heap changes no trajectory ($frames frames)" "$TMP/on.csv" "$TMP/off.csv"
done

# rendering never changes the simulation, and record writes every frame
f="$S/simple.vroc"
"$VROC" -b -q "$f" -c "trace = $TMP/plain.csv; run 10" > /dev/null 2>&1
"$VROC" -b -q "$f" -c "output = \"$TMP/rec\"; record = on; trace = $TMP/rec.csv; run 10" > /dev/null 2>&1
same "rendering changes no trajectory" "$TMP/plain.csv" "$TMP/rec.csv"
n=$(ls "$TMP/rec" 2>/dev/null | grep -c '^frame-0000[0-9][0-9]-\(left\|right\)\.png$')
[ "$n" -eq 20 ] && ok "record = on with run 10 writes 20 files" || notok "record = on with run 10 writes 20 files" "got $n"
"$VROC" -b -q "$f" -c "output = \"$TMP/one\"; stereo = sbs; refresh; stereo = anaglyph; refresh; stereo = mono; step; refresh" > /dev/null 2>&1
for want in frame-000000-sbs.png frame-000000-anaglyph.png frame-000001-left.png; do
    [ -s "$TMP/one/$want" ] && ok "refresh writes $want" || notok "refresh writes $want" "$(ls "$TMP/one")"
done
# a folder that cannot be written: a clear error, and a batch run stops there with a
# failure status (at the prompt time goes on: test_shell)
: > "$TMP/file"
out=$("$VROC" -b "$f" -c "output = \"$TMP/file/sub\"; record = on; run 3; time" 2>&1)
status=$?
case "$out" in
*"error: record:"*"$TMP/file/sub"*"time stopped"*"time = "*) notok "an output folder that cannot be written stops a batch run" "$out" ;;
*"error: record:"*"$TMP/file/sub"*"time stopped"*)
    [ $status -ne 0 ] && ok "an output folder that cannot be written stops a batch run" ||
        notok "an output folder that cannot be written stops a batch run" "exit status $status" ;;
*) notok "an output folder that cannot be written stops a batch run" "$out" ;;
esac
exit 0
