#!/bin/sh
# run.sh: runs every test of vroc and ends with one line "N passed, N failed".
#
# Unit tests (build/tests/test_*) print TAP through cmocka; each "ok" or "not ok"
# line is one test.  Script tests (tests/*.sh but this file) print "ok NAME" or
# "not ok NAME" lines the same way; a test that does not apply to a build says
# "... # SKIP" (cmocka's skip(): the memory test under the sanitizers) and is counted
# as skipped.  Everything runs twice: with the normal build and
# with the AddressSanitizer + UndefinedBehaviorSanitizer build (VROC=build-san/vroc).
# Full output goes to tests/out/log; failures are repeated at the end.
set -u
cd "$(dirname "$0")/.." || exit 1
mkdir -p tests/out
log=tests/out/log
: > "$log"
pass=0
fail=0
skipped=0
failed=""

count() { # reads TAP-ish output on stdin, label in $1
    while IFS= read -r line; do
        printf '%s\n' "$line" >> "$log"
        case "$line" in
            *"# SKIP"*) skipped=$((skipped + 1)) ;;
            "ok "*) pass=$((pass + 1)) ;;
            "not ok "*) fail=$((fail + 1)); failed="$failed
$1: $line" ;;
        esac
    done
}

export CMOCKA_MESSAGE_OUTPUT=TAP
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0:exitcode=99
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# The unit tests of both builds first, as many at once as there are processors:
# they are pure computation and share nothing (each output and status goes to
# its own file under tests/out/unit), so this only saves time.  The scripts run
# one at a time after them: the window's and the prompt's tests time what a
# person does, and want the machine to themselves.
units=tests/out/unit
rm -rf "$units"
mkdir -p "$units"
for t in build/tests/test_* build-san/tests/test_*; do
    [ -x "$t" ] && printf '%s\n' "$t"
done | xargs -P "$(nproc 2>/dev/null || echo 2)" -I{} sh -c '
    f=$0/$(printf "%s" "$1" | tr / _); t0=$(date +%s)
    "$1" > "$f.out" 2>&1; echo $? > "$f.status"; echo $(($(date +%s) - t0)) > "$f.time"' "$units" {}
for build in build build-san; do
    for t in $build/tests/test_*; do
        [ -x "$t" ] || continue
        echo "# $t" >> "$log"
        f=$units/$(printf '%s' "$t" | tr / _)
        out=$(cat "$f.out" 2>/dev/null)
        status=$(cat "$f.status" 2>/dev/null || echo 127)
        echo "# $t took $(cat "$f.time" 2>/dev/null) s (beside the other unit tests)" >> "$log"
        printf '%s\n' "$out" | { count "$t"; echo "$pass $fail $skipped" > tests/out/.counts; printf '%s' "$failed" > tests/out/.failed; }
        read -r pass fail skipped < tests/out/.counts
        failed=$(cat tests/out/.failed)
        if [ $status -ne 0 ] && ! printf '%s\n' "$out" | grep -q '^not ok'; then
            fail=$((fail + 1)); failed="$failed
$t: exited with status $status"
            printf '%s\n' "$out" | tail -20 >> "$log"
        fi
    done
    for s in tests/*.sh; do
        [ "$s" = tests/run.sh ] && continue
        echo "# $s ($build)" >> "$log"
        bin=./vroc; [ "$build" = build-san ] && bin=build-san/vroc
        t0=$(date +%s)
        out=$(VROC=$bin BUILD=$build sh "$s" 2>&1)
        status=$?
        echo "# $s ($build) took $(($(date +%s) - t0)) s" >> "$log"
        printf '%s\n' "$out" | { count "$s ($build)"; echo "$pass $fail $skipped" > tests/out/.counts; printf '%s' "$failed" > tests/out/.failed; }
        read -r pass fail skipped < tests/out/.counts
        failed=$(cat tests/out/.failed)
        if [ $status -ne 0 ]; then
            fail=$((fail + 1)); failed="$failed
$s ($build): exited with status $status"
        fi
    done
done
rm -f tests/out/.counts tests/out/.failed
rm -rf "$units"
if [ -n "$failed" ]; then
    echo "failures (full log in $log):$failed"
fi
if [ "$skipped" -gt 0 ]; then
    echo "$pass passed, $fail failed, $skipped skipped"
else
    echo "$pass passed, $fail failed"
fi
[ "$fail" -eq 0 ]
