/* bench_mesh.c: the mesh readers' benchmark (issue 38; bench/run.sh prints its
 * table).
 *
 *   bench_mesh make DIR    writes DIR/torus-1m.stl, a binary STL of 1,000,000
 *                          triangles, and DIR/torus-600k.obj, an OBJ of 600,000
 *                          triangles: tori, tessellated in a grid (their vertices
 *                          shared, as a scan's are; half of them on the hull)
 *   bench_mesh read FILE   reads FILE as `file =` does (its bytes, their SHA-256
 *                          left out, the reader, the drawing mesh): one line
 *                          read_s=... cpu_s=... peak_rss_mb=... points=... triangles=...
 *   bench_mesh load FILE   the same, then the body: the exact hull of the points
 *                          and its mass properties (shape_build), as `file =`
 *                          does: load_s=... hull_s=... peak_rss_mb=... hull_vertices=...
 *   bench_mesh child CMD...  runs CMD (assimp info FILE) and prints wall_s=...
 *                          peak_rss_mb=... status=... of it (wait4's rusage)
 *
 * Each measurement is one process, so that its peak resident set is its own.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <stdbool.h>
#include <unistd.h>

#include "bench.h"
#include "core/shape.h"
#include "mesh/meshfile.h"

/* Point (i, j) of an nu x nv grid on a torus of radii 1 and 0.35, in float32. */
static void torus(int i, int j, int nu, int nv, float out[3])
{
    double u = 2 * M_PI * (i % nu) / nu, v = 2 * M_PI * (j % nv) / nv, r = 1 + 0.35 * cos(v);
    out[0] = (float)(r * cos(u));
    out[1] = (float)(r * sin(u));
    out[2] = (float)(0.35 * sin(v));
}

static int make(const char *dir)
{
    char path[4096];
    /* 1000 x 500 quads, two triangles each */
    int nu = 1000, nv = 500;
    snprintf(path, sizeof path, "%s/torus-1m.stl", dir);
    FILE *f = fopen(path, "wb");
    if (!f) return perror(path), 1;
    char header[80] = "binary STL: a torus of 1,000,000 triangles (vroc's bench_mesh)";
    fwrite(header, 1, 80, f);
    unsigned n = 2u * (unsigned)nu * (unsigned)nv;
    unsigned char c[4] = {(unsigned char)n, (unsigned char)(n >> 8), (unsigned char)(n >> 16),
                          (unsigned char)(n >> 24)};
    fwrite(c, 1, 4, f);
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            float p[4][3], rec[12];
            torus(i, j, nu, nv, p[0]);
            torus(i + 1, j, nu, nv, p[1]);
            torus(i + 1, j + 1, nu, nv, p[2]);
            torus(i, j + 1, nu, nv, p[3]);
            static const int T[2][3] = {{0, 1, 2}, {0, 2, 3}};
            for (int t = 0; t < 2; t++) {
                memset(rec, 0, sizeof rec);
                for (int k = 0; k < 3; k++) memcpy(&rec[3 + 3 * k], p[T[t][k]], sizeof p[0]);
                fwrite(rec, sizeof rec, 1, f); /* (little-endian floats on this machine) */
                fwrite("\0\0", 1, 2, f);
            }
        }
    if (fclose(f) != 0) return perror(path), 1;
    /* 600 x 500 quads as 600,000 triangles, vertices shared */
    nu = 600;
    nv = 500;
    snprintf(path, sizeof path, "%s/torus-600k.obj", dir);
    f = fopen(path, "w");
    if (!f) return perror(path), 1;
    fprintf(f, "# a torus of 600,000 triangles (vroc's bench_mesh)\no torus\n");
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            float p[3];
            torus(i, j, nu, nv, p);
            fprintf(f, "v %.7g %.7g %.7g\n", p[0], p[1], p[2]);
        }
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            int a = i * nv + j + 1, b = ((i + 1) % nu) * nv + j + 1;
            int c2 = ((i + 1) % nu) * nv + (j + 1) % nv + 1, d = i * nv + (j + 1) % nv + 1;
            fprintf(f, "f %d %d %d\nf %d %d %d\n", a, b, c2, a, c2, d);
        }
    if (fclose(f) != 0) return perror(path), 1;
    return 0;
}

/* Reads path into a source; NULL with the message printed. */
static mesh_source *read_source(const char *path)
{
    unsigned char *data;
    size_t len;
    char err[512];
    if (mesh_read_bytes(path, &data, &len, err, sizeof err) != 0) {
        fprintf(stderr, "bench_mesh: %s: %s\n", path, err);
        return NULL;
    }
    mesh_file m;
    int rc = mesh_parse(data, len, path, &m, err, sizeof err);
    free(data);
    if (rc != 0) {
        fprintf(stderr, "bench_mesh: %s\n", err);
        return NULL;
    }
    mesh_source *src = mesh_source_make(&m, path, err, sizeof err);
    mesh_file_free(&m);
    if (!src) fprintf(stderr, "bench_mesh: %s\n", err);
    return src;
}

static int read_or_load(const char *path, bool load)
{
    double t0 = now(), c0 = cpu_now();
    mesh_source *src = read_source(path);
    if (!src) return 1;
    double t1 = now(), c1 = cpu_now();
    if (!load) {
        printf("read_s=%.4f cpu_s=%.4f peak_rss_mb=%.1f points=%d triangles=%d\n", t1 - t0,
               c1 - c0, peak_rss_mb(), src->src.np, src->src.draw.nt);
        shape_source_release(&src->src);
        return 0;
    }
    shape_params p = shape_defaults(SHAPE_POLYHEDRON);
    p.src = &src->src;
    shape s;
    char err[512];
    if (shape_build(&s, &p, err, sizeof err) != 0) {
        fprintf(stderr, "bench_mesh: %s: %s\n", path, err);
        return 1;
    }
    double t2 = now();
    printf("load_s=%.4f hull_s=%.4f peak_rss_mb=%.1f hull_vertices=%d hull_faces=%d\n", t2 - t0,
           t2 - t1, peak_rss_mb(), s.hull->nv, s.hull->nf);
    shape_free(&s);
    shape_source_release(&src->src);
    return 0;
}

static int child(char **argv)
{
    double t0 = now();
    pid_t pid = fork();
    if (pid < 0) return perror("fork"), 1;
    if (pid == 0) {
        int null = open("/dev/null", O_WRONLY);
        if (null >= 0) dup2(null, 1);
        execvp(argv[0], argv);
        _exit(127);
    }
    int status;
    struct rusage ru;
    if (wait4(pid, &status, 0, &ru) < 0) return perror("wait4"), 1;
    printf("wall_s=%.4f peak_rss_mb=%.1f status=%d\n", now() - t0, (double)ru.ru_maxrss / 1024,
           WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status));
    return 0;
}

int main(int argc, char **argv)
{
    if (argc >= 3 && strcmp(argv[1], "make") == 0) return make(argv[2]);
    if (argc == 3 && strcmp(argv[1], "read") == 0) return read_or_load(argv[2], false);
    if (argc == 3 && strcmp(argv[1], "load") == 0) return read_or_load(argv[2], true);
    if (argc >= 3 && strcmp(argv[1], "child") == 0) return child(argv + 2);
    fprintf(stderr, "usage: bench_mesh make DIR | read FILE | load FILE | child CMD...\n");
    return 2;
}
