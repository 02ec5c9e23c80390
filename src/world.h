/* world.h: everything vroc simulates and shows: the objects and the system settings.
 *
 * The world owns its bodies (in creation order, which is also the order of
 * `list`, `save` and the trace) and the settings of Table A.5 and language.md.
 * settings_defaults gives every start-up value in one place.  The world knows
 * nothing of text, prompts or pixels: the shell and the renderer read it.
 */
#ifndef VROC_WORLD_H
#define VROC_WORLD_H

#include <stdbool.h>
#include <stdio.h>

#include "body.h"
#include "closest.h"
#include "vmath.h"

#define PATH_MAX_VROC 1024

typedef enum { STEREO_PAIR, STEREO_SBS, STEREO_ANAGLYPH, STEREO_MONO } stereo_mode;
typedef enum { REAL_SOLID, REAL_WIRE, REAL_HIDDEN } real_mode;

/* A direction and an amount, as `force = (x,y,z) m` and `hand_rotate = (x,y,z) r`
 * are typed. */
typedef struct {
    vec3 dir;
    double amount;
} dir_amount;

typedef struct {
    /* time (Table A.5) */
    double time_step;       /* frame step, s; 0 halts */
    double collision_dist;  /* m */
    double internal_step;   /* forced internal step, s; 0 automatic */
    double max_linear;      /* m/s */
    double max_angular;     /* rad/s */
    dir_amount force;       /* direction as typed, magnitude m/s^2 */
    /* sound */
    char collision_sound[PATH_MAX_VROC];
    double collision_vol;
    /* schedule */
    bool collision_heap;
    vec3 random_box;
    unsigned long seed;
    /* head and views */
    vec3 head, look_at, up;
    double ipd, fov;
    int image_w, image_h;
    char output[PATH_MAX_VROC];
    stereo_mode stereo;
    int background[3];
    real_mode real;
    bool record;
    /* hand-held tracker (thesis Appendix A.1.2) */
    vec3 hand;
    dir_amount hand_rotate; /* axis and angle, radians */
    bool trigger;
    bool select_mode;
    char tracker[PATH_MAX_VROC];
} settings;

typedef struct {
    long frames;          /* frames advanced */
    long subframes;       /* internal steps taken */
    long pair_checks;     /* pair distance queries */
    long collisions;      /* collisions answered */
    double wall_time;     /* seconds spent advancing time */
    double render_time;   /* seconds spent drawing and writing frames */
    long frames_written;  /* image files written */
    long restarts;        /* closest-feature walks redone from scratch */
    long heap_pops;       /* pairs taken from the schedule to be checked */
} stats;

/* A pair of objects that may collide: dynamic-dynamic or dynamic-static (resting
 * objects count as dynamic), never static-static (thesis 3.3.2). */
typedef struct {
    int a, b;             /* body indices, a < b */
    closest_cache cache;  /* closest features of the last check */
    closest_cache hit;    /* those of its last collision: where the time of impact
                           * and the answer start, so that they do not depend on
                           * which checks the schedule made (sim.c) */
    double next;          /* earliest time the pair could collide (the schedule) */
    double checked;       /* when next was found from its objects' speeds, or +inf
                           * when it holds only while their motions do (sim.c) */
    double toi;           /* its first contact found in this internal step, valid */
    long toi_a, toi_b;    /*   while its objects fly from flights numbered so (sim.c) */
    bool along;           /* next came from sched_predict_along: it holds only while
                           * both objects fly as they flew when it was found */
    bool far;             /* next came from sched_predict_far, when its objects had */
    double jumped_a, jumped_b; /* been moved at once so far (body.jumped), */
    bool far_slide_a, far_slide_b; /* counting that object's slide's lesser
                           * acceleration (only a steady slide's: body.slide_steady) */
    double speed_a, speed_b; /* the speeds next was found from (slack included) */
} pair;

/* A pair's first contact as its time of impact found it (sim.c): the pair at
 * time t, apart, and the features the search ended on; t is NAN when there is
 * none to reuse. */
typedef struct {
    closest_result r;
    closest_cache cache;
    double t;
} pair_hit;

/* An entry of the schedule's heap: a pair's time, kept next to its index so that
 * sifting reads no pair; or the time an object's box ends. */
typedef struct {
    double next;
    long pair;            /* a pair, or npairs + k for object k's box */
} sched_entry;

typedef struct world {
    body **bodies;        /* n bodies, creation order */
    int n, cap;
    settings set;
    double time;          /* simulated time, s */
    double time_base;     /* time = time_base + base_frames * base_step, so that */
    double base_step;     /* frames of one time_step add up without drift */
    long base_frames;
    long frame;           /* frame number */
    bool running;         /* `start` given and not stopped */
    stats st;
    FILE *trace;          /* `trace = FILE`, or NULL */
    char trace_path[PATH_MAX_VROC];
    FILE *events;         /* `events = FILE`, or NULL */
    char events_path[PATH_MAX_VROC];
    pair *pairs;          /* the pairs, rebuilt by the simulation when pairs_dirty */
    pair_hit *hits;       /* each pair's last first contact found */
    long npairs, cappairs;
    bool pairs_dirty;     /* objects were added, deleted or changed mass */
    sched_entry *heap;    /* the schedule: a binary min-heap of (next, pair) over
                           * the pairs and the objects' boxes (nheap entries), and
                           * after the last an end mark that no time precedes */
    long *heap_pos;       /* each entry's place in it (apart from the pairs, so that
                           * sifting writes no pair) */
    long nheap;
    struct sched_box *box; /* each object's box (schedule.h) */
    bool *parked;         /* each pair's: its time is +inf because its objects'
                           * boxes do not meet; it waits until one of them is
                           * made again (apart from the pairs, so that a box's
                           * renewal reads no pair) */
    struct sched_bound *bound; /* each near pair's bound, as its time was found */
    long *obj_first;      /* the pairs of object k: obj_pairs[obj_first[k] .. */
    long *obj_pairs;      /*   obj_first[k + 1] - 1], */
    int *obj_other;       /*   and the other object of each */
    bool sched_dirty;     /* a command changed something: every pair is due, and
                           * the simulation copies its bodies afresh (set it after
                           * changing a body other than by its state, x to the end) */
    long *due;            /* scratch: the pairs checked in a step, their new times */
    double *due_next;
    long capdue;
    body *snap;           /* scratch: each object's state at snap_t, during an internal */
    double *snap_t;       /*   step: where its flight starts (sim.c); snap_id numbers */
    long *snap_id;        /*   each such start, from flight_count */
    long flight_count;
    body *pre;            /* scratch: the colliding pair's states before the answer */
    bool *touched;        /* scratch: the other objects a collision's answer changed */
    long *end_id;         /* scratch: the flight each moving object was last flown to
                           * the end of the internal step from (sim.c) */
    body *scratch;        /* scratch: SIM_SCRATCH copies of each object (sim.c) */
    int *movers, nmovers; /* scratch: the objects that are not static, in order */
    int capsnap;
} world;

settings settings_defaults(void);

void world_init(world *w);
/* Removes every object and closes the logs (the world can be reused after
 * world_init). */
void world_free(world *w);

/* Frees the schedule's arrays (schedule.c builds them: heap to parked), leaving
 * none. */
void world_free_schedule(world *w);

/* Index of the object named name, or -1. */
int world_find(const world *w, const char *name);

/* Appends b (taking ownership).  Returns its index, or -1 on allocation failure
 * (b is then freed). */
int world_add(world *w, body *b);

/* Removes and frees object i; later objects shift down by one. */
void world_delete(world *w, int i);

/* Number of dynamic (including resting) and static objects. */
void world_counts(const world *w, int *dynamic, int *stat);

/* Pairs checked for collision: n(n-1)/2 + n s for n dynamic and s static objects. */
long world_pairs(const world *w);

/* The global acceleration: force.dir / |force.dir| * force.amount (zero when
 * none).  Inline, as are the next: the schedule and every flight ask for it. */
static inline vec3 world_accel(const world *w)
{
    vec3 d = w->set.force.dir;
    /* a unit direction (gravity's (0, 0, -1)) needs no square root: the same to
     * the bit as normalising it */
    if (v3_len2(d) == 1) return v3_scale(d, w->set.force.amount);
    return v3_scale(v3_norm(d), w->set.force.amount);
}

/* The global acceleration as body b feels it: less the part that presses it onto
 * the support it slides on (sim.c). */
static inline vec3 world_body_accel(const world *w, const body *b)
{
    vec3 a = world_accel(w);
    if (b->slide < 0) return a;
    double an = v3_dot(a, b->slide_n);
    return an < 0 ? v3_mad(a, b->slide_n, -an) : a;
}

/* Internal steps per frame: ceil(time_step / hmax) with hmax = internal_step when
 * set, else collision_dist / (2 max_linear); 1 when that bound is infinite; 0 when
 * time_step is 0. */
long world_subframes(const world *w);

#endif
