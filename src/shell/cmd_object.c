/* cmd_object.c: the commands that make, remove and change objects (thesis Tables
 * A.1 to A.4): sphere, cube, superquadric, delete, and every property.  A property
 * is set through the core (edit.h), which wakes what it disturbs. */
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "core/edit.h"
#include "core/hold.h"
#include "handlers.h"
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
                 "%s: no current object: create one with sphere NAME, cube NAME or superquadric "
                 "NAME, or write NAME.%s = ...",
                 st->cmd->name, st->cmd->name);
        return -1;
    }
    return sh->current;
}

cmd_status cmd_create(shell *sh, const stmt *st)
{
    shape_kind kind = strcmp(st->cmd->name, "sphere") == 0 ? SHAPE_SPHERE
                      : strcmp(st->cmd->name, "cube") == 0 ? SHAPE_CUBE
                                                           : SHAPE_SUPERQUADRIC;
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

static cmd_status cmd_property_of(shell *sh, const stmt *st, int i)
{
    const body *b = sh->w.bodies[i];
    const command *c = st->cmd;
    const char *n = c->name;
    if (!(c->classes & (1u << b->sp.kind))) {
        sh_warn(sh, st, "%s does not apply to %s '%s' (a %s); ignored", n,
                body_type_name(b->sp.kind), b->name, body_type_name(b->sp.kind));
        return CMD_OK;
    }
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
