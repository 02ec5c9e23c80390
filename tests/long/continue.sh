#!/bin/sh
# long/continue.sh: the long sweep of exact state (make check-long; issue 31).
# Every shipped scene saved after every 10th frame from 0 to 300; and 50 random
# worlds of 20 to 200 objects in a walled room under gravity, falling into piles
# that come to rest on its floor, with a ball the hand grabs and throws by a
# tracker file (the first two with the collision heap off), saved after every
# 5th frame from 0 to 20, while they fall, pile and are thrown at, and run on 10
# frames.  Each saved world must read back to the bit and run on to the unbroken
# run's trace and hash (tests/sweep.sh says what is checked).  The sweeps run two
# at a time, on the two cores the tests may use.
#
# The random objects' elasticity is 0.5, so that piles come to rest: some piles
# of perfectly elastic objects, a few seconds in, collide 100,000 times a second
# and take minutes a frame (the schedule's worst case, not the saved state's).
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../sweep.sh"
S=$(cd "$(dirname "$0")/../../scenes" && pwd)
cd "$TMP" || exit 1

set -- "$S"/*.vroc
while [ $# -gt 0 ]; do
    for f in "$1" ${2:+"$2"}; do
        sweep "$(basename "$f" .vroc)" "$f" "$(seq 0 10 300)" 20 > "$TMP/out-$(basename "$f")" 2>&1 &
    done
    wait
    cat "$TMP/out-$(basename "$1")" ${2:+"$TMP/out-$(basename "$2")"}
    shift
    [ $# -gt 0 ] && shift
done

# world K: N objects from 20 to 200, random places, sizes, speeds and spins
# (seed K) in a room 4 m wide, 2.7 m tall, over a floor at z = -1.25; a ball
# above them that the hand holds from time 0 and throws between 0.4 and 0.9 s
# (direction, speed and spin drawn from K); heap off for K = 0 and 5 (the heap
# off checks every pair every step: 20 and 38 objects)
world() { # K: writes world-K.vroc and world-K.csv
    awk -v k="$1" -v dir="$TMP" 'BEGIN {
        srand(1000 + k)
        n = 20 + int(k * 180 / 49)
        f = dir "/world-" k ".vroc"
        print "gravity" > f
        print "cube floor; mass = -1; size = (2, 2, 0.1); translate = (0, 0, -1.35); elasticity = 0.5" > f
        print "cube wall-n; mass = -1; size = (2.2, 0.1, 1.4); translate = (0, 2.1, 0)" > f
        print "cube wall-s; mass = -1; size = (2.2, 0.1, 1.4); translate = (0, -2.1, 0)" > f
        print "cube wall-e; mass = -1; size = (0.1, 2, 1.4); translate = (2.1, 0, 0)" > f
        print "cube wall-w; mass = -1; size = (0.1, 2, 1.4); translate = (-2.1, 0, 0)" > f
        print "sphere ball; radius = 0.1; mass = 0.4; elasticity = 0.7; translate = (0, 0, 1.3)" > f
        printf "seed = %d; random_box = (1.95, 1.95, 1.05)\nrandom %d\n", k + 1, n > f
        # (random names them from random7 on, after the six objects above)
        for (i = 7; i < 7 + n; i++) printf "random%d.elasticity = 0.5\n", i > f
        if (k == 0 || k == 5) print "collision_heap = off" > f
        printf "select on\ntracker = \"world-%d.csv\"\n", k > f
        close(f)
        c = dir "/world-" k ".csv"
        print "time,x,y,z,qw,qx,qy,qz,trigger,button" > c
        t1 = 0.4 + 0.5 * rand()                      # the throw ends, and the hand lets go
        a = 6.2832 * rand(); s = 1 + 3 * rand(); w = 4 * rand()
        vx = s * cos(a); vy = s * sin(a); vz = 1 + 2 * rand()
        printf "0,0,0,1.3,1,0,0,0,1,0\n0.2,0,0,1.3,1,0,0,0,1,0\n" > c
        # from 0.2 s to t1 the hand goes at (vx, vy, vz), turning about z by w (t1 - 0.2)
        d = t1 - 0.2; h = w * d / 2
        printf "%.6f,%.6f,%.6f,%.6f,%.9f,0,0,%.9f,1,0\n", t1, vx * d, vy * d, 1.3 + vz * d, cos(h), sin(h) > c
        printf "%.6f,%.6f,%.6f,%.6f,%.9f,0,0,%.9f,0,0\n", t1 + 0.1, vx * d, vy * d, 1.3 + vz * d, cos(h), sin(h) > c
        close(c)
    }'
}
k=0
while [ $k -lt 50 ]; do
    for j in $k $((k + 1)); do
        world $j
        sweep "random-world-$j" "$TMP/world-$j.vroc" "$(seq 0 5 20)" 10 > "$TMP/out-$j" 2>&1 &
    done
    wait
    cat "$TMP/out-$k" "$TMP/out-$((k + 1))"
    k=$((k + 2))
done
