/* cmd_object.c: the commands that make, remove and change objects (thesis Tables
 * A.1 to A.4): sphere, cube, superquadric, polyhedron, delete, and every property.
 * A property is set through the core (edit.h), which wakes what it disturbs.  A
 * polyhedron's file is read by the mesh readers (mesh/meshfile.h) and hashed here
 * (SHA-256, nettle), so that a saved world can tell when the file has changed. */
#include <nettle/sha2.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "core/edit.h"
#include "core/hold.h"
#include "handlers.h"
#include "infile.h"
#include "mesh/meshfile.h"
#include "shell.h"

/* The object a property statement applies to: NAME.property's, or the current
 * one; -1 (reported) when there is none. */
static int target(shell *sh, const stmt *st)
{
    if (st->object) {
        int i = world_find(&sh->w, st->object);
        if (i < 0) sh_error(sh, st, "no object named '%s'", st->object);
        return i;
    }
    if (sh->current < 0) {
        sh_error(sh, st,
                 "%s: no current object: create one with sphere NAME, cube NAME, superquadric "
                 "NAME or polyhedron NAME, or write NAME.%s = ...",
                 st->cmd->name, st->cmd->name);
        return -1;
    }
    return sh->current;
}

cmd_status cmd_create(shell *sh, const stmt *st)
{
    shape_kind kind = strcmp(st->cmd->name, "sphere") == 0         ? SHAPE_SPHERE
                      : strcmp(st->cmd->name, "cube") == 0         ? SHAPE_CUBE
                      : strcmp(st->cmd->name, "superquadric") == 0 ? SHAPE_SUPERQUADRIC
                                                                   : SHAPE_POLYHEDRON;
    int i = world_find(&sh->w, st->word);
    if (i >= 0) {
        const body *b = sh->w.bodies[i];
        if (b->sp.kind != kind) {
            sh_error(sh, st, "'%s' is already a %s; it cannot also be a %s", st->word,
                     body_type_name(b->sp.kind), st->cmd->name);
            return CMD_ERROR;
        }
        sh->current = i;
        return CMD_OK;
    }
    body *b = malloc(sizeof *b);
    if (!b) {
        sh_error(sh, st, "out of memory");
        return CMD_ERROR;
    }
    body_init(b, st->word, kind);
    b->friction = sh->w.set.default_friction;
    b->rolling_friction = sh->w.set.default_rolling_friction;
    view_palette(sh->made, b->color); /* distinguishable colours in turn */
    char err[256];
    if (body_build(b, err, sizeof err) != 0) {
        sh_error(sh, st, "%s", err);
        free(b);
        return CMD_ERROR;
    }
    i = world_add(&sh->w, b);
    if (i < 0) {
        sh_error(sh, st, "out of memory");
        return CMD_ERROR;
    }
    sh->current = i;
    sh->made++;
    return CMD_OK;
}

static void fix_index(int *idx, int deleted)
{
    if (*idx == deleted) *idx = -1;
    else if (*idx > deleted) (*idx)--;
}

cmd_status cmd_delete(shell *sh, const stmt *st)
{
    int i = world_find(&sh->w, st->word);
    if (i < 0) {
        sh_error(sh, st, "no object named '%s'", st->word);
        return CMD_ERROR;
    }
    edit_delete(&sh->w, i);
    fix_index(&sh->current, i);
    hand_object_deleted(&sh->hand, i);
    return CMD_OK;
}

/* Whether property statement st applies to object i: when it does not, a warning
 * says it is ignored. */
static bool applies(shell *sh, const stmt *st, int i)
{
    const body *b = sh->w.bodies[i];
    if (st->cmd->classes & (1u << b->sp.kind)) return true;
    sh_warn(sh, st, "%s does not apply to %s '%s' (a %s); ignored", st->cmd->name,
            body_type_name(b->sp.kind), b->name, body_type_name(b->sp.kind));
    return false;
}

static cmd_status cmd_property_of(shell *sh, const stmt *st, int i)
{
    const body *b = sh->w.bodies[i];
    const command *c = st->cmd;
    const char *n = c->name;
    if (!applies(sh, st, i)) return CMD_OK;
    char err[256];
    if (edit_property(&sh->w, i, c->off, st->num, err, sizeof err) != 0) {
        sh_error(sh, st, "%s", err);
        return CMD_ERROR;
    }
    double x = st->num[0];
    if ((c->off == offsetof(body, sp.exp1) || c->off == offsetof(body, sp.exp2)) && x > 2)
        sh_warn(sh, st,
                "%s = %g makes '%s' non-convex; its collision shape is the convex hull of "
                "its tessellation",
                n, x, b->name);
    return CMD_OK;
}

cmd_status cmd_property(shell *sh, const stmt *st)
{
    int i = target(sh, st);
    return i < 0 ? CMD_ERROR : cmd_property_of(sh, st, i);
}

/* The exact state's statements (language.md, "Exact state"): each sets what it
 * names as save wrote it, through edit.h's exact functions. */
cmd_status cmd_exact(shell *sh, const stmt *st)
{
    int i = target(sh, st);
    if (i < 0) return CMD_ERROR;
    world *w = &sh->w;
    const body *b = w->bodies[i];
    const char *n = st->cmd->name;
    char err[256];
    if (strcmp(n, "orientation") == 0) {
        edit_exact_orientation(w, i, (quat){st->num[0], st->num[1], st->num[2], st->num[3]});
    } else if (strcmp(n, "velocity") == 0) {
        edit_exact_velocity(w, i, stmt_vec(st));
    } else if (strcmp(n, "angular_momentum") == 0) {
        edit_exact_momentum(w, i, stmt_vec(st));
    } else if (strcmp(n, "hold_pivot") == 0 || strcmp(n, "hold_velocity") == 0) {
        bool pivot = strcmp(n, "hold_pivot") == 0;
        if (hold_exact(w, i, pivot ? stmt_vec(st) : b->hold_pivot, pivot ? b->hold_v : stmt_vec(st)) != 0) {
            sh_error(sh, st, "'%s' is not held: grip = %s holds it", b->name, b->name);
            return CMD_ERROR;
        }
    } else if (strcmp(n, "slide_on") == 0) {
        int s = world_find(w, st->word);
        if (s < 0 || !body_is_static(w->bodies[s])) {
            sh_error(sh, st, s < 0 ? "no object named '%s'" : "'%s' is not static: nothing slides on it",
                     st->word);
            return CMD_ERROR;
        }
        edit_exact_support(w, i, s, b->slide_face);
    } else if (strcmp(n, "slide_face") == 0) {
        edit_exact_support(w, i, b->slide_on, (int)st->num[0]);
    } else if (strcmp(n, "mode") == 0 || strcmp(n, "resting") == 0) {
        body_mode mode = strcmp(n, "mode") == 0 ? (body_mode)st->num[0] : b->mode;
        bool resting = strcmp(n, "resting") == 0 ? st->num[0] != 0 : b->state == STATE_RESTING;
        if (edit_exact_contact(w, i, mode, resting, err, sizeof err) != 0) {
            sh_error(sh, st, "%s", err);
            return CMD_ERROR;
        }
    } else { /* touching */
        int j = world_find(w, st->word);
        if (j < 0) {
            sh_error(sh, st, "no object named '%s'", st->word);
            return CMD_ERROR;
        }
        if (edit_exact_touching(w, i, j, err, sizeof err) != 0) {
            sh_error(sh, st, "%s", err);
            return CMD_ERROR;
        }
    }
    return CMD_OK;
}

/* ---- polyhedra from files ---- */

/* The polyhedron source of the file at path (resolved as the parser found it),
 * with the SHA-256 of its bytes; NULL with the message in err. */
static mesh_source *load_file(const char *path, char *err, size_t errlen)
{
    /* through the door every file read comes through (infile.h): its size cap, no
     * endless wait for a pipe, Ctrl-C; then its text's line cap */
    infile in;
    char why[300];
    if (infile_read(&in, path, MESH_MAX_FILE, why, sizeof why) != 0) {
        snprintf(err, errlen, "cannot read '%s': %s", path, why);
        return NULL;
    }
    unsigned char *data = (unsigned char *)in.data;
    size_t len = in.len, text = mesh_text_length(data, len);
    infile_lines lines;
    infile_line ln;
    int got;
    infile_lines_init(&lines, in.data, text, MESH_MAX_LINE);
    /* (a NUL byte is binary data: the readers judge that) */
    while (!memchr(data, '\0', text) && (got = infile_next_line(&lines, &ln, why, sizeof why)) != 0) {
        if (got < 0) {
            snprintf(err, errlen, "%s:%ld: %s", path, ln.number, why);
            infile_free(&in);
            return NULL;
        }
    }
    unsigned char digest[SHA256_DIGEST_SIZE];
    struct sha256_ctx ctx;
    sha256_init(&ctx);
    sha256_update(&ctx, len, data);
    sha256_digest(&ctx, sizeof digest, digest);
    mesh_file m;
    int rc = mesh_parse(data, len, path, &m, err, errlen);
    free(data); /* before the mesh is made: the larger files are large */
    if (rc != 0) return NULL;
    mesh_source *src = mesh_source_make(&m, path, err, errlen);
    mesh_file_free(&m);
    if (src) memcpy(src->sha256, digest, sizeof digest);
    return src;
}

/* The polyhedron statement st applies to: its index, or -1 (an error, reported)
 * or -2 (not a polyhedron: ignored with a warning). */
static int polyhedron_target(shell *sh, const stmt *st)
{
    int i = target(sh, st);
    return i < 0 ? -1 : applies(sh, st, i) ? i : -2;
}

cmd_status cmd_file(shell *sh, const stmt *st)
{
    int i = polyhedron_target(sh, st);
    if (i < 0) return i == -1 ? CMD_ERROR : CMD_OK;
    char err[1024];
    mesh_source *src = load_file(st->word, err, sizeof err);
    if (!src) {
        sh_error(sh, st, "%s", err);
        return CMD_ERROR;
    }
    char why[512];
    if (edit_source(&sh->w, i, &src->src, why, sizeof why) != 0) {
        sh_error(sh, st, "%s: %s", st->word, why);
        return CMD_ERROR;
    }
    const body *b = sh->w.bodies[i];
    long off = shape_off_hull(&b->shape);
    if (off > 0)
        sh_warn(sh, st,
                "'%s': %ld of its %d triangles are not on its convex hull, so it collides as "
                "its hull, not as drawn; to collide as drawn, split it offline into convex "
                "pieces (CoACD or V-HACD) saved as OBJ groups",
                st->word, off, b->shape.draw.nt);
    if (b->shape.mass_from == MASS_PIECES && !body_is_static(b))
        sh_warn(sh, st,
                "'%s': its faces do not close a consistently oriented surface, so its mass "
                "properties are those of its %d pieces' hulls together, where overlaps count "
                "twice",
                st->word, b->shape.pieces);
    return CMD_OK;
}

cmd_status cmd_pieces(shell *sh, const stmt *st)
{
    int i = polyhedron_target(sh, st);
    if (i < 0) return i == -1 ? CMD_ERROR : CMD_OK;
    const body *b = sh->w.bodies[i];
    if ((int)st->num[0] != b->shape.pieces) {
        sh_error(sh, st, "pieces is read only: '%s' collides as %d convex piece%s (got %d)",
                 b->name, b->shape.pieces, b->shape.pieces == 1 ? "" : "s", (int)st->num[0]);
        return CMD_ERROR;
    }
    return CMD_OK;
}

cmd_status cmd_sha256(shell *sh, const stmt *st)
{
    int i = polyhedron_target(sh, st);
    if (i < 0) return i == -1 ? CMD_ERROR : CMD_OK;
    const body *b = sh->w.bodies[i];
    const mesh_source *src = mesh_source_of(b->sp.src);
    if (!src) {
        sh_warn(sh, st, "'%s' has no file to compare the SHA-256 with; ignored", b->name);
        return CMD_OK;
    }
    char hex[2 * SHA256_DIGEST_SIZE + 1];
    for (int k = 0; k < SHA256_DIGEST_SIZE; k++) snprintf(hex + 2 * k, 3, "%02x", src->sha256[k]);
    if (strcasecmp(hex, st->word) != 0)
        sh_warn(sh, st,
                "'%s' has changed since it was saved: its SHA-256 is %s, not %s; '%s' takes "
                "its shape from it as it is now",
                src->path, hex, st->word, b->name);
    return CMD_OK;
}
