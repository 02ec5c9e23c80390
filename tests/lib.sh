# lib.sh: helpers for vroc's script tests (sourced, POSIX sh).
# Each check prints "ok - TEXT" or "not ok - TEXT"; tests/run.sh counts them.
VROC=${VROC:-./vroc}
case "$VROC" in /*) ;; *) VROC="$(pwd)/$VROC" ;; esac
VAL_VROC="$(cd "$(dirname "$0")/.." && pwd)/build-val/vroc" # (same_traces)
TMP=$(mktemp -d /tmp/vroc-test-XXXXXX)
trap 'rm -rf "$TMP"' EXIT
export HOME="$TMP"   # no history file of the user's is touched
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}

ok() { echo "ok - $1"; }
# its input without the speed limits' warning (the first collision result a
# limit cut: commands/max_angular), for checks of what else a run says
no_cut_warning() { grep -v ": each such cut loses energy, and stats counts them (speed_cuts); raise "; }
notok() { echo "not ok - $1"; shift; for l in "$@"; do echo "#   $l"; done; }

# expect TEXT STATUS PATTERN CMD...: CMD exits with STATUS and its output
# (stdout and stderr) contains PATTERN (a fixed string).
expect() {
    desc=$1 want_status=$2 pattern=$3
    shift 3
    out=$("$@" 2>&1)
    status=$?
    if [ "$status" -eq "$want_status" ] && printf '%s' "$out" | grep -qF -- "$pattern"; then
        ok "$desc"
    else
        notok "$desc" "status $status (want $want_status)" "output: $(printf '%s' "$out" | head -5)"
    fi
}

# same TEXT FILE1 FILE2: the two files are identical
same() {
    if cmp -s "$2" "$3"; then ok "$1"; else notok "$1" "$(diff "$2" "$3" | head -10)"; fi
}

# The prompt through tmux (prompt.sh, hand_prompt.sh).  tmux_ready: tmux is there
# (else a failed check: the caller exits), its server kept in the test's folder.
# Then the session $SES's screen, keys typed into it, and checks of what it shows.
tmux_ready() {
    if ! command -v tmux >/dev/null 2>&1; then
        notok "tmux is installed (make deps installs it)"
        return 1
    fi
    export TMUX_TMPDIR="$TMP"
}
# start_session ARGS: the session $SES, 120x40, running vroc ARGS (shell words,
# as typed) in $TMP with HOME there; EXIT=N shows its exit status after it
start_session() {
    tmux -f /dev/null new-session -d -s "$SES" -x 120 -y 40 \
        "cd '$TMP' && HOME='$TMP' ASAN_OPTIONS='$ASAN_OPTIONS' '$VROC' $*; echo EXIT=\$?; sleep 30"
}
# (a loaded machine's tmux may answer a capture with nothing: ask again)
screen() {
    for _ in 1 2 3 4 5; do
        _scr=$(tmux capture-pane -p -t "$SES" -S -80 2>/dev/null)
        [ -n "$(printf '%s' "$_scr" | tr -d '[:space:]')" ] && break
        sleep 0.2
    done
    printf '%s\n' "$_scr"
}
type_() { tmux send-keys -t "$SES" "$@"; }
# wait until the screen shows PATTERN (fixed string), up to 20 s (sanitizer builds are slow)
wait_for() {
    i=0
    while [ $i -lt 200 ]; do
        screen | grep -qF -- "$1" && return 0
        sleep 0.1
        i=$((i + 1))
    done
    return 1
}
check_screen() { # TEXT PATTERN
    if wait_for "$2"; then ok "$1"; else notok "$1" "screen: $(screen | tail -8)"; fi
}

# An X server of the test's own (window.sh, examples.sh): xvfb_start runs Xvfb at
# 24-bit depth on a display number it picks itself (-displayfd), sets DISPLAY to
# it and XPID to its process, or fails (1) saying why; xvfb_stop stops it.  The
# caller's EXIT trap calls xvfb_stop.
XPID=
xvfb_start() {
    if ! command -v Xvfb >/dev/null 2>&1; then
        notok "Xvfb is installed (make deps installs it)"
        return 1
    fi
    # -noreset: by default the server resets when its last client leaves, and
    # refuses connections while it does; with a probe (xdotool) connecting and
    # leaving every 0.1 s, a vroc that opened its window at such a moment
    # found no server.
    Xvfb -displayfd 3 -noreset -screen 0 1280x1024x24 -nolisten tcp 3>"$TMP/display" 2>"$TMP/xvfb.log" &
    XPID=$!
    i=0
    while [ ! -s "$TMP/display" ] && [ $i -lt 100 ]; do sleep 0.1; i=$((i + 1)); done
    if [ ! -s "$TMP/display" ]; then
        notok "Xvfb starts" "$(cat "$TMP/xvfb.log")"
        return 1
    fi
    DISPLAY=":$(cat "$TMP/display")"
    export DISPLAY
    # and it answers (a client gets through) before the test goes on
    i=0
    while ! xdpyinfo >/dev/null 2>&1 && [ $i -lt 100 ]; do sleep 0.1; i=$((i + 1)); done
    if ! xdpyinfo >/dev/null 2>&1; then
        notok "Xvfb answers on $DISPLAY" "$(cat "$TMP/xvfb.log")"
        return 1
    fi
}
xvfb_stop() { [ -n "$XPID" ] && kill "$XPID" 2>/dev/null; XPID=; }

# split_runs NAME FILE: a run split anywhere equals the whole, by hash (run 10
# then step equals run 11, run 7 then run 13 equals run 20), and the two differ.
split_runs() {
    h11=$("$VROC" -b -q "$2" -c "run 11; hash" 2>&1)
    h10=$("$VROC" -b -q "$2" -c "run 10; step; hash" 2>&1)
    h20=$("$VROC" -b -q "$2" -c "run 20; hash" 2>&1)
    h713=$("$VROC" -b -q "$2" -c "run 7; run 13; hash" 2>&1)
    if [ "$h11" = "$h10" ] && [ "$h20" = "$h713" ] && [ "$h11" != "$h20" ]; then
        ok "$1: run 10 then step equals run 11, run 7 then run 13 equals run 20"
    else
        notok "$1: run 10 then step equals run 11, run 7 then run 13 equals run 20" \
            "run 11: $h11" "run 10; step: $h10" "run 20: $h20" "run 7; run 13: $h713"
    fi
}

# same_hash NAME FILE A B WHAT: the statements A, and B, each run on FILE by a
# vroc of its own and then hashed, give the same hash ("NAME: WHAT").
same_hash() {
    ha=$("$VROC" -b -q "$2" -c "$3; hash" 2>&1)
    hb=$("$VROC" -b -q "$2" -c "$4; hash" 2>&1)
    if [ "$ha" = "$hb" ]; then ok "$1: $5"; else notok "$1: $5" "$3: $ha" "$4: $hb"; fi
}

# same_traces NAME FILE N [STATEMENTS]: N frames of FILE give the same trace with
# the heap on and off, and (the normal build) in the validation build, whose
# invariants are checked after every internal step.  The heap-on run's output,
# with STATEMENTS run after it, is left in out-on.
same_traces() {
    "$VROC" -b -q "$2" -c "collision_heap = on; trace = on.csv; run $3${4:+; $4}" > out-on 2>&1
    "$VROC" -b -q "$2" -c "collision_heap = off; trace = off.csv; run $3" > out-off 2>&1
    same "$1: the heap changes no trajectory ($3 frames)" on.csv off.csv
    [ "${BUILD:-build}" = build ] || return 0
    if [ -x "$VAL_VROC" ]; then
        "$VAL_VROC" -b -q "$2" -c "trace = val.csv; run $3" > out-val 2>&1
        same "$1: the validation build keeps every invariant, with the same trace" on.csv val.csv
    else
        notok "$1: the validation build runs it" "$VAL_VROC is missing"
    fi
}
