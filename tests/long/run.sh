#!/bin/sh
# long/run.sh: make check-long: the sweeps too long for make check, with the
# normal build (each tests/long/*.sh but this file), ending with "N passed, N
# failed" and the time taken.  Full output in tests/out/long.log.
set -u
cd "$(dirname "$0")/../.." || exit 1
mkdir -p tests/out
log=tests/out/long.log
: > "$log"
start=$(date +%s)
for s in tests/long/*.sh; do
    [ "$s" = tests/long/run.sh ] && continue
    echo "# $s" >> "$log"
    VROC=./vroc BUILD=build sh "$s" >> "$log" 2>&1 || echo "not ok - $s exited with status $?" >> "$log"
done
pass=$(grep -c '^ok ' "$log")
fail=$(grep -c '^not ok ' "$log")
if [ "$fail" -gt 0 ]; then
    echo "failures (full log in $log):"
    grep -A8 '^not ok ' "$log" | head -60
fi
echo "$pass passed, $fail failed in $(( $(date +%s) - start )) s"
[ "$fail" -eq 0 ]
