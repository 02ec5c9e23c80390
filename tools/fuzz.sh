#!/bin/sh
# fuzz.sh: coverage-guided fuzz campaigns with AFL++ (`make fuzz`): of vroc's
# language, and of the four mesh readers; and the language's seeds
# (`sh tools/fuzz.sh seeds`).
#
# FUZZ_TARGETS names the campaigns, one after the other, each of FUZZ_TIME
# seconds: `script` (the language, below) and `obj`, `stl`, `off`, `ply` (the
# readers: build-fuzz/tests/fuzz_mesh FORMAT INPUT reads the input with that
# reader and makes its drawing mesh, from the seeds of every format in
# tests/fuzz/mesh-seeds/, with a dictionary of the formats' keywords).  All five
# by default.  A reader's finding goes into tests/fuzz/regress/ as
# mesh-FORMAT-WHAT, which `make check` replays with that reader (tests/fuzz.sh).
#
# The script target is the real program built with afl-clang-fast and the sanitizers
# (build-fuzz/vroc), run as `vroc -b -q INPUT` on each input, so every statement
# of the language, the simulation and the views can be reached.  It starts from
# tests/fuzz/seeds/ (the scenes, and one script per command: its example) with a
# dictionary made from commands/ (tools/fuzzdict.awk), and runs for FUZZ_TIME
# seconds (60 by default) at nice 10.  FUZZ_SEEDS names another folder to start
# from, such as an earlier campaign's out/default/queue.
#
# Nothing it writes can leave the scratch folder FUZZ_DIR (build-fuzz/run): vroc
# runs with that folder's work/ as its working directory and HOME, and with
# VROC_SANDBOX=1, under which vroc refuses to write (save, trace, events, output,
# -o) anywhere but below its working directory: no absolute path, no "..".  Each
# campaign keeps AFL++'s queue, crashes and hangs in FUZZ_DIR/out-TARGET.  Each
# input in out-TARGET/default/crashes and .../hangs is to be read: one that
# crashed, or hung without legitimately large work (run 1e9 is legitimate), goes
# into tests/fuzz/regress/, which `make check` replays under the sanitizers
# (tests/fuzz.sh).
set -eu
cd "$(dirname "$0")/.."
root=$(pwd)

if [ "${1:-}" = seeds ]; then
    rm -f tests/fuzz/seeds/*.vroc
    for f in commands/*; do
        sed -n '/^example:$/,$p' "$f" | sed 1d > "tests/fuzz/seeds/cmd-$(basename "$f").vroc"
    done
    for f in scenes/*.vroc; do cp "$f" "tests/fuzz/seeds/scene-$(basename "$f")"; done
    echo "fuzz: $(ls tests/fuzz/seeds | wc -l) seeds in tests/fuzz/seeds"
    exit 0
fi

time=${FUZZ_TIME:-60}
targets=${FUZZ_TARGETS:-script obj stl off ply}
scratch=${FUZZ_DIR:-$root/build-fuzz/run}
bin=$root/build-fuzz/vroc
meshbin=$root/build-fuzz/tests/fuzz_mesh
[ -x "$bin" ] || { echo "fuzz: $bin is missing (make fuzz builds it)" >&2; exit 1; }
[ -x "$meshbin" ] || { echo "fuzz: $meshbin is missing (make fuzz builds it)" >&2; exit 1; }
rm -rf "$scratch"
mkdir -p "$scratch/work"
cp "$bin" "$scratch/vroc" # a rebuild during the campaign leaves it alone
cp "$meshbin" "$scratch/fuzz_mesh"
awk -f tools/fuzzdict.awk commands/* > "$scratch/vroc.dict"
# the mesh formats' keywords
for w in v vn vt f o g solid facet normal outer loop vertex endloop endfacet endsolid \
    OFF COFF NOFF STOFF ply format ascii binary_little_endian binary_big_endian 1.0 \
    element property list char uchar short ushort int uint float double int8 uint8 \
    int32 uint32 float32 float64 end_header vertex_indices vertex_index face comment \
    nx ny nz nan inf -1 1e308; do
    printf '"%s"\n' "$w"
done > "$scratch/mesh.dict"

cd "$scratch/work"
export VROC_SANDBOX=1 HOME="$scratch/work" VROC_SCENES="$root/scenes"
export AFL_SKIP_CPUFREQ=1 AFL_NO_UI=1 AFL_I_DONT_CARE_ABOUT_MISSING_CRASHES=1
export AFL_NO_AFFINITY=1 AFL_SKIP_BIN_CHECK=0
export ASAN_OPTIONS=abort_on_error=1:detect_leaks=0:symbolize=0:allocator_may_return_null=1
export UBSAN_OPTIONS=halt_on_error=1:abort_on_error=1:print_stacktrace=1

for target in $targets; do
    out=$scratch/out-$target
    case "$target" in
    script)
        seeds=${FUZZ_SEEDS:-$root/tests/fuzz/seeds}
        set -- -x "$scratch/vroc.dict" -t 3000 -m none -- "$scratch/vroc" -b -q @@ ;;
    obj | stl | off | ply)
        seeds=$root/tests/fuzz/mesh-seeds
        set -- -x "$scratch/mesh.dict" -t 2000 -m none -- "$scratch/fuzz_mesh" "$target" @@ ;;
    *) echo "fuzz: unknown target '$target' (script, obj, stl, off, ply)" >&2; exit 1 ;;
    esac
    echo "fuzz: $target, $time s in $out (nice 10)"
    nice -n 10 afl-fuzz -V "$time" -i "$seeds" -o "$out" "$@" > "$out.log" 2>&1 || {
        tail -30 "$out.log" >&2
        exit 1
    }
    stats=$out/default/fuzzer_stats
    get() { sed -n "s/^$1 *: *//p" "$stats"; }
    echo "fuzz: $target: $(get execs_done) executions in $(get run_time) s, $(get execs_per_sec)/s"
    echo "fuzz: $target: coverage $(get bitmap_cvg) of the map, $(get edges_found) edges of $(get total_edges)"
    echo "fuzz: $target: corpus $(get corpus_count), crashes $(get saved_crashes), hangs $(get saved_hangs)"
    for d in crashes hangs; do
        for f in "$out/default/$d"/id*; do
            [ -f "$f" ] && echo "fuzz: read $f"
        done
    done
done
exit 0
