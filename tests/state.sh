#!/bin/sh
# state.sh: exact state (issue 24; language.md, "Exact state").  For every scene:
# run 20, save, then 30 frames on from the running world and from the saved file
# read into a fresh vroc give the same trace and hash, to the bit (and say the
# same, but for the speed limits' warning: a world read back counts its cuts
# afresh, as stats are not part of the state); a run split
# anywhere (run 10 then step, run 7 then run 13) equals the whole (run 11, run 20)
# by hash, and no split is refused as interpenetrating.  Reading a saved world
# leaves the user's logs alone, and a saved random sequence goes on where it was.
. "$(dirname "$0")/lib.sh"
S=$(cd "$(dirname "$0")/../scenes" && pwd)
cd "$TMP" || exit 1

for f in "$S"/*.vroc; do
    n=$(basename "$f" .vroc)
    "$VROC" -b -q "$f" -c "run 20; save $n.save.vroc; trace = $n.a.csv; run 30; hash" > "$n.a.txt" 2>&1
    "$VROC" -b -q "$n.save.vroc" -c "trace = $n.b.csv; run 30; hash" > "$n.b.txt" 2>&1
    no_cut_warning < "$n.a.txt" > "$n.a.said"
    no_cut_warning < "$n.b.txt" > "$n.b.said"
    if [ -s "$n.a.csv" ] && cmp -s "$n.a.csv" "$n.b.csv" && cmp -s "$n.a.said" "$n.b.said" &&
        grep -q '^hash = [0-9a-f]\{16\}$' "$n.a.txt"; then
        ok "$n: saved at frame 20 and read back, 30 frames on give the same trace and hash"
    else
        notok "$n: saved at frame 20 and read back, 30 frames on give the same trace and hash" \
            "$(cat "$n.a.txt" "$n.b.txt" | head -4)" "$(cmp "$n.a.csv" "$n.b.csv" 2>&1)"
    fi
    h11=$("$VROC" -b -q "$f" -c "run 11; hash" 2>&1)
    h10=$("$VROC" -b -q "$f" -c "run 10; step; hash" 2>&1)
    h20=$("$VROC" -b -q "$f" -c "run 20; hash" 2>&1)
    h713=$("$VROC" -b -q "$f" -c "run 7; run 13; hash" 2>&1)
    if [ "$h11" = "$h10" ] && [ "$h20" = "$h713" ] && [ "$h11" != "$h20" ]; then
        ok "$n: run 10 then step equals run 11, run 7 then run 13 equals run 20"
    else
        notok "$n: run 10 then step equals run 11, run 7 then run 13 equals run 20" \
            "run 11: $h11" "run 10; step: $h10" "run 20: $h20" "run 7; run 13: $h713"
    fi
done

# saving a world whose logs are open, and reading it back, leaves the logs as they were
"$VROC" -b -q "$S/simple.vroc" -c "trace = t.csv; events = e.csv; run 5; save w.vroc" >/dev/null 2>&1
cp t.csv t0.csv
"$VROC" -b -q w.vroc -c "run 3" >/dev/null 2>&1
same "reading a saved world does not reopen its trace" t0.csv t.csv
grep -q '^# trace = "t.csv"$' w.vroc && ok "save writes the logs as comments" ||
    notok "save writes the logs as comments" "$(grep trace w.vroc)"

# the random sequence goes on where it was
"$VROC" -b -q -c "seed = 5; random 3; save r.vroc; random 2; list" > r1.txt 2>&1
"$VROC" -b -q r.vroc -c "random 2; list" > r2.txt 2>&1
same "a saved random sequence goes on where it was" r1.txt r2.txt

# exact statements read back to the bit: a quaternion, a momentum, -0
out=$("$VROC" -b -q -c "cube c; orientation = (0.5, 0.5, 0.5, 0.5); velocity = (-0, 9, 0); angular_momentum = (0.1, -0.2, 0.3); precision = exact; print c; print c.velocity" 2>&1)
printf '%s\n' "$out" | grep -qx 'orientation = (0.5, 0.5, 0.5, 0.5)' &&
    printf '%s\n' "$out" | grep -qx 'c.velocity = (-0, 9, 0)' &&
    printf '%s\n' "$out" | grep -qx 'angular_momentum = (0.1, -0.2, 0.3)' &&
    ok "orientation, velocity (unlimited, -0 kept) and angular_momentum print as given" ||
    notok "orientation, velocity (unlimited, -0 kept) and angular_momentum print as given" "$out"
expect "orientation must be a unit quaternion" 1 "orientation must be a unit quaternion" \
    "$VROC" -b -q -c "cube c; orientation = (1, 1, 0, 0)"
expect "a slide needs a static support" 1 "a slide needs slide_on" \
    "$VROC" -b -q -c "sphere s; mode = slide"
expect "touching needs two objects" 1 "the same object" \
    "$VROC" -b -q -c "sphere s; touching = s"

# a user's own overlap is still refused
expect "an overlap the user made is refused" 1 "interpenetrate" \
    "$VROC" -b -q -c "sphere a; sphere b; translate = (0.5, 0, 0); run 1"
