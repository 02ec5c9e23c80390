/* feed.h: a live tracker feed: rows read from a named pipe as they come (language.md,
 * "The hand and the tool panel").
 *
 * Any tracker bridge may write rows of the tracker-file format into a FIFO that
 * vroc reads (`mkfifo hand.fifo; tracker = hand.fifo`).  The pipe is opened without
 * blocking, so vroc does not wait for a writer; the prompt's select() loop watches
 * its descriptor and reads what has come, with no threads.  A header line and
 * comments may come and are skipped.  A writer that comes and goes ends the feed:
 * the reader learns it from poll()'s hang-up, which Linux gives a reader only once
 * a writer has been and gone, not before the first one comes.
 */
#ifndef VROC_FEED_H
#define VROC_FEED_H

#include <stdbool.h>
#include <stddef.h>

#include "tracker.h"

#define FEED_PATH_MAX 1024
#define FEED_LINE_MAX (TRACKER_LINE_MAX + 1) /* a line and its NUL */

typedef struct {
    int fd;                     /* -1 when closed */
    char path[FEED_PATH_MAX];
    char buf[FEED_LINE_MAX];    /* the part of a line read so far */
    size_t len;
    long line;                  /* lines read so far */
    bool overlong;              /* the line being read is longer than buf: skipped */
    double last_t;              /* the last row's time (tracker_check_spacing) */
    bool have_last;
} tracker_feed;

/* What feed_read found. */
typedef enum { FEED_WAITING, FEED_ENDED, FEED_FAILED } feed_state;

/* A closed feed. */
void feed_init(tracker_feed *f);

/* True when path names a FIFO. */
bool feed_is_fifo(const char *path);

/* Opens the FIFO at path for reading without blocking.  Returns 0, or -1 with a
 * message in err. */
int feed_open(tracker_feed *f, const char *path, char *err, size_t errlen);

void feed_close(tracker_feed *f);

/* Reads what has arrived, without waiting: each complete row goes to row(ctx, r);
 * a line that is not a row, or a row nearer in time to the one before than a file
 * allows (tracker_check_spacing), goes to bad(ctx, "path:line: problem").  Returns
 * FEED_WAITING while the writer may write more (or none has come yet), FEED_ENDED
 * once the writer went away, FEED_FAILED when reading failed (err says why). */
feed_state feed_read(tracker_feed *f, void (*row)(void *ctx, const tracker_row *r),
                     void (*bad)(void *ctx, const char *msg), void *ctx, char *err, size_t errlen);

#endif
