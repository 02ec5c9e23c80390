#!/bin/sh
# hashes.sh: the determinism regression (as Box2D's test_determinism.c).  The
# SHA-256 of each scene's trace CSV, 100 frames with the collision heap on and off,
# must be the one recorded in tests/trace-hashes, in the normal and the sanitizer
# build alike; and with the normal build, the validation build (build-val/vroc:
# the schedule's and the polyhedra's invariants checked after every internal step)
# must run every scene so and give the same traces.
#
# After a change meant to change the simulation, `make record-hashes` (this script
# with --record) writes tests/trace-hashes anew from ./vroc; the commit says why.
. "$(dirname "$0")/lib.sh"
ROOT=$(cd "$(dirname "$0")/.." && pwd)
S="$ROOT/scenes"
FILE="$ROOT/tests/trace-hashes"
FRAMES=100

# trace_hash VROC SCENE HEAP: the SHA-256 of the scene's trace, or "failed: ..."
trace_hash() {
    rm -f "$TMP/t.csv"
    if ! out=$("$1" -b -q "$2" -c "collision_heap = $3; trace = $TMP/t.csv; run $FRAMES" 2>&1); then
        echo "failed: $(printf '%s' "$out" | head -2 | tr '\n' ' ')"
        return
    fi
    sha256sum "$TMP/t.csv" | cut -d' ' -f1
}

if [ "${1:-}" = --record ]; then
    : > "$TMP/new"
    for f in "$S"/*.vroc; do
        name=$(basename "$f" .vroc)
        for heap in on off; do
            h=$(trace_hash "$VROC" "$f" "$heap")
            case "$h" in failed*) echo "record-hashes: $name heap $heap: $h" >&2; exit 1 ;; esac
            echo "$name $heap $h" >> "$TMP/new"
        done
    done
    {
        echo "# SHA-256 of each scene's trace CSV: $FRAMES frames, collision heap on and off."
        echo "# Written by 'make record-hashes'; checked by tests/hashes.sh."
        cat "$TMP/new"
    } > "$FILE"
    echo "record-hashes: $(grep -vc '^#' "$FILE") hashes written to tests/trace-hashes"
    exit 0
fi

if [ ! -f "$FILE" ]; then
    notok "tests/trace-hashes exists (make record-hashes writes it)"
    exit 0
fi
VAL="$ROOT/build-val/vroc"
for f in "$S"/*.vroc; do
    name=$(basename "$f" .vroc)
    for heap in on off; do
        want=$(awk -v n="$name" -v h="$heap" '$1 == n && $2 == h { print $3 }' "$FILE")
        got=$(trace_hash "$VROC" "$f" "$heap")
        if [ -z "$want" ]; then
            notok "$name (heap $heap): a hash is recorded in tests/trace-hashes" "got $got"
        elif [ "$got" = "$want" ]; then
            ok "$name (heap $heap): the trace's SHA-256 is the recorded one"
        else
            notok "$name (heap $heap): the trace's SHA-256 is the recorded one" "want $want" "got  $got"
        fi
        [ "${BUILD:-build}" = build ] || continue
        if [ ! -x "$VAL" ]; then
            notok "$name (heap $heap): the validation build runs it" "$VAL is missing"
            continue
        fi
        got=$(trace_hash "$VAL" "$f" "$heap")
        if [ "$got" = "$want" ]; then
            ok "$name (heap $heap): the validation build keeps every invariant, with the same trace"
        else
            notok "$name (heap $heap): the validation build keeps every invariant, with the same trace" \
                "want $want" "got  $got"
        fi
    done
done
exit 0
