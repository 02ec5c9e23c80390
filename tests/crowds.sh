#!/bin/sh
# crowds.sh: the earlier guarantees on a world whose events run away (issue 35,
# guard.h): the closed box of 50 under gravity of seed 11, where one object
# takes part in a thousand events within one internal step of frame 13, and its
# contacts are answered with no bounce for the rest of that step.  (The seed is
# whichever box crowds early: seed 55's did, in frame 4, until the random
# superquadrics' hulls came from their tessellation, numbered otherwise; seed
# 78's, whose step ran to 100,000 events before the guard and let an object
# through the floor, runs away no more since a cluster's steps stop their closed
# points: cluster.h.)  Saved after frames 12 and 13 (13 under the sanitizers)
# and read back to the bit (tests/sweep.sh); a run split anywhere equals the
# whole, split just before the frame too; the heap on and off, and the
# validation build, give the same trace; stats counts the crowd, and no guard,
# overflow, restart or unsolved contact.
# It is issue 35's frictionless box: friction and rolling friction 0.
. "$(dirname "$0")/lib.sh"
. "$(dirname "$0")/sweep.sh"
cd "$TMP" || exit 1
W="$TMP/box11.vroc"
cat > "$W" <<'V'
default_friction = 0; default_rolling_friction = 0
seed = 11; random_box = (1, 1, 1); random 50
cube floor; mass = -1; size = (1.2, 1.2, 0.1); translate = (0, 0, -1.1)
cube ceiling; mass = -1; size = (1.2, 1.2, 0.1); translate = (0, 0, 1.1)
cube wall-e; mass = -1; size = (0.1, 1.2, 1.2); translate = (1.1, 0, 0)
cube wall-w; mass = -1; size = (0.1, 1.2, 1.2); translate = (-1.1, 0, 0)
cube wall-n; mass = -1; size = (1.2, 0.1, 1.2); translate = (0, 1.1, 0)
cube wall-s; mass = -1; size = (1.2, 0.1, 1.2); translate = (0, -1.1, 0)
gravity
V

frames="12 13"
[ "${BUILD:-build}" = build-san ] && frames="13"
sweep crowds "$W" "$frames" 3

split_runs "crowds" "$W"
same_hash crowds "$W" "run 13" "run 12; run 1" "run 12 then run 1 equals run 13 (the crowd's frame)"

n=14
same_traces crowds "$W" "$n" stats
if grep -q '^crowds = [1-9]' out-on && grep -q '^guards = 0$' out-on && grep -q '^overflows = 0$' out-on &&
    grep -q '^restarts = 0$' out-on && grep -q '^unsolved = 0$' out-on && ! grep -q 'ran away' out-on; then
    ok "crowds: stats counts the crowd, and no guard, overflow, restart or unsolved contact"
else
    notok "crowds: stats counts the crowd, and no guard, overflow, restart or unsolved contact" \
        "$(grep -E '^(crowds|guards|overflows|restarts|unsolved) =|ran away' out-on)"
fi
exit 0
