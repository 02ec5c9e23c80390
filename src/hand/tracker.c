/* tracker.c: reading and writing the tracker-file format, and the hand's path
 * between rows (tracker.h). */
#include "tracker.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/grow.h"
#include "core/limits.h"
#include "shell/infile.h"

/* How far from 1 a row's quaternion may be before it is an error. */
#define TRACKER_UNIT_TOL 1e-6

static const char *const column[10] = {"time", "x", "y", "z", "qw", "qx", "qy", "qz",
                                       "trigger", "button"};

static const char *skip_space(const char *s)
{
    while (*s == ' ' || *s == '\t' || *s == '\r') s++;
    return s;
}

/* True when s, less surrounding blanks, is exactly the header (with blanks
 * allowed around its names). */
static bool is_header(const char *s)
{
    for (int k = 0; k < 10; k++) {
        s = skip_space(s);
        size_t n = strlen(column[k]);
        if (strncmp(s, column[k], n) != 0) return false;
        s = skip_space(s + n);
        if (k < 9 && *s++ != ',') return false;
    }
    return *s == '\0';
}

tracker_line tracker_line_kind(const char *line)
{
    const char *s = skip_space(line);
    if (*s == '\0' || *s == '#') return TRACKER_SKIP;
    return is_header(s) ? TRACKER_HEADER_LINE : TRACKER_DATA;
}

int tracker_parse_row(const char *line, tracker_row *row, char *err, size_t errlen)
{
    double x[10];
    const char *s = line;
    for (int k = 0; k < 10; k++) {
        s = skip_space(s);
        char *end;
        errno = 0;
        x[k] = strtod(s, &end);
        if (end == s || (*skip_space(end) != ',' && *skip_space(end) != '\0')) {
            size_t n = strcspn(s, ",");
            snprintf(err, errlen, "%s is not a number (got '%.*s')", column[k], (int)(n > 40 ? 40 : n), s);
            return -1;
        }
        if (!isfinite(x[k])) {
            snprintf(err, errlen, "%s must be finite (got %g)", column[k], x[k]);
            return -1;
        }
        s = skip_space(end);
        if (k < 9) {
            if (*s != ',') {
                snprintf(err, errlen, "the row has %d columns; the header has 10 (%s)", k + 1,
                         TRACKER_HEADER);
                return -1;
            }
            s++;
        }
    }
    if (*s != '\0') {
        snprintf(err, errlen, "the row has more than 10 columns (%s)", TRACKER_HEADER);
        return -1;
    }
    if (x[0] < 0 || x[0] > LIM_CLOCK_MAX) {
        snprintf(err, errlen, "time must be between 0 and %g (got %g)", LIM_CLOCK_MAX, x[0]);
        return -1;
    }
    for (int k = 1; k <= 3; k++) {
        if (fabs(x[k]) > LIM_POSITION_MAX) {
            snprintf(err, errlen, "%s must be between %g and %g (got %g)", column[k],
                     -LIM_POSITION_MAX, LIM_POSITION_MAX, x[k]);
            return -1;
        }
    }
    for (int k = 8; k < 10; k++) {
        if (x[k] != 0 && x[k] != 1) {
            snprintf(err, errlen, "%s must be 0 or 1 (got %g)", column[k], x[k]);
            return -1;
        }
    }
    quat q = {x[4], x[5], x[6], x[7]};
    double len = q_len(q);
    if (!(fabs(len - 1) <= TRACKER_UNIT_TOL)) {
        snprintf(err, errlen, "the quaternion (%g, %g, %g, %g) is not a unit one (its length is %.9g)",
                 q.w, q.x, q.y, q.z, len);
        return -1;
    }
    row->t = x[0];
    row->p = v3(x[1], x[2], x[3]);
    row->q = len == 1 ? q : q_normalize(q);
    row->trigger = x[8] != 0;
    row->button = x[9] != 0;
    return 0;
}

void tracker_free(tracker_path *tp)
{
    free(tp->rows);
    tp->rows = NULL;
    tp->n = tp->cap = 0;
}

int tracker_append(tracker_path *tp, const tracker_row *r)
{
    tracker_row *rows = grow_for_one(tp->rows, tp->n, &tp->cap, sizeof *rows, 64);
    if (!rows) return -1;
    tp->rows = rows;
    tp->rows[tp->n++] = *r;
    return 0;
}

int tracker_check_spacing(double before, double t, char *err, size_t errlen)
{
    if (!(t > before && t - before < LIM_TIME_MIN)) return 0;
    snprintf(err, errlen, "time %.17g is %g s after the row before: rows are at the same time, or "
             "at least %g s apart", t, t - before, LIM_TIME_MIN);
    return -1;
}

/* The failure of tracker_load: out emptied, the file let go, the message kept. */
static int load_fails(tracker_path *out, infile *in)
{
    tracker_free(out);
    infile_free(in);
    return -1;
}

int tracker_load(const char *path, tracker_path *out, char *err, size_t errlen)
{
    memset(out, 0, sizeof *out);
    infile in;
    char msg[256];
    if (infile_read(&in, path, TRACKER_MAX_BYTES, msg, sizeof msg) != 0) {
        snprintf(err, errlen, "cannot read '%s': %s", path, msg);
        return -1;
    }
    infile_lines lines;
    infile_line ln;
    int got;
    bool header = false;
    infile_lines_init(&lines, in.data, in.len, TRACKER_LINE_MAX);
    while ((got = infile_next_line(&lines, &ln, msg, sizeof msg)) != 0) {
        long lineno = ln.number;
        if (got < 0) {
            snprintf(err, errlen, "%s:%ld: %s", path, lineno, msg);
            return load_fails(out, &in);
        }
        char line[TRACKER_LINE_MAX + 1];
        memcpy(line, ln.s, ln.len);
        line[ln.len] = '\0';
        tracker_line kind = tracker_line_kind(line);
        if (kind == TRACKER_SKIP) continue;
        if (!header) {
            if (kind != TRACKER_HEADER_LINE) {
                snprintf(err, errlen, "%s:%ld: expected the header %s", path, lineno, TRACKER_HEADER);
                return load_fails(out, &in);
            }
            header = true;
            continue;
        }
        tracker_row r;
        if (kind == TRACKER_HEADER_LINE) {
            snprintf(err, errlen, "%s:%ld: the header again, where a row should be", path, lineno);
            return load_fails(out, &in);
        }
        if (tracker_parse_row(line, &r, msg, sizeof msg) != 0) {
            snprintf(err, errlen, "%s:%ld: %s", path, lineno, msg);
            return load_fails(out, &in);
        }
        if (out->n > 0 && r.t < out->rows[out->n - 1].t) {
            snprintf(err, errlen, "%s:%ld: time %.17g comes before the row above's %.17g (rows go in time order)",
                     path, lineno, r.t, out->rows[out->n - 1].t);
            return load_fails(out, &in);
        }
        if (out->n > 0 && tracker_check_spacing(out->rows[out->n - 1].t, r.t, msg, sizeof msg) != 0) {
            snprintf(err, errlen, "%s:%ld: %s", path, lineno, msg);
            return load_fails(out, &in);
        }
        if (tracker_append(out, &r) != 0) {
            snprintf(err, errlen, "%s:%ld: out of memory", path, lineno);
            return load_fails(out, &in);
        }
    }
    if (!header || out->n == 0) {
        snprintf(err, errlen, "%s: %s", path, header ? "no rows after the header" : "empty: no header " TRACKER_HEADER);
        return load_fails(out, &in);
    }
    infile_free(&in);
    return 0;
}

vec3 tracker_turn(quat a, quat b)
{
    quat r = q_mul(b, q_conj(a));
    if (r.w < 0) r = (quat){-r.w, -r.x, -r.y, -r.z}; /* the short way */
    vec3 axis;
    double angle;
    q_to_axis_angle(r, &axis, &angle);
    return v3_scale(axis, angle);
}

quat tracker_turned(quat a, vec3 r)
{
    double angle = v3_len(r);
    if (angle == 0) return a;
    return q_normalize(q_mul(q_axis_angle(r, angle), a));
}

/* The last row at or before t (-1 when t is before the first). */
static int row_at(const tracker_path *tp, double t)
{
    int lo = 0, hi = tp->n; /* the first row after t, by bisection */
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        if (tp->rows[mid].t <= t) lo = mid + 1;
        else hi = mid;
    }
    return lo - 1;
}

void tracker_pose(const tracker_path *tp, double t, vec3 *p, quat *q)
{
    int k = row_at(tp, t);
    if (k < 0) k = 0;
    const tracker_row *a = &tp->rows[k];
    *p = a->p;
    *q = a->q;
    if (k + 1 >= tp->n || t <= a->t) return;
    const tracker_row *b = &tp->rows[k + 1];
    double s = (t - a->t) / (b->t - a->t);
    *p = v3_lerp(a->p, b->p, s);
    *q = tracker_turned(a->q, v3_scale(tracker_turn(a->q, b->q), s));
}

void tracker_segment_rates(const tracker_path *tp, int k, vec3 *v, vec3 *w)
{
    *v = *w = v3(0, 0, 0);
    if (k < 0 || k + 1 >= tp->n) return;
    const tracker_row *a = &tp->rows[k], *b = &tp->rows[k + 1];
    double dt = b->t - a->t;
    if (!(dt > 0)) return;
    *v = v3_scale(v3_sub(b->p, a->p), 1 / dt);
    *w = v3_scale(tracker_turn(a->q, b->q), 1 / dt);
}

int tracker_write_row(FILE *f, const tracker_row *r)
{
    return fprintf(f, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d,%d\n", r->t, r->p.x, r->p.y,
            r->p.z, r->q.w, r->q.x, r->q.y, r->q.z, r->trigger, r->button);
}
