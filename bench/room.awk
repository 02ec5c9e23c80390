# room.awk: a room 8 m by 8 m, 6 m high, as one OBJ of square tiles n to a metre
# (n = 2.5: 2,000 tiles; n = 0.125 would be less than one: pass n = 0 for the six
# faces alone) whose faces all face in, and a scene of 100 random objects in it
# (bench/run.sh: a room of many static pieces against the same objects in an
# empty box).
#   awk -v n=2.5 -v obj=FILE.obj -v scene=FILE.vroc -f bench/room.awk
function v(x, y, z) { printf "v %.6f %.6f %.6f\n", x, y, z > obj; return ++nv }
# a wall from corner o along u (nu tiles) and w (nw tiles), facing u x w
function face(ox, oy, oz, ux, uy, uz, wx, wy, wz, nu, nw,    i, j, a, b, c, d) {
    for (i = 0; i < nu; i++)
        for (j = 0; j < nw; j++) {
            a = v(ox + ux * i / nu + wx * j / nw, oy + uy * i / nu + wy * j / nw, oz + uz * i / nu + wz * j / nw)
            b = v(ox + ux * (i + 1) / nu + wx * j / nw, oy + uy * (i + 1) / nu + wy * j / nw,
                  oz + uz * (i + 1) / nu + wz * j / nw)
            c = v(ox + ux * (i + 1) / nu + wx * (j + 1) / nw, oy + uy * (i + 1) / nu + wy * (j + 1) / nw,
                  oz + uz * (i + 1) / nu + wz * (j + 1) / nw)
            d = v(ox + ux * i / nu + wx * (j + 1) / nw, oy + uy * i / nu + wy * (j + 1) / nw,
                  oz + uz * i / nu + wz * (j + 1) / nw)
            printf "f %d %d %d %d\n", a, b, c, d > obj
        }
}
BEGIN {
    nxy = n > 0 ? int(8 * n + 0.5) : 1
    nz = n > 0 ? int(6 * n + 0.5) : 1
    printf "o room\n" > obj
    face(-4, -4, -3, 8, 0, 0, 0, 8, 0, nxy, nxy)   # floor, up
    face(-4, -4, 3, 0, 8, 0, 8, 0, 0, nxy, nxy)    # ceiling, down
    face(-4, -4, -3, 0, 0, 6, 8, 0, 0, nz, nxy)    # y = -4, towards +y
    face(4, -4, -3, 0, 0, 6, 0, 8, 0, nz, nxy)     # x = 4, towards -x
    face(4, 4, -3, 0, 0, 6, -8, 0, 0, nz, nxy)     # y = 4, towards -y
    face(-4, 4, -3, 0, 0, 6, 0, -8, 0, nz, nxy)    # x = -4, towards +x
    printf "time_step = 0.1\nmax_linear = 2\nmax_angular = 2\ncollision_dist = 0.2\n" > scene
    printf "polyhedron room\nmass = -1\nfile = \"%s\"\n", obj > scene
    printf "random_box = (3.6, 3.6, 2.6)\nseed = 1\nrandom 100\n" > scene
}
