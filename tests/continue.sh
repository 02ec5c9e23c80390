#!/bin/sh
# continue.sh: exact state after every frame (issue 31; language.md, "Exact
# state"): every shipped scene saved after each frame from 0 to 40, read back and
# run on 20 frames, to the bit (tests/sweep.sh says what is checked).  The
# sanitizer build checks a few frames of each (a sweep of every frame there would
# take minutes); make check-long sweeps further.
. "$(dirname "$0")/lib.sh"
. "$(dirname "$0")/sweep.sh"
S=$(cd "$(dirname "$0")/../scenes" && pwd)
cd "$TMP" || exit 1

frames=$(seq 0 40)
[ "${BUILD:-build}" = build-san ] && frames="0 3 17"
for f in "$S"/*.vroc; do
    sweep "$(basename "$f" .vroc)" "$f" "$frames" 20
done
