# kitchen.awk: writes the mesh files of scenes/kitchen.vroc (a room, a table, a
# cup, a bowl and a chair), so that the scene needs no generator:
#   awk -v dir=scenes -f tools/kitchen.awk
# The room is one OBJ of single faces (floor, ceiling, four walls) whose normals
# point into the room: a static object makes each a slab behind it.  The others
# are rigid unions of convex pieces, one OBJ group each, every piece a closed,
# outward-facing solid, so that their mass properties are the exact ones of the
# closed mesh (shape.c).  Lengths in metres, z up.
function out(name) { file = dir "/" name; nv = 0; printf "" > file }
function v(x, y, z) { printf "v %.9f %.9f %.9f\n", x, y, z > file; return ++nv }
function f4(a, b, c, d) { printf "f %d %d %d %d\n", a, b, c, d > file }
function group(name) { printf "g %s\n", name > file }
# a box from (x0, y0, z0) to (x1, y1, z1), faces outward
function box(name, x0, y0, z0, x1, y1, z1,    b) {
    group(name)
    b = nv
    v(x0, y0, z0); v(x1, y0, z0); v(x1, y1, z0); v(x0, y1, z0)
    v(x0, y0, z1); v(x1, y0, z1); v(x1, y1, z1); v(x0, y1, z1)
    f4(b + 1, b + 4, b + 3, b + 2); f4(b + 5, b + 6, b + 7, b + 8)
    f4(b + 1, b + 2, b + 6, b + 5); f4(b + 2, b + 3, b + 7, b + 6)
    f4(b + 3, b + 4, b + 8, b + 7); f4(b + 4, b + 1, b + 5, b + 8)
}
# a piece of a ring wall between angles t0 and t1: inner radius r0 at z0 to r1 at
# z1, thickness w outward; eight points, six planar quads
function wall(name, t0, t1, r0, r1, z0, z1, w,    b, c0, s0, c1, s1) {
    group(name)
    b = nv
    c0 = cos(t0); s0 = sin(t0); c1 = cos(t1); s1 = sin(t1)
    v(r0 * c0, r0 * s0, z0); v(r0 * c1, r0 * s1, z0)                       # 1 2 inner bottom
    v((r0 + w) * c0, (r0 + w) * s0, z0); v((r0 + w) * c1, (r0 + w) * s1, z0) # 3 4 outer bottom
    v(r1 * c0, r1 * s0, z1); v(r1 * c1, r1 * s1, z1)                       # 5 6 inner top
    v((r1 + w) * c0, (r1 + w) * s0, z1); v((r1 + w) * c1, (r1 + w) * s1, z1) # 7 8 outer top
    f4(b + 1, b + 3, b + 4, b + 2)   # bottom
    f4(b + 5, b + 6, b + 8, b + 7)   # top
    f4(b + 1, b + 2, b + 6, b + 5)   # inner
    f4(b + 3, b + 7, b + 8, b + 4)   # outer
    f4(b + 1, b + 5, b + 7, b + 3)   # side at t0
    f4(b + 2, b + 4, b + 8, b + 6)   # side at t1
}
# a flat disc of n sides, radius r, from z0 to z1
function disc(name, n, r, z0, z1,    b, k, t) {
    group(name)
    b = nv
    for (k = 0; k < n; k++) { t = 2 * PI * k / n; v(r * cos(t), r * sin(t), z0) }
    for (k = 0; k < n; k++) { t = 2 * PI * k / n; v(r * cos(t), r * sin(t), z1) }
    printf "f" > file
    for (k = n; k >= 1; k--) printf " %d", b + k > file
    printf "\nf" > file
    for (k = 1; k <= n; k++) printf " %d", b + n + k > file
    printf "\n" > file
    for (k = 1; k <= n; k++) f4(b + k, b + k % n + 1, b + n + k % n + 1, b + n + k)
}
# a vessel: a disc base and a ring of n wall pieces
function vessel(name, n, rb, zb, r0, r1, h, w,    k) {
    disc("base", 2 * n, rb, 0, zb)
    for (k = 0; k < n; k++)
        wall(sprintf("wall%d", k + 1), 2 * PI * k / n, 2 * PI * (k + 1) / n, r0, r1, zb, h, w)
}
BEGIN {
    PI = atan2(0, -1)
    if (dir == "") dir = "scenes"

    out("kitchen-room.obj")
    print "# kitchen-room.obj: a kitchen 5 m by 4 m, 2.6 m high, as single faces whose" > file
    print "# normals point inside (written by tools/kitchen.awk)" > file
    print "o room" > file
    v(-2.5, -2, 0); v(2.5, -2, 0); v(2.5, 2, 0); v(-2.5, 2, 0)
    v(-2.5, -2, 2.6); v(2.5, -2, 2.6); v(2.5, 2, 2.6); v(-2.5, 2, 2.6)
    f4(1, 2, 3, 4)   # floor, up
    f4(5, 8, 7, 6)   # ceiling, down
    f4(1, 5, 6, 2)   # y = -2, towards +y
    f4(2, 6, 7, 3)   # x = 2.5, towards -x
    f4(3, 7, 8, 4)   # y = 2, towards -y
    f4(4, 8, 5, 1)   # x = -2.5, towards +x

    out("kitchen-table.obj")
    print "# kitchen-table.obj: a table 1.2 m by 0.8 m, 0.75 m high: a top and four legs" > file
    print "# (written by tools/kitchen.awk)" > file
    box("top", -0.6, -0.4, 0.71, 0.6, 0.4, 0.75)
    box("leg1", -0.55, -0.35, 0, -0.5, -0.3, 0.71)
    box("leg2", 0.5, -0.35, 0, 0.55, -0.3, 0.71)
    box("leg3", 0.5, 0.3, 0, 0.55, 0.35, 0.71)
    box("leg4", -0.55, 0.3, 0, -0.5, 0.35, 0.71)

    out("kitchen-cup.obj")
    print "# kitchen-cup.obj: a cup 0.12 m across and 0.1 m high: a base and twelve" > file
    print "# wall pieces (written by tools/kitchen.awk)" > file
    vessel("cup", 12, 0.06, 0.01, 0.05, 0.05, 0.1, 0.01)

    out("kitchen-bowl.obj")
    print "# kitchen-bowl.obj: a bowl 0.3 m across at its rim and 0.08 m deep: a base and" > file
    print "# sixteen flared wall pieces (written by tools/kitchen.awk)" > file
    vessel("bowl", 16, 0.08, 0.01, 0.07, 0.14, 0.08, 0.01)

    out("kitchen-chair.obj")
    print "# kitchen-chair.obj: a chair, its seat 0.45 m high: a seat, four legs and a" > file
    print "# back (written by tools/kitchen.awk)" > file
    box("seat", -0.22, -0.22, 0.42, 0.22, 0.22, 0.46)
    box("leg1", -0.22, -0.22, 0, -0.18, -0.18, 0.42)
    box("leg2", 0.18, -0.22, 0, 0.22, -0.18, 0.42)
    box("leg3", 0.18, 0.18, 0, 0.22, 0.22, 0.42)
    box("leg4", -0.22, 0.18, 0, -0.18, 0.22, 0.42)
    box("back", -0.22, 0.18, 0.46, 0.22, 0.22, 0.9)
}
