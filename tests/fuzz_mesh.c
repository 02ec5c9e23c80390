/* fuzz_mesh.c: the mesh readers' fuzz target (tools/fuzz.sh, tests/fuzz.sh).
 *
 * `fuzz_mesh FORMAT FILE` reads FILE with one reader (obj, stl, off or ply) or,
 * with `any`, as vroc does (the content decides), then makes the drawing mesh
 * from what it read.  It exits 0 when the file is read and 1 when it is refused;
 * anything else (a signal, a sanitizer's report) is a finding.  A message that
 * does not name the file is a finding too: it aborts.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/shape.h"
#include "mesh/meshfile.h"

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: fuzz_mesh obj|stl|off|ply|any FILE\n");
        return 2;
    }
    static const char *names[] = {"obj", "stl", "off", "ply"};
    int format = -1;
    for (int k = 0; k < 4; k++)
        if (strcmp(argv[1], names[k]) == 0) format = k;
    if (format < 0 && strcmp(argv[1], "any") != 0) {
        fprintf(stderr, "fuzz_mesh: unknown format '%s'\n", argv[1]);
        return 2;
    }
    unsigned char *data;
    size_t len;
    char err[512];
    if (mesh_read_bytes(argv[2], &data, &len, err, sizeof err) != 0) {
        fprintf(stderr, "fuzz_mesh: %s: %s\n", argv[2], err);
        return 1;
    }
    mesh_file m;
    int rc = format < 0 ? mesh_parse(data, len, argv[2], &m, err, sizeof err)
                        : mesh_parse_as((mesh_format)format, data, len, argv[2], &m, err, sizeof err);
    free(data);
    if (rc != 0) {
        if (strncmp(err, argv[2], strlen(argv[2])) != 0) abort(); /* a message names the file */
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    mesh_source *src = mesh_source_make(&m, argv[2], err, sizeof err);
    mesh_file_free(&m);
    if (!src) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    /* every triangle names vertices of the mesh */
    const mesh *d = &src->src.draw;
    for (int t = 0; t < d->nt; t++)
        for (int k = 0; k < 3; k++)
            if (d->tri[t][k] < 0 || d->tri[t][k] >= d->nv) abort();
    printf("%s: %d points, %d triangles\n", argv[2], src->src.np, d->nt);
    shape_source_release(&src->src);
    return 0;
}
