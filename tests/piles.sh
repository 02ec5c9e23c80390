#!/bin/sh
# piles.sh: the earlier guarantees on a pile whose objects press together (issue
# 35, cluster.h, apart.h): 60 random objects of seed 2 with elasticity 0.5
# dropped into a room, stepped as clusters from the first second on, their
# closed points stopped at each step's end, and pairs left overlapping moved
# apart at frames' ends.  Saved after frames 10 and 11 (11 under the
# sanitizers) and read back to the bit (tests/sweep.sh); a run split anywhere
# equals the whole; the heap on and off, and the validation build, give the
# same trace; and the same run twice gives the same hash.  It is issue 35's
# frictionless pile: friction and rolling friction 0.
. "$(dirname "$0")/lib.sh"
. "$(dirname "$0")/sweep.sh"
cd "$TMP" || exit 1
W="$TMP/pile2.vroc"
cat > make.vroc <<'V'
default_friction = 0; default_rolling_friction = 0
gravity
cube floor; mass = -1; size = (2, 2, 0.1); translate = (0, 0, -1.35)
cube wall-n; mass = -1; size = (2.2, 0.1, 1.4); translate = (0, 2.1, 0)
cube wall-s; mass = -1; size = (2.2, 0.1, 1.4); translate = (0, -2.1, 0)
cube wall-e; mass = -1; size = (0.1, 2, 1.4); translate = (2.1, 0, 0)
cube wall-w; mass = -1; size = (0.1, 2, 1.4); translate = (-2.1, 0, 0)
seed = 2; random_box = (1.95, 1.95, 1.05)
random 60
V
# (every object's elasticity 0.5, as test_pressure's piles have it)
"$VROC" -b -q make.vroc -c "save made.vroc" > /dev/null 2>&1
sed 's/^elasticity = 1$/elasticity = 0.5/' made.vroc > "$W"
if [ "$(grep -c '^elasticity = 0.5$' "$W")" -eq 65 ]; then ok "piles: a pile of 60 with elasticity 0.5 made"
else notok "piles: a pile of 60 with elasticity 0.5 made" "$(grep -c '^elasticity' "$W") elasticities"; fi

frames="10 11"
[ "${BUILD:-build}" = build-san ] && frames="11"
sweep piles "$W" "$frames" 3

split_runs "piles" "$W"
same_hash piles "$W" "run 15" "run 15" "the same run twice gives the same hash"

same_traces piles "$W" 20 stats
if grep -q '^unsolved = 0$' out-on && grep -q '^guards = 0$' out-on; then
    ok "piles: no unsolved contact and no guard"
else
    notok "piles: no unsolved contact and no guard" "$(grep -E '^(unsolved|guards) =' out-on)"
fi
exit 0
