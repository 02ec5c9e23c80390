#!/bin/sh
# console_prompt.sh: the console beyond the thesis at the prompt, through tmux as
# a person uses it: an expression and its caret, did you mean, Tab on value words,
# properties and settings, the prompt while time runs, start and stop saying what
# they did, a long run's status line and Ctrl-C, exit.
. "$(dirname "$0")/lib.sh"
tmux_ready || exit 0
SES=vroc$$

start_session "-c 'sound = off'"
check_screen "the prompt" "vroc>"

type_ "sphere b; radius = 2^-1 * (1 + 1/3)" Enter
type_ "print b.radius" Enter
check_screen "an expression at the prompt" "b.radius = 0.666666666667"
type_ "radius = 1/(2 - 2)" Enter
check_screen "an error in an expression" "error: radius: division by zero"
check_screen "quotes the line" "    radius = 1/(2 - 2)"
sleep 0.2
screen | grep -qx '              ^' && ok "and points at the column of the division" ||
    notok "and points at the column of the division" "$(screen | grep -A2 'division by zero')"
type_ "radus = 1" Enter
check_screen "an unknown command suggests the nearest" "did you mean radius? (help lists them all)"

type_ "collision_sound = kn" Tab
check_screen "Tab completes a value word before file names" "vroc> collision_sound = knock"
type_ C-u "print b.ra" Tab
check_screen "Tab completes a property after print NAME." "vroc> print b.radius"
type_ C-u "show time_s" Tab
check_screen "Tab completes a setting after show" "vroc> show time_step"
type_ Enter
check_screen "show NAME prints one setting" "time_step = 0.1"

type_ "start" Enter
check_screen "start says what it did" "time runs from time = 0: stop or Ctrl-C stops it"
sleep 1
check_screen "while time runs the prompt shows it" "vroc[t="
t1=$(screen | sed -n 's/.*vroc\[t=\([0-9.]*\)\]>.*/\1/p' | tail -1)
sleep 1
t2=$(screen | sed -n 's/.*vroc\[t=\([0-9.]*\)\]>.*/\1/p' | tail -1)
awk -v a="$t1" -v b="$t2" 'BEGIN { exit !(b > a && a > 0) }' &&
    ok "the prompt's time goes on while nothing is typed ($t1, then $t2)" ||
    notok "the prompt's time goes on while nothing is typed" "$t1 then $t2"
type_ "stop" Enter
check_screen "stop says what it did" "stopped at time = "
sleep 0.5
screen | grep -v '^$' | tail -1 | grep -q '^vroc> *$' && ok "after stop the prompt is vroc> again" ||
    notok "after stop the prompt is vroc> again" "$(screen | grep -v '^$' | tail -3)"

type_ "run 3" Enter
type_ "random_box = (3, 3, 3); random 150; run 10000000" Enter
check_screen "a long run shows a status line" "run: frame "
screen | grep 'run: frame' | grep -q 'frames/s, .* left' &&
    ok "with frames/s and the time left: $(screen | grep 'run: frame' | tail -1)" ||
    notok "with frames/s and the time left" "$(screen | tail -3)"
sleep 0.5
type_ C-c
check_screen "Ctrl-C stops the run where it is" "interrupted at time = "
if screen | grep -q 'run: frame'; then notok "the status line is erased at the end" "$(screen | tail -4)"
else ok "the status line is erased at the end"; fi
type_ "energy" Enter
check_screen "energy at the prompt" "total_energy = "
type_ "exit" Enter
check_screen "exit leaves with status 0" "EXIT=0"
tmux kill-session -t "$SES" 2>/dev/null
exit 0
