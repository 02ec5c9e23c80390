# spin.awk: two objects of radius 0.3 spinning in place 0.1 m apart, about
# different axes, never touching (issue 40: closest features on coherent motion
# whose cost does not grow with the polyhedra; bench/run.sh runs it with the heap
# off, so the pair is searched every internal step).  kind=sq: superquadrics of
# exponents 1 at res x res; kind=file: polyhedra read from an OFF file of n points
# spread over the sphere (a Fibonacci lattice, every point on the hull), written
# to obj.
#   awk -v kind=sq -v res=160 -f bench/spin.awk > SCENE.vroc
#   awk -v kind=file -v n=5000 -v obj=FILE.off -f bench/spin.awk > SCENE.vroc
function object(name, x, w) {
    if (kind == "sq") {
        printf "superquadric %s\na1 = 0.3\na2 = 0.3\na3 = 0.3\nures = %d\nvres = %d\n", name, res, res
    } else {
        printf "polyhedron %s\nfile = \"%s\"\n", name, obj
    }
    printf "mass = 1\ntranslate = (%s, 0, 0)\nangular_vel = %s\n", x, w
}
BEGIN {
    if (kind == "file") {
        g = 3.14159265358979323846 * (3 - sqrt(5))
        printf "OFF\n%d 0 0\n", n > obj
        for (i = 0; i < n; i++) {
            z = 1 - (2 * i + 1.0) / n; r = sqrt(1 - z * z)
            printf "%.17g %.17g %.17g\n", 0.3 * r * cos(g * i), 0.3 * r * sin(g * i), 0.3 * z > obj
        }
        close(obj)
    }
    printf "time_step = 0.1\ncollision_dist = 0.2\nmax_linear = 2\nmax_angular = 4\n"
    object("s1", 0, "(0.3, 1, 0.2)")
    object("s2", 0.7, "(-1, 0.4, 0.5)")
}
