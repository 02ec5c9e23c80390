/* viewer.h: the live window (`window = on`; language.md, "The console beyond the
 * thesis"): the views as time runs, keys that run time, and the mouse as the head
 * and the hand.
 *
 * The window (view/window.h) shows what the PNG files of refresh would hold, as
 * `stereo` lays them out (view_picture: pair and sbs side by side), with the hand
 * and the panel when they show.  It is drawn again after every statement the
 * shell runs, after every frame (at most VIEWER_FPS times a second of wall time
 * while a run goes faster, and always after a run's last frame), and when the
 * mouse moves the head or the hand.
 *
 * Keys: space runs `start` or `stop`, `.` `step`, `r` `refresh`, Escape closes the
 * window.  While a statement runs (`run N`), space stops it as Ctrl-C does and
 * Escape closes the window; other keys wait for the prompt.
 *
 * The mouse:
 *  - as the head, when it is not the hand: a drag with the left button turns the
 *    head about look_at (across the picture's height, half a turn), the wheel
 *    takes it nearer to look_at or farther (by 1.1 a notch);
 *  - as the hand (hand.h's live source), in select mode when no tracker file or
 *    feed has the hand: the pointer places the hand on the plane facing the viewer
 *    at the hand's depth (on the panel, where the pointer is over it and nothing
 *    is held), the wheel takes that plane farther (away) or nearer, the left
 *    button is the trigger and the right one the re-select button.  Pressing the
 *    left button over an object first brings the plane to where the pointer meets
 *    it, so that the trigger takes it.  A press shorter than a frame still reaches
 *    the hand: the trigger stays down until the hand has taken a sample;
 *  - on a control of the panel outside select mode, the left button presses it
 *    as the hand's trigger does (the mouse is the hand for that click).
 * While time runs the hand takes the mouse's samples at frame boundaries (a frame
 * behind it); while time stands still it takes them at once, as rows of a feed.
 *
 * The window is the console's, not the world's: save does not write it, and
 * restart leaves it open.
 */
#ifndef VROC_VIEWER_H
#define VROC_VIEWER_H

#include <stdbool.h>

struct shell;
typedef struct viewer viewer;

/* Pictures a second, at most, while a run goes faster than that. */
#define VIEWER_FPS 60

/* True when the window is open. */
bool viewer_is_open(const struct shell *sh);

/* The prompt's turn: what the user did in the window acts (keys run their
 * commands), the hand takes the mouse's sample while time stands still, and the
 * window is drawn again where anything changed. */
void viewer_turn(struct shell *sh);

/* How long the prompt may sleep (wait, < 0: until a key) with the window open:
 * wait or less, so that the window answers. */
double viewer_wait(const struct shell *sh, double wait);

/* At a frame boundary, before the hand's frame begins or ends: what the user did
 * in the window is read, and the hand is given the mouse's sample. */
void viewer_sample(struct shell *sh);

/* After a frame: the window is drawn again when due (last: the last frame of those
 * advanced now, always drawn). */
void viewer_frame(struct shell *sh, bool last);

/* Statements ran: the window is drawn again. */
void viewer_changed(struct shell *sh);

/* Closes the window (the end of the program). */
void viewer_free(struct shell *sh);

#endif
