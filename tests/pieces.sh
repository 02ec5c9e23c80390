#!/bin/sh
# pieces.sh: the earlier guarantees on a world of bodies of several pieces (issue
# 39).  A room of 320 tiles read from one file (bench/room.awk writes it: 8 x 8 x
# 6 m, every tile a static slab), a cup and a chair of convex pieces standing on
# its floor, and 24 random objects (more than BROAD_SMALL: the broad phase's
# static tree, piece by piece), under gravity:
#   - nothing leaves the room, and a run says nothing of overflows or overlaps;
#   - the collision heap changes no trajectory;
#   - a run split anywhere equals the whole, and no split is refused as
#     interpenetrating;
#   - the validation build (every invariant checked after each internal step)
#     gives the same trace;
#   - saved after every frame, it reads back to the bit and runs on to the same
#     trace and hash (sweep.sh).
# And a cup stood on a seam of two tiles or a corner of four comes to rest there
# on the floor, as on one face (a slide that began on the edge of the face its
# contact named ended where it began, again and again); a box slid across three
# seams goes on as on one face, with no friction: at x0 + v t, at its height, at
# its speed, with no collision after it landed.
. "$(dirname "$0")/lib.sh"
. "$(dirname "$0")/sweep.sh"
ROOT=$(cd "$(dirname "$0")/.." && pwd)
S="$ROOT/scenes"
cd "$TMP" || exit 1
awk -v n=1 -v obj=room.obj -v scene=/dev/null -f "$ROOT/bench/room.awk"

frames=100 sweeps=$(seq 0 30)
[ "${BUILD:-build}" = build-san ] && frames=15 sweeps="0 9 23"

cat > w.vroc <<EOF
gravity
polyhedron room
mass = -1
file = "$TMP/room.obj"
polyhedron cup
mass = 0.3
elasticity = 0.3
file = "$S/kitchen-cup.obj"
translate = (1, 1, -2.9999)
polyhedron chair
mass = 4
elasticity = 0.2
file = "$S/kitchen-chair.obj"
translate = (-1, -1, -2.9999)
random_box = (3.5, 3.5, 2.5)
seed = 3
random 24
EOF

out=$("$VROC" -b -q w.vroc -c "print room.pieces; collision_heap = on; trace = on.csv; run $frames; stats" 2>&1)
"$VROC" -b -q w.vroc -c "collision_heap = off; trace = off.csv; run $frames" > off.txt 2>&1
if printf '%s\n' "$out" | grep -qx 'room.pieces = 320' && printf '%s\n' "$out" | grep -qx 'overflows = 0' &&
    printf '%s\n' "$out" | grep -qx 'unsolved = 0'; then
    ok "a room of 320 tiles, a cup, a chair and 24 objects run $frames frames with no overflow"
else
    notok "a room of 320 tiles, a cup, a chair and 24 objects run $frames frames with no overflow" \
        "$(printf '%s\n' "$out" | grep -E 'error|pieces|overflows|unsolved' | head -4)"
fi
# (the room is -4 to 4 across and -3 to 3 high: a centre outside it went through;
# the cup's and the chair's origins are on their bases, which lie on the floor,
# as close as contacts keep: within a micrometre)
gone=$(awk -F, 'NR > 1 && $3 != "room" && ($4 <= -4 || $4 >= 4 || $5 <= -4 || $5 >= 4 || $6 <= -3 - 1e-6 || $6 >= 3) {
                    print "frame " $1 ": " $3 " at (" $4 ", " $5 ", " $6 ")"; exit }' on.csv)
rows=$(awk -F, 'NR > 1 && $1 == '"$frames"' && $3 != "room"' on.csv | wc -l)
if [ -z "$gone" ] && [ "$rows" -eq 26 ]; then
    ok "every object stays inside the room of tiles at every frame"
else
    notok "every object stays inside the room of tiles at every frame" "${gone:-$rows objects at the end}"
fi
same "the heap changes no trajectory in a room of tiles ($frames frames)" on.csv off.csv

h11=$("$VROC" -b -q w.vroc -c "run 11; hash" 2>&1)
h10=$("$VROC" -b -q w.vroc -c "run 10; step; hash" 2>&1)
h20=$("$VROC" -b -q w.vroc -c "run 20; hash" 2>&1)
h713=$("$VROC" -b -q w.vroc -c "run 7; run 13; hash" 2>&1)
if [ "$h11" = "$h10" ] && [ "$h20" = "$h713" ] && [ "$h11" != "$h20" ]; then
    ok "in a room of tiles, run 10 then step equals run 11, run 7 then run 13 equals run 20"
else
    notok "in a room of tiles, run 10 then step equals run 11, run 7 then run 13 equals run 20" \
        "run 11: $h11" "run 10; step: $h10" "run 20: $h20" "run 7; run 13: $h713"
fi

VAL="$ROOT/build-val/vroc"
if [ "${BUILD:-build}" = build ]; then
    if "$VAL" -b -q w.vroc -c "trace = val.csv; run $frames" > val.txt 2>&1; then
        same "the validation build keeps every invariant in a room of tiles, with the same trace" on.csv val.csv
    else
        notok "the validation build keeps every invariant in a room of tiles" "$(head -3 val.txt)"
    fi
fi

sweep room-of-tiles w.vroc "$sweeps" 20

# a cup on a seam of two tiles, and on a corner of four: at rest on the floor
for at in "1, 0.5" "1, 1"; do
    out=$("$VROC" -b -q -c "gravity; polyhedron room; mass = -1; file = \"$TMP/room.obj\"
        polyhedron cup; mass = 0.3; elasticity = 0.3; file = \"$S/kitchen-cup.obj\"
        translate = ($at, -2.9999); run 40; list; stats; precision = exact; print cup.translate" 2>&1)
    z=$(printf '%s\n' "$out" | sed -n 's/^cup.translate = (.*, .*, \(.*\))$/\1/p')
    if printf '%s\n' "$out" | grep -q '^cup  *polyhedron  *resting$' &&
        printf '%s\n' "$out" | grep -qx 'overflows = 0' &&
        awk -v z="$z" 'BEGIN { exit !(z != "" && z + 3 >= 0 && z + 3 < 1e-6) }'; then
        ok "a cup stood at ($at) on the tiles' seams rests on the floor (z = $z)"
    else
        notok "a cup stood at ($at) on the tiles' seams rests on the floor" \
            "$(printf '%s\n' "$out" | grep -E 'error|cup|overflows' | head -4)"
    fi
done

# a box at rest on a frictionless tile (half-size 0.1: its centre 0.1 above the
# floor), given v = (1, 0.3, 0) for 2 s, crosses the seams x = 1, x = 2 and y = 1 (its one
# collision: where it landed, 0.1 mm down)
out=$("$VROC" -b -q -c "default_friction = 0; default_rolling_friction = 0
    gravity; polyhedron room; mass = -1; file = \"$TMP/room.obj\"
    cube c; size = (0.1, 0.1, 0.1); elasticity = 0.3; translate = (0.5, 0.5, -2.8999)
    run 20; linear_vel = (1, 0.3, 0); run 20; stats; precision = exact
    print c.translate; print c.linear_vel; time" 2>&1)
pos=$(printf '%s\n' "$out" | sed -n 's/^c.translate = (\(.*\))$/\1/p' | tr -d ' ')
vel=$(printf '%s\n' "$out" | sed -n 's/^c.linear_vel = (\(.*\))$/\1/p' | tr -d ' ')
if printf '%s\n' "$out" | grep -qx 'collisions = 1' && printf '%s\n' "$out" | grep -qx 'time = 4' &&
    awk -v p="$pos" -v v="$vel" 'BEGIN { split(p, x, ","); split(v, u, ",")
        exit !(x[1] - 2.5 < 1e-9 && 2.5 - x[1] < 1e-9 && x[2] - 1.1 < 1e-9 && 1.1 - x[2] < 1e-9 &&
               x[3] + 2.9 < 1e-6 && -2.9 - x[3] < 1e-6 && u[1] == 1 && u[2] == 0.3 && u[3] == 0) }'; then
    ok "a box slid across three seams of the tiles goes on as on one face (at ($pos))"
else
    notok "a box slid across three seams of the tiles goes on as on one face" \
        "$(printf '%s\n' "$out" | grep -E 'error|collisions =|translate|linear_vel|time' | head -5)"
fi
exit 0
