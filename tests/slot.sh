#!/bin/sh
# slot.sh: the earlier guarantees on a crowd whose cluster has more contact
# points than the 64 a cluster once held (issue 35, cluster.h, rows.h): a row of
# 26 balls of elasticity 0.5 filling a slot 1e-7 m wider than a ball end to end
# (test_pressure's crowd_in_slot_rests), frictionless.  Saved after frames 6 and 7,
# while they press together and still move, and read back to the bit
# (tests/sweep.sh); a run split anywhere equals the whole; the same run twice
# gives the same hash; the heap on and off, and the validation build, give the
# same trace; and every contact is answered: nothing unsolved, no guard, no pair
# moved apart at a frame's end.
. "$(dirname "$0")/lib.sh"
. "$(dirname "$0")/sweep.sh"
cd "$TMP" || exit 1
W="$TMP/slot.vroc"
awk 'BEGIN {
    h = 0.05 + 5e-8
    print "default_friction = 0; default_rolling_friction = 0"
    print "gravity"
    print "cube floor; mass = -1; size = (0.5, 1.5, 0.05); translate = (0, 0, -0.05)"
    printf "cube side-e; mass = -1; size = (0.05, 1.5, 1); translate = (%.17g, 0, 1)\n", h + 0.05
    printf "cube side-w; mass = -1; size = (0.05, 1.5, 1); translate = (%.17g, 0, 1)\n", -h - 0.05
    print "cube end-n; mass = -1; size = (0.05, 0.05, 1); translate = (0, 1.35, 1)"
    print "cube end-s; mass = -1; size = (0.05, 0.05, 1); translate = (0, -1.35, 1)"
    for (i = 0; i < 26; i++)
        printf "sphere b%d; radius = 0.05; elasticity = 0.5; translate = (0, %.17g, %.17g); velocity = (%g, 0, 0)\n", i, -1.25 + i * 0.1, 0.05 + 0.1 * (1 + i % 4) + 0.05, (i % 3 - 1) * 0.5
}' > "$W"

# (frames 6 and 7: landed and pressed together, not yet at rest)
moving=$("$VROC" -b -q "$W" -c "run 7; stats" 2>&1 | sed -n 's/^resting = //p' | tail -1)
if [ -n "$moving" ] && [ "$moving" -lt 26 ]; then ok "slot: after 7 frames the row still moves ($moving of 26 resting)"
else notok "slot: after 7 frames the row still moves" "resting: $moving"; fi

sweep slot "$W" "6 7" 3
split_runs "slot" "$W"
same_hash slot "$W" "run 15" "run 15" "the same run twice gives the same hash"

same_traces slot "$W" 15 stats
if grep -q '^unsolved = 0$' out-on && grep -q '^guards = 0$' out-on && grep -q '^separations = 0$' out-on &&
    grep -q '^resting = 26$' out-on; then
    ok "slot: every contact answered (nothing unsolved, no guard, nothing moved apart), and all 26 rest"
else
    notok "slot: every contact answered (nothing unsolved, no guard, nothing moved apart), and all 26 rest" \
        "$(grep -E '^(unsolved|guards|separations|resting) =' out-on)"
fi
exit 0
