#!/bin/sh
# hand_prompt.sh: the hand at the prompt, driven through tmux as a person uses it:
# rows written into a named pipe while time runs move the hand, grab and throw;
# the writer going away ends the feed; a tracker file presses the panel's Start on
# the wall clock and its Stop on simulated time, and the hand log of that session,
# replayed, does the same; Tab completes grip's words.  The test starts its own
# tmux server (in its own folder) and stops it.
. "$(dirname "$0")/lib.sh"
tmux_ready || exit 0
SES=vrochand$$
trap 'tmux kill-server 2>/dev/null; rm -rf "$TMP"' EXIT

tmux -f /dev/null new-session -d -s "$SES" -x 160 -y 50 \
    "cd '$TMP' && HOME='$TMP' ASAN_OPTIONS='$ASAN_OPTIONS' '$VROC' -q; echo EXIT=\$?; sleep 30"
check_screen "the prompt" "vroc>"

# ---- a live feed: rows written into a FIFO while time runs ----
mkfifo "$TMP/hand.fifo"
type_ "sphere ball; radius = 0.1; translate = (0, 0, 1); select on; tracker = hand.fifo; start" Enter
sleep 0.5
{
    echo "time,x,y,z,qw,qx,qy,qz,trigger,button"
    echo "0,0,0,1,1,0,0,0,1,0"   # grabs the ball where it is
    sleep 0.6
    echo "0.5,1,0,1,1,0,0,0,1,0" # carries it 1 m along x
    sleep 0.6
    echo "1,1,0,2,1,0,0,0,0,0"   # 1 m up in 0.5 s (the ball jumps with it), and lets go:
    sleep 0.5                    # thrown at 2 m/s up from z = 2
} > "$TMP/hand.fifo"
check_screen "the writer going away ends the live feed, with a warning" "the writer of 'hand.fifo' went away"
type_ "stop; show" Enter
check_screen "the hand followed the rows" "hand = (1, 0, 2)"
type_ "print ball; list" Enter
check_screen "the ball, grabbed and carried, was thrown: it is dynamic again" "ball                 sphere        dynamic"
out=$(screen | sed -n 's/^translate = (\(.*\))$/\1/p' | tail -1)
if printf '%s\n' "$out" | awk -F', ' '{ exit !($1 > 0.99 && $1 < 1.01 && $3 > 2.05) }'; then
    ok "the hand carried the ball to x = 1 and threw it up"
else notok "the hand carried the ball to x = 1 and threw it up" "translate = ($out)"; fi
lv=$(screen | sed -n 's/^linear_vel = (\(.*\))$/\1/p' | tail -1)
if printf '%s\n' "$lv" | awk -F', ' '{ exit !($1 == 0 && $2 == 0 && $3 == 2) }'; then
    ok "thrown with the velocity of the feed's last rows, (0, 0, 2)"
else notok "thrown with the velocity of the feed's last rows" "linear_vel = ($lv)"; fi

# ---- a tracker file presses Start on the wall clock, Stop on simulated time ----
cat > "$TMP/press.csv" <<'EOF'
time,x,y,z,qw,qx,qy,qz,trigger,button
0,-0.0533,0.49,-0.1875,1,0,0,0,0,0
0.5,-0.0533,0.49,-0.1875,1,0,0,0,1,0
0.6,-0.0533,0.49,-0.1875,1,0,0,0,0,0
1.6,-0.16,0.49,-0.1875,1,0,0,0,0,0
1.7,-0.16,0.49,-0.1875,1,0,0,0,1,0
1.8,-0.16,0.49,-0.1875,1,0,0,0,0,0
EOF
type_ "restart; panel = on; hand_log = rec.csv; tracker = press.csv" Enter
sleep 4
type_ "time" Enter
check_screen "time ran" "time = "
t=$(screen | sed -n 's/^time = //p' | tail -1)
# Start at 0.5 s on the wall clock; then the clock is simulated time, and Stop
# comes 1.2 s later, at the end of the frame it falls in
if awk -v t="$t" 'BEGIN { exit !(t > 1.15 && t < 1.25) }'; then ok "the panel's Start, pressed by the file, ran time until its Stop (time = $t)"
else notok "the panel's Start and Stop, pressed by the file" "time = $t"; fi
type_ "hand_log = off; restart; panel = on; tracker = rec.csv" Enter
sleep 4
type_ "time" Enter
sleep 0.5
t2=$(screen | sed -n 's/^time = //p' | tail -1)
if awk -v t="$t2" 'BEGIN { exit !(t > 1.1 && t < 1.3) }'; then ok "the hand log of that session, replayed, presses Start and Stop again (time = $t2)"
else notok "the hand log, replayed, presses Start and Stop again" "time = $t2"; fi

# ---- completion of grip's words ----
type_ "grip = pa" Tab
check_screen "Tab completes grip's words" "vroc> grip = panel"
type_ C-u "quit" Enter
check_screen "quit leaves with status 0" "EXIT=0"
exit 0
