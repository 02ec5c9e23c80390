#!/bin/sh
# sound.sh: soundtracks checked from outside: the WAV header (with ffprobe) and
# length against simulated time; each logged collision heard at its time plus the
# sound's travel, as loud as language.md's reference says (so a harder impact
# louder); left and right; off silent; a sound file of a known tone heard at its
# frequency; a burst of 1,024 collisions in one frame limited, not clipped; bad
# paths; save.  Samples are read by build/tests/wavtool, a WAV parser of its own.
. "$(dirname "$0")/lib.sh"
S=$(cd "$(dirname "$0")/../scenes" && pwd)
WT="$(cd "$(dirname "$0")/.." && pwd)/build/tests/wavtool"
if [ ! -x "$WT" ]; then
    notok "build/tests/wavtool is built (make check-build)"
    exit 0
fi
for c in ffprobe ffmpeg; do
    command -v $c >/dev/null 2>&1 || { notok "$c is installed (make deps installs it)"; exit 0; }
done

# check TEXT CONDITION-AS-AWK-EXPRESSION VALUES: ok when awk finds it true of $1.. $n
check() {
    desc=$1 cond=$2
    shift 2
    if echo "$@" | awk "{ exit !($cond) }"; then ok "$desc"; else notok "$desc" "values: $*"; fi
}
val() { sed -n "s/.*$1=\([^ ]*\).*/\1/p"; } # val KEY: the value of KEY=V in the input

# ---- the header and the length: sample n is simulated time n / 48000 ----
"$VROC" -b -q "$S/simple.vroc" -c "soundtrack = $TMP/simple.wav; run 30" 2>"$TMP/err"
probe=$(ffprobe -v error -show_entries stream=codec_name,sample_rate,channels -of compact=p=0 "$TMP/simple.wav" 2>&1)
case "$probe" in "codec_name=pcm_s16le|sample_rate=48000|channels=2") ok "ffprobe: a WAV file of 16-bit PCM, 48 kHz, stereo" ;;
    *) notok "ffprobe: a WAV file of 16-bit PCM, 48 kHz, stereo" "$probe" "$(cat "$TMP/err")" ;; esac
info=$("$WT" info "$TMP/simple.wav")
[ "$info" = "rate=48000 channels=2 bits=16 frames=144000" ] && ok "run 30 of 0.1 s gives 3 s: 144,000 samples" ||
    notok "run 30 of 0.1 s gives 3 s: 144,000 samples" "$info"
"$VROC" -b -q "$S/simple.vroc" -c "time_step = 0.05; run 3; soundtrack = $TMP/mid.wav; run 17; time_step = 0.025; run 4" 2>/dev/null
n=$("$WT" info "$TMP/mid.wav" | val frames)
[ "$n" = 45600 ] && ok "a soundtrack started mid-run holds the time after it (0.95 s), across a time_step change" ||
    notok "a soundtrack started mid-run holds the time after it (0.95 s)" "frames=$n"
"$VROC" -b -q "$S/simple.vroc" -c "soundtrack = $TMP/off.wav; run 10; soundtrack = off; run 10" 2>/dev/null
n=$("$WT" info "$TMP/off.wav" | val frames)
[ "$n" = 48000 ] && ok "soundtrack = off ends the file there" || notok "soundtrack = off ends the file there" "frames=$n"
pk=$("$WT" peak "$TMP/simple.wav")
check "the Simple scene is heard (peak above 2,000)" '$1 > 2000' "$(echo "$pk" | val left)"

# ---- a ball bouncing in front of the head: each bounce heard on time, at its loudness ----
cat > "$TMP/drop.vroc" <<'EOS'
gravity
cube floor; mass = -1; size = (5, 5, 0.1); translate = (0, 0, -0.1)
sphere ball; radius = 0.1; mass = 0.5; elasticity = 0.7; translate = (0, 0, 1)
head = (0, -2, 0.5); look_at = (0, 0, 0.5); up = (0, 0, 1)
collision_sound = click
EOS
"$VROC" -b -q "$TMP/drop.vroc" -c "events = $TMP/drop.csv; soundtrack = $TMP/drop.wav; run 20" 2>"$TMP/err"
# the bounces: impulse > 0.2 N s, 50 ms clear of the collisions before and after
awk -F, 'NR > 1 { t[NR] = $1; j[NR] = $10; px[NR] = $4; py[NR] = $5; pz[NR] = $6; n = NR }
    END { for (i = 2; i <= n; i++) if (j[i] > 0.2 && (i == 2 || t[i] - t[i-1] > 0.05) && (i == n || t[i+1] - t[i] > 0.05))
        print t[i], j[i], sqrt(px[i]^2 + (py[i] + 2)^2 + (pz[i] - 0.5)^2) }' "$TMP/drop.csv" > "$TMP/bounces"
nb=$(wc -l < "$TMP/bounces")
check "the ball bounces at least 4 times clearly" '$1 >= 4' "$nb"
: > "$TMP/late"
: > "$TMP/peaks"
while read -r t j r; do
    want=$(awk -v t="$t" -v r="$r" 'BEGIN { printf "%.6f", t + r / 343 }')
    ref=$(awk -v j="$j" -v r="$r" 'BEGIN { printf "%d", 0.25 * j / r * 32767 }')
    level=$(awk -v p="$ref" 'BEGIN { printf "%d", p * 0.05 }')
    on=$("$WT" onset "$TMP/drop.wav" "$(awk -v w="$want" 'BEGIN { print w - 0.01 }')" \
        "$(awk -v w="$want" 'BEGIN { print w + 0.01 }')" "$level")
    l=$(echo "$on" | val left)
    awk -v l="$l" -v w="$want" 'BEGIN { exit !(l >= 0 && l - w <= 0.001 && w - l <= 0.001) }' ||
        echo "collision at $t: heard at $l, due at $want" >> "$TMP/late"
    p=$("$WT" peak "$TMP/drop.wav" "$want" "$(awk -v w="$want" 'BEGIN { print w + 0.03 }')" | val left)
    echo "$j $p $ref" >> "$TMP/peaks"
done < "$TMP/bounces"
[ -s "$TMP/late" ] && notok "each bounce is heard within 1 ms of its logged time plus distance / 343" "$(cat "$TMP/late")" ||
    ok "each of $nb bounces is heard within 1 ms of its logged time plus distance / 343"
awk '{ if ($2 < 0.98 * $3 || $2 > 1.02 * $3) bad = bad " " $0 } END { if (bad) print bad; exit bad != "" }' "$TMP/peaks" > "$TMP/bad" &&
    ok "each bounce peaks at 0.25 * impulse / distance of full scale, within 2%" ||
    notok "each bounce peaks at 0.25 * impulse / distance of full scale, within 2%" "impulse peak expected: $(cat "$TMP/bad")"
sort -g "$TMP/peaks" | awk 'NR > 1 && $2 <= last { bad = 1 } { last = $2 } END { exit bad }' &&
    ok "a harder impact gives a larger peak" || notok "a harder impact gives a larger peak" "$(sort -g "$TMP/peaks")"

# ---- left and right: louder and earlier in the nearer ear ----
side() { # X: drop a ball at (X, 2) seen from the origin looking along +y; prints wavtool lines
    cat > "$TMP/side.vroc" <<EOS
gravity
cube floor; mass = -1; size = (5, 5, 0.1); translate = (0, 0, -0.1)
sphere ball; radius = 0.1; translate = ($1, 2, 1)
head = (0, 0, 0.5); look_at = (0, 1, 0.5); up = (0, 0, 1)
collision_sound = knock
EOS
    "$VROC" -b -q "$TMP/side.vroc" -c "events = $TMP/side.csv; soundtrack = $TMP/side.wav; run 6" 2>/dev/null
    t=$(awk -F, 'NR == 2 { print $1 }' "$TMP/side.csv")
    "$WT" peak "$TMP/side.wav" "$t" "$(awk -v t="$t" 'BEGIN { print t + 0.05 }')"
    "$WT" onset "$TMP/side.wav" "$t" "$(awk -v t="$t" 'BEGIN { print t + 0.05 }')" 300
}
out=$(side -2)
pl=$(echo "$out" | head -1 | val left) pr=$(echo "$out" | head -1 | val right)
ol=$(echo "$out" | tail -1 | val left) or=$(echo "$out" | tail -1 | val right)
check "a collision on the left is louder in the left ear" '$1 > 1.5 * $2' "$pl $pr"
check "and reaches the left ear earlier (by 0.2 to 0.66 ms)" '$2 - $1 >= 0.0002 && $2 - $1 <= 0.00067' "$ol $or"
out=$(side 2)
pl=$(echo "$out" | head -1 | val left) pr=$(echo "$out" | head -1 | val right)
ol=$(echo "$out" | tail -1 | val left) or=$(echo "$out" | tail -1 | val right)
check "a collision on the right is louder in the right ear" '$2 > 1.5 * $1' "$pl $pr"
check "and reaches the right ear earlier" '$1 - $2 >= 0.0002 && $1 - $2 <= 0.00067' "$ol $or"

# ---- silence ----
for how in "collision_sound = off" "collision_vol = 0" "ball.volume = 0" "floor.volume = 0"; do
    "$VROC" -b -q "$TMP/drop.vroc" -c "$how; soundtrack = $TMP/quiet.wav; run 20" 2>/dev/null
    pk=$("$WT" peak "$TMP/quiet.wav")
    [ "$pk" = "left=0 right=0" ] && ok "$how is silent" || notok "$how is silent" "$pk"
done

# ---- a sound file of a known tone comes out at its frequency ----
ffmpeg -v error -y -f lavfi -i "sine=frequency=660:sample_rate=44100:duration=0.5" "$TMP/tone.flac"
"$VROC" -b -q "$TMP/drop.vroc" -c "collision_sound = $TMP/tone.flac; events = $TMP/tone.csv; soundtrack = $TMP/tone.wav; run 8" 2>"$TMP/err"
t=$(awk -F, 'NR == 2 { print $1 }' "$TMP/tone.csv")
f=$("$WT" freq "$TMP/tone.wav" "$(awk -v t="$t" 'BEGIN { print t + 0.05 }')" "$(awk -v t="$t" 'BEGIN { print t + 0.4 }')" | val freq)
check "a 660 Hz tone file (FLAC, 44.1 kHz) is heard at 660 Hz (within 2 Hz)" '$1 > 658 && $1 < 662' "${f:-none} $(cat "$TMP/err")"

# ---- a burst of 1,024 collisions in one frame: limited, never at full scale ----
awk 'BEGIN { print "gravity"; print "cube floor; mass = -1; size = (3, 3, 0.1); translate = (0, 0, -0.1)"
    for (i = 0; i < 32; i++) for (j = 0; j < 32; j++)
        printf "sphere b%d_%d; radius = 0.04; ures = 6; vres = 4; translate = (%g, %g, 0.3)\n", i, j, -1.6 + i * 0.1, -1.6 + j * 0.1
    print "head = (0, -6, 2); look_at = (0, 0, 0); up = (0, 0, 1)" }' > "$TMP/burst.vroc"
"$VROC" -b -q "$TMP/burst.vroc" -c "events = $TMP/burst.csv; soundtrack = $TMP/burst.wav; run 4" 2>"$TMP/err"
most=$(awk -F, 'NR > 1 { n[int($1 * 10)]++ } END { m = 0; for (k in n) if (n[k] > m) m = n[k]; print m }' "$TMP/burst.csv")
check "the burst has at least 1,000 collisions in one frame" '$1 >= 1000' "$most"
pk=$("$WT" peak "$TMP/burst.wav")
check "no sample of the burst at full scale (limited below 32767, yet loud)" \
    '$1 < 32767 && $2 < 32767 && $1 > 25000' "$(echo "$pk" | val left) $(echo "$pk" | val right)"

# ---- bad paths; save keeps outputs as comments ----
expect "an unwritable soundtrack path: batch exit 1" 1 "soundtrack: cannot write '/nonexistent/dir/s.wav'" \
    "$VROC" -b -c "soundtrack = /nonexistent/dir/s.wav; run 1"
expect "a sound file that is not a sound: batch exit 1" 1 "collision_sound: '$TMP/drop.csv' is not a sound file" \
    "$VROC" -b -c "collision_sound = $TMP/drop.csv"
"$VROC" -b -q -c "soundtrack = $TMP/saved.wav; sphere a; save $TMP/saved.vroc" 2>/dev/null
grep -q "^# soundtrack = \"$TMP/saved.wav\"$" "$TMP/saved.vroc" && ok "save writes the soundtrack as a comment" ||
    notok "save writes the soundtrack as a comment" "$(grep soundtrack "$TMP/saved.vroc")"
rm -f "$TMP/saved.wav"
"$VROC" -b -q "$TMP/saved.vroc" -c "run 2" 2>/dev/null
[ ! -e "$TMP/saved.wav" ] && ok "reading a saved world does not start its soundtrack" ||
    notok "reading a saved world does not start its soundtrack"
out=$("$VROC" -b -c "sound = on; show" 2>&1)
case "$out" in *"sound = on"*) ok "sound = on is kept in batch (and plays nothing there)" ;; *) notok "sound = on is kept in batch" "$out" ;; esac
out=$("$VROC" -b -c "show" 2>&1)
case "$out" in *"sound = off"*) ok "sound is off in batch" ;; *) notok "sound is off in batch" "$out" ;; esac
exit 0
