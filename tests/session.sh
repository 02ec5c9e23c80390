#!/bin/sh
# session.sh: the vroc binary run on scripts and command lines, as users run it.
. "$(dirname "$0")/lib.sh"
S=$(cd "$(dirname "$0")/../scenes" && pwd)

expect "--version" 0 "vroc 0." "$VROC" --version
expect "--help" 0 "usage: vroc [-b] [-q] [-v] [-o DIR] [-c COMMANDS] [FILE ...]" "$VROC" --help
expect "an unknown option exits 2" 2 "unknown option -z" "$VROC" -z
expect "-c without its value exits 2" 2 "-c needs a value" "$VROC" -c

expect "the Simple scene: 4 objects" 0 "objects = 4" "$VROC" -b "$S/simple.vroc" -c stats
expect "the Simple scene: 6 pairs" 0 "pairs = 6" "$VROC" -b "$S/simple.vroc" -c stats
expect "the Simple scene: 6 subframes" 0 "subframes = 6" "$VROC" -b "$S/simple.vroc" -c stats

# batch: the first error stops the run with status 1, naming file and line
printf 'sphere a\nradius = 0.5\n\nradius = -2\n' > "$TMP/bad.vroc"
expect "batch: an error in a file exits 1 with file:line" 1 "bad.vroc:4: error: radius must be between 1e-06 and 10000 (got -2)" \
    "$VROC" -b "$TMP/bad.vroc"
out=$("$VROC" -b "$TMP/bad.vroc" -c 'print a' 2>&1)
case "$out" in *"sphere a"*) notok "batch: nothing runs after the first error" "$out" ;;
    *) ok "batch: nothing runs after the first error" ;; esac
out=$("$VROC" -b -c 'sphere a' -c 'bogus' -c 'print a' 2>&1); status=$?
case "$status:$out" in 1:*"error: unknown command 'bogus'"*) ok "batch: -c error exits 1" ;;
    *) notok "batch: -c error exits 1" "$status $out" ;; esac

# piped input: no prompt echoed, errors name <stdin> and its line, exit 1
out=$(printf 'sphere a\nradius = 2\nprint a\n' | "$VROC" 2>&1); status=$?
case "$status:$out" in "0:sphere a"*"radius = 2"*) ok "pipe: statements run, no prompt" ;;
    *) notok "pipe: statements run, no prompt" "$status $out" ;; esac
case "$out" in *"vroc>"*) notok "pipe: no prompt echoed" "$out" ;; *) ok "pipe: no prompt echoed" ;; esac
out=$(printf 'sphere a\n\nbogus 1\nprint a\n' | "$VROC" 2>&1); status=$?
case "$status:$out" in "1:<stdin>:3: error: unknown command 'bogus'"*) ok "pipe: first error stops with <stdin>:LINE, status 1" ;;
    *) notok "pipe: first error stops with <stdin>:LINE, status 1" "$status $out" ;; esac
out=$(printf 'sphere a\nquit\nbogus\n' | "$VROC" 2>&1); status=$?
[ $status -eq 0 ] && ok "pipe: quit leaves with 0" || notok "pipe: quit leaves with 0" "$status $out"
out=$(printf 'sphere a\n' | "$VROC" 2>&1); status=$?
[ $status -eq 0 ] && ok "pipe: end of input leaves with 0" || notok "pipe: end of input leaves with 0" "$status"

# files named on the command line run first, then -c
printf 'sphere first\n' > "$TMP/one.vroc"
expect "files then -c" 0 "first" "$VROC" -b "$TMP/one.vroc" -c 'list'
expect "-o sets the output folder" 0 "output = \"$TMP/out\"" "$VROC" -b -o "$TMP/out" -c show
expect "-o survives restart" 0 "output = \"$TMP/out\"" "$VROC" -b -o "$TMP/out" -c 'restart; show'
out=$("$VROC" -b -q -c "sphere a; save $TMP/q.vroc" 2>&1)
[ -z "$out" ] && ok "-q prints nothing for save" || notok "-q prints nothing for save" "$out"
out=$("$VROC" -b -c "sphere a; save $TMP/q.vroc" 2>&1)
case "$out" in *"saved 1 objects"*) ok "without -q save says what it did" ;; *) notok "without -q save says what it did" "$out" ;; esac

# read: relative paths inside a file come from that file's folder; scenes from
# the installed folder (VROC_SCENES here)
mkdir -p "$TMP/a/b"
printf 'sphere inner\n' > "$TMP/a/b/inner.vroc"
printf 'read b/inner.vroc\n' > "$TMP/a/outer.vroc"
expect "read: paths relative to the reading file" 0 "inner" sh -c "cd / && '$VROC' -b '$TMP/a/outer.vroc' -c list"
expect "read: the scenes folder is searched" 0 "objects = 4" \
    sh -c "cd '$TMP' && VROC_SCENES='$S' '$VROC' -b -c 'read simple.vroc; stats'"
printf 'read simple.vroc\n' > "$TMP/a/scene-reader.vroc"
expect "read: a file finds a scene in the scenes folder too" 0 "objects = 4" \
    sh -c "cd / && VROC_SCENES='$S' '$VROC' -b '$TMP/a/scene-reader.vroc' -c stats"

# files nest 16 deep, whether the first is named on the command line or read
mkdir -p "$TMP/nest"
for i in $(seq 1 17); do echo "read f$((i + 1)).vroc" > "$TMP/nest/f$i.vroc"; done
echo "sphere deepest" > "$TMP/nest/f18.vroc"
for how in "command line" read; do
    for n in 16 17; do
        first=$((19 - n))
        if [ "$how" = read ]; then
            out=$(cd "$TMP/nest" && "$VROC" -b -c "read f$first.vroc; list" 2>&1)
        else
            out=$(cd "$TMP/nest" && "$VROC" -b "f$first.vroc" -c list 2>&1)
        fi
        status=$?
        if [ $n -eq 16 ]; then
            case "$status:$out" in 0:deepest*) ok "$how: $n files reading each other run" ;;
                *) notok "$how: $n files reading each other run" "status $status" "$out" ;; esac
        else
            case "$status:$out" in 1:*"f17.vroc:1: error: files read each other deeper than 16 levels (at 'f18.vroc')"*)
                ok "$how: $n files reading each other are refused at the same place" ;;
                *) notok "$how: $n files reading each other are refused at the same place" "status $status" "$out" ;; esac
        fi
    done
done

# a thrown sphere under gravity after run 10, to 1e-9, whatever internal_step
for step in 0 0.001 0.03; do
    out=$("$VROC" -b -q -c "gravity; internal_step = $step; sphere s; translate = (0, 0, 1); linear_vel = (1, 2, 5); run 10; precision = exact; print s")
    pos=$(printf '%s\n' "$out" | sed -n 's/^translate = (\(.*\))$/\1/p')
    if printf '%s\n' "$pos" | awk -F', ' '{ t = 1; ex = 1*t; ey = 2*t; ez = 1 + 5*t - 4.9*t*t;
        d = ($1-ex)^2 + ($2-ey)^2 + ($3-ez)^2; exit !(sqrt(d) < 1e-9) }'; then
        ok "thrown sphere at the closed-form place (internal_step $step)"
    else
        notok "thrown sphere at the closed-form place (internal_step $step)" "$pos"
    fi
done

# save, restart, read: the same print for every object
cat > "$TMP/world.vroc" <<'EOS'
gravity
sphere ball; radius = 0.3; translate = (0.1, 0.2, 3); linear_vel = (1, -2, 0.5); angular_vel = (0.1, 0.2, 0.3)
cube box; size = (0.5, 0.25, 0.125); rotate = (1, 2, 3) 0.7; angular_vel = (1, 0.5, 2); mass = 2.5
superquadric pillow; exp1 = 0.4; exp2 = 1.7; a1 = 0.6; a2 = 0.4; a3 = 0.2; ures = 14; vres = 9; color = (250, 200, 10); translate = (3, 0, 0)
cube floor; mass = -1; size = (5, 5, 0.1); translate = (0, 0, -5)
run 13
EOS
# (the box lands spinning faster than max_angular: the limit's warning is the
# first run's alone)
"$VROC" -b -q "$TMP/world.vroc" -c "precision = exact; print ball; print box; print pillow; print floor; print box.rotate; save $TMP/saved.vroc" 2>&1 |
    no_cut_warning > "$TMP/p1"
"$VROC" -b -q -c "read $TMP/saved.vroc; precision = exact; print ball; print box; print pillow; print floor; print box.rotate" > "$TMP/p2" 2>&1
same "save and read give the same print for every object" "$TMP/p1" "$TMP/p2"
grep -q "^box.rotate = (1, 2, 3) 0.7$" "$TMP/p1" || ! grep -q "^box.rotate = " "$TMP/p1" &&
    notok "a spinning box's orientation is its simulated one, not as typed" "$(grep rotate "$TMP/p1")" || ok "a spinning box's orientation is its simulated one, not as typed"
"$VROC" -b -q "$TMP/world.vroc" -c "show" 2>&1 | no_cut_warning > "$TMP/s1"
"$VROC" -b -q -c "read $TMP/saved.vroc; show" > "$TMP/s2" 2>&1
same "save and read give the same show" "$TMP/s1" "$TMP/s2"

# restart and quit end the logs, as trace's and events' pages say
"$VROC" -b -q -c "sphere a; trace = $TMP/r.csv; events = $TMP/re.csv; restart; sphere b; run 2; show" > "$TMP/r.show" 2>&1
grep -q '^trace = off$' "$TMP/r.show" && grep -q '^events = off$' "$TMP/r.show" && [ "$(wc -l < "$TMP/r.csv")" -eq 2 ] &&
    ok "restart closes the trace and the events log" ||
    notok "restart closes the trace and the events log" "$(grep -E '^(trace|events)' "$TMP/r.show")" "$(wc -l < "$TMP/r.csv") lines"

# start in a script: time does not run by itself there
expect "start in batch says how time runs" 0 "use run N in scripts" "$VROC" -b -c 'start; time'
