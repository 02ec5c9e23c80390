/* reader.h: what the four readers share (meshfile.h): the builder they feed,
 * which welds and sorts the vertices at the end, messages with the file and the
 * place, and a cursor over text lines.
 *
 * A reader gives the builder the file's vertices in its own order (mb_vertex;
 * STL, whose triangles repeat their corners, welds as it goes: mb_vertex_weld),
 * then its faces as runs of corners (mb_corner, mb_face_end) that index those
 * vertices, with the normals it has, and its groups (mb_group).  mb_finish welds
 * identical vertices, sorts them and renumbers the corners.
 */
#ifndef VROC_MESH_READER_H
#define VROC_MESH_READER_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "meshfile.h"

typedef struct {
    mesh_file *m;      /* what is being built (m->v holds the vertices as given) */
    int cap_v, cap_n, cap_g;
    long nc, cap_c;    /* corners so far */
    int cap_f;
    int *weld;         /* open addressing: vertex index + 1, or 0 (mb_vertex_weld) */
    size_t weld_cap;   /* a power of two */
    const char *name;  /* the file, for messages */
    char *err;
    size_t errlen;
} mesh_builder;

void mb_init(mesh_builder *b, mesh_file *m, const char *name, char *err, size_t errlen);
/* Frees what the builder and m hold (after an error). */
void mb_abandon(mesh_builder *b);

/* Messages: "name:line: why", "name: byte N: why", "name: why".  Each returns -1. */
int mb_err_line(mesh_builder *b, long line, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
int mb_err_byte(mesh_builder *b, size_t offset, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
int mb_err(mesh_builder *b, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* "out of memory" for the place given (line or byte offset: which says binary). */
int mb_oom(mesh_builder *b);

/* Room for n more vertices, normals or faces at once, so that a reader that knows
 * its counts allocates once (each -1 when out of memory). */
int mb_reserve_vertices(mesh_builder *b, long n);
int mb_reserve_faces(mesh_builder *b, long faces, long corners);

/* Appends a vertex as the file gives it; returns its index, or -1 (out of
 * memory, or more than INT_MAX). */
int mb_vertex(mesh_builder *b, vec3 p);
/* The index of a vertex equal to p, appending it when there is none yet. */
int mb_vertex_weld(mesh_builder *b, vec3 p);
int mb_normal(mesh_builder *b, vec3 n);
/* A corner of the face being given: vertex v, normal n (-1 for none). */
int mb_corner(mesh_builder *b, int v, int n);
/* Ends the face being given (at least 3 corners: the reader checks). */
int mb_face_end(mesh_builder *b);
/* The faces from here on are the group named name (len bytes); a group that
 * ends with no face is dropped. */
int mb_group(mesh_builder *b, const char *name, size_t len);

/* Welds, sorts and renumbers; checks that there is a vertex.  Returns 0, or -1
 * with the message (m then freed). */
int mb_finish(mesh_builder *b);

/* ---- text ---- */

/* Lines of text: [p, eol) is the current line (without its '\n' or "\r\n"), line
 * its number from 1. */
typedef struct {
    const char *p, *eol, *next, *end;
    long line;
} text_cursor;

/* Starts at data; tc_next_line must be called first. */
void tc_init(text_cursor *c, const char *data, size_t len);
/* Moves to the next line; false at the end of the text. */
bool tc_next_line(text_cursor *c);
/* Skips blanks (space, tab, \v, \f, \r) in the current line. */
void tc_skip_blanks(text_cursor *c);
/* At the end of the current line, after blanks, or at a '#' comment. */
bool tc_at_eol(text_cursor *c);

/* A number at *pp (which must not be a blank) that ends at a blank, '#' or end,
 * where the text has a blank, a line end or its NUL: 0,
 * -1 when it is not a number, -2 when it is not finite (NaN, infinity, overflow).
 * *pp moves past it. */
int parse_double(const char **pp, const char *end, double *out);
/* A whole number (optional sign, decimal digits): 0, or -1 when it is not one or
 * is beyond +-2^62. */
int parse_long(const char **pp, const char *end, long long *out);

/* The word at p (up to a blank, a line end, '#' or end): its length. */
size_t word_len(const char *p, const char *end);
/* Case-sensitive: whether the word at p is w. */
bool word_is(const char *p, const char *end, const char *w);

/* ---- binary ---- */

static inline uint32_t le32(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* The readers, one per format (obj.c, stl.c, off.c, ply.c): each parses data
 * (len bytes, a NUL after them) into b and returns 0 or -1 with the message. */
int mesh_read_obj(mesh_builder *b, const char *data, size_t len);
int mesh_read_stl(mesh_builder *b, const unsigned char *data, size_t len);
int mesh_read_off(mesh_builder *b, const char *data, size_t len);
int mesh_read_ply(mesh_builder *b, const unsigned char *data, size_t len);

/* Whether a binary STL of len bytes (at least 84) is what data's count says. */
bool mesh_stl_binary(const unsigned char *data, size_t len);

#endif
