/* world.h: everything vroc simulates: the objects, the simulation settings, the
 * clock, and the collisions of the last frame.
 *
 * The world owns its bodies (in creation order, which is also the order of `list`,
 * `save` and the trace) and the settings that decide how time runs (Table A.5:
 * time_step, collision_dist, internal_step, the speed limits, the force, and the
 * collision heap).  sim_settings_defaults gives every start-up value in one place.
 * It also holds the state the simulation keeps between frames, each part owned
 * by its own module, which initialises and frees it: the pairs (pairs.h), the
 * schedule (schedule.h), the flights of the internal step (step.h) and the
 * scratch its events are answered in (answer.h).  The world knows
 * nothing of text, prompts, files or pixels: the shell and the views read it, and
 * read the frame's collisions from `events` (as Box2D's contact events).
 */
#ifndef VROC_WORLD_H
#define VROC_WORLD_H

#include <stdbool.h>

#include "answer.h"
#include "body.h"
#include "broad.h"
#include "force.h"
#include "guard.h"
#include "pairs.h"
#include "schedule.h"
#include "step.h"
#include "vmath.h"

/* The settings of simulated time (Table A.5 and language.md). */
typedef struct {
    double time_step;       /* frame step, s; 0 halts */
    double collision_dist;  /* m */
    double internal_step;   /* forced internal step, s; 0 automatic */
    double max_linear;      /* m/s */
    double max_angular;     /* rad/s */
    dir_amount force;       /* direction as typed, magnitude m/s^2 */
    bool collision_heap;    /* the schedule (on), or every pair every step (off) */
    double default_friction;         /* what new objects take: friction, */
    double default_rolling_friction; /*   rolling_friction (the shell sets them) */
} sim_settings;

/* A collision's result, or a throw (hold.h), that a speed limit cut (sim.h): the
 * object, the limit, and the speed it would have had. */
typedef struct {
    int object;           /* its index then */
    bool angular;         /* max_angular cut its spin (rad/s); else max_linear its
                           * speed (m/s) */
    double speed;         /* what it would have had */
    double limit;         /* the limit it was cut to */
    bool thrown;          /* a throw's, not a collision's */
} sim_cut;

/* The first last resort of the event guard (guard.h): at time t, in the event of
 * objects a and b (b -1: an object's own event; indices then), `stopped` objects
 * were stopped where they were. */
typedef struct {
    double t;
    int a, b;
    int stopped;
} sim_guard;

/* The simulation's counters since the world was made. */
typedef struct {
    long frames;          /* frames advanced */
    long subframes;       /* internal steps taken */
    long pair_checks;     /* pair distance queries */
    long collisions;      /* collisions answered */
    long restarts;        /* closest-feature walks redone from scratch (closest.h:
                           * never expected) */
    long unsolved;        /* contact problems with no solution (a collision's, a
                           * cluster's kicks): the impulses are not applied; never
                           * expected but for a held body, which stops instead */
    long overflows;       /* internal steps cut short after twice
                           * SIM_MAX_EVENTS_PER_STEP events (guard.h; never
                           * expected) */
    long crowds;          /* objects whose contacts were answered with no
                           * restitution for the rest of a step, after
                           * SIM_CROWD_EVENTS events in it (guard.h) */
    long guards;          /* internal steps that reached SIM_MAX_EVENTS_PER_STEP
                           * events, where the crowded objects stopped (guard.h) */
    sim_guard first_guard; /* the first of them (when guards > 0) */
    long speed_cuts;      /* collisions and throws whose result max_linear or
                           * max_angular cut: each loses energy (elasticity 1 keeps
                           * it only within the limits) */
    sim_cut first_cut;    /* the first of them (when speed_cuts > 0) */
    long energy_cuts;     /* contact problems with friction whose restitution was
                           * scaled down: it would have raised the kinetic energy */
    long cone_unconverged; /* cone solves that stopped short of FRICTION_TOL */
    long painleve;        /* contact problems with friction with no consistent
                           * answer (Painleve): answered without friction there */
    int first_painleve;   /* an object of the first of them (when painleve > 0) */
    long fallen;          /* objects that fell more than SIM_FALL_DEPTH below the
                           * lowest static object (each once: body.fell) */
    long waves_cut;       /* instants whose waves were ended by a last solve with
                           * no restitution, after 4 n waves of n contacts (a ball
                           * pinched between two walls, a lossy stack: instant.h) */
    long heap_pops;       /* pairs taken from the schedule to be checked */
    long events_lost;     /* collisions not reported in events (out of memory) */
    long late_pairs;      /* (heap off) contacts found of pairs the broad phase did
                           * not hold near: it was late; never expected */
    long separations;     /* pairs moved apart at frames' ends (apart.h) */
    double deepest;       /* (validation build) the deepest overlap of any pair
                           * after any event (m; 0: none), of objects deepest_a and
                           * deepest_b (apart_watch) */
    int deepest_a, deepest_b;
} sim_stats;


/* One collision answered: at time t, bodies a and b (indices) at point p, with
 * normal n (unit, from b towards a), impulse magnitude j (N s) and closing speed
 * speed (m/s) before it. */
typedef struct {
    double t;
    int a, b;
    vec3 p, n;
    double j, speed;
} sim_event;

typedef struct world {
    body **bodies;        /* n bodies, creation order */
    int n, cap;
    int *names;           /* an open-addressing index of the names: index + 1, or 0
                           * for an empty place (ncap places, a power of two) */
    int ncap;
    sim_settings set;
    double time;          /* simulated time, s */
    double time_base;     /* time = time_base + base_frames * base_step, so that */
    double base_step;     /* frames of one time_step add up without drift */
    long base_frames;
    long frame;           /* frame number */
    sim_stats st;
    sim_event *events;    /* the collisions of the last frame, in order (sim_frame */
    long nevents;         /*   empties it as it starts) */
    long capevents;
    pair_list pairs;      /* pairs.h */
    broad_phase broad;    /* broad.h */
    schedule sched;       /* schedule.h */
    step_state step;      /* step.h */
    answer_scratch answer; /* answer.h */
    guard_work guard;     /* guard.h */
    bool sched_dirty;     /* something changed other than by the simulation: every
                           * pair is due, and the simulation copies its bodies
                           * afresh (edit.h sets it) */
    bool out_of_memory;   /* a frame ran out of memory on the way (sim_frame says so) */
} world;

/* The start-up values of Table A.5 (time_step 0.1, collision_dist 0.25,
 * max_linear 8, max_angular 4, no force, the heap on). */
sim_settings sim_settings_defaults(void);

void world_init(world *w);
/* Removes every object and frees what the simulation keeps (the world can be
 * reused after world_init). */
void world_free(world *w);

/* Index of the object named name, or -1. */
int world_find(const world *w, const char *name);

/* Appends b (taking ownership).  Returns its index, or -1 on allocation failure
 * (b is then freed). */
int world_add(world *w, body *b);

/* Removes and frees object i; later objects shift down by one (the indices the
 * objects keep of each other follow). */
void world_delete(world *w, int i);

/* Number of dynamic (including resting) and static objects. */
void world_counts(const world *w, int *dynamic, int *stat);

/* Pairs checked for collision: n(n-1)/2 + n s for n dynamic and s static objects. */
long world_pairs(const world *w);

/* Appends a collision to the frame's events; counts it in st.events_lost when
 * there is no memory for it. */
void world_event(world *w, const sim_event *e);

/* The global acceleration (force.h). */
static inline vec3 world_accel(const world *w) { return force_accel(w->set.force); }

/* The global acceleration as body b feels it (force.h). */
static inline vec3 world_body_accel(const world *w, const body *b)
{
    return force_on(w->set.force, b);
}

/* Internal steps per frame: ceil(time_step / hmax) with hmax = internal_step when
 * set, else collision_dist / (2 max_linear); 1 when that bound is infinite; 0 when
 * time_step is 0. */
long world_subframes(const world *w);

/* A 64-bit hash (FNV-1a) of the simulated time and of every object's name,
 * state, mode, position, orientation, velocity and angular momentum, and a held
 * object's pivot and its velocity, bit for bit (language.md, "Exact state"). */
unsigned long long world_hash(const world *w);

#endif
