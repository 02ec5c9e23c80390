/* infile.h: the one door every file vroc reads comes through: a size cap, a line
 * cap, and no wait without an end.
 *
 * A file is read whole into memory (infile_read), at most max_bytes of it: a
 * regular file larger than that is refused before a byte is read.  A named pipe,
 * a device or a socket is read as its bytes come, without blocking: when nothing
 * comes for infile_timeout() seconds (a pipe no program writes to, a terminal no
 * one types at) the read stops with an error, and so it does at the cap (/dev/zero)
 * and at Ctrl-C (shell_interrupted).  A folder is refused.  Its lines are then
 * walked with a line cap (infile_lines): a line longer than the cap, or a NUL
 * byte in a text file, is an error the caller places with its line number.
 *
 * Every reader names its caps beside its format: scripts (lang.c: LANG_MAX_FILE,
 * LANG_MAX_LINE), tracker files (tracker.h), sound files (clip.c).  A new reader
 * (the mesh files' readers) does the same:
 *
 *     infile in;
 *     char why[256];
 *     if (infile_read(&in, path, MESH_MAX_BYTES, why, sizeof why) != 0) {
 *         snprintf(err, errlen, "cannot read '%s': %s", path, why);
 *         return -1;
 *     }
 *     // a binary format: in.data, in.len;  a text format, line by line:
 *     infile_lines it;
 *     infile_line ln;
 *     int got;
 *     infile_lines_init(&it, in.data, in.len, MESH_MAX_LINE);
 *     while ((got = infile_next_line(&it, &ln, why, sizeof why)) > 0) {
 *         ... ln.s (ln.len bytes, no newline, not NUL-terminated), ln.number ...
 *     }
 *     if (got < 0) ... "path:ln.number: why" (too long, or a NUL byte) ...
 *     infile_free(&in);
 */
#ifndef VROC_INFILE_H
#define VROC_INFILE_H

#include <signal.h>
#include <stddef.h>

/* The size cap of the files vroc reads whole: scripts, tracker files, sound files
 * (a scene is a few kilobytes; a saved world of 10,000 objects 8 MB). */
#define INFILE_MAX_BYTES (64L * 1024 * 1024)

/* How long vroc waits, by default, for a pipe, a device or a program that gives
 * no sign of life (infile_timeout). */
#define INFILE_TIMEOUT_DEFAULT 30.0

/* Ctrl-C's flag (shell.h: the SIGINT handler sets it), which long reads and
 * waits watch: declared and defined here, so that the hand's and the sound's
 * readers need not see the shell. */
extern volatile sig_atomic_t shell_interrupted;

/* A file read whole. */
typedef struct {
    char *data; /* len bytes, and a NUL after them */
    size_t len;
} infile;

/* Reads path whole into in, at most max_bytes.  Returns 0, or -1 with the reason
 * alone in why (for "cannot read 'PATH': REASON"): the system's, "it is a
 * folder", "it is larger than N bytes", "nothing came through it for N s",
 * "interrupted" or "out of memory"; in is then empty. */
int infile_read(infile *in, const char *path, size_t max_bytes, char *why, size_t whylen);

void infile_free(infile *in);

/* Seconds vroc waits for a pipe, a device or a program (ffmpeg) that neither
 * gives nor takes anything: the environment variable VROC_TIMEOUT when it is a
 * number > 0, else INFILE_TIMEOUT_DEFAULT. */
double infile_timeout(void);

/* ---- lines ---- */

typedef struct {
    const char *s; /* the line, without its newline */
    size_t len;
    long number;   /* 1 for the first */
} infile_line;

typedef struct {
    const char *p, *end;
    size_t max_line;
    long number;
} infile_lines;

/* Walks the len bytes at data as lines of at most max_line bytes each (not
 * counting the newline). */
void infile_lines_init(infile_lines *it, const char *data, size_t len, size_t max_line);

/* The next line into ln: 1, or 0 at the end, or -1 with the problem in why and
 * its line's number in ln->number: "a line longer than N bytes", "a NUL byte
 * (binary file?)". */
int infile_next_line(infile_lines *it, infile_line *ln, char *why, size_t whylen);

#endif
