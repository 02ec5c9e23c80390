#!/bin/sh
# prompt.sh: the prompt driven through tmux as a person would use it: typing, Tab
# completion, history, an error and going on, start and Ctrl-C, Ctrl-D.
. "$(dirname "$0")/lib.sh"
tmux_ready || exit 0
SES=vroc$$

start_session
check_screen "the banner and the prompt" "vroc>"

type_ "sph" Tab
check_screen "Tab completes a command" "vroc> sphere"
type_ "ball" Enter
type_ "rad" Tab
check_screen "Tab completes a property of the current object" "vroc> radius"
type_ "= 0.5" Enter
type_ "bogus 1" Enter
check_screen "an error is reported" "error: unknown command 'bogus'"
type_ "bal" Tab
check_screen "Tab completes an object name" "vroc> ball."
type_ "co" Tab
check_screen "Tab completes a property after NAME." "vroc> ball.color"
type_ "= (1, 2, 3)" Enter
type_ "print ba" Tab Enter
check_screen "the session goes on after the error" "color = (1, 2, 3)"
check_screen "and the radius typed before it holds" "radius = 0.5"
type_ "stereo = ana" Tab
check_screen "Tab completes a setting's choices" "stereo = anaglyph"
type_ Enter
type_ Up
check_screen "Up recalls the last line" "vroc> stereo = anaglyph"
type_ C-u "mode = st" Tab
check_screen "Tab completes mode's choices, stick among them" "vroc> mode = stick"
type_ C-u "print ball" Enter
type_ "start" Enter
sleep 1
type_ C-c
check_screen "Ctrl-C stops running time" "stopped at time = "
type_ "time" Enter
sleep 0.5
t1=$(screen | sed -n 's/^time = //p' | tail -1)
case "$t1" in ""|0) notok "time ran in real time while the prompt waited" "time = $t1" ;;
    *) ok "time ran in real time while the prompt waited" ;; esac
type_ "time" Enter
sleep 0.5
t2=$(screen | sed -n 's/^time = //p' | tail -1)
[ "$t1" = "$t2" ] && ok "after Ctrl-C time stands still" || notok "after Ctrl-C time stands still" "$t1 then $t2"
type_ "half typed" C-c
type_ "list" Enter
check_screen "Ctrl-C at the prompt clears the line and vroc goes on" "ball                 sphere"
type_ C-d
check_screen "Ctrl-D leaves with status 0" "EXIT=0"
if grep -q "^stereo = anaglyph *$" "$TMP/.vroc_history" 2>/dev/null; then ok "history kept in ~/.vroc_history"
else notok "history kept in ~/.vroc_history" "$(cat "$TMP/.vroc_history" 2>&1)"; fi

# a second session recalls the first one's history.  It starts before the first one is
# killed: killing a server's last session makes the server exit, and a new-session sent
# while it exits can fail ("server exited unexpectedly").
FIRST=$SES
SES=vroc$$b
start_session -q
tmux kill-session -t "$FIRST" 2>/dev/null
check_screen "a second session starts" "vroc>"
type_ Up
check_screen "history survives between sessions" "vroc> list"
type_ C-u "quit" Enter
check_screen "quit leaves with status 0" "EXIT=0"
tmux kill-session -t "$SES" 2>/dev/null
exit 0
