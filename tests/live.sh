#!/bin/sh
# live.sh: live sound at the prompt against a real PulseAudio server that this test
# starts (a null sink, on a private socket, stopped at the end): what vroc played,
# recorded from the sink's monitor with parec, matches the soundtrack of the same
# run (envelopes cross-correlated, so the stream's latency does not matter).  And
# where no server answers: one warning when time first runs, never at start-up,
# and time runs on; in batch nothing is asked.  A server that goes away while it
# plays is a failed output (outfile.h): an error that names it, sound off, time
# going on at the prompt.
. "$(dirname "$0")/lib.sh"
S=$(cd "$(dirname "$0")/../scenes" && pwd)
WT="$(cd "$(dirname "$0")/.." && pwd)/build/tests/wavtool"
for c in tmux pulseaudio parec pactl; do
    command -v $c >/dev/null 2>&1 || { notok "$c is installed (make deps installs it)"; exit 0; }
done
[ -x "$WT" ] || { notok "build/tests/wavtool is built (make check-build)"; exit 0; }

export TMUX_TMPDIR="$TMP"
PA="$TMP/pa"
mkdir -p "$PA/xdg"
pa_pid="" rec_pid="" hum_pid=""
stop_all() {
    [ -n "$rec_pid" ] && kill "$rec_pid" 2>/dev/null
    [ -n "$hum_pid" ] && kill "$hum_pid" 2>/dev/null
    [ -n "$pa_pid" ] && kill "$pa_pid" 2>/dev/null && wait "$pa_pid" 2>/dev/null
    tmux kill-server 2>/dev/null
    rm -rf "$TMP"
}
trap stop_all EXIT
trap 'exit 1' HUP INT TERM

SES=live$$
# ends the session, and waits until its tmux server has gone (it exits with its
# last session: a new session started meanwhile may meet it shutting down)
end_session() {
    tmux kill-session -t "$SES" 2>/dev/null
    i=0
    while tmux ls >/dev/null 2>&1 && [ $i -lt 50 ]; do sleep 0.1; i=$((i + 1)); done
}
type_() { tmux send-keys -t "$SES" "$@"; }
wait_for() { # PATTERN [TENTHS]: the screen shows PATTERN within TENTHS/10 s (default 20 s)
    i=0
    while [ $i -lt "${2:-200}" ]; do
        screen | grep -qF -- "$1" && return 0
        sleep 0.1
        i=$((i + 1))
    done
    return 1
}
# vroc at an interactive prompt in tmux, with ENV (env's arguments: PULSE_SERVER=...,
# -u NAME) set, and
# its own HOME and XDG_RUNTIME_DIR ($VHOME, $VXDG): where a sound server it
# started would leave its socket and pid file
VHOME="$TMP/home" VXDG="$TMP/xdg"
mkdir -p "$VHOME" "$VXDG"
start_vroc() {
    tmux -f /dev/null new-session -d -s "$SES" -x 150 -y 40 \
        "cd '$TMP' && env $1 HOME='$VHOME' XDG_RUNTIME_DIR='$VXDG' ASAN_OPTIONS='$ASAN_OPTIONS' '$VROC' -q; echo EXIT=\$?; sleep 30"
    wait_for "vroc>" || notok "vroc starts at the prompt" "$(screen | tail -5)"
}

# ---- no server: one warning when time first runs, not at start-up; nothing waits ----
# (no server named: libpulse looks in vroc's runtime folder, where an autospawned
# server would start)
start_vroc "-u PULSE_SERVER -u DISPLAY"
type_ "soundt" Tab
wait_for "vroc> soundtrack" 50 && ok "Tab completes soundtrack" || notok "Tab completes soundtrack" "$(screen | tail -3)"
type_ C-u "movie = o" Tab
wait_for "vroc> movie = off" 50 && ok "Tab completes movie = off" || notok "Tab completes movie = off" "$(screen | tail -3)"
type_ C-u "sphere ball; translate = (0, 3, 0); show" Enter
wait_for "movie = off"
case "$(screen)" in *warning*) notok "no warning at start-up" "$(screen | tail -5)" ;;
    *"sound = on"*) ok "no warning at start-up, and sound shows on at the prompt" ;;
    *) notok "sound shows on at an interactive prompt" "$(screen | tail -5)" ;; esac
type_ "start" Enter
if wait_for "warning: sound: no sound server answers" 50; then ok "one warning when time first runs"
else notok "one warning when time first runs" "$(screen | tail -5)"; fi
sleep 1
type_ "stop; start" Enter
sleep 0.5
type_ "stop; time; show" Enter
wait_for "movie = off"
n=$(screen | grep -c "no sound server answers")
[ "$n" = 1 ] && ok "the warning is shown once" || notok "the warning is shown once" "$n times"
t=$(screen | sed -n 's/^time = //p' | tail -1)
awk -v t="$t" 'BEGIN { exit !(t >= 0.5) }' && ok "time ran on without a server (time = $t)" || notok "time ran on without a server" "time = $t"
screen | grep -q "^sound = off" && ok "and sound turned off" || notok "and sound turned off" "$(screen | tail -5)"
type_ "quit" Enter
wait_for "EXIT=0" && ok "quit leaves with status 0" || notok "quit leaves with status 0" "$(screen | tail -5)"
end_session
# an autospawned server daemonizes and leaves vroc's process tree, so other
# processes say nothing of it on a shared machine; but it would make its socket
# and pid file in vroc's own runtime folder (or under its HOME)
made=$(find "$VHOME" "$VXDG" -path '*pulse*' \( -type s -o -name pid -o -name '*.pid' \) 2>/dev/null)
[ -z "$made" ] && ok "no sound server was started by vroc (no autospawn: no pulse/ socket or pid file)" ||
    notok "no sound server was started by vroc" "$made"

# ---- batch: the server is never asked ----
out=$(PULSE_SERVER=unix:$TMP/no-such-socket "$VROC" -b "$S/simple.vroc" -c "start; run 10; show" 2>&1)
case "$out" in *warning*) notok "batch asks no server" "$out" ;; *"sound = off"*) ok "batch asks no server and sound is off" ;;
    *) notok "batch: sound is off" "$out" ;; esac

# ---- a real server ----
env HOME="$PA" XDG_RUNTIME_DIR="$PA/xdg" pulseaudio -n --daemonize=no --exit-idle-time=-1 \
    --disable-shm=yes --use-pid-file=no --system=no \
    -L "module-null-sink sink_name=vroc_null rate=48000 channels=2" \
    -L "module-native-protocol-unix socket=$PA/sock auth-anonymous=1" > "$PA/log" 2>&1 &
pa_pid=$!
export PULSE_SERVER="unix:$PA/sock"
i=0
until pactl info > /dev/null 2>&1 || [ $i -ge 100 ]; do sleep 0.1; i=$((i + 1)); done
if ! pactl info > /dev/null 2>&1; then
    notok "a PulseAudio server starts on a private socket" "$(tail -5 "$PA/log")"
    exit 0
fi
ok "a PulseAudio server starts on a private socket, with a null sink"
# a stream of silence keeps the sink running: an idle null sink sleeps up to 2 s
# before it reads a new stream (vroc's thread would drop that much as late)
pacat --raw --rate=48000 --channels=2 --format=s16le --latency-msec=30 < /dev/zero > /dev/null 2>&1 &
hum_pid=$!
parec -d vroc_null.monitor --rate=48000 --channels=2 --format=s16le --latency-msec=20 > "$TMP/rec.raw" 2>"$TMP/parec.err" &
rec_pid=$!
# the monitor too can take a second to deliver its first samples: wait for them
i=0
while [ "$(stat -c %s "$TMP/rec.raw")" -lt 38400 ] && [ $i -lt 100 ]; do sleep 0.1; i=$((i + 1)); done
start_vroc "PULSE_SERVER=$PULSE_SERVER"
type_ "read $S/simple.vroc; collision_sound = knock; soundtrack = $TMP/track.wav" Enter
type_ "start" Enter
sleep 3.2
type_ C-c # with the stream's threads running, Ctrl-C still reaches the prompt
if wait_for "stopped at time = " 30; then ok "Ctrl-C stops time while sound plays"
else notok "Ctrl-C stops time while sound plays" "$(screen | tail -5)"; fi
sleep 0.5
type_ "soundtrack = off; time; show" Enter
wait_for "movie = off"
screen | grep -q "warning" && notok "no warning with a server" "$(screen | grep warning)" || ok "no warning with a server"
screen | grep -q "^sound = on" && ok "sound is on" || notok "sound is on" "$(screen | tail -5)"
sleep 0.5
kill "$rec_pid" "$hum_pid" 2>/dev/null
wait "$rec_pid" "$hum_pid" 2>/dev/null
rec_pid="" hum_pid=""
type_ "quit" Enter
wait_for "EXIT=0" && ok "quit leaves with status 0" || notok "quit leaves with status 0" "$(screen | tail -8)"
n=$("$WT" info "$TMP/track.wav" | sed -n 's/.*frames=//p')
awk -v n="$n" 'BEGIN { exit !(n >= 2.5 * 48000) }' && ok "the soundtrack holds the run (${n} samples)" ||
    notok "the soundtrack holds the run" "frames=$n"
pk=$("$WT" peak "$TMP/rec.raw" | sed -n 's/left=\([0-9]*\).*/\1/p')
awk -v p="$pk" 'BEGIN { exit !(p > 1000) }' && ok "the sink heard vroc (peak $pk)" ||
    notok "the sink heard vroc" "peak ${pk:-none}; $(cat "$TMP/parec.err")"
xc=$("$WT" xcorr "$TMP/rec.raw" "$TMP/track.wav" 10)
corr=$(echo "$xc" | sed -n 's/.*corr=//p')
awk -v c="$corr" 'BEGIN { exit !(c > 0.85) }' && ok "what was played matches the soundtrack ($xc)" ||
    notok "what was played matches the soundtrack (envelope correlation > 0.85)" "$xc"

# ---- the server goes away while sound plays: the one rule of a failed output ----
end_session
start_vroc "PULSE_SERVER=$PULSE_SERVER"
type_ "read $S/simple.vroc; start" Enter
sleep 1.5
kill "$pa_pid" 2>/dev/null
wait "$pa_pid" 2>/dev/null
pa_pid=""
if wait_for "error: sound: cannot write to the sound server" 50; then
    ok "a server that stops taking the sound is an error naming it and why"
else
    notok "a server that stops taking the sound is an error naming it and why" "$(screen | tail -5)"
fi
screen | grep -q "; sound is now off$" && ok "and sound is turned off" || notok "and sound is turned off" "$(screen | tail -5)"
sleep 1
type_ "stop; time; show" Enter
wait_for "movie = off"
t=$(screen | sed -n 's/^time = //p' | tail -1)
awk -v t="$t" 'BEGIN { exit !(t >= 2) }' && ok "time went on at the prompt without the sound (time = $t)" ||
    notok "time went on at the prompt without the sound" "time = $t"
screen | grep -q "^sound = off" && ok "show says sound = off" || notok "show says sound = off" "$(screen | tail -5)"
n=$(screen | grep -c "cannot write to the sound server")
[ "$n" = 1 ] && ok "the failure is told once" || notok "the failure is told once" "$n times"
type_ "quit" Enter
wait_for "EXIT=0" && ok "quit leaves with status 0 after it" || notok "quit leaves with status 0 after it" "$(screen | tail -8)"
exit 0
