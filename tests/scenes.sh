#!/bin/sh
# scenes.sh: every scene loads and runs in vroc -b without a warning; the thesis's
# environments reproduce Table 5.1 (objects, pairs, subframes); no dynamic object
# overlaps anything at the start; refresh draws each thesis environment.
. "$(dirname "$0")/lib.sh"
S=$(cd "$(dirname "$0")/../scenes" && pwd)
frames=20
[ "${BUILD:-build}" = build-san ] && frames=8

for f in "$S"/*.vroc; do
    name=$(basename "$f" .vroc)
    out=$("$VROC" -b -q "$f" -c "run $frames" 2>&1)
    status=$?
    if [ $status -eq 0 ] && [ -z "$out" ]; then ok "$name runs in vroc -b, quietly"
    else notok "$name runs in vroc -b, quietly" "status $status" "$(printf '%s' "$out" | head -3)"; fi

    # no dynamic object overlaps another object at the start
    "$VROC" -b -q "$f" -c list > "$TMP/list" 2>&1
    dyn=$(awk '$3 == "dynamic" { print $1 }' "$TMP/list")
    all=$(awk '{ print $1 }' "$TMP/list")
    cmds=""
    for a in $dyn; do
        for b in $all; do [ "$a" != "$b" ] && cmds="$cmds distance $a $b;"; done
    done
    if [ -n "$cmds" ]; then
        min=$("$VROC" -b -q "$f" -c "$cmds" 2>&1 | sed -n 's/^distance = //p' | sort -g | head -1)
        if awk -v d="$min" 'BEGIN { exit !(d > 0) }'; then ok "$name: nothing overlaps at the start (closest gap $min m)"
        else notok "$name: nothing overlaps at the start" "closest: $min"; fi
    fi
done

# Table 5.1: environment, objects, pairs, subframes
while read -r name objects pairs subframes; do
    f="$S/$name.vroc"
    if [ ! -f "$f" ]; then notok "$name.vroc exists"; continue; fi
    got=$("$VROC" -b -q "$f" -c stats | awk -F' = ' '$1=="objects"{o=$2} $1=="pairs"{p=$2} $1=="subframes"{s=$2} END{print o, p, s}')
    want="$objects $pairs $subframes"
    [ "$got" = "$want" ] && ok "$name: Table 5.1 gives $want" || notok "$name: Table 5.1 gives $want" "got $got"
    "$VROC" -b -q "$f" -c "output = \"$TMP/$name\"; refresh" > /dev/null 2>&1
    if [ -s "$TMP/$name/frame-000000-left.png" ] && [ -s "$TMP/$name/frame-000000-right.png" ]; then
        ok "$name: refresh writes the stereo pair"
    else
        notok "$name: refresh writes the stereo pair" "$(ls "$TMP/$name" 2>&1)"
    fi
done <<EOT
simple 4 6 6
computer-desks 43 438 2
basketball 9 8 58
office 43 308 12
bounce 35 342 6
EOT
exit 0
