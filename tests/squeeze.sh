#!/bin/sh
# squeeze.sh: a held paddle pushes a ball against a static wall (issue 35), driven
# three ways: by one `hand =` jump, by `hand =` statements 0.2 m a frame, and by a
# tracker file at 1 m/s.  Nothing may pass through anything: the ball ends between
# the paddle and the wall, the paddle on its side of the wall; and the validation
# build's watch (stats' `deepest`, measured after every event) finds no pair
# deeper than 1e-9 m in each other.
#
# The geometry, worked out here: the wall's near face is at x = 0.55 - 0.05 =
# 0.5; the paddle is 0.05 thick each side of its centre, the ball's radius 0.1.
# So the ball (centre b) is between them when p + 0.05 <= b - 0.1 and
# b + 0.1 <= 0.5, and it has reached the wall when b + 0.1 >= 0.5 - 1e-6.
. "$(dirname "$0")/lib.sh"
ROOT=$(cd "$(dirname "$0")/.." && pwd)
VAL="$ROOT/build-val/vroc"
SET='precision = exact
cube wall; size = (0.05, 1, 1); translate = (0.55, 0, 0); mass = -1
cube paddle; size = (0.05, 0.3, 0.3); translate = (-0.35, 0, 0)
sphere ball; radius = 0.1
select on; reach = 0.01; hand = (-0.35, 0, 0)'

# play NAME SCRIPT: runs SCRIPT (statements) into $TMP/NAME
play() { printf '%s\n' "$2" > "$TMP/$1.vroc"; "$VROC" -b -q "$TMP/$1.vroc" > "$TMP/$1" 2>&1; }

# the x of an object's translate in vroc's output: x OBJECT FILE
x() { awk -v o="$1" '$1 == "cube" || $1 == "sphere" { cur = $2 } cur == o && $1 == "translate" { gsub(/[(,]/, " "); print $3 }' "$2" | tail -1; }

# between NAME FILE REACHED: the final places in FILE
between() {
    p=$(x paddle "$2") b=$(x ball "$2")
    if awk -v p="$p" -v b="$b" 'BEGIN { exit !(p + 0.05 <= b - 0.1 + 1e-9 && b + 0.1 <= 0.5 + 1e-9 && p + 0.05 <= 0.5) }'; then
        ok "$1: the ball ends between the paddle and the wall, the paddle on its side"
    else notok "$1: the ball ends between the paddle and the wall, the paddle on its side" "paddle $p, ball $b"; fi
    [ "$3" = reached ] || return 0
    if awk -v b="$b" 'BEGIN { exit !(b + 0.1 >= 0.5 - 1e-6) }'; then ok "$1: the ball reaches the wall"
    else notok "$1: the ball reaches the wall" "ball $b"; fi
}

# deepest NAME SCRIPT: the validation build's watch over every event
deepest() {
    if [ ! -x "$VAL" ]; then notok "$1: the validation build runs it" "$VAL is missing"; return; fi
    printf '%s\nstats\n' "$2" > "$TMP/$1-val.vroc"
    d=$("$VAL" -b -q "$TMP/$1-val.vroc" 2>&1 | awk '$1 == "deepest" { print $3 }')
    if [ -n "$d" ] && awk -v d="$d" 'BEGIN { exit !(d <= 1e-9) }'; then ok "$1: no pair deeper than 1e-9 m in another after any event (validation build)"
    else notok "$1: no pair deeper than 1e-9 m in another after any event (validation build)" "deepest = $d"; fi
}

# ---- one jump: the paddle sweeps towards (0.65, 0, 0) and stops at the ball ----
jump="$SET
trigger = on; hand = (0.65, 0, 0)
print paddle"
play jump0 "$jump"
p=$(x paddle "$TMP/jump0")
if awk -v p="$p" 'BEGIN { exit !(p + 0.05 <= -0.1 && p + 0.05 >= -0.1 - 1e-6) }'; then
    ok "jump: the paddle sweeps to the ball, and stops where it touches"
else notok "jump: the paddle sweeps to the ball, and stops where it touches" "paddle at $p: its face should be at -0.1"; fi
jump="$jump
run 10; print ball; print paddle"
play jump "$jump"
between jump "$TMP/jump" reached
deepest jump "$jump"

# ---- statements, 0.2 m a frame, on to 0.65 (beyond the wall) ----
steps="$SET
trigger = on"
for k in 1 2 3 4 5 6 7 8 9 10; do
    steps="$steps
hand = ($(awk -v k=$k 'BEGIN { printf "%.17g", -0.35 + 0.2 * k }'), 0, 0); run 1"
done
steps="$steps
print ball; print paddle"
play steps "$steps"
between steps "$TMP/steps" reached
deepest steps "$steps"

# ---- a tracker file: 1 m/s from -0.35 to 0.65 over 1 s, rows every 0.01 s ----
awk 'BEGIN { print "time,x,y,z,qw,qx,qy,qz,trigger,button"
             for (k = 0; k <= 100; k++) printf "%.17g,%.17g,0,0,1,0,0,0,1,0\n", k / 100, -0.35 + k / 100 }' > "$TMP/push.csv"
track="$SET
tracker = $TMP/push.csv; run 15; print ball; print paddle"
play track "$track"
between tracker "$TMP/track" reached
deepest tracker "$track"
