# sweep.sh: the continuation sweep (sourced after lib.sh; tests/continue.sh and
# tests/long/continue.sh use it).  The exact-state promise (language.md, "Exact
# state"): a world saved after any frame, read into a fresh vroc, is the same
# world to the bit and runs on to the same trace and hash as the run that never
# stopped.
#
# sweep NAME SETUP FRAMES ON: SETUP is the statements (or a file) that make the
# world; FRAMES the frames after which it is saved (ascending, from 0); ON how
# many frames each saved world runs on.  One vroc makes the world and saves it
# after each of those frames, writing its trace and, after every frame, its time
# and hash; one vroc per saved world reads it back and runs on.  Each saved world
# must:
#   - read back without an error, to the hash the world had when it was saved,
#     and saved again, to the same file (every number read back to the bit);
#   - run on to the trace rows the unbroken run wrote for those frames, to the
#     bit (rows from its first frame to its last: the panel's Step button may add
#     frames);
#   - end at the hash the unbroken run had at that time (where the unbroken run
#     printed one: after each of its frames but those a button added).
# And the unbroken run, saved and hashed after every frame, gives the trace of
# the same run in one go (a save and a hash change nothing).
# Prints two ok or not ok lines.  (The body runs in a subshell: its variables
# are its own, and leave the caller's loops alone.)

sweep() (
    name=$1 setup=$2 frames=$3 on=$4
    last=$(printf '%s\n' $frames | tail -1)
    total=$((last + on))
    d="$TMP/sweep-$name"
    mkdir -p "$d"
    # the unbroken run: saved after the frames asked for, time and hash after each
    cmds="trace = $d/a.csv; time; hash"
    f=0
    next_save() { for k in $frames; do [ "$k" -eq "$f" ] && echo yes && return; done; }
    [ "$(next_save)" = yes ] && cmds="$cmds; save $d/s$f.vroc"
    while [ $f -lt $total ]; do
        f=$((f + 1))
        cmds="$cmds; run 1; time; hash"
        [ "$(next_save)" = yes ] && cmds="$cmds; save $d/s$f.vroc"
    done
    if [ "${setup%.vroc}" != "$setup" ]; then
        "$VROC" -b -q "$setup" -c "$cmds" > "$d/a.txt" 2>&1
        st=$?
        "$VROC" -b -q "$setup" -c "trace = $d/r.csv; run $total" > "$d/r.txt" 2>&1
    else
        "$VROC" -b -q -c "$setup" -c "$cmds" > "$d/a.txt" 2>&1
        st=$?
        "$VROC" -b -q -c "$setup" -c "trace = $d/r.csv; run $total" > "$d/r.txt" 2>&1
    fi
    if [ $st -ne 0 ]; then
        notok "$name: the unbroken run saved after each frame" "$(head -3 "$d/a.txt")"
        return
    fi
    if cmp -s "$d/a.csv" "$d/r.csv"; then
        ok "$name: saving and hashing after each frame leaves the run as it was ($total frames)"
    else
        notok "$name: saving and hashing after each frame leaves the run as it was" \
            "$(cmp "$d/a.csv" "$d/r.csv" 2>&1)"
    fi
    # time -> hash of the unbroken run, as "T H" lines
    awk '/^time = /{t=$3} /^hash = /{print t, $3}' "$d/a.txt" > "$d/hashes"
    bad="" checked=0
    for k in $frames; do
        s="$d/s$k.vroc"
        out=$("$VROC" -b -q "$s" -c "time; hash; save $d/c$k.vroc; trace = $d/b$k.csv; run $on; time; hash" 2>&1)
        if [ $? -ne 0 ]; then
            bad="$bad
#   frame $k: $(printf '%s' "$out" | head -2 | tr '\n' ' ')"
            continue
        fi
        t0=$(printf '%s\n' "$out" | awk '/^time = /{print $3; exit}')
        h0=$(printf '%s\n' "$out" | awk '/^hash = /{print $3; exit}')
        t1=$(printf '%s\n' "$out" | awk '/^time = /{t=$3} END{print t}')
        h1=$(printf '%s\n' "$out" | awk '/^hash = /{h=$3} END{print h}')
        want0=$(awk -v t="$t0" '$1 == t {print $2; exit}' "$d/hashes")
        want1=$(awk -v t="$t1" '$1 == t {print $2; exit}' "$d/hashes")
        # (but for the trace, open in the unbroken run, which save names in a comment)
        grep -v '^# trace = ' "$s" > "$d/s.txt"
        grep -v '^# trace = ' "$d/c$k.vroc" > "$d/c.txt"
        if ! cmp -s "$d/s.txt" "$d/c.txt"; then
            bad="$bad
#   frame $k: saved again once read back, it differs: $(diff "$d/s.txt" "$d/c.txt" | sed -n 2p)"
            continue
        fi
        if [ "$h0" != "$want0" ]; then
            bad="$bad
#   frame $k: read back to hash $h0 at time $t0, saved at $want0"
            continue
        fi
        if [ -n "$want1" ] && [ "$h1" != "$want1" ]; then
            bad="$bad
#   frame $k: ran on to hash $h1 at time $t1, the unbroken run to $want1"
            continue
        fi
        [ -n "$want1" ] && checked=$((checked + 1))
        # the unbroken run's rows of the frames the read-back world ran
        awk -F, 'NR == FNR { if (FNR > 1) { if (first == "") first = $1; lastf = $1 } next }
                 FNR == 1 || ($1 + 0 >= first + 0 && $1 + 0 <= lastf + 0)' \
            "$d/b$k.csv" "$d/a.csv" > "$d/w$k.csv"
        if ! cmp -s "$d/w$k.csv" "$d/b$k.csv"; then
            bad="$bad
#   frame $k: the trace differs: $(cmp "$d/w$k.csv" "$d/b$k.csv" 2>&1 | head -1)"
        fi
    done
    n=$(printf '%s\n' $frames | wc -l)
    if [ -z "$bad" ]; then
        ok "$name: saved after each of $n frames, read back to the bit and run on $on frames to the same trace and hash ($checked ends hashed)"
    else
        echo "not ok - $name: saved after each of $n frames, read back to the bit and run on $on frames to the same trace and hash"
        printf '%s\n' "$bad" | sed 1d | head -8
        nb=$(printf '%s\n' "$bad" | sed 1d | wc -l)
        [ "$nb" -gt 8 ] && echo "#   and $((nb - 8)) frames more"
    fi
    [ -n "${SWEEP_KEEP:-}" ] || rm -rf "$d"
)
