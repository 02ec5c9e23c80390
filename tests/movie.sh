#!/bin/sh
# movie.sh: movies checked with ffprobe from outside: size (side by side, padded
# to even), frame count and rate against simulated time (movie_rate, and
# time_step changes), pictures between frames where the rate asks for them, the
# soundtrack muxed in or not, the file finished by movie = off or the end; errors
# for a missing ffmpeg, an unwritable path and a missing extension; and the
# simulation the same with and without a movie.
. "$(dirname "$0")/lib.sh"
S=$(cd "$(dirname "$0")/../scenes" && pwd)
for c in ffprobe ffmpeg; do
    command -v $c >/dev/null 2>&1 || { notok "$c is installed (make deps installs it)"; exit 0; }
done

# probe FILE: "WIDTHxHEIGHT frames=N rate=R audio=CODEC|none"
probe() {
    v=$(ffprobe -v error -count_frames -select_streams v:0 \
        -show_entries stream=width,height,nb_read_frames,r_frame_rate -of csv=p=0 "$1" 2>&1)
    a=$(ffprobe -v error -select_streams a -show_entries stream=codec_name -of csv=p=0 "$1" 2>&1)
    echo "$v ${a:-none}" | awk -F'[, ]' '{ printf "%sx%s frames=%s rate=%s audio=%s\n", $1, $2, $4, $3, $5 }'
}
is() { # TEXT GOT WANT
    [ "$2" = "$3" ] && ok "$1" || notok "$1" "got:  $2" "want: $3"
}

"$VROC" -b -q "$S/simple.vroc" -c "image_size = (161, 121); soundtrack = $TMP/a.wav; movie = $TMP/pair.mp4; run 20" 2>"$TMP/err"
is "pair: both eyes side by side, odd sizes padded (322x122), 60 pictures at 30/s (movie_rate's default) for 20 frames, AAC sound" \
    "$(probe "$TMP/pair.mp4")" "322x122 frames=60 rate=30/1 audio=aac"
d=$(ffprobe -v error -show_entries format=duration -of csv=p=0 "$TMP/pair.mp4")
awk -v d="$d" 'BEGIN { exit !(d > 1.95 && d < 2.1) }' && ok "the movie lasts the 2 s of simulated time" ||
    notok "the movie lasts the 2 s of simulated time" "duration $d" "$(cat "$TMP/err")"
ad=$(ffprobe -v error -select_streams a -show_entries stream=duration -of csv=p=0 "$TMP/pair.mp4")
awk -v d="$ad" 'BEGIN { exit !(d > 1.9 && d < 2.1) }' && ok "and so does its sound" || notok "and so does its sound" "audio duration $ad"
ls -a "$TMP" | grep -q vroc-part && notok "no part files are left beside the movie" "$(ls -a "$TMP")" ||
    ok "no part files are left beside the movie"

# film TEXT WANT NAME COMMANDS: the Simple scene run with COMMANDS, which write the
# movie $TMP/NAME, probes as WANT
film() {
    "$VROC" -b -q "$S/simple.vroc" -c "$4" 2>/dev/null
    is "$1" "$(probe "$TMP/$3")" "$2"
}
film "mono: the left eye, no sound without a soundtrack" "160x120 frames=5 rate=10/1 audio=none" \
    mono.mp4 "image_size = (160, 120); stereo = mono; movie_rate = 10; movie = $TMP/mono.mp4; run 5"
film "anaglyph in Matroska" "160x120 frames=5 rate=10/1 audio=none" \
    ana.mkv "image_size = (160, 120); stereo = anaglyph; movie_rate = 10; movie = $TMP/ana.mkv; run 5"
film "sbs in WebM, what the extension names" "320x120 frames=3 rate=10/1 audio=none" \
    sbs.webm "image_size = (160, 120); stereo = sbs; movie_rate = 10; movie = $TMP/sbs.webm; run 3"

# video time is simulated time: at 10 pictures a second, 1 s at 0.1, 0.5 s at 0.05
# (a picture every other frame), 1 s at 0.2 (two a frame): 25 pictures
film "time_step changes: pictures keep simulated time (25 at 10/s)" \
    "128x48 frames=25 rate=10/1 audio=none" steps.mp4 \
    "image_size = (64, 48); movie_rate = 10; movie = $TMP/steps.mp4; run 10; time_step = 0.05; run 10; time_step = 0.2; run 5"
film "the frame rate is movie_rate (25/s)" "128x48 frames=7 rate=25/1 audio=none" \
    r25.mp4 "time_step = 0.04; image_size = (64, 48); movie_rate = 25; movie = $TMP/r25.mp4; run 7"
film "movie_rate as the movie starts holds for it (an expression: 60/2)" "128x48 frames=30 rate=30/1 audio=none" \
    r30.mp4 "image_size = (64, 48); movie_rate = 60/2; movie = $TMP/r30.mp4; movie_rate = 5; run 10"

film "movie = off finishes the file there" "128x48 frames=4 rate=10/1 audio=none" \
    early.mp4 "image_size = (64, 48); movie_rate = 10; movie = $TMP/early.mp4; run 4; movie = off; run 4"
# a soundtrack started after the movie: silence first, then its sound, as long as the movie
film "a soundtrack that starts later is muxed in all the same" "128x48 frames=15 rate=10/1 audio=aac" \
    late.mp4 "image_size = (64, 48); movie_rate = 10; movie = $TMP/late.mp4; run 5; soundtrack = $TMP/late.wav; run 10"

# pictures between frames: a ball crossing the view at 3 m/s, 3 frames of 0.1 s at
# 30 pictures a second: 9 pictures, each a third of a frame on, evenly spaced (not
# three copies of each frame's view)
"$VROC" -b -q -c "image_size = (160, 128); stereo = mono; sphere b; radius = 0.05; translate = (-0.5, 1.5, 0); linear_vel = (3, 0, 0); movie = $TMP/between.mp4; run 3" 2>/dev/null
cols=""
for n in 0 1 2 3 4 5 6 7 8; do
    ffmpeg -v error -y -i "$TMP/between.mp4" -vf "select=eq(n\,$n)" -frames:v 1 -f rawvideo -pix_fmt gray "$TMP/b.gray"
    cols="$cols $(od -An -v -tu1 -w160 "$TMP/b.gray" | awk '{ for (i = 1; i <= NF; i++) if ($i > 40) { s += i; c++ } } END { printf "%.2f", c ? s / c : -1 }')"
done
echo "$cols" | awk '{ for (i = 2; i <= NF; i++) { d = $i - $(i - 1); s += d; if (d < lo || i == 2) lo = d; if (d > hi) hi = d }
    exit !(NF == 9 && lo > 3 && hi - lo < 0.15 * s / 8) }' &&
    ok "pictures within a frame show the ball between its places (columns$cols)" ||
    notok "pictures within a frame show the ball between its places" "columns:$cols"

# the frames show the scene: a frame taken out of the movie is not one flat colour
ffmpeg -v error -y -i "$TMP/pair.mp4" -vf "select=eq(n\,10)" -frames:v 1 -f rawvideo -pix_fmt gray "$TMP/f10.gray" 2>&1
spread=$(od -An -v -tu1 "$TMP/f10.gray" | awk '{ for (i = 1; i <= NF; i++) { n++; if ($i > 60) lit++ } } END { print n, lit + 0 }')
echo "$spread" | awk '{ exit !($1 == 322 * 122 && $2 > 200) }' && ok "a frame of the movie shows the objects" ||
    notok "a frame of the movie shows the objects" "pixels, lit: $spread"

# frame n of the movie is the view after simulated frame n + 1, as record writes it
# (H.264 changes a pixel by less than 1 on average; the frame before differs more)
mkdir -p "$TMP/rec"
"$VROC" -b -q "$S/simple.vroc" -c "image_size = (160, 128); output = $TMP/rec; record = on; movie_rate = 10; movie = $TMP/rec/m.mp4; run 8" 2>/dev/null
ffmpeg -v error -y -i "$TMP/rec/m.mp4" -vf "select=eq(n\,4),crop=160:128:0:0" -frames:v 1 -f rawvideo -pix_fmt rgb24 "$TMP/rec/f4.rgb"
mad() { # the mean absolute difference of the movie's frame 4 (left eye) and a PNG
    ffmpeg -v error -y -i "$1" -f rawvideo -pix_fmt rgb24 "$TMP/rec/png.rgb"
    od -An -v -tu1 -w1 "$TMP/rec/f4.rgb" > "$TMP/rec/a"
    od -An -v -tu1 -w1 "$TMP/rec/png.rgb" > "$TMP/rec/b"
    paste "$TMP/rec/a" "$TMP/rec/b" | awk '{ d = $1 - $2; s += d < 0 ? -d : d; n++ } END { print (n == 61440 ? s / n : 999) }'
}
d5=$(mad "$TMP/rec/frame-000005-left.png") d4=$(mad "$TMP/rec/frame-000004-left.png")
awk -v a="$d5" -v b="$d4" 'BEGIN { exit !(a < 1 && a < b) }' &&
    ok "frame 4 of the movie is the left view recorded after frame 5 (differs by $d5, from frame 4 by $d4)" ||
    notok "frame 4 of the movie is the left view recorded after frame 5" "mean differences: $d5 (frame 5), $d4 (frame 4)"

# a movie shows what the views show: the tool panel and the hand's pointer too,
# with record off (issue 31).  panel-demo's frame 4 of a movie made without
# record against the left view a run with record wrote after frame 5; and its
# panel's light buttons, counted, against the same movie with panel = off.
mkdir -p "$TMP/pd"
pd() { # NAME STATEMENTS: panel-demo at 160x128, one eye, with STATEMENTS
    "$VROC" -b -q "$S/panel-demo.vroc" -c "image_size = (160, 128); stereo = mono; $2; run 6" 2>/dev/null
}
pd on "movie_rate = 10; movie = $TMP/pd/on.mp4"
pd off "panel = off; movie_rate = 10; movie = $TMP/pd/off.mp4"
pd rec "output = $TMP/pd; record = on"
buttons() { # the light grey pixels (the panel's buttons) of frame 4 of movie $1,
    # which mad then compares
    ffmpeg -v error -y -i "$1" -vf "select=eq(n\,4)" -frames:v 1 -f rawvideo -pix_fmt rgb24 "$TMP/rec/f4.rgb"
    od -An -v -tu1 -w3 "$TMP/rec/f4.rgb" | awk '$1 > 170 && $2 > 170 && $3 > 175 && $3 - $1 < 30 { n++ } END { print n + 0 }'
}
off=$(buttons "$TMP/pd/off.mp4")
doff=$(mad "$TMP/pd/frame-000005-left.png")
on=$(buttons "$TMP/pd/on.mp4")
don=$(mad "$TMP/pd/frame-000005-left.png")
awk -v on="$on" -v off="$off" -v d="$don" -v d0="$doff" 'BEGIN { exit !(on > 100 && off < 10 && d < 3 && 2 * d < d0) }' &&
    ok "a movie without record shows the panel as the views do ($on button pixels, $off without it; differs from the view by $don, by $doff without the panel)" ||
    notok "a movie without record shows the panel as the views do" \
        "button pixels: $on with the panel, $off without" "mean difference from the recorded view: $don, $doff without the panel"

# the simulation never depends on the movie or the soundtrack
# (the hash line alone: the sanitizer build may add LeakSanitizer's list of the
# suppressions it used, Mesa's memory, when frames were drawn)
h1=$("$VROC" -b -q "$S/simple.vroc" -c "run 20; hash" 2>&1 | grep '^hash = ')
h2=$("$VROC" -b -q "$S/simple.vroc" -c "image_size = (64, 48); movie = $TMP/h.mp4; soundtrack = $TMP/h.wav; run 20; hash" 2>&1 | grep '^hash = ')
is "the same hash with and without a movie and a soundtrack" "$h2" "$h1"

# errors
expect "no ffmpeg on PATH: a clear error, batch exit 1" 1 "movie: the ffmpeg program is not installed" \
    env PATH=/nonexistent "$VROC" -b -c "movie = $TMP/x.mp4"
expect "an unwritable movie path: batch exit 1" 1 "movie: cannot write '/nonexistent/dir/m.mp4'" \
    "$VROC" -b -c "movie = /nonexistent/dir/m.mp4"
expect "a movie named with no extension" 1 "has no extension to name its format" \
    "$VROC" -b -c "movie = $TMP/movie"
expect "a format ffmpeg does not know stops a batch run at the first frame" 1 "Unable to find a suitable output format" \
    "$VROC" -b -c "sphere a; translate = (0, 5, 0); movie = $TMP/x.nosuchformat; run 2"
ls -a "$TMP" | grep -q nosuchformat && notok "and leaves no file behind" "$(ls -a "$TMP")" || ok "and leaves no file behind"
"$VROC" -b -q -c "movie = $TMP/saved.mp4; sphere a; save $TMP/saved.vroc" 2>/dev/null
grep -q "^# movie = \"$TMP/saved.mp4\"$" "$TMP/saved.vroc" && ok "save writes the movie as a comment" ||
    notok "save writes the movie as a comment" "$(grep movie "$TMP/saved.vroc")"
exit 0
