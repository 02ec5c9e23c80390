#!/bin/sh
# bench/run.sh: vroc's benchmarks next to the thesis's chapter 5 tables (design.md,
# "Performance").  Run from the repository root after the benchmarks are built
# (`make bench` does both).
#
# Measures with build/bench/bench_sim (see its header for what is timed):
#   - the thesis scenes (Table 5.1): simulation only with the collision heap on and
#     off, and with both eyes rendered into memory at 640x512 after every frame;
#     100 frames (10 s of simulated time at 0.1 s, as the thesis's "average over
#     approximately 10 seconds"), median of 5 runs or more; the heap on and off
#     in turn, run for run (bench_sim --heap both), until the slower side has 2 s
#     of runs (up to 101 each), so that the two sides of the heap's ratio meet the
#     same state of the machine (3 runs or more for the rendered runs);
#   - the random environment (Table 5.6) for 20 to 100 objects, and 200, 500 and
#     1000 for scaling (fewer runs and frames there, as printed);
#   - the gas of issue 27: 100, 1,000, 2,000, 3,000, 4,000 and 10,000 objects, one
#     per cubic metre in a closed room (bench_sim --gas; the issue's rows before it,
#     and its 3,000), each measured in a process of its own (its peak memory is its
#     own), and the same objects run by Bullet at 1/60 s (build/bench/bullet_gas,
#     when libbullet-dev was there to build it);
#   - a room of one file (issue 39): 100 random objects in a room of 2,000 static
#     pieces (tiles, bench/room.awk), against the same objects in the same room of
#     its six faces alone (an empty box);
#   - crowds (issue 35): 100 balls in V-grooves and in a slot (bench/crowd.awk);
#   - the mesh readers (issue 38): a binary STL of 1,000,000 triangles and an OBJ of
#     600,000, made in the scratch folder (build/bench/bench_mesh), read, and read
#     with the body built, against `assimp info` where assimp-utils is installed;
# then prints build/bench/bench_view and build/bench/bench_closest.
#
# Environment: BENCH_QUICK=1 measures less (1 run, fewer frames) for a smoke test.

set -u

SIM=build/bench/bench_sim
TMP=$(mktemp -d "${TMPDIR:-/tmp}/vroc-bench.XXXXXX") || exit 1
trap 'rm -rf "$TMP"' EXIT INT TERM
RAW="$TMP/raw"
: >"$RAW"

QUICK=${BENCH_QUICK:-0}
# A slow scene is measured as it is, within bounds: a run stops after BUDGET seconds
# (the figure covers the frames it did, marked *), and no further run of the same
# measurement starts after MAXT seconds of runs.
BUDGET=20
MAXT=20
# After SOFT seconds in all (slow scenes), every later measurement is cut to one run
# of at most 10 s, so that `make bench` stays near ten minutes; the output says so.
SOFT=${BENCH_SOFT:-420}
START=$(date +%s)

if [ ! -x "$SIM" ]; then
    echo "bench/run.sh: $SIM is missing; run 'make bench'" >&2
    exit 1
fi

# ---------------------------------------------------------------- helpers

# field LINE KEY: the value of KEY=value in a bench_sim line (empty when absent).
field() {
    printf '%s\n' "$1" | tr ' ' '\n' | sed -n "s/^$2=//p"
}

# num VALUE: a figure for a table: thousands separated, 1 or 2 decimals when small,
# '-' for none.
num() {
    awk -v v="$1" 'BEGIN {
        if (v == "" || v == "-") { printf "-"; exit }
        a = v < 0 ? -v : v
        if (a >= 100) {
            s = sprintf("%.0f", a); o = ""
            while (length(s) > 3) { o = "," substr(s, length(s) - 2) o; s = substr(s, 1, length(s) - 3) }
            printf "%s%s%s", (v < 0 ? "-" : ""), s, o
        } else if (a >= 10) printf "%.1f", v
        else printf "%.2f", v
    }'
}

# ratio A B: A / B with "x", '-' when either is missing or B is 0.
ratio() {
    awk -v a="$1" -v b="$2" 'BEGIN {
        if (a == "" || b == "" || a == "-" || b == "-" || b + 0 == 0) { printf "-"; exit }
        r = a / b
        if (r >= 100) printf "%.0fx", r; else if (r >= 10) printf "%.1fx", r
        else if (r >= 0.1) printf "%.2fx", r; else printf "%.2gx", r
    }'
}

# measure TAG ARGS...: runs bench_sim, keeps its line in $TMP/TAG (empty on failure,
# with the reason in $TMP/TAG.err) and in the raw list.
measure() {
    tag=$1
    shift
    printf 'bench: %-28s' "$tag" >&2
    t0=$(date +%s)
    set -- --budget "$BUDGET" --max-time "$MAXT" "$@"
    if [ $((t0 - START)) -gt "$SOFT" ]; then
        set -- "$@" --runs 1 --budget 10 --max-time 10
        echo "$tag" >>"$TMP/cut"
    fi
    if "$SIM" "$@" >"$TMP/$tag" 2>"$TMP/$tag.err"; then
        cat "$TMP/$tag" >>"$RAW"
        printf ' %3ss  %s fps\n' "$(($(date +%s) - t0))" "$(num "$(field "$(head -n 1 "$TMP/$tag")" frames_per_s)")" >&2
    else
        : >"$TMP/$tag"
        printf ' failed: %s\n' "$(head -n 1 "$TMP/$tag.err")" >&2
    fi
}

# measure_pair ID ARGS...: measures with the heap on and off in turn (bench_sim
# --heap both: alike machine states for both sides of the heap's ratio), kept as
# ID.on and ID.off.
measure_pair() {
    id_=$1
    shift
    measure "$id_.both" "$@" --heap both
    head -n 1 "$TMP/$id_.both" >"$TMP/$id_.on"
    sed -n 2p "$TMP/$id_.both" >"$TMP/$id_.off"
}

# get TAG KEY: a field of a measurement ('' when it was not made).
get() {
    if [ -s "$TMP/$1" ]; then field "$(cat "$TMP/$1")" "$2"; fi
}

# note TAG: " (truncated)" when a run hit the time budget.
trunc() {
    if [ "$(get "$1" truncated)" = 1 ]; then printf '*'; fi
}

rule() {
    printf '%s\n' "------------------------------------------------------------------------------------------------------------"
}

# ---------------------------------------------------------------- the thesis's figures

# id|name|file|objects|pairs|subframes|HP750 f/s|HP750 sub/s|HP750 no-heap f/s|sub/s|
#   PxPl5 1GP f/s|sub/s|PxPl5 25GP f/s|sub/s|best f/s|goal f/s|heap goal
# Tables 5.1 to 5.5 of the thesis; goals from design.md.
THESIS='simple|Simple|scenes/simple.vroc|4|6|6|34|204|23|138|28|168|28|168|34|30000|-
computer-desks|Computer Desks|scenes/computer-desks.vroc|43|438|2|4|8|1|2|7|14|18|36|18|15000|10
basketball|Virtual Basketball|scenes/basketball.vroc|9|8|58|22|1276|5|290|21|1218|23|1334|23|20000|-
office|Office|scenes/office.vroc|43|308|12|4|48|0.2|2.4|7|84|15|180|15|15000|10
bounce|Bounce|scenes/bounce.vroc|35|342|6|4|24|0.4|2.4|13|78|18|108|18|15000|10'

# N|pairs|stereo f/s|sub/s (Table 5.6, Pixel-Planes 5, 25 GPs)
RANDOM_THESIS='20|190|22|44
40|780|17|34
60|1770|16|32
80|3160|13|26
100|4950|12.5|25'
RANDOM_GOAL=1000 # frames/s, Random 100, simulation only (design.md)

if [ "$QUICK" = 1 ]; then
    F=20; R=1; R3=1; MT=0
else
    F=100; R=5; R3=3; MT=2
fi

# ---------------------------------------------------------------- measurements

MISSING=""
printf '%s\n' "$THESIS" | while IFS='|' read -r id name file rest; do
    if [ ! -f "$file" ]; then
        echo "bench: $file is missing: $name skipped" >&2
        continue
    fi
    measure_pair "$id" "$file" --frames "$F" --runs "$R" --min-time "$MT"
    measure "$id.render" "$file" --frames "$F" --runs "$R3" --heap on --render
done
for id in $(printf '%s\n' "$THESIS" | cut -d'|' -f1); do
    file=$(printf '%s\n' "$THESIS" | grep "^$id|" | cut -d'|' -f3)
    [ -f "$file" ] || MISSING="$MISSING $file"
done
# issue 40: the thesis scenes over 600 frames as well (as they come to rest)
if [ "$QUICK" = 1 ]; then F600=60; else F600=600; fi
for id in $(printf '%s\n' "$THESIS" | cut -d'|' -f1); do
    file=$(printf '%s\n' "$THESIS" | grep "^$id|" | cut -d'|' -f3)
    [ -f "$file" ] && measure "$id.600" "$file" --frames "$F600" --runs "$R3" --heap on
done

for n in 20 40 60 80 100; do
    measure "random$n.on" --random "$n" --frames "$F" --runs "$R" --heap on
    measure "random$n.off" --random "$n" --frames "$F" --runs "$R3" --heap off
    measure "random$n.render" --random "$n" --frames "$F" --runs "$R3" --heap on --render
done
if [ "$QUICK" = 1 ]; then
    SCALE="200:1:10 500:1:5 1000:1:3"
else
    SCALE="200:3:100 500:3:20 1000:3:20"
fi
for s in $SCALE; do
    n=${s%%:*}
    rf=${s#*:}
    measure "random$n.on" --random "$n" --frames "${rf#*:}" --runs "${rf%%:*}" --heap on \
        --budget 60 --max-time 50
done

# ---------------------------------------------------------------- report

echo
echo "vroc benchmarks: this machine next to the thesis (Chapter 5)"
rule
printf 'machine: %s, %s cores; %s\n' \
    "$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo 2>/dev/null | head -n 1)" \
    "$(getconf _NPROCESSORS_ONLN 2>/dev/null || echo '?')" "$(uname -sr)"
printf 'vroc: %s%s, %s\n' "$(git rev-parse --short HEAD 2>/dev/null || echo '?')" \
    "$(if [ -n "$(git status --porcelain -- src 2>/dev/null)" ]; then echo ' (src modified)'; fi)" \
    "$(date '+%Y-%m-%d %H:%M')"
echo "One core, one thread (llvmpipe may use more for drawing).  frames/s = frames / wall time"
echo "of sim_frame (and view_render), first frame included (not what \`start' makes ready"
echo "before time runs: the pairs, the schedule, the copies of the moving objects); every"
echo "figure is the median of the runs, each run on a freshly loaded scene.  Thesis:"
echo "HP750 = HP-750 TVRX-T4 (mono 640x512 images), PxPl5 = Pixel-Planes 5 with 1 or 25"
echo "GPs (stereo, head-tracked)."
if [ -n "$MISSING" ]; then
    echo "Missing scenes, not measured:$MISSING"
fi
if [ "$QUICK" = 1 ]; then echo "BENCH_QUICK=1: 1 run of 20 frames each, figures rough."; fi

echo
echo "Table 5.1: environment characteristics (thesis / vroc)"
rule
printf '%-20s %14s %16s %16s  %s\n' environment objects pairs subframes match
printf '%s\n' "$THESIS" | while IFS='|' read -r id name file to tp ts rest; do
    if [ ! -s "$TMP/$id.on" ]; then
        printf '%-20s %6s / %-6s %7s / %-6s %7s / %-6s  %s\n' "$name" "$to" - "$tp" - "$ts" - \
            "not measured"
        continue
    fi
    vo=$(get "$id.on" objects); vp=$(get "$id.on" pairs); vs=$(get "$id.on" subframes)
    m=yes
    [ "$vo/$vp/$vs" = "$to/$tp/$ts" ] || m=NO
    printf '%-20s %6s / %-6s %7s / %-6s %7s / %-6s  %s\n' "$name" "$to" "$vo" "$tp" "$vp" "$ts" "$vs" "$m"
done

echo
echo "Tables 5.2, 5.4, 5.5: frames/s (subframes/s), collision heap on"
rule
printf '%-20s %-11s %-11s %-11s | %-20s %-18s | %5s %7s %9s\n' \
    "" "thesis" "thesis" "thesis" "vroc" "vroc sim +" "thesis" "vroc" "vroc sim"
printf '%-20s %-11s %-11s %-11s | %-20s %-18s | %5s %7s %9s\n' \
    environment "HP750" "PxPl5 1GP" "PxPl5 25GP" "simulation only" "stereo 640x512" best goal "/ goal"
printf '%s\n' "$THESIS" | while IFS='|' read -r id name file to tp ts hf hs nf ns gf gs pf ps best goal hg; do
    sim="-"; ren="-"; vs=""
    if [ -s "$TMP/$id.on" ]; then
        vf=$(get "$id.on" frames_per_s)
        sim="$(num "$vf") ($(num "$(get "$id.on" subframes_per_s)"))$(trunc "$id.on")"
        vs=$(ratio "$vf" "$goal")
    fi
    if [ -s "$TMP/$id.render" ]; then
        ren="$(num "$(get "$id.render" frames_per_s)") ($(num "$(get "$id.render" subframes_per_s)"))$(trunc "$id.render")"
    fi
    printf '%-20s %-11s %-11s %-11s | %-20s %-18s | %5s %7s %9s\n' "$name" "$hf ($hs)" "$gf ($gs)" \
        "$pf ($ps)" "$sim" "$ren" "$best" "$(num "$goal")" "${vs:--}"
done
echo "goal: design.md's simulation-only frames/s; '/ goal' >= 1.00x meets it.  The stereo column"
echo "adds view_render of both eyes into memory after every frame (no PNG files)."

echo
echo "Table 5.3: collision heap off (frames/s, subframes/s) and what the heap buys"
rule
printf '%-20s %-12s %8s | %-20s %-20s %9s %6s | %-17s\n' \
    "" "thesis HP750" "thesis" "vroc" "vroc" "vroc" "" "pair checks/frame"
printf '%-20s %-12s %8s | %-20s %-20s %9s %6s | %-17s\n' \
    environment "heap off" "on/off" "heap off" "heap on" "on/off" goal "on / off"
printf '%s\n' "$THESIS" | while IFS='|' read -r id name file to tp ts hf hs nf ns gf gs pf ps best goal hg; do
    tr_=$(ratio "$hf" "$nf")
    off="-"; on="-"; r="-"; pc="-"
    if [ -s "$TMP/$id.off" ]; then
        off="$(num "$(get "$id.off" frames_per_s)") ($(num "$(get "$id.off" subframes_per_s)"))$(trunc "$id.off")"
    fi
    if [ -s "$TMP/$id.on" ]; then
        on="$(num "$(get "$id.on" frames_per_s)") ($(num "$(get "$id.on" subframes_per_s)"))$(trunc "$id.on")"
    fi
    if [ -s "$TMP/$id.on" ] && [ -s "$TMP/$id.off" ]; then
        r=$(ratio "$(get "$id.on" frames_per_s)" "$(get "$id.off" frames_per_s)")
        pc="$(num "$(get "$id.on" pair_checks_per_frame)") / $(num "$(get "$id.off" pair_checks_per_frame)")"
    fi
    g="-"
    [ "$hg" = "-" ] || g=">=${hg}x"
    printf '%-20s %-12s %8s | %-20s %-20s %9s %6s | %-17s\n' "$name" "$nf ($ns)" "$tr_" "$off" "$on" "$r" "$g" "$pc"
done
echo "thesis on/off = Table 5.2 / Table 5.3 (HP750).  goal: design.md, heap on >= 10x heap off."
echo "vroc's heap on and off runs are made in turn, each on a fresh scene (medians of each side)."

echo
echo "Where the frames go (simulation only, heap on; per frame of 0.1 s unless said)"
rule
printf '%-20s %11s %12s %12s %12s %12s %11s\n' environment "collisions" "pair checks" \
    "checks/pair" "heap pops" "restarts" "1st frame"
printf '%s\n' "$THESIS" | while IFS='|' read -r id name rest; do
    [ -s "$TMP/$id.on" ] || continue
    printf '%-20s %11s %12s %12s %12s %12s %8s ms\n' "$name" \
        "$(num "$(get "$id.on" collisions_per_frame)")" "$(num "$(get "$id.on" pair_checks_per_frame)")" \
        "$(num "$(awk -v c="$(get "$id.on" pair_checks_per_frame)" -v p="$(get "$id.on" pairs)" \
            'BEGIN { if (p > 0) printf "%.2f", c / p; else printf "-" }')")" \
        "$(num "$(get "$id.on" heap_pops_per_frame)")" "$(num "$(get "$id.on" restarts_per_frame)")" \
        "$(num "$(get "$id.on" first_frame_ms)")"
done
echo "pair checks: closest-feature queries, the time-of-impact search's (a few per collision)"
echo "included; checks/pair: those per object pair; heap pops: pairs taken from the"
echo "schedule; restarts: walks redone from scratch; 1st frame: the first frame's own time."

echo
echo "Table 5.6: random objects, frames/s (subframes/s)"
rule
printf '%-7s %-17s | %-12s | %-19s %-17s %-17s %7s | %7s %9s %9s\n' \
    "" "pairs" "thesis" "vroc" "vroc sim +" "vroc" "heap" "collis." "pair" "heap pops"
printf '%-7s %-17s | %-12s | %-19s %-17s %-17s %7s | %7s %9s %9s\n' \
    objects "thesis/vroc" "PxPl5 25GP" "simulation only" "stereo 640x512" "heap off" "on/off" "/frame" "checks/f" "/frame"
row() { # N thesis-pairs thesis-fps thesis-sub
    n=$1; t="random$1"
    tpairs=$2; tf=$3
    sim="-"; ren="-"; off="-"; r="-"; c="-"; pc="-"; hp="-"; vp="-"
    if [ -s "$TMP/$t.on" ]; then
        vp=$(get "$t.on" pairs)
        sim="$(num "$(get "$t.on" frames_per_s)") ($(num "$(get "$t.on" subframes_per_s)"))$(trunc "$t.on")"
        c=$(num "$(get "$t.on" collisions_per_frame)")
        pc=$(num "$(get "$t.on" pair_checks_per_frame)")
        hp=$(num "$(get "$t.on" heap_pops_per_frame)")
    fi
    [ -s "$TMP/$t.render" ] && ren="$(num "$(get "$t.render" frames_per_s)") ($(num "$(get "$t.render" subframes_per_s)"))$(trunc "$t.render")"
    if [ -s "$TMP/$t.off" ]; then
        off="$(num "$(get "$t.off" frames_per_s)") ($(num "$(get "$t.off" subframes_per_s)"))$(trunc "$t.off")"
        r=$(ratio "$(get "$t.on" frames_per_s)" "$(get "$t.off" frames_per_s)")
    fi
    th="-"
    [ "$tf" = "-" ] || th="$tf ($4)"
    printf '%-7s %-17s | %-12s | %-19s %-17s %-17s %7s | %7s %9s %9s\n' "$n" "$tpairs / $vp" "$th" \
        "$sim" "$ren" "$off" "$r" "$c" "$pc" "$hp"
}
printf '%s\n' "$RANDOM_THESIS" | while IFS='|' read -r n p f s; do row "$n" "$p" "$f" "$s"; done
echo "scaling (simulation only, heap on; not in the thesis):"
for s in $SCALE; do
    n=${s%%:*}
    row "$n" "$((n * (n - 1) / 2))" - -
done
r100=$(get random100.on frames_per_s)
printf 'goal: Random 100 at %s frames/s simulation only; vroc %s (%s of the goal).\n' \
    "$(num $RANDOM_GOAL)" "$(num "$r100")" "$(ratio "$r100" "$RANDOM_GOAL")"
l=$(get random20.on random_box); h=$(get random100.on random_box)
echo "The random environment: 'random N' (mixed spheres, cubes and superquadrics 0.08 to 0.2 m,"
echo "up to 2 m/s and 2 rad/s, elasticity 1), no force, time_step 0.1, max_linear 2,"
echo "collision_dist 0.2 (2 subframes, as the thesis); random_box (X, X, 2) with X = 2 sqrt(N/20)"
echo "(the same density for every N: random_box ${l:-?} at 20 ... ${h:-?} at 100), closed by 6"
echo "static walls (each adds N pairs: vroc's pairs are N(N-1)/2 + 6N).  Runs x frames: 20..100:"
echo "$R x $F heap on, $R3 x $F heap off and stereo;$(for s in $SCALE; do n=${s%%:*}; rf=${s#*:}; printf ' %s: %s x %s;' "$n" "${rf%%:*}" "${rf#*:}"; done)"
echo "heap off not measured beyond 100."
echo "Every measurement: a run stops after $BUDGET s, and no run starts after $MAXT s of runs"
echo "(the scaling rows: 60 s and 50 s)."
if [ -s "$TMP/cut" ]; then
    echo "Over $SOFT s in all: these were cut to 1 run of at most 10 s: $(tr '\n' ' ' <"$TMP/cut")"
fi
if grep -q 'truncated=1' "$RAW"; then
    echo "* a run stopped at the $BUDGET s budget: the figure covers the frames it did."
fi

# ---------------------------------------------------------------- the gas (issue 27)

GAS_SIZES="100 1000 2000 3000 4000 10000"
if [ "$QUICK" = 1 ]; then GAS_FRAMES=5; else GAS_FRAMES=20; fi
BULLET=build/bench/bullet_gas
for n in $GAS_SIZES; do
    measure "gas$n" --gas "$n" --frames "$GAS_FRAMES" --runs 1 --heap on --budget 120 \
        --max-time 120 --export "$TMP/gas$n.txt"
    if [ -x "$BULLET" ] && [ -s "$TMP/gas$n.txt" ]; then
        printf 'bench: %-28s' "bullet$n" >&2
        if "$BULLET" "$TMP/gas$n.txt" >"$TMP/bullet$n" 2>"$TMP/bullet$n.err"; then
            printf ' %s s\n' "$(field "$(cat "$TMP/bullet$n")" wall_s)" >&2
            cat "$TMP/bullet$n" >>"$RAW"
        else
            : >"$TMP/bullet$n"
            printf ' failed: %s\n' "$(head -n 1 "$TMP/bullet$n.err")" >&2
        fi
    fi
done

echo
echo "Scaling: the gas of issue 27 (simulation only, heap on; not in the thesis)"
rule
printf '%-8s %12s %9s %10s %9s %9s %9s | %11s %9s %7s\n' objects "thesis pairs" "existing" \
    frames/s "wall s" "set-up s" "peak MB" "Bullet s" "Bullet MB" "ratio"
for n in $GAS_SIZES; do
    t="gas$n"
    [ -s "$TMP/$t" ] || { printf '%-8s not measured\n' "$n"; continue; }
    fps=$(get "$t" frames_per_s)
    wall=$(awk -v f="$(get "$t" frames)" -v r="$fps" 'BEGIN { if (r > 0) printf "%.3g", f / r }')
    bw="-"; bm="-"; br="-"
    if [ -s "$TMP/bullet$n" ]; then
        bw=$(awk -v w="$(field "$(cat "$TMP/bullet$n")" wall_s)" 'BEGIN { printf "%.3g", w }')
        bm=$(field "$(cat "$TMP/bullet$n")" peak_rss_mb)
        br=$(ratio "$bw" "$wall")
    fi
    printf '%-8s %12s %9s %10s %9s %9s %9s | %11s %9s %7s\n' "$(num "$(get "$t" objects)")" \
        "$(num "$(get "$t" pairs)")" "$(num "$(get "$t" existing_pairs)")" "$(num "$fps")$(trunc "$t")" \
        "$wall" "$(num "$(get "$t" setup_s)")" "$(num "$(get "$t" peak_rss_mb)")" \
        "$bw" "$(num "$bm")" "$br"
done
echo "The gas: 'random N' (mixed spheres, cubes and superquadrics 0.08 to 0.2 m, up to 2 m/s"
echo "and 2 rad/s, elasticity 1) in random_box = (L, L, L), L = N^(1/3) / 2, closed by six"
echo "static walls: one object per cubic metre; no force, time_step 0.1, max_linear 2,"
echo "collision_dist 0.2 (2 subframes); $GAS_FRAMES frames ($(awk -v f="$GAS_FRAMES" 'BEGIN { print f / 10 }') s simulated), 1 run each in a process"
echo "of its own.  thesis pairs: every dynamic pair (Table 5.1's count); existing: the pairs"
echo "that exist after the last frame; wall s: the frames' wall time; set-up: loading the scene"
echo "and making ready what the frames need; peak MB: the process's peak resident set."
if [ -x "$BULLET" ]; then
    echo "Bullet: the same objects (bench_sim --export) in Bullet $(pkg-config --modversion bullet 2>/dev/null)'s default world at its"
    echo "usual 1/60 s step for the same simulated time (bench/bullet_gas.cpp): its stepping's"
    echo "wall time and peak memory; ratio = Bullet's wall / vroc's (issue 27's goal: >= 4x)."
else
    echo "Bullet: not measured (no libbullet-dev: make deps installs it)."
fi

# the collision scenes of scenes/ (issue 5): frames/s with collisions, heap on
echo
echo "Collision scenes: simulation only, heap on (frames/s, collisions and pair checks per frame)"
rule
printf '%-18s %14s %12s %14s\n' scene frames/s collisions pair-checks
for id in ball-on-table newtons-cradle box-drop billiards; do
    [ -f "scenes/$id.vroc" ] || continue
    measure "$id.on" "scenes/$id.vroc" --frames "$F" --runs "$R" --min-time "$MT" --heap on
    printf '%-18s %14s %12s %14s\n' "$id" "$(num "$(get "$id.on" frames_per_s)")" \
        "$(get "$id.on" collisions_per_frame)" "$(get "$id.on" pair_checks_per_frame)"
done

for b in view closest; do
    echo
    echo "bench_$b"
    rule
    if [ -x "build/bench/bench_$b" ]; then
        "build/bench/bench_$b" || echo "(bench_$b failed with status $?)"
    else
        echo "build/bench/bench_$b is missing: skipped"
    fi
done

# closest features on coherent motion (issue 40): two objects spinning 0.1 m apart,
# heap off (the pair searched every internal step), at growing vertex counts
echo
echo "Closest features on coherent motion: two objects spinning 0.1 m apart, heap off"
rule
printf '%-34s %14s %14s %14s %12s %8s\n' objects "frames/s" "cpu frames/s" "pair checks/f" "time / least" goal
if [ "$QUICK" = 1 ]; then SPIN_F=2000; else SPIN_F=20000; fi
for s in sq10 sq40 sq80 sq160 file100 file5000; do
    case $s in
        sq*) awk -v kind=sq -v res="${s#sq}" -f bench/spin.awk >"$TMP/spin-$s.vroc" ;;
        file*) awk -v kind=file -v n="${s#file}" -v obj="$TMP/spin-$s.off" -f bench/spin.awk >"$TMP/spin-$s.vroc" ;;
    esac
    measure "spin-$s" "$TMP/spin-$s.vroc" --frames "$SPIN_F" --runs "$R3" --heap off
done
for s in sq10 sq40 sq80 sq160 file100 file5000; do
    case $s in
        sq*) base=sq10; label="superquadrics ${s#sq} x ${s#sq}"; g="-"; [ $s = sq160 ] && g="<=1.5x" ;;
        *) base=file100; label="polyhedra of $(num "${s#file}") points (OFF)"; g="-"; [ $s = file5000 ] && g="<=1.5x" ;;
    esac
    printf '%-34s %14s %14s %14s %12s %8s\n' "$label" "$(num "$(get "spin-$s" frames_per_s)")" \
        "$(num "$(get "spin-$s" cpu_frames_per_s)")" "$(get "spin-$s" pair_checks_per_frame)" \
        "$(ratio "$(get "spin-$base" cpu_frames_per_s)" "$(get "spin-$s" cpu_frames_per_s)")" "$g"
done
echo "Superquadrics of exponents 1 and radius 0.3 (a tessellated ball), or the hulls of points spread"
echo "over such a ball read from an OFF file, spinning about different axes and never touching;"
echo "$SPIN_F frames, $R3 runs (bench/spin.awk).  time / least: processor time per frame against"
echo "10 x 10 (or 100 points).  Goal (issue 40): 160 x 160 within 1.5x of 10 x 10, and 5,000 points"
echo "within 1.5x of 100, with every pair searched every internal step."

# a room of one file (issue 39): its pieces cost only those near each object
echo
echo "Polyhedra from files: a room of many static pieces (simulation only, heap on)"
rule
awk -v n=2.5 -v obj="$TMP/room2000.obj" -v scene="$TMP/room2000.vroc" -f bench/room.awk
awk -v n=0 -v obj="$TMP/room6.obj" -v scene="$TMP/room6.vroc" -f bench/room.awk
measure room2000 "$TMP/room2000.vroc" --frames "$F" --runs "$R" --min-time "$MT" --heap on
measure room6 "$TMP/room6.vroc" --frames "$F" --runs "$R" --min-time "$MT" --heap on
printf '%-34s %14s %14s %12s %14s\n' room "frames/s" "cpu frames/s" collisions/f "pair checks/f"
for r in room2000 room6; do
    printf '%-34s %14s %14s %12s %14s\n' "$(if [ $r = room6 ]; then echo "6 faces (an empty box)"; else echo "2,000 tiles"; fi)" \
        "$(num "$(get "$r" frames_per_s)")" "$(num "$(get "$r" cpu_frames_per_s)")" \
        "$(get "$r" collisions_per_frame)" "$(get "$r" pair_checks_per_frame)"
done
printf 'time with 2,000 pieces / with 6: %s of wall time, %s of processor time (goal <= 1.5)\n' \
    "$(ratio "$(get room6 frames_per_s)" "$(get room2000 frames_per_s)")" \
    "$(ratio "$(get room6 cpu_frames_per_s)" "$(get room2000 cpu_frames_per_s)")"
echo "A room 8 m by 8 m, 6 m high, of one OBJ whose faces face in: 2,000 tiles 0.4 m across, or its"
echo "six faces; each face a static slab; 100 objects of random 100 (seed 1) in it, 100 frames."

# crowds (issue 35): 100 balls with e = 0.5 in V-grooves and in a slot barely wider
# than a ball, 10 s of simulated time each (a slow one is cut at the budget, *)
echo
echo "Crowds: 100 balls, e = 0.5, closed at both ends, 100 frames (simulation only, heap on)"
rule
awk -v kind=groove -v a=30 -v b=60 -f bench/crowd.awk >"$TMP/groove30.vroc"
awk -v kind=groove -v a=45 -v b=45 -f bench/crowd.awk >"$TMP/groove45.vroc"
awk -v kind=slot -f bench/crowd.awk >"$TMP/slot.vroc"
awk -v kind=slot -v friction=0 -f bench/crowd.awk >"$TMP/slot0.vroc"
printf '%-34s %14s %14s %12s %14s\n' crowd "frames/s" "cpu frames/s" collisions/f "pair checks/f"
for c in groove30 groove45 slot slot0; do
    # the slots rest after some 25 frames and a minute of computing without
    # friction, and after 9 frames and a minute with it (test_pressure's
    # hundred_in_slot_rest and rough_hundred_in_slot_rest): their budgets let
    # them get there
    case $c in slot0) more="--budget 120 --max-time 120";; slot) more="--budget 150 --max-time 150";;
        *) more="";; esac
    # shellcheck disable=SC2086
    measure "$c" "$TMP/$c.vroc" --frames 100 --runs 1 --heap on $more
    printf '%-34s %14s %14s %12s %14s\n' "$(case $c in groove30) echo "V-groove, faces at 30 and 60 deg";;
        groove45) echo "V-groove, faces at 45 and 45 deg";; slot) echo "slot 1e-7 m wider than a ball";;
        *) echo "the same slot without friction";; esac)" \
        "$(num "$(get "$c" frames_per_s)")$(trunc "$c")" "$(num "$(get "$c" cpu_frames_per_s)")" \
        "$(get "$c" collisions_per_frame)" "$(get "$c" pair_checks_per_frame)"
done

# polyhedra from files (issue 38): the readers against assimp's, on files made here
echo
echo "Polyhedra from files: reading large meshes (median of 3 runs, each a process of its own)"
rule
MESH=build/bench/bench_mesh
if [ -x "$MESH" ] && "$MESH" make "$TMP" 2>"$TMP/mesh.err"; then
    # med3 MODE FILE KEY: the median of 3 runs' KEY, and the most peak_rss_mb of them
    med3() {
        : >"$TMP/m3"
        for r in 1 2 3; do
            if [ "$1" = assimp ]; then "$MESH" child assimp info "$2" >>"$TMP/m3" 2>/dev/null
            else "$MESH" "$1" "$2" >>"$TMP/m3" 2>/dev/null; fi
        done
        t=$(while read -r l; do field "$l" "$3"; done <"$TMP/m3" | sort -g | sed -n 2p)
        m=$(while read -r l; do field "$l" peak_rss_mb; done <"$TMP/m3" | sort -g | tail -n 1)
        printf '%s %s' "${t:--}" "${m:--}"
    }
    printf '%-15s | %7s %7s %7s | %9s %7s %7s | %8s %7s\n' file "read s" "cpu s" "peak MB" \
        "file = s" "hull s" "peak MB" "assimp s" "peak MB"
    for f in torus-1m.stl torus-600k.obj; do
        set -- $(med3 read "$TMP/$f" read_s)
        r=$1 rm=$2
        rc=$(while read -r l; do field "$l" cpu_s; done <"$TMP/m3" | sort -g | sed -n 2p)
        set -- $(med3 load "$TMP/$f" load_s)
        l=$1 lm=$2
        h=$(while read -r l_; do field "$l_" hull_s; done <"$TMP/m3" | sort -g | sed -n 2p)
        if command -v assimp >/dev/null 2>&1; then
            set -- $(med3 assimp "$TMP/$f" wall_s)
            a=$1 am=$2
        else
            a=- am=-
        fi
        printf '%-15s | %7s %7s %7s | %9s %7s %7s | %8s %7s\n' "$f" "$r" "${rc:--}" "$rm" "$l" \
            "${h:--}" "$lm" "$a" "$am"
    done
    echo "torus-1m.stl: a binary STL of 1,000,000 triangles (50 MB; 500,000 points, half of them"
    echo "on the hull); torus-600k.obj: an OBJ of 600,000 triangles (23 MB; 300,000 points).  read:"
    echo "the file's bytes, the reader (welding and sorting) and the drawing mesh (smooth normals);"
    echo "file =: that and the body: the exact hull of every point and its mass properties, as the"
    echo "file statement builds it; assimp: 'assimp info FILE' (reads, then post-processes).  Wall"
    echo "seconds, and the reader's processor seconds (cpu s: what it cost, whatever else ran)."
    echo "Issue 38's goals: the STL read in under 1 s and 200 MB, the OBJ in under 1 s."
    command -v assimp >/dev/null 2>&1 || echo "assimp: not measured (assimp-utils is not installed)."
else
    echo "bench_mesh failed: $(head -n 2 "$TMP/mesh.err" 2>/dev/null)"
fi

# ---------------------------------------------------------------- issue 40's goals

# goal LABEL FIGURE TEXT TEST: a row of the goals' table; TEST is an awk condition
# on x (the figure), and the row says yes, no, or '-' when there is no figure.
goal() {
    met=$(awk -v x="$2" "BEGIN { if (x == \"\" || x == \"-\") print \"-\"; else if ($4) print \"yes\"; else print \"no\" }")
    printf '%-58s %14s %16s %5s\n' "$1" "$(num "$2")" "$3" "$met"
}
# cpu_ratio A B: B's processor time per frame over A's (A's cpu frames/s over B's)
cpu_ratio() {
    awk -v a="$(get "$1" cpu_frames_per_s)" -v b="$(get "$2" cpu_frames_per_s)" \
        'BEGIN { if (a > 0 && b > 0) printf "%.2f", a / b }'
}
echo
echo "Issue 40's goals against this run's figures"
rule
printf '%-58s %14s %16s %5s\n' goal figure target met
for id in computer-desks office bounce; do
    name=$(printf '%s\n' "$THESIS" | grep "^$id|" | cut -d'|' -f2)
    goal "$name: frames/s, simulation only, first $F frames" "$(get "$id.on" frames_per_s)" ">= 15,000" "x >= 15000"
    goal "$name: frames/s, simulation only, $F600 frames" "$(get "$id.600" frames_per_s)" ">= 15,000" "x >= 15000"
done
goal "Simple keeps its rate: frames/s, first $F frames" "$(get simple.on frames_per_s)" "~700,000 (-10%)" "x >= 630000"
goal "Simple: frames/s, $F600 frames" "$(get simple.600 frames_per_s)" "~700,000 (-10%)" "x >= 630000"
goal "Virtual Basketball keeps its rate: frames/s, first $F frames" "$(get basketball.on frames_per_s)" "~200,000 (-10%)" "x >= 180000"
goal "Virtual Basketball: frames/s, $F600 frames" "$(get basketball.600 frames_per_s)" "~200,000 (-10%)" "x >= 180000"
for id in computer-desks office bounce; do
    name=$(printf '%s\n' "$THESIS" | grep "^$id|" | cut -d'|' -f2)
    goal "$name: heap on / heap off" \
        "$(awk -v a="$(get "$id.on" frames_per_s)" -v b="$(get "$id.off" frames_per_s)" 'BEGIN { if (a > 0 && b > 0) printf "%.2f", a / b }')" \
        ">= 10" "x >= 10"
done
for n in 1000 10000; do
    r=""
    if [ -s "$TMP/gas$n" ] && [ -s "$TMP/bullet$n" ]; then
        r=$(awk -v w="$(field "$(cat "$TMP/bullet$n")" wall_s)" -v f="$(get "gas$n" frames)" \
            -v r="$(get "gas$n" frames_per_s)" 'BEGIN { if (r > 0) printf "%.2f", w / (f / r) }')
    fi
    goal "the gas of $(num "$n"): Bullet's wall time / vroc's (one run)" "$r" ">= 4" "x >= 4"
done
goal "the gas of 10,000: peak memory, MB" "$(get gas10000 peak_rss_mb)" "< 300" "x < 300"
goal "the gas of 10,000: set-up, s" "$(get gas10000 setup_s)" "< 0.5" "x < 0.5"
goal "closest, heap off: time per frame 160 x 160 / 10 x 10" "$(cpu_ratio spin-sq10 spin-sq160)" "<= 1.5" "x <= 1.5"
goal "closest, heap off: 5,000 points / 100 (OFF files)" "$(cpu_ratio spin-file100 spin-file5000)" "<= 1.5" "x <= 1.5"
echo "Frames/s are wall time (the tables above); the closest-feature ratios are processor time"
echo "(steadier on a shared machine); the gas's ratio is wall time, vroc's frames and Bullet's"
echo "steps measured in this run.  'Keeps its rate': within 10% of the issue's figure."

echo
echo "raw bench_sim lines (fields: see bench/bench_sim.c)"
rule
cat "$RAW"
for f in "$TMP"/*.err; do
    [ -s "$f" ] || continue
    echo "$(basename "$f" .err): $(head -n 3 "$f")"
done
