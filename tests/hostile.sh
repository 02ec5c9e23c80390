#!/bin/sh
# hostile.sh: input as an attacker would give it (issue 32), each finding a test.
# Values that escape the limits (tracker rows, throws, the simulation's own
# states, names, -o), input that would hang or eat memory (devices, named pipes,
# reads nested in reads), and messages that would echo raw bytes.  Where a limit is
# involved, just inside and just outside it.  Timeouts are shortened with
# VROC_TIMEOUT; memory is bounded with ulimit -v in the normal build (the
# sanitizers reserve terabytes of address space).
. "$(dirname "$0")/lib.sh"
cd "$TMP" || exit 1
H=time,x,y,z,qw,qx,qy,qz,trigger,button
san=false
[ "${BUILD:-build}" = build-san ] && san=true

# is TEXT GOT WANT
is() { [ "$2" = "$3" ] && ok "$1" || notok "$1" "got:  $2" "want: $3"; }
# has TEXT OUTPUT LINE: OUTPUT holds LINE (the sanitizer build may add lines)
has() { printf '%s\n' "$2" | grep -qxF -- "$3" && ok "$1" || notok "$1" "want: $3" "got: $(printf '%s' "$2" | head -5)"; }
# bounded KB CMD...: CMD with at most KB kilobytes of memory (normal build only)
bounded() {
    kb=$1
    shift
    if $san; then "$@"; else (ulimit -v "$kb" && "$@"); fi
}

# ---- tracker rows within the limits of a statement ----
printf '%s\n0,0,0,1.5,1,0,0,0,0,0\n1,1e308,0,1.5,1,0,0,0,0,0\n' "$H" > far.csv
expect "a tracker row at x = 1e308 is refused with file:line" 1 \
    "far.csv:3: x must be between -1e+06 and 1e+06 (got 1e+308)" "$VROC" -b -c "tracker = far.csv"
printf '%s\n0,0,0,1.5,1,0,0,0,0,0\n1,-1e6,1e6,1.5,1,0,0,0,0,0\n' "$H" > edge.csv
expect "a tracker row at the edge, x = -1e6 and y = 1e6, is taken" 0 "hand = (-1000000, 1000000, 1.5)" \
    "$VROC" -b -c "tracker = edge.csv; run 11; show"
printf '%s\n0,0,0,1.5,1,0,0,0,1,0\n1e-300,1,0,1.5,1,0,0,0,0,0\n' "$H" > near.csv
expect "tracker rows 1e-300 s apart are refused (they would throw at 1e300 m/s)" 1 \
    "near.csv:3: time 1e-300 is 1e-300 s after the row before: rows are at the same time, or at least 1e-06 s apart" \
    "$VROC" -b -c "tracker = near.csv"
printf '%s\n0,0,0,1.5,1,0,0,0,1,0\n1e-6,0.001,0,1.5,1,0,0,0,0,0\n' "$H" > apart.csv
expect "tracker rows 1e-6 s apart are taken" 0 "tracker = " "$VROC" -b -c "tracker = apart.csv; show"

# ---- a throw within max_linear, and counted ----
out=$("$VROC" -b -c 'sphere ball; radius=0.1; translate=(0,0,1.5); select on; hand=(0,0,1.5); trigger=on; time_step=1e-6; step; hand=(1e6,0,1.5); trigger=off; print ball; stats' 2>&1)
has "a throw from statements is cut to max_linear (the issue's: 1e12 m/s)" "$out" "linear_vel = (8, 0, 0)"
has "and counted among the speed cuts" "$out" "speed_cuts = 1"
has "and the cut warns, naming the limit to raise" "$out" \
    "warning: max_linear = 8 cut the speed a throw gave 'ball' (1e+12 m/s): each such cut loses energy, and stats counts them (speed_cuts); raise max_linear to keep it"
out=$("$VROC" -b -c 'sphere ball; radius=0.1; translate=(0,0,1.5); select on; hand=(0,0,1.5); trigger=on; time_step=0.5; step; hand=(4,0,1.5); trigger=off; print ball; stats' 2>&1)
has "a throw at max_linear exactly is not cut" "$out" "linear_vel = (8, 0, 0)"
has "nor counted" "$out" "speed_cuts = 0"
printf '%s\n0,0,0,1.5,1,0,0,0,1,0\n0.1,0,0,1.5,1,0,0,0,1,0\n0.2,0,0,1.5,0.70710678118654757,0,0,0.70710678118654757,0,0\n' "$H" > spin.csv
out=$("$VROC" -b -c 'sphere ball; radius=0.1; translate=(0,0,1.5); select on; tracker = spin.csv; run 3; print ball; stats' 2>&1)
has "a tracker's spinning throw (7.9 rad/s) is cut to max_angular" "$out" "angular_vel = (0, 0, 4)"

# ---- the simulation's own states read back ----
out=$("$VROC" -b -c 'sphere ball; gravity; run 5000; save fall.vroc' 2>&1)
has "a ball that falls for 500 s rests where it leaves the limits, with one warning naming it" "$out" \
    "warning: 'ball' left the limits of a state at time = 451.8 (a coordinate beyond 1000000 m: translate = (0, 0, -1000203.8760009465)): it rests where it left them, at translate = (0, 0, -1000000)"
out=$("$VROC" -b fall.vroc -c 'run 10; print ball' 2>&1)
has "its saved state reads back, and it stays at rest" "$out" "translate = (0, 0, -1000000)"
out=$("$VROC" -b -c 'sphere ball; gravity; run 4517; print ball' 2>&1)
has "a fall of 451.7 s, just inside, goes on falling" "$out" "resting = off"
out=$("$VROC" -b -c 'sphere ball; force = (0, 0, -1) 10000; run 20; save fast.vroc' 2>&1)
has "a ball faster than the limits of a velocity (1000 g for 1.1 s) rests too" "$out" \
    "warning: 'ball' left the limits of a state at time = 1.1 (a velocity beyond 10000 m/s, or a spin beyond what the limits give): it rests where it left them, at translate = (0, 0, -6049.999999999977)"
expect "and reads back" 0 "linear_vel = (0, 0, 0)" "$VROC" -b fast.vroc -c 'print ball'
expect "the clock runs to its limit, 1e12 s" 0 "time = 1000000000000" \
    "$VROC" -b -c 'precision = exact; time_step = 1000; clock = (999999998000, 0); run 2; time'
expect "and no further" 1 "error: time cannot run past 1000000000000 s" \
    "$VROC" -b -c 'time_step = 1000; clock = (999999998000, 0); run 3'

# ---- names: an object named like one of grip's words reads back held ----
for n in none off fly panel time_step collision_dist; do
    "$VROC" -b -q -c "sphere $n; select on; trigger = on; save g-$n.vroc" 2>&1
    got=$(grep '^grip =' g-$n.vroc)
    back=$("$VROC" -b -q g-$n.vroc -c "show" 2>&1 | grep '^grip =')
    [ "$got" = "grip = \"$n\"" ] && [ "$back" = "$got" ] && ok "an object named $n is held as \"$n\" in save, and reads back so" ||
        notok "an object named $n is held as \"$n\" in save, and reads back so" "saved: $got" "read back: $back"
done
expect "grip = panel, unquoted, is the panel" 0 "grip = panel" "$VROC" -b -q -c 'sphere panel; select on; grip = panel; show'

# ---- -o ----
expect "-o \"\" is refused (output = \"\" would not read back)" 2 "vroc: -o: the folder name is empty" \
    "$VROC" -b -o "" -c show
"$VROC" -b -q -o 'a"b\c' -c 'save o.vroc'
expect "a folder name with a quote and a backslash is saved so that it reads back" 0 'output = "a\"b\\c"' \
    "$VROC" -b -q o.vroc -c show

# ---- messages never echo raw bytes ----
printf 'sphere a\n\377\376x = 1\n' > bin.vroc
has "bytes that are not printable are escaped in messages" "$("$VROC" -b bin.vroc 2>&1)" \
    "bin.vroc:2: error: unknown command '\\xff\\xfex' (help lists them all)"
printf 'read "a\001\033[2J\302\233b"\n' > ctl.vroc
has "control characters too (C0, C1)" "$("$VROC" -b ctl.vroc 2>&1)" \
    "ctl.vroc:1: error: cannot read 'a\\x01\\x1b[2J\\xc2\\x9bb': No such file or directory"
printf 'sphere caf\303\251\n' > utf.vroc
expect "printable UTF-8 is left as it is" 1 "'café' is not a valid object name" "$VROC" -b utf.vroc
printf '%s\n0,\033[2J,0,0,1,0,0,0,0,0\n' "$H" > esc.csv
expect "a tracker row's bytes are escaped too" 1 "esc.csv:2: x is not a number (got '\\x1b[2J')" \
    "$VROC" -b -c 'tracker = esc.csv'

# ---- input that would hang or eat memory ----
expect "tracker = /dev/zero stops at the size cap, in bounded memory" 1 \
    "error: tracker: cannot read '/dev/zero': it is larger than 67108864 bytes" \
    bounded 600000 "$VROC" -b -c 'tracker = /dev/zero'
expect "read /dev/zero too" 1 "cannot read '/dev/zero': it is larger than 67108864 bytes" \
    bounded 600000 "$VROC" -b -c 'read /dev/zero'
# a row padded to n bytes
padded() { awk -v h="$H" -v n="$1" 'BEGIN { print h; r = "10,0,0,0,1,0,0,0,0,0"; printf "%s", r;
    for (i = length(r); i < n; i++) printf " "; print "" }'; }
padded 1024 > line1024.csv
padded 1025 > line1025.csv
expect "a tracker line of 1024 bytes is taken" 0 "tracker = " "$VROC" -b -c 'tracker = line1024.csv; show'
expect "one of 1025 bytes is refused" 1 "line1025.csv:2: a line longer than 1024 bytes" \
    "$VROC" -b -c 'tracker = line1025.csv'
out=$(head -c 100000000 /dev/zero | bounded 600000 "$VROC" 2>&1); status=$?
is "statements piped from /dev/zero stop at the line cap, in bounded memory" "$status:$out" \
    "1:<stdin>:1: error: a line longer than 1048576 bytes"
out=$(printf 'sphere a\nli\000st\n' | "$VROC" 2>&1); status=$?
is "a NUL byte in piped statements is an error, not a line cut short" "$status:$out" \
    "1:<stdin>:2: error: a NUL byte (binary input?)"
mkfifo fifo
expect "read of a named pipe no program writes to times out" 1 \
    "cannot read 'fifo': nothing came through it for 1 s (a pipe no program writes to?)" \
    env VROC_TIMEOUT=1 "$VROC" -b -c 'read fifo'
expect "collision_sound of such a pipe too" 1 \
    "error: collision_sound: cannot read 'fifo': nothing came through it for 1 s" \
    env VROC_TIMEOUT=1 "$VROC" -b -c 'collision_sound = fifo'
(printf 'sphere piped\n' > fifo) &
expect "a named pipe that a program writes to is read" 0 "piped" "$VROC" -b -c 'read fifo; list'
wait
# a mesh file comes through the same door: a pipe times out, a line is capped
expect "a polyhedron's file that is a named pipe no program writes to times out" 1 \
    "cannot read 'fifo': nothing came through it for 1 s" \
    env VROC_TIMEOUT=1 "$VROC" -b -c 'polyhedron p; file = fifo'
tetra() { # FILE N: a tetrahedron in OBJ, its first line a comment of N bytes
    awk -v n="$2" 'BEGIN { printf "#"; for (i = 1; i < n; i++) printf "x"; print "";
        print "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\nf 1 3 4\nf 2 3 4" }' > "$1"
}
tetra t1.obj 1048576
tetra t2.obj 1048577
expect "a mesh file's line of 1 MiB is read" 0 "polyhedron" "$VROC" -b -c 'polyhedron p; file = t1.obj; list'
expect "one of 1 MiB and a byte is refused with file:line" 1 "t2.obj:1: a line longer than 1048576 bytes" \
    "$VROC" -b -c 'polyhedron p; file = t2.obj'
# random N takes room as objects find it: 90 million asked of a box that holds
# 611 took 8 GB before (the fuzz campaign's hang)
expect "random 90111111 in a box for 611 says so, in bounded memory" 1 \
    "error: random: only 611 of the 90111111 objects found room in random_box" \
    bounded 300000 "$VROC" -b -c 'random 90111111'
# reads nested in reads: ten files that each read the next ten times
for d in 0 1 2 3 4 5 6; do
    : > "f$d.vroc"
    for k in 1 2 3 4 5 6 7 8 9 10; do echo "read f$((d + 1)).vroc" >> "f$d.vroc"; done
done
echo "sphere leaf" > f7.vroc
expect "reads nested seven deep, ten each (1e7 reads), stop at the cap in bounded memory" 1 \
    "cannot read 'f7.vroc': more than 10000 files read in all (files that read others many times over?)" \
    bounded 300000 "$VROC" -b f0.vroc
awk 'BEGIN { for (i = 0; i < 9999; i++) print "read f7.vroc" }' > r9999.vroc
awk 'BEGIN { for (i = 0; i < 10000; i++) print "read f7.vroc" }' > r10000.vroc
expect "10000 files read in all are read" 0 "leaf" "$VROC" -b r9999.vroc -c list
expect "10001 are not" 1 "r10000.vroc:10000: error: cannot read 'f7.vroc': more than 10000 files read" \
    "$VROC" -b r10000.vroc

# ---- sound files hold finite samples ----
# a mono 32-bit float WAV at 48 kHz of four samples (0.5, X, 0.5, 0)
float_wav() { # FILE X (X as the octal escapes of its four little-endian bytes)
    printf 'RIFF\064\000\000\000WAVEfmt \020\000\000\000\003\000\001\000\200\273\000\000\000\356\002\000\004\000\040\000data\020\000\000\000' > "$1"
    printf "\\000\\000\\000\\077$2\\000\\000\\000\\077\\000\\000\\000\\000" >> "$1"
}
float_wav nan.wav '\000\000\300\177'
float_wav inf.wav '\000\000\200\177'
float_wav ok.wav '\000\000\200\076'
expect "a float WAV holding NaN is refused" 1 "holds a sample that is not a finite number (nan, at frame 1)" \
    "$VROC" -b -c 'collision_sound = nan.wav'
expect "one holding infinity too" 1 "holds a sample that is not a finite number (inf, at frame 1)" \
    "$VROC" -b -c 'collision_sound = inf.wav'
expect "one of finite samples is taken" 0 "collision_sound = \"ok.wav\"" \
    "$VROC" -b -c 'collision_sound = ok.wav; show'

# ---- writes that never destroy what was there ----
limited() { # BLOCKS CMD...: CMD with the file size limit, SIGXFSZ ignored (outputs.sh)
    blocks=$1
    shift
    (trap '' XFSZ; ulimit -f "$blocks" && "$@")
}
noparts() { # TEXT [FOLDER]: no part file is left in FOLDER (here)
    left=$(ls -A "${2:-.}" | grep vroc-part)
    [ -z "$left" ] && ok "$1" || notok "$1" "$left"
}
"$VROC" -b -q -c 'sphere old; save w.vroc'
cp w.vroc w-before.vroc
out=$(limited 8 "$VROC" -b -q -c 'random_box = (9, 9, 9); random 60; save w.vroc' 2>&1); status=$?
has "a save that outgrows the file size limit fails, saying why" "$out" "error: save: cannot write 'w.vroc': File too large"
same "and leaves the old file whole" w-before.vroc w.vroc
noparts "and no part file"
limited 400 "$VROC" -b -q -c 'random_box = (9, 9, 9); random 60; save w.vroc'
grep -q '^sphere random1$\|^cube random1$\|^superquadric random1$' w.vroc && ok "under a wider limit the same save replaces it" ||
    notok "under a wider limit the same save replaces it" "$(head -3 w.vroc)"
chmod 640 w.vroc
"$VROC" -b -q -c 'sphere again; save w.vroc'
is "a saved file keeps the mode the old one had" "$(stat -c %a w.vroc)" 640
"$VROC" -b -q -c 'sphere new; save fresh.vroc'
is "a new one gets 0666 less the umask" "$(stat -c %a fresh.vroc)" "$(printf '%o' $((0666 & ~$(umask))))"
ln -s w.vroc link.vroc
"$VROC" -b -q -c 'sphere through; save link.vroc'
[ -L link.vroc ] && grep -q '^sphere through$' w.vroc && ok "a save through a link replaces the file it names, and the link stays" ||
    notok "a save through a link replaces the file it names, and the link stays" "$(ls -l link.vroc w.vroc)"
# the logs start beside too: a trace whose first rows cannot be written leaves the old one
printf 'old trace\n' > t.csv
out=$(limited 2 "$VROC" -b -q -c 'random_box = (9, 9, 9); random 60; trace = t.csv' 2>&1)
has "a trace that cannot start fails, saying why" "$out" "error: trace: cannot write 't.csv': File too large"
is "and the old trace is whole" "$(cat t.csv)" "old trace"
noparts "and no part file is left"
printf 'old hand log\n' > h.csv
out=$(limited 0 "$VROC" -b -q -c 'hand_log = h.csv' 2>&1)
has "a hand log likewise" "$out" "error: hand_log: cannot write 'h.csv': File too large"
is "and the old one is whole" "$(cat h.csv)" "old hand log"
printf 'old events\n' > e.csv
out=$(limited 0 "$VROC" -b -q -c 'events = e.csv' 2>&1)
has "an events log likewise" "$out" "error: events: cannot write 'e.csv': File too large"
is "and the old one is whole" "$(cat e.csv)" "old events"
noparts "and no part files are left"

# named pipes: one no program reads is refused at once; one a program reads is written
mkfifo out.fifo
for w in "save out.fifo" "trace = out.fifo" "events = out.fifo" "hand_log = out.fifo"; do
    expect "$w, a named pipe no program reads, is refused at once" 1 "cannot write 'out.fifo': no program reads the named pipe" \
        timeout 10 "$VROC" -b -c "sphere a; $w"
done
expect "soundtrack = out.fifo is refused (a soundtrack is rewritten as it grows)" 1 \
    "error: soundtrack: cannot write 'out.fifo': a named pipe (the file is rewritten as it grows)" \
    timeout 10 "$VROC" -b -c "soundtrack = out.fifo"
expect "movie = out.fifo is refused" 1 "error: movie: cannot write 'out.fifo': not a regular file" \
    timeout 10 "$VROC" -b -c "movie = out.fifo.mp4; movie = off; movie = out.fifo"
exec 3<> out.fifo # (a reader, and a writer that keeps it from ending)
timeout 10 "$VROC" -b -q -c 'sphere a; save out.fifo'
is "a named pipe a program reads is written in place" "$(head -n 1 <&3 | cut -c 1-6)" "# vroc"
exec 3<&-
[ -p out.fifo ] && ok "and stays a named pipe" || notok "and stays a named pipe"

# VROC_SANDBOX resolves paths: a link on the way must not lead out
mkdir -p box/sub outside
ln -s "$TMP/outside" box/out
ln -s sub box/in
ln -s "$TMP/outside/x.vroc" box/x.vroc
ln -s "$TMP/outside/nothing.vroc" box/dangling.vroc
echo "outside" > outside/x.vroc
out=$(cd box && VROC_SANDBOX=1 "$VROC" -b -c 'sphere a; save out/x.vroc' 2>&1)
has "VROC_SANDBOX: a save through a link to a folder outside is refused" "$out" \
    "error: save: 'out/x.vroc' leads outside the current folder through a link, and VROC_SANDBOX allows writing only below it"
out=$(cd box && VROC_SANDBOX=1 "$VROC" -b -c 'sphere a; save x.vroc' 2>&1)
has "and one to a link that names a file outside" "$out" \
    "error: save: 'x.vroc' leads outside the current folder through a link, and VROC_SANDBOX allows writing only below it"
out=$(cd box && VROC_SANDBOX=1 "$VROC" -b -c 'output = out' 2>&1)
has "and an output folder that is such a link" "$out" \
    "error: output: 'out' leads outside the current folder through a link, and VROC_SANDBOX allows writing only below it"
(cd box && VROC_SANDBOX=1 "$VROC" -b -q -c 'sphere a; save dangling.vroc')
[ -f box/dangling.vroc ] && [ ! -L box/dangling.vroc ] && ok "a link to nothing is replaced by the file, not followed" ||
    notok "a link to nothing is replaced by the file, not followed" "$(ls -l box)"
[ "$(ls -A outside)" = x.vroc ] && [ "$(cat outside/x.vroc)" = outside ] && ok "nothing was written outside" ||
    notok "nothing was written outside" "$(ls -A outside)"
(cd box && VROC_SANDBOX=1 "$VROC" -b -q -c 'sphere a; save in/y.vroc')
[ -f box/sub/y.vroc ] && ok "a link that stays inside is followed" || notok "a link that stays inside is followed" "$(ls -lR box)"

# ---- movies: ffmpeg's failures are seen, and the old movie kept ----
if command -v ffmpeg >/dev/null 2>&1 && command -v ffprobe >/dev/null 2>&1; then
    real=$(command -v ffmpeg)
    mkdir -p fake/stall fake/nospace
    # an ffmpeg that never reads its input (nor works)
    printf '#!/bin/sh\necho $$ > "%s/stall.pid"\nexec sleep 1000\n' "$TMP" > fake/stall/ffmpeg
    # one that encodes, but whose mux finds the disk full: it leaves a broken file
    # and says why on its standard error, as ffmpeg does
    cat > fake/nospace/ffmpeg <<FAKE
#!/bin/sh
case " \$* " in *" -map "*)
    for a; do out=\$a; done
    printf 'half a movie' > "\$out"
    echo "[mp4 @ 0x5555] av_interleaved_write_frame(): No space left on device" >&2
    exit 1 ;;
esac
exec "$real" "\$@"
FAKE
    chmod +x fake/stall/ffmpeg fake/nospace/ffmpeg
    "$VROC" -b -q -c 'sphere a; translate = (0, 3, 0); image_size = (16, 16); movie = old.mp4; run 3' 2>/dev/null
    cp old.mp4 old-before.mp4
    out=$(PATH="$TMP/fake/stall:$PATH" VROC_TIMEOUT=1 timeout 60 "$VROC" -b -c 'sphere a; translate = (0, 3, 0); image_size = (160, 120); movie = old.mp4; run 20' 2>&1); status=$?
    has "an ffmpeg that never reads times out with an error" "$out" \
        "error: movie: ffmpeg took no frame and did no work for 1 s: it is stopped (VROC_TIMEOUT sets how long vroc waits); movie is now off, time stopped"
    is "and the batch run exits 1" "$status" 1
    same "and the old movie is whole" old-before.mp4 old.mp4
    noparts "and no part file is left"
    [ -s stall.pid ] && ! kill -0 "$(cat stall.pid)" 2>/dev/null && ok "and the stalled ffmpeg is stopped" ||
        notok "and the stalled ffmpeg is stopped" "pid $(cat stall.pid 2>&1)"
    out=$(PATH="$TMP/fake/nospace:$PATH" "$VROC" -b -c 'sphere a; translate = (0, 3, 0); image_size = (16, 16); soundtrack = s.wav; movie = old.mp4; run 5' 2>&1); status=$?
    has "a movie whose sound cannot be muxed in (a full disk) is reported as failed" "$out" \
        "error: movie: cannot write 'old.mp4': No space left on device"
    has "and says the old file is kept" "$out" "error: movie: 'old.mp4' is not written, and what was there is kept"
    is "and the batch run exits 1" "$status" 1
    same "and the old movie is whole" old-before.mp4 old.mp4
    noparts "and no part file (the video, the sound, the muxed file) is left"
    [ -f s.wav ] && ok "the soundtrack itself is written" || notok "the soundtrack itself is written" "$(ls -A)"
    # a time_step grown from 1e-3 to 1000 wants 1e6 pictures of one frame
    out=$("$VROC" -b -c 'sphere a; image_size = (16, 16); movie_rate = 1000; time_step = 0.001; movie = rep.mp4; step; time_step = 1000; step; movie = off' 2>&1)
    has "a frame that wants 1e6 pictures gets 1000, and the movie says so" "$out" \
        "warning: movie: a frame of time_step = 1000 s would be 1000000 pictures at 1000 a second; it gets 1000, and the movie skips the rest (its sound goes on, out of step from there)"
    frames() { ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 "$1"; }
    is "the movie holds the first frame's picture and the 1000" "$(frames rep.mp4)" 1001
    out=$("$VROC" -b -c 'sphere a; image_size = (16, 16); movie_rate = 1000; time_step = 0.001; movie = rep2.mp4; step; time_step = 1; step; movie = off' 2>&1)
    printf '%s' "$out" | grep -q warning && notok "1000 pictures of a frame, just inside, are no news" "$out" ||
        ok "1000 pictures of a frame, just inside, are no news"
    is "and all are in the movie" "$(frames rep2.mp4)" 1001
    "$VROC" -b -q -c 'movie = empty.mp4; movie = off; movie = empty2.mp4' 2>/dev/null
    [ ! -e empty.mp4 ] && [ ! -e empty2.mp4 ] && ok "a movie of no frame leaves no file (not even of 0 bytes)" ||
        notok "a movie of no frame leaves no file (not even of 0 bytes)" "$(ls -l empty*.mp4)"
    noparts "no part file is left"
else
    notok "ffmpeg and ffprobe are installed (make deps installs them)"
fi

# ---- Ctrl-C stops long loops ----
# interrupted SECONDS COMMANDS: vroc -b -c COMMANDS, sent SIGINT after SECONDS;
# its exit status, its output in int.out
interrupted() {
    "$VROC" -b -c "$2" > int.out 2>&1 &
    pid=$!
    sleep "$1"
    kill -INT $pid
    wait $pid
}
# a batch run: it stops with an error, its movie finished with the frames made
interrupted 2 'sphere a; translate = (0, 3, 0); image_size = (16, 16); movie = int.mp4; run 1000000000'
is "kill -INT stops a batch run of 1e9 frames with status 1" "$?" 1
grep -q "^error: interrupted at time = " int.out && ok "saying where it stopped" || notok "saying where it stopped" "$(head -3 int.out)"
n=$(ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 int.mp4 2>&1)
[ "${n:-0}" -gt 0 ] 2>/dev/null && ok "and its movie is finished ($n frames)" || notok "and its movie is finished" "$n"
noparts "and no part file is left"
interrupted 1 'random_box = (10000, 10000, 10000); random 1000000; list'
is "kill -INT stops random 1000000" "$?" 1
grep -q "^error: random: interrupted after [0-9]* of the 1000000 objects, so none was added$" int.out &&
    ok "and says none was added" || notok "and says none was added" "$(head -3 int.out)"
# at the prompt: a frame's thousand pictures stop, and the prompt comes back
if tmux_ready; then
    SES=vrochostile$$
    tmux -f /dev/null new-session -d -s "$SES" -x 200 -y 40 \
        "cd '$TMP' && HOME='$TMP' ASAN_OPTIONS='$ASAN_OPTIONS' '$VROC'; echo EXIT=\$?; sleep 30"
    check_screen "the prompt" "vroc>"
    type_ "sphere a; translate = (0, 3, 0); time_step = 1e-6; movie = prompt.mp4; step; time_step = 1000; step; print a" Enter
    sleep 1
    type_ C-c
    check_screen "Ctrl-C stops a frame's thousand pictures at the prompt" "interrupted at time = 1000.000001"
    type_ "movie = off; list" Enter
    check_screen "and the prompt goes on" "a                    sphere"
    type_ "random_box = (10000, 10000, 10000); random 1000000" Enter
    sleep 1
    type_ C-c
    check_screen "Ctrl-C stops random 1000000 at the prompt" "error: random: interrupted after"
    type_ "quit" Enter
    check_screen "and vroc goes on to quit with status 0" "EXIT=0"
    tmux kill-session -t "$SES" 2>/dev/null
fi

# ---- true messages ----
if $san; then
    ok "out of memory says out of memory # SKIP the sanitizers take no memory limit"
else
    out=$(bounded 300000 "$VROC" -b -c 'random_box = (10000, 10000, 10000); random 1000000' 2>&1)
    case "$out" in *"out of memory"*) ok "random 1000000 out of memory says out of memory" ;;
        *) notok "random 1000000 out of memory says out of memory" "$out" ;; esac
fi
for o in --help --version; do
    out=$("$VROC" $o 2>&1 >/dev/full); status=$?
    is "vroc $o > /dev/full fails, saying why" "$status:$out" "1:error: cannot write the standard output: No space left on device"
done
is "vroc --version writes its version" "$("$VROC" --version)" "vroc 0.1.0"
exit 0
