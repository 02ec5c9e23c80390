#!/bin/sh
# instants.sh: the earlier guarantees on a world of contacts that begin at one
# instant (issue 34; tests/instants.vroc: a plank on two supports, a ball into a
# groove, a touching cradle on a floor, a ball onto a touching stack, a leaning
# cube, e = 1): saved after every frame from 0 to 40 (a few under the
# sanitizers) and read back to the bit (tests/sweep.sh); a run split anywhere
# equals the whole; the heap on and off, and the validation build (its
# invariants checked after every internal step), give the same trace; no
# restart, unsolved contact or overflow; and after 100 frames nothing overlaps.
# Then a pair whose collision the speed limits cut does not chatter.
. "$(dirname "$0")/lib.sh"
. "$(dirname "$0")/sweep.sh"
W="$(cd "$(dirname "$0")" && pwd)/instants.vroc"
cd "$TMP" || exit 1

frames=$(seq 0 40)
[ "${BUILD:-build}" = build-san ] && frames="0 3 17"
sweep instants "$W" "$frames" 20

split_runs "instants" "$W"

n=100
[ "${BUILD:-build}" = build-san ] && n=20
same_traces instants "$W" "$n"

# the stats, and every dynamic object's distance to every other object after the
# run (none in: each at least minus the contact distance, 1e-9 m)
dyn="plank groove-ball c1 c2 c3 c4 c5 stack-low stack-top stack-ball leaning"
all="floor support-left support-right groove-left groove-right cradle-left cradle-right $dyn"
cmds="run $n; stats"
for a in $dyn; do
    for b in $all; do
        [ "$a" = "$b" ] && continue
        cmds="$cmds; distance $a $b"
    done
done
"$VROC" -b -q "$W" -c "$cmds" > end.txt 2>&1
if grep -q '^restarts = 0$' end.txt && grep -q '^unsolved = 0$' end.txt && grep -q '^overflows = 0$' end.txt; then
    ok "instants: stats shows no restart, unsolved contact or overflow"
else
    notok "instants: stats shows no restart, unsolved contact or overflow" "$(grep -E '^(restarts|unsolved|overflows) =' end.txt)"
fi
bad=$(awk '/^distance/ && $3 + 0 < -1e-9 { print }' end.txt | head -3)
m=$(grep -c '^distance' end.txt)
if [ -z "$bad" ] && [ "$m" -gt 100 ]; then
    ok "instants: after $n frames nothing overlaps ($m distances)"
else
    notok "instants: after $n frames nothing overlaps ($m distances)" "$bad"
fi
# a pair whose collision the speed limits cut stays closed, and does not part
# and meet again ever more slowly (tests/spinning-pair.vroc: 2 collisions on
# main before the instants, 49,411 in 14 frames before the fix)
"$VROC" -b -q "$(dirname "$W")/spinning-pair.vroc" -c "run 14; stats" > pair.txt 2>&1
c=$(awk '/^collisions = / { print $3 }' pair.txt)
if [ -n "$c" ] && [ "$c" -ge 1 ] && [ "$c" -le 50 ] && grep -q '^speed_cuts = [1-9]' pair.txt; then
    ok "instants: a spinning pair whose collision max_angular cuts stays together ($c collisions)"
else
    notok "instants: a spinning pair whose collision max_angular cuts stays together" "$(grep -E '^(collisions|speed_cuts) =' pair.txt)"
fi
exit 0
