/* meshfile.h: polyhedra read from mesh files (OBJ, STL, OFF, PLY) by vroc's own
 * readers, and turned into what the core builds a polyhedron from.
 *
 * A file becomes a mesh_file: its vertices welded (identical coordinates made one)
 * and sorted, its faces as the file gives them (polygons of any size, indices into
 * the welded vertices), the normals it gives, and its groups (OBJ `o` and `g`, STL
 * `solid`s; one group otherwise), each a run of faces.  The content decides the
 * format; the file's extension only settles a text file that has no header (OBJ,
 * or an OFF without its "OFF").  Every bad file is refused with a message that
 * names the file and the line, or the byte offset in binary data, and says why;
 * counts in a header are checked against the file's size before anything is
 * allocated.  The readers use no library but libc.
 *
 * mesh_source_make then makes the core's shape_source (core/shape.h): the welded
 * points, the faces in runs by convex piece (the groups when the file names more
 * than one, else the connected components of the faces), and a triangle mesh of the file's own faces to draw (concave polygons
 * cut into triangles by ear clipping; the file's normals, or smooth ones made
 * where it gives none, with creases kept at sharp edges).
 */
#ifndef VROC_MESHFILE_H
#define VROC_MESHFILE_H

#include <stddef.h>

#include "core/shape.h"
#include "core/vmath.h"

/* Files larger than this are refused before they are read; the lines of their
 * text (a text format's, a binary PLY's header) are at most MESH_MAX_LINE bytes
 * (the shell reads a file through its door, shell/infile.h, and checks them). */
#define MESH_MAX_FILE (1L << 30)
#define MESH_MAX_LINE (1L << 20)

typedef enum { MESH_OBJ, MESH_STL, MESH_OFF, MESH_PLY } mesh_format;

/* A run of faces the file names as one: an OBJ group (a change of `o` or `g`
 * starts the next), an STL solid; the whole file otherwise. */
typedef struct {
    char name[64]; /* as the file names it (cut to 63 bytes), "" when it names none */
    int first;     /* its faces: first .. first + count - 1 */
    int count;
} mesh_group;

typedef struct {
    mesh_format format;
    const char *form;  /* "OBJ", "binary STL", "ASCII STL", "OFF", "ASCII PLY",
                        * "binary little-endian PLY", "binary big-endian PLY" */
    int nv;            /* distinct vertices, sorted by x, then y, then z */
    vec3 *v;
    int nf;            /* faces: face f's corners are corner[face_first[f] ..
                        * face_first[f + 1] - 1], in the file's order */
    int *face_first;   /* nf + 1 offsets */
    int *corner;       /* each corner's vertex (into v) */
    int nn;            /* normals the file gives (OBJ vn, PLY nx ny nz, NOFF) */
    vec3 *n;
    int *corner_n;     /* each corner's normal (into n, -1 for none), or NULL when
                        * the file gives none */
    int ng;            /* groups, in the file's order, covering every face */
    mesh_group *g;
} mesh_file;

/* Reads the whole file at path into *data (NUL-terminated after its *len bytes;
 * the caller frees it).  Returns 0, or -1 with why in err ("it is a folder",
 * the system's reason, a file larger than MESH_MAX_FILE). */
int mesh_read_bytes(const char *path, unsigned char **data, size_t *len, char *err, size_t errlen);

/* How many of data's first bytes are lines of text: none for a binary STL, a
 * PLY's header up to its end_header line, all of any other file. */
size_t mesh_text_length(const unsigned char *data, size_t len);

/* The format of data as its content says (name's extension settles a text file
 * with no header), or -1 with why in err (an empty file; one that is neither text
 * nor a binary STL of its size). */
int mesh_detect(const unsigned char *data, size_t len, const char *name, char *err, size_t errlen);

/* Parses data (len bytes, with a NUL after them) as format into *m, named name in
 * messages.  Returns 0, or -1 with "name:LINE: why" or "name: byte N: why" in err
 * (m then holds nothing to free).  A file with no vertex is an error; one without
 * faces is not (its hull is drawn). */
int mesh_parse_as(mesh_format format, const unsigned char *data, size_t len, const char *name,
                  mesh_file *m, char *err, size_t errlen);

/* mesh_detect and mesh_parse_as. */
int mesh_parse(const unsigned char *data, size_t len, const char *name, mesh_file *m, char *err,
               size_t errlen);

void mesh_file_free(mesh_file *m);

/* The core's source of a polyhedron (core/shape.h), with the file it came from. */
typedef struct {
    shape_source src;          /* what the core sees (first: the core frees it
                                * through src.release) */
    char *path;                /* the file, as it was read */
    unsigned char sha256[32];  /* of its bytes (the shell's: it hashes them) */
} mesh_source;

/* The source of a polyhedron from m, which it leaves as it is: m's welded
 * vertices and a triangle mesh of its faces with normals, and path.  NULL, with
 * err, when out of memory.  It is freed by shape_source_release. */
mesh_source *mesh_source_make(const mesh_file *m, const char *path, char *err, size_t errlen);

/* What shape_source_release calls for a mesh_source. */
void mesh_source_release(shape_source *src);

/* The mesh_source that src is, or NULL when it is none. */
static inline const mesh_source *mesh_source_of(const shape_source *src)
{
    return src && src->release == mesh_source_release ? (const mesh_source *)src : NULL;
}

/* Cuts the polygon p[0 .. n-1], whose normal (Newell's: any length, its sense
 * the polygon's winding) is nrm, into n - 2 triangles by ear clipping: writes
 * their corners, as indices into p and in the polygon's winding, to tri.  A
 * polygon that crosses itself or doubles back is still cut into n - 2 triangles
 * that follow its outline.  Returns the number written (n - 2), or -1 when out
 * of memory. */
int mesh_ear_clip(const vec3 *p, int n, vec3 nrm, int (*tri)[3]);

#endif
