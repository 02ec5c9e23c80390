#!/bin/sh
# console.sh: the console beyond the thesis, in batch (language.md, "The console
# beyond the thesis"): arithmetic in values, show NAME and print OBJ.PROPERTY,
# "did you mean", clean numbers and precision.  The prompt's side is in
# console_prompt.sh.
. "$(dirname "$0")/lib.sh"
S=$(cd "$(dirname "$0")/../scenes" && pwd)
cd "$TMP" || exit 1

# has TEXT OUTPUT LINE...: every LINE is a whole line of OUTPUT
has() {
    desc=$1 out=$2
    shift 2
    for l in "$@"; do
        printf '%s\n' "$out" | grep -qxF -- "$l" || { notok "$desc" "missing: $l" "$out"; return; }
    done
    ok "$desc"
}
# lacks TEXT OUTPUT PATTERN: no line of OUTPUT matches the regular expression
lacks() {
    if printf '%s\n' "$2" | grep -q -- "$3"; then notok "$1" "$(printf '%s\n' "$2" | grep -- "$3")"; else ok "$1"; fi
}

# ---- arithmetic in values
out=$("$VROC" -b -q -c 'sphere b; radius = 1/4; rotate = (0, 0, 1) pi/2; angular_vel = (0, 0, 2*90 deg); precision = exact; print b.radius; print b.rotate; print b.angular_vel' 2>&1)
has "values may be expressions, and deg converts to radians" "$out" \
    "b.radius = 0.25" "b.rotate = (0, 0, 1) 1.5707963267948966" "b.angular_vel = (0, 0, 3.141592653589793)"
"$VROC" -b -q -c "sphere b; radius = 1/3; translate = (sqrt(2), -2^2, min(1, 2)); save $TMP/x.vroc" 2>&1
has "save writes plain numbers" "$(cat x.vroc)" "radius = 0.3333333333333333" "translate = (1.4142135623730951, -4, 1)"
printf 'sphere b\n\nradius = 2*(1 + 3\n' > bad.vroc
out=$("$VROC" -b bad.vroc 2>&1); status=$?
has "an error in an expression names file:line and points at the column (status $status)" "$out" \
    "bad.vroc:3: error: radius: this '(' is not closed" "    radius = 2*(1 + 3" "               ^"
[ $status -eq 1 ] && ok "a batch run stops at it with status 1" || notok "a batch run stops at it with status 1" "$status"
expect "fov is in degrees: deg is refused" 1 "fov is in degrees already" "$VROC" -b -c 'fov = 60 deg'

# ---- did you mean, and exit
expect "an unknown command suggests the nearest" 1 \
    "error: unknown command 'radus': did you mean radius? (help lists them all)" "$VROC" -b -c 'sphere a; radus = 1'
expect "an unknown property suggests the nearest" 1 \
    "error: 'colr' is not an object property: did you mean color? (help lists them all)" "$VROC" -b -c 'sphere a; a.colr = (1, 2, 3)'
expect "a word far from every name suggests nothing" 1 \
    "error: unknown command 'frobnicate' (help lists them all)" "$VROC" -b -c 'frobnicate'
expect "help of a typo suggests too" 1 "did you mean rotate?" "$VROC" -b -c 'help rotat'
out=$(printf 'sphere a\nexit\nprint a\n' | "$VROC" 2>&1); status=$?
[ $status -eq 0 ] && [ -z "$out" ] && ok "exit quits as quit does" || notok "exit quits as quit does" "$status $out"

# ---- queries
out=$("$VROC" -b -q -c 'time_step = 0.05; show time_step; show select; sphere b; print b.translate' 2>&1)
[ "$out" = "time_step = 0.05
select off
b.translate = (0, 0, 0)" ] && ok "show NAME and print OBJ.PROPERTY print one line each" ||
    notok "show NAME and print OBJ.PROPERTY print one line each" "$out"
expect "show of a property says how to see it" 1 "show: radius is a property of objects: print NAME.radius" \
    "$VROC" -b -c 'show radius'
expect "show of a typo suggests a setting" 1 "show: 'time_stpe' is not a setting: did you mean time_step?" \
    "$VROC" -b -c 'show time_stpe'
expect "print of a property of another type is an error" 1 "print: radius does not apply to cube 'c'" \
    "$VROC" -b -c 'cube c; print c.radius'
out=$("$VROC" -b -q -c 'cube c; rotate = (1, 0, 0) 0.5; linear_vel = (1, 2, 3); print c; print c.velocity; print c.rotate' 2>&1)
for q in linear_vel angular_vel orientation angular_momentum translate; do
    n=$(printf '%s\n' "$out" | grep -c "^$q = ")
    [ "$n" -eq 1 ] || { notok "print lists each quantity once" "$q: $n times" "$out"; break; }
done
[ "$n" -eq 1 ] && ok "print lists each quantity once"
lacks "print leaves out the alias velocity and the derived rotate" "$out" "^\(velocity\|rotate\) = "
has "both still answer print OBJ.velocity and print OBJ.rotate" "$out" \
    "c.velocity = (1, 2, 3)" "c.rotate = (1, 0, 0) 0.5"

# ---- clean numbers: 12 digits, no -0, no rounding dust beside what matters
out=$("$VROC" -b -q -c 'time_step = 0.1; run 34; time; precision = exact; time' 2>&1)
[ "$out" = "time = 3.4
time = 3.4000000000000004" ] && ok "time shows 12 digits, and precision = exact the shortest exact decimal" ||
    notok "time shows 12 digits, and precision = exact the shortest exact decimal" "$out"
out=$("$VROC" -b -q -c 'sphere a; sphere b; translate = (-3, 0, 0); distance b a' 2>&1)
has "distance's normal shows no -0" "$out" "normal = (-1, 0, 0)"
out=$("$VROC" -b -q -c 'sphere a; linear_vel = (2, 1e-13, -0); print a.linear_vel; precision = exact; print a.linear_vel' 2>&1)
has "a component below 1e-12 of the largest shows as 0; exact shows it" "$out" \
    "a.linear_vel = (2, 0, 0)" "a.linear_vel = (2, 1e-13, -0)"
out=$("$VROC" -b -q -c "sphere a; translate = (0.1, 0.2, 0.3); linear_vel = (1/3, 0, 0); time_step = 0.1; run 34; trace = $TMP/t.csv; events = $TMP/e.csv; save $TMP/s.vroc; show; stats" 2>&1)
has "show and stats are clean" "$out" "time_step = 0.1" "sim_time = 3.4"
grep -q "saved at time = 3.4000000000000004 " s.vroc && grep -q "^translate = (1.2333333333333298, 0.2, 0.3)$" s.vroc &&
    grep -q ',3.4000000000000004,a,' t.csv && ok "save and trace are exact whatever precision says" ||
    notok "save and trace are exact whatever precision says" "$(grep -e time -e translate s.vroc)" "$(tail -1 t.csv)"
expect "precision takes short or exact" 1 "precision must be one of short|exact (got 'long')" \
    "$VROC" -b -c 'precision = long'

# ---- warnings: a contact with friction with no answer, an object that left the room
# A rod (1 m, thin) landing on its end at 0.9 rad from the floor, sliding fast
# towards that end, with mu = 3, jams (Painleve): one warning names it, whatever
# follows.  (Its end r = L (cos a, -sin a) from the centre, I = m L^2 / 3: along
# the normal impulse with sliding friction -mu along x, the end's normal speed
# changes by (1 + 3 cos^2 a - 3 mu sin a cos a) / m per unit, negative, a jam,
# for mu > (1 + 3 cos^2 a) / (3 sin a cos a) = 1.48 at a = 0.9.)
out=$("$VROC" -b -q -c "gravity; max_angular = 1000; max_linear = 100; cube floor; mass = -1; size = (20, 20, 0.1); translate = (0, 0, -0.1); friction = 3" \
    -c "cube rod; size = (0.5, 0.01, 0.01); friction = 3; rotate = (0, 1, 0) 0.9; translate = (0, 0, 0.5 * sin(0.9) + 0.011); linear_vel = (3, 0, -0.5); run 10; run 10; stats" 2>&1)
[ "$(printf '%s\n' "$out" | grep -c "^warning: a contact of 'rod' with friction had no consistent answer (Painleve): it was answered without friction there, and stats counts such contacts (painleve)$")" = 1 ] &&
    [ "$(printf '%s\n' "$out" | grep -c '^warning')" = 1 ] && printf '%s\n' "$out" | grep -q '^painleve = [1-9]' &&
    ok "a Painleve contact warns once, naming its object, and stats counts it" ||
    notok "a Painleve contact warns once, naming its object, and stats counts it" "$out"
# A ball dropped from z = 1 beside a floor whose lowest point is z = -0.2 is 100 m
# below it when 1 - 4.9 t^2 < -100.2: after 4.545 s, in frame 46.
out=$("$VROC" -b -q -c "gravity; cube floor; mass = -1; size = (1, 1, 0.1); translate = (0, 0, -0.1); sphere ball; radius = 0.1; translate = (3, 0, 1); sphere still; radius = 0.1; translate = (0, 0, 0.1)" \
    -c "run 45; print ball.translate; run 1; print ball.translate; run 20; stats" 2>&1)
printf '%s\n' "$out" | awk '
    /^warning/ { if (seen) bad = 1; seen = 1; if (prints != 1 || $0 != "warning: '"'"'ball'"'"' has fallen more than 100 m below the lowest static object: it falls on") bad = 1 }
    /^ball.translate/ { prints++ }
    /^fallen = / { fallen = $3 }
    END { exit bad || !seen || fallen != 1 }' &&
    ok "an object 100 m below the lowest static object warns once, naming it, in the frame it gets there" ||
    notok "an object 100 m below the lowest static object warns once, naming it, in the frame it gets there" "$out"

# ---- energy at a glance
out=$("$VROC" -b -q -c 'gravity; max_angular = 10; sphere ball; mass = 2; translate = (1, 0, 3); linear_vel = (0, 4, 0); angular_vel = (0, 0, 5); energy; energy ball' 2>&1)
# kinetic 2 * 16 / 2 = 16 and (2/5) m r^2 w^2 / 2 = 10; potential m g z = 58.8; L about the
# origin (1, 0, 3) x (0, 8, 0) + I w = (-24, 0, 8) + (0, 0, 4)
has "energy prints the textbook's figures" "$out" "kinetic_energy = 26" "kinetic_linear = 16" \
    "kinetic_rotational = 10" "potential_energy = 58.8" "total_energy = 84.8" \
    "linear_momentum = (0, 8, 0)" "angular_momentum = (-24, 0, 12)" "angular_momentum_com = (0, 0, 4)"
out=$("$VROC" -b -q -c 'default_friction = 0; default_rolling_friction = 0; sphere a; linear_vel = (1, 0, 0); sphere b; translate = (3, 0, 0); energy; run 30; energy' 2>&1)
first=$(printf '%s\n' "$out" | grep '^total_energy' | head -1)
last=$(printf '%s\n' "$out" | grep '^total_energy' | tail -1)
[ "$first" = "total_energy = 0.5" ] && [ "$first" = "$last" ] &&
    printf '%s\n' "$out" | grep -q "^kinetic_linear = 0.5$" &&
    ok "an elastic collision keeps the total energy ($last)" ||
    notok "an elastic collision keeps the total energy" "$out"
expect "energy of a static object says it holds none" 0 "# floor is static: it never moves, and holds no energy" \
    "$VROC" -b -c 'cube floor; mass = -1; energy floor'
"$VROC" -b -q -c "sphere a; linear_vel = (3, 0, 0); trace = t2.csv; run 1" 2>&1
[ "$(head -1 t2.csv)" = "frame,time,name,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,state,ke" ] &&
    [ "$(tail -1 t2.csv | cut -d, -f18)" = "4.5" ] && ok "the trace's ke column follows state (3 m/s: 4.5 J)" ||
    notok "the trace's ke column follows state (3 m/s: 4.5 J)" "$(head -1 t2.csv)" "$(tail -1 t2.csv)"

# ---- plot: the picture gnuplot draws, read back (its size, and that it is no blank)
# png_size FILE: "W H" from the PNG's header
png_size() { od -An -tu1 -j16 -N8 "$1" | awk '{ print $1*16777216 + $2*65536 + $3*256 + $4, $5*16777216 + $6*65536 + $7*256 + $8 }'; }
# png_ink FILE: "distinct-grey-levels dark-pixels" of the picture
png_ink() {
    ffmpeg -v error -y -i "$1" -f rawvideo -pix_fmt gray - 2>/dev/null | od -An -v -tu1 |
        awk '{ for (i = 1; i <= NF; i++) { seen[$i] = 1; if ($i < 128) dark++ } } END { print length(seen), dark + 0 }'
}
if command -v gnuplot >/dev/null 2>&1; then
    W="gravity; cube floor; mass = -1; size = (3, 3, 0.1); translate = (0, 0, -0.1); sphere ball; radius = 0.2; translate = (0, 0, 1); linear_vel = (0.5, 0.3, 2); elasticity = 0.8"
    out=$("$VROC" -b -c "$W; run 40; plot energy = e.png; plot momentum = m.png; plot ball.height = h.png" 2>&1)
    for f in e m h; do
        size=$(png_size $f.png 2>/dev/null); ink=$(png_ink $f.png)
        want="900 520"; [ $f = m ] && want="900 900"
        set -- $ink
        if [ "$size" = "$want" ] && [ "${1:-0}" -ge 8 ] && [ "${2:-0}" -ge 2000 ]; then
            ok "plot writes $f.png: $size, $1 grey levels, $2 dark pixels"
        else
            notok "plot writes $f.png ($want, drawn)" "size $size ink $ink" "$out"
        fi
    done
    has "plot says what it drew" "$out" "plotted energy over 41 frames to e.png"
    rm -f e.png
    expect "a run restarted has nothing to plot" 1 "plot: this run has no frames to plot yet" \
        "$VROC" -b -c "$W; run 5; restart; plot energy = e.png"
    [ -f e.png ] && notok "a failed plot writes nothing" || ok "a failed plot writes nothing"
    expect "plot of an object not in the run" 1 "plot: no object named 'nobody' in this run" \
        "$VROC" -b -c "$W; run 5; plot nobody.height = e.png"
else
    notok "gnuplot is installed (make deps installs gnuplot-nox)"
fi
mkdir -p nopath
expect "where gnuplot is missing, plot says so" 1 "plot: the gnuplot program is not installed" \
    env PATH="$TMP/nopath" "$VROC" -b -c 'sphere a; run 3; plot energy = e.png'
# recording the figures never changes the trace: a run split by plots gives the same file
"$VROC" -b -q "$S/bounce.vroc" -c "trace = one.csv; run 60" > /dev/null 2>&1
"$VROC" -b -q "$S/bounce.vroc" -c "trace = two.csv; run 20; plot energy = p1.png; run 25; plot momentum = p2.png; run 15" > /dev/null 2>&1
[ -s one.csv ] && same "recording and plotting the figures never changes the trace" one.csv two.csv ||
    notok "recording and plotting the figures never changes the trace" "no trace"

# ---- progress: batch runs show none unless -v, which writes a line a second
# into a file (standard error is not a terminal here)
"$VROC" -b -c 'sphere b; run 1500000' > quiet.out 2>&1
[ ! -s quiet.out ] && ok "a batch run shows no progress" || notok "a batch run shows no progress" "$(head -3 quiet.out)"
# a run far longer than the test, whatever the machine's speed, stopped by Ctrl-C
# (SIGINT) after 2.5 s of whole lines a second
timeout -s INT 2.5 "$VROC" -b -v -c 'sphere b; run 100000000; time' > v.out 2> v.err
if grep -q '^run: frame [0-9]* of 100000000, time = [0-9.e+]*, [0-9]* frames/s, .* left$' v.err &&
    ! grep -q "$(printf '\r')" v.err; then
    ok "-v shows the progress of a long run as whole lines: $(tail -1 v.err)"
else
    notok "-v shows the progress of a long run as whole lines" "$(cat v.err)" "$(cat v.out)"
fi
"$VROC" -b -v -c 'sphere b; run 100' > v2.out 2>&1
[ ! -s v2.out ] && ok "-v shows nothing for a short run" || notok "-v shows nothing for a short run" "$(cat v2.out)"

# ---- default colours: a palette in turn, red first, again after restart
out=$("$VROC" -b -q -c 'cube floor; sphere a; cube b; sphere c; print floor.color; print a.color; print b.color; print c.color; restart; sphere d; print d.color' 2>&1)
n=$(printf '%s\n' "$out" | sed -n 's/^[a-z]*\.color = //p' | head -4 | sort -u | wc -l)
printf '%s\n' "$out" | grep -qx 'floor.color = (255, 0, 0)' && [ "$n" -eq 4 ] &&
    printf '%s\n' "$out" | grep -qx 'd.color = (255, 0, 0)' &&
    ok "new objects take distinguishable colours in turn, the thesis's red first" ||
    notok "new objects take distinguishable colours in turn, the thesis's red first" "$out"

# ---- read starts a new run for plot, as restart does
printf 'sphere other\n' > other.vroc
expect "read starts a new run: nothing to plot after it" 1 "plot: this run has no frames to plot yet" \
    "$VROC" -b -c "sphere a; run 5; read other.vroc; plot energy = r.png"

# ---- help's texts: six groups, and no line broken early (help ipd printed "Default" alone)
expect "help help says six groups" 0 "in six groups: objects, object properties, system" "$VROC" -b -c 'help help'
out=$("$VROC" -b -c 'help ipd' 2>&1)
printf '%s\n' "$out" | grep -qx 'Default' && notok "help ipd keeps its lines whole" "$out" ||
    ok "help ipd keeps its lines whole"
