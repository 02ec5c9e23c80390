#!/bin/sh
# fuzz.sh: a coverage-guided fuzz campaign of vroc's language with AFL++
# (`make fuzz`), and the seeds it starts from (`sh tools/fuzz.sh seeds`).
#
# The target is the real program built with afl-clang-fast and the sanitizers
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
# -o) anywhere but below its working directory: no absolute path, no "..".  AFL++
# keeps its queue, crashes and hangs in FUZZ_DIR/out.  Each input in
# out/default/crashes and out/default/hangs is to be read: one that crashed, or
# hung without legitimately large work (run 1e9 is legitimate), goes into
# tests/fuzz/regress/, which `make check` replays under the sanitizers
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
scratch=${FUZZ_DIR:-$root/build-fuzz/run}
bin=$root/build-fuzz/vroc
[ -x "$bin" ] || { echo "fuzz: $bin is missing (make fuzz builds it)" >&2; exit 1; }
rm -rf "$scratch"
mkdir -p "$scratch/work"
cp "$bin" "$scratch/vroc" # a rebuild during the campaign leaves it alone
awk -f tools/fuzzdict.awk commands/* > "$scratch/vroc.dict"

cd "$scratch/work"
export VROC_SANDBOX=1 HOME="$scratch/work" VROC_SCENES="$root/scenes"
export AFL_SKIP_CPUFREQ=1 AFL_NO_UI=1 AFL_I_DONT_CARE_ABOUT_MISSING_CRASHES=1
export AFL_NO_AFFINITY=1 AFL_SKIP_BIN_CHECK=0
export ASAN_OPTIONS=abort_on_error=1:detect_leaks=0:symbolize=0:allocator_may_return_null=1
export UBSAN_OPTIONS=halt_on_error=1:abort_on_error=1:print_stacktrace=1
echo "fuzz: $time s in $scratch (nice 10)"
seeds=${FUZZ_SEEDS:-$root/tests/fuzz/seeds}
nice -n 10 afl-fuzz -V "$time" -i "$seeds" -o "$scratch/out" \
    -x "$scratch/vroc.dict" -t 3000 -m none -- "$scratch/vroc" -b -q @@ > "$scratch/afl.log" 2>&1 || {
    tail -30 "$scratch/afl.log" >&2
    exit 1
}

stats=$scratch/out/default/fuzzer_stats
get() { sed -n "s/^$1 *: *//p" "$stats"; }
echo "fuzz: $(get execs_done) executions in $(get run_time) s, $(get execs_per_sec)/s"
echo "fuzz: coverage $(get bitmap_cvg) of the map, $(get edges_found) edges of $(get total_edges)"
echo "fuzz: corpus $(get corpus_count), crashes $(get saved_crashes), hangs $(get saved_hangs)"
for d in crashes hangs; do
    for f in "$scratch/out/default/$d"/id*; do
        [ -f "$f" ] && echo "fuzz: read $f"
    done
done
exit 0
