#!/bin/sh
# outputs.sh: a write that fails is never silent.  The trace, the events, the hand log, save,
# the frames (record and refresh), the soundtrack (libsndfile writes it), the
# movie (ffmpeg writes it) and standard output each fail loudly: an error that
# names the file and the system's reason, and in a batch run exit status 1 at the
# first failure.  /dev/full fails every write (ENOSPC); `ulimit -f` with
# SIGXFSZ ignored makes a file fail when it outgrows the limit (EFBIG), which is
# how a log or a frame fails in the middle of a run.
. "$(dirname "$0")/lib.sh"
S=$(cd "$(dirname "$0")/../scenes" && pwd)
cd "$TMP" || exit 1

expect "trace = /dev/full is an error" 1 "error: trace: cannot write '/dev/full': No space left on device" \
    "$VROC" -b -c 'sphere a; trace = /dev/full; run 30'
expect "events = /dev/full is an error" 1 "error: events: cannot write '/dev/full': No space left on device" \
    "$VROC" -b -c 'sphere a; events = /dev/full; run 30'
expect "save /dev/full is an error" 1 "error: save: cannot write '/dev/full': No space left on device" \
    "$VROC" -b -c 'sphere a; save /dev/full'
expect "hand_log = /dev/full is an error" 1 "error: hand_log: cannot write '/dev/full': No space left on device" \
    "$VROC" -b -c 'sphere a; hand_log = /dev/full; run 30'
out=$("$VROC" -b -c 'sphere a; trace = /dev/full; print a' 2>/dev/null); status=$?
[ $status -eq 1 ] && [ -z "$out" ] && ok "the failed trace stops the batch run before print" ||
    notok "the failed trace stops the batch run before print" "status $status" "$out"

# standard output: what print and show write is checked too
out=$("$VROC" -b -c 'sphere a; show' 2>&1 >/dev/full); status=$?
case "$status:$out" in "1:error: cannot write the standard output: No space left on device")
    ok "show > /dev/full exits 1 and says why" ;;
    *) notok "show > /dev/full exits 1 and says why" "status $status" "$out" ;; esac

# a file size limit: the failure comes in the middle of the run
limited() { # BLOCKS CMD...: CMD with the file size limit, SIGXFSZ ignored
    blocks=$1
    shift
    (trap '' XFSZ; ulimit -f "$blocks" && "$@")
}
out=$(limited 40 "$VROC" -b "$S/bounce.vroc" -c "trace = t.csv; run 200; print ball1" 2>&1); status=$?
out=$(printf '%s\n' "$out" | no_cut_warning) # (the scene's max_angular cuts a spin)
case "$status:$out" in "1:error: trace: cannot write 't.csv': File too large; trace is now off, time stopped")
    ok "a trace that outgrows the file size limit stops the batch run, saying why" ;;
    *) notok "a trace that outgrows the file size limit stops the batch run, saying why" "status $status" "$out" ;; esac
[ -s t.csv ] && [ "$(wc -c < t.csv)" -le 40960 ] && ok "the trace was written up to the limit" ||
    notok "the trace was written up to the limit" "$(ls -l t.csv 2>&1)"
out=$(limited 4 "$VROC" -b "$S/bounce.vroc" -c "events = e.csv; run 300; print ball1" 2>&1); status=$?
case "$status:$out" in "1:error: events: cannot write 'e.csv': File too large; events is now off, time stopped")
    ok "an events log that outgrows the limit stops the batch run, saying why" ;;
    *) notok "an events log that outgrows the limit stops the batch run, saying why" "status $status" "$out" ;; esac

# the hand log gets a row every frame: the hand moved by statements between runs
out=$(limited 4 "$VROC" -b "$S/basketball-throw.vroc" -c "hand_log = h.csv; hand = (0, 0, 0); run 300; hand = (1, 1, 1); run 300; print ball" 2>&1); status=$?
case "$status:$out" in "1:error: hand_log: cannot write 'h.csv': File too large; hand_log is now off, time stopped")
    ok "a hand log that outgrows the limit stops the batch run, saying why" ;;
    *) notok "a hand log that outgrows the limit stops the batch run, saying why" "status $status" "$out" ;; esac
out=$(VROC_SANDBOX=1 "$VROC" -b -c 'hand_log = /tmp/h.csv' 2>&1); status=$?
case "$status:$out" in "1:error: hand_log: '/tmp/h.csv' is outside the current folder, and VROC_SANDBOX allows writing only below it")
    ok "under VROC_SANDBOX the hand log is written only below the working folder" ;;
    *) notok "under VROC_SANDBOX the hand log is written only below the working folder" "status $status" "$out" ;; esac
expect "hand_log = off checks the last rows" 0 "sphere a" \
    "$VROC" -b -c "sphere a; hand_log = h2.csv; hand = (1, 0, 0); hand_log = off; print a"

# frames: output is a folder, so only the size limit can fail them
# (the sanitizer build may add LeakSanitizer's list of the suppressions it used:
# Mesa's own memory, view.c; so the error is looked for as a whole line)
out=$(limited 1 "$VROC" -b -c "sphere a; translate = (0, 3, 0); output = rec; record = on; run 5; print a" 2>&1); status=$?
if [ $status -eq 1 ] && printf '%s\n' "$out" | grep -qxF "error: record: cannot write 'rec/frame-000001-left.png': File too large; record is now off, time stopped" &&
    ! printf '%s\n' "$out" | grep -q "^sphere a"; then
    ok "a recorded frame that cannot be written stops the batch run, saying why"
else
    notok "a recorded frame that cannot be written stops the batch run, saying why" "status $status" "$out"
fi
[ -e rec/frame-000001-left.png ] && notok "a frame that failed is not left half written" ||
    ok "a frame that failed is not left half written"
expect "refresh that cannot write its frame is an error" 1 \
    "error: refresh: cannot write 'ref/frame-000000-left.png': File too large" \
    limited 1 "$VROC" -b -c "sphere a; translate = (0, 3, 0); output = ref; refresh"
# the same limit lets a trace of a few rows through: the test itself can fail
expect "under the same limit a small trace is written" 0 "sphere a" \
    limited 1 "$VROC" -b -c "sphere a; trace = small.csv; run 1; trace = off; print a"

# the soundtrack and the movie: not stdio, but the same rule and the same message
# (line by line: the sanitizer build may add LeakSanitizer's list, as above)
has_line() { printf '%s\n' "$1" | grep -qxF -- "$2"; }
# stops TEXT BLOCKS COMMANDS LINE: the Simple scene run with COMMANDS (then
# `print ball1`) under a size limit of BLOCKS exits 1 with the error LINE, and
# prints nothing after it
stops() {
    out=$(limited "$2" "$VROC" -b "$S/simple.vroc" -c "$3; print ball1" 2>&1); status=$?
    if [ $status -eq 1 ] && has_line "$out" "$4" && ! has_line "$out" "sphere ball1"; then ok "$1"
    else notok "$1" "status $status" "$out"; fi
}
expect "soundtrack = /dev/full is an error" 1 "error: soundtrack: cannot write '/dev/full': No space left on device" \
    "$VROC" -b -c 'sphere a; soundtrack = /dev/full; run 3'
stops "a soundtrack that outgrows the file size limit stops the batch run, saying why" 64 \
    "soundtrack = s.wav; run 30" "error: soundtrack: cannot write 's.wav': File too large; soundtrack is now off, time stopped"
# a soundtrack is written beside its path and placed when finished: one that
# failed leaves nothing (and an old file whole: hostile.sh)
[ ! -e s.wav ] && [ -z "$(ls -A | grep vroc-part)" ] && ok "the failed soundtrack leaves no file and no part file behind" ||
    notok "the failed soundtrack leaves no file and no part file behind" "$(ls -A)"
if command -v ffmpeg >/dev/null 2>&1; then
    expect "movie = /dev/full is an error, and /dev/full stays a device" 1 \
        "error: movie: cannot write '/dev/full': not a regular file" "$VROC" -b -c 'movie = /dev/full'
    [ -c /dev/full ] && ! ls -a /dev | grep -q vroc-part && ok "nothing is written beside /dev/full" ||
        notok "nothing is written beside /dev/full" "$(ls -la /dev/full /dev/.vroc-part* 2>&1)"
    stops "a movie that outgrows the file size limit stops the batch run, saying why" 16 \
        "image_size = (160, 120); movie = m.mp4; run 100" \
        "error: movie: cannot write 'm.mp4': File too large; movie is now off, time stopped"
    [ -z "$(ls -a | grep -e '^m\.mp4$' -e vroc-part)" ] && ok "the failed movie leaves no file behind" ||
        notok "the failed movie leaves no file behind" "$(ls -a)"
else
    notok "ffmpeg is installed (make deps installs it)"
fi
# VROC_SANDBOX (the fuzz campaign's): the soundtrack and the movie stay below the folder too
expect "VROC_SANDBOX refuses a soundtrack outside the folder" 1 \
    "error: soundtrack: '/tmp/vroc-sandbox.wav' is outside the current folder" \
    env VROC_SANDBOX=1 "$VROC" -b -c 'soundtrack = /tmp/vroc-sandbox.wav'
expect "VROC_SANDBOX refuses a movie outside the folder" 1 "error: movie: '../m.mp4' is outside the current folder" \
    env VROC_SANDBOX=1 "$VROC" -b -c 'movie = ../m.mp4'
[ ! -e /tmp/vroc-sandbox.wav ] && [ ! -e ../m.mp4 ] && ok "and writes neither" || notok "and writes neither"

# read from a pipe, the first failure also ends the run with status 1
out=$(printf 'sphere a\ntrace = /dev/full\nprint a\n' | "$VROC" 2>&1); status=$?
case "$status:$out" in "1:<stdin>:2: error: trace: cannot write '/dev/full': No space left on device")
    ok "piped input: a failed trace exits 1 with <stdin>:LINE" ;;
    *) notok "piped input: a failed trace exits 1 with <stdin>:LINE" "status $status" "$out" ;; esac
exit 0
