#!/bin/sh
# valgrind.sh: the normal build under valgrind's memcheck: no invalid access, no
# leak.  (The sanitizer build is checked by AddressSanitizer instead; valgrind
# cannot run it.)  Mesa keeps some memory of its own when vroc draws: the leaks
# with a frame in libOSMesa are suppressed (tests/valgrind.supp), every other
# leak and every invalid access fails.
. "$(dirname "$0")/lib.sh"
if [ "${BUILD:-build}" = build-san ]; then exit 0; fi
if ! command -v valgrind >/dev/null 2>&1; then
    notok "valgrind is installed (make deps installs it)"
    exit 0
fi
S=$(cd "$(dirname "$0")/../scenes" && pwd)
SUPP=$(cd "$(dirname "$0")" && pwd)/valgrind.supp
VG="valgrind -q --error-exitcode=3 --leak-check=full --errors-for-leak-kinds=definite,indirect --suppressions=$SUPP"
grind() { # TEXT CMD...
    desc=$1
    shift
    out=$($VG "$@" 2>&1 >/dev/null)
    status=$?
    if [ $status -eq 3 ]; then notok "valgrind: $desc" "$(printf '%s' "$out" | head -20)"
    else ok "valgrind: $desc"; fi
}
grind "a thesis scene runs, saves and reads back" "$VROC" -b -q "$S/simple.vroc" \
    -c "trace = $TMP/t.csv; events = $TMP/e.csv; run 30; save $TMP/w.vroc; restart; read $TMP/w.vroc; run 5; stats"
grind "objects of every kind collide" "$VROC" -b -q \
    -c "gravity; cube floor; mass = -1; size = (2, 2, 0.1); superquadric p; exp1 = 0.5; translate = (0, 0, 1.5)" \
    -c "angular_vel = (1, 2, 0); cube c; translate = (0.4, 0.3, 3); sphere s; radius = 0.3; translate = (-1, 0, 2); run 40"
grind "a soundtrack of the built-in sounds" "$VROC" -b -q "$S/simple.vroc" \
    -c "collision_sound = bell; soundtrack = $TMP/b.wav; run 8; collision_sound = click; run 4"
grind "a soundtrack of a sound file (the one just written)" "$VROC" -b -q "$S/simple.vroc" \
    -c "collision_sound = $TMP/b.wav; soundtrack = $TMP/f.wav; run 12; soundtrack = off"
grind "a broken script" "$VROC" -b -q -c "sphere a; radius = -1"
grind "random objects with the heap off" "$VROC" -b -q -c "random 20; collision_heap = off; run 10"
grind "a scene that draws: refresh, then record" "$VROC" -b -q "$S/simple.vroc" \
    -c "image_size = (32, 24); output = \"$TMP/vg-frames\"; refresh; stereo = anaglyph; record = on; run 2"
[ -s "$TMP/vg-frames/frame-000002-anaglyph.png" ] && ok "valgrind: the scene that draws wrote its frames" ||
    notok "valgrind: the scene that draws wrote its frames" "$(ls "$TMP/vg-frames" 2>&1)"
# (VROC_TEST_LIGHT: test_shell's two tests of hundreds of random objects over
# hundreds of frames skip here; they took 90% of its four minutes under valgrind)
export VROC_TEST_LIGHT=1
for t in build/tests/test_lang build/tests/test_flight build/tests/test_shell; do
    [ -x "$t" ] && grind "$(basename "$t")" "$t"
done
exit 0
