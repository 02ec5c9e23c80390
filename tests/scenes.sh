#!/bin/sh
# scenes.sh: every scene loads and runs in vroc -b without a warning (but the
# speed limits', where the scene's cut a collision's result), and without a fault
# counted in stats; the thesis's environments reproduce Table 5.1
# (objects, pairs, subframes); no dynamic object overlaps anything at the start,
# and the objects meant to rest on something sit a hair above it; refresh draws
# each thesis environment.
. "$(dirname "$0")/lib.sh"
S=$(cd "$(dirname "$0")/../scenes" && pwd)
frames=20
[ "${BUILD:-build}" = build-san ] && frames=8

# gaps NAME FILE: one `distance` per pair the simulation checks (each dynamic
# object against every static one and, once, every other dynamic one), all in one
# run of vroc; writes "A B D" lines to $TMP/NAME.gaps and the number of pairs to
# $TMP/NAME.n.  Returns vroc's status.
gaps() {
    "$VROC" -b -q "$2" -c list > "$TMP/$1.list" 2>&1 || return 1
    awk '{ name[NR] = $1; dyn[NR] = ($3 != "static") }
        END {
            for (i = 1; i <= NR; i++) {
                if (!dyn[i]) continue
                for (j = 1; j <= NR; j++)
                    if (j != i && !(dyn[j] && j < i)) print name[i], name[j]
            }
        }' "$TMP/$1.list" > "$TMP/$1.pairs"
    wc -l < "$TMP/$1.pairs" | tr -d ' ' > "$TMP/$1.n"
    : > "$TMP/$1.gaps"
    [ -s "$TMP/$1.pairs" ] || return 0
    cmds=$(awk '{ printf "distance %s %s;", $1, $2 }' "$TMP/$1.pairs")
    "$VROC" -b -q "$2" -c "$cmds" > "$TMP/$1.dist" 2>&1
    status=$?
    sed -n 's/^distance = //p' "$TMP/$1.dist" | paste -d' ' "$TMP/$1.pairs" - > "$TMP/$1.gaps"
    return $status
}

for f in "$S"/*.vroc; do
    name=$(basename "$f" .vroc)
    out=$("$VROC" -b -q "$f" -c "run $frames; stats" 2>&1)
    status=$?
    said=$(printf '%s\n' "$out" | grep -vE '^[a-z_]+ = ' | no_cut_warning)
    if [ $status -eq 0 ] && [ -z "$said" ]; then ok "$name runs in vroc -b, quietly"
    else notok "$name runs in vroc -b, quietly" "status $status" "$(printf '%s' "$said" | head -3)"; fi
    # and no fault shows in stats: no walk redone, no contact unsolved, no step
    # whose events ran away to the guard's last resort or were cut short
    faults=$(printf '%s\n' "$out" | awk -F' = ' '$1 == "restarts" || $1 == "unsolved" || $1 == "overflows" || $1 == "guards" { n++; if ($2 != 0) print }
        END { if (n != 4) print "stats gave", n + 0, "of the four counters" }')
    [ -z "$faults" ] && ok "$name: stats shows no restart, unsolved contact, guard or overflow" \
        || notok "$name: stats shows no restart, unsolved contact, guard or overflow" "$faults"

    # no dynamic object overlaps another object at the start
    if gaps "$name" "$f"; then
        bad=$(awk 'NF < 3 || $3 + 0 <= 0 { print $1, $2, $3 }' "$TMP/$name.gaps" | head -3)
        min=$(awk '{ print $3 }' "$TMP/$name.gaps" | sort -g | head -1)
        if [ -z "$bad" ]; then ok "$name: nothing overlaps at the start (closest gap ${min:-none} m)"
        else notok "$name: nothing overlaps at the start" "$bad"; fi
    else
        notok "$name: nothing overlaps at the start" "distance failed: $(head -3 "$TMP/$name.dist")"
    fi
done

# Table 5.1: environment, objects, pairs, subframes; and how many of its dynamic
# objects start at rest on something, 0.5 to 2 mm above it
while read -r name objects pairs subframes resting; do
    f="$S/$name.vroc"
    if [ ! -f "$f" ]; then notok "$name.vroc exists"; continue; fi
    got=$("$VROC" -b -q "$f" -c stats | awk -F' = ' '$1=="objects"{o=$2} $1=="pairs"{p=$2} $1=="subframes"{s=$2} END{print o, p, s}')
    want="$objects $pairs $subframes"
    [ "$got" = "$want" ] && ok "$name: Table 5.1 gives $want" || notok "$name: Table 5.1 gives $want" "got $got"

    # every pair the simulation checks was measured above
    n=$(cat "$TMP/$name.n" 2>/dev/null)
    [ "$n" = "$pairs" ] && ok "$name: the overlap check covers all $pairs pairs" \
        || notok "$name: the overlap check covers all $pairs pairs" "it measured ${n:-no} pairs"

    # the objects meant to rest sit a hair above their support: a dynamic
    # object's closest gap is either 0.5 to 2 mm (resting) or over 2 cm (free)
    awk '{ if (!($1 in g) || $3 + 0 < g[$1]) g[$1] = $3 + 0
           if (!($2 in g) || $3 + 0 < g[$2]) g[$2] = $3 + 0 }
        END { for (o in g) print o, g[o] }' "$TMP/$name.gaps" > "$TMP/$name.closest"
    awk 'NR == FNR { if ($3 == "static") st[$1] = 1; next } !($1 in st)' \
        "$TMP/$name.list" "$TMP/$name.closest" > "$TMP/$name.dyn"
    got=$(awk '$2 >= 0.0005 && $2 <= 0.002' "$TMP/$name.dyn" | wc -l | tr -d ' ')
    odd=$(awk '$2 > 0.002 && $2 < 0.02 || $2 < 0.0005 { print $1, $2 }' "$TMP/$name.dyn" | head -3)
    if [ "$got" = "$resting" ] && [ -z "$odd" ]; then
        ok "$name: $resting objects rest a hair above their supports, the rest are clear"
    else
        notok "$name: $resting objects rest a hair above their supports, the rest are clear" \
            "$got rest" "$odd"
    fi

    "$VROC" -b -q "$f" -c "output = \"$TMP/$name\"; refresh" > /dev/null 2>&1
    if [ -s "$TMP/$name/frame-000000-left.png" ] && [ -s "$TMP/$name/frame-000000-right.png" ]; then
        ok "$name: refresh writes the stereo pair"
    else
        notok "$name: refresh writes the stereo pair" "$(ls "$TMP/$name" 2>&1)"
    fi
done <<EOT
simple 4 6 6 0
computer-desks 43 438 2 0
basketball 9 8 58 0
office 43 308 12 8
bounce 35 342 6 10
EOT
exit 0
