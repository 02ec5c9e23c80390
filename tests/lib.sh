# lib.sh: helpers for vroc's script tests (sourced, POSIX sh).
# Each check prints "ok - TEXT" or "not ok - TEXT"; tests/run.sh counts them.
VROC=${VROC:-./vroc}
case "$VROC" in /*) ;; *) VROC="$(pwd)/$VROC" ;; esac
TMP=$(mktemp -d /tmp/vroc-test-XXXXXX)
trap 'rm -rf "$TMP"' EXIT
export HOME="$TMP"   # no history file of the user's is touched
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}

ok() { echo "ok - $1"; }
notok() { echo "not ok - $1"; shift; for l in "$@"; do echo "#   $l"; done; }

# expect TEXT STATUS PATTERN CMD...: CMD exits with STATUS and its output
# (stdout and stderr) contains PATTERN (a fixed string).
expect() {
    desc=$1 want_status=$2 pattern=$3
    shift 3
    out=$("$@" 2>&1)
    status=$?
    if [ "$status" -eq "$want_status" ] && printf '%s' "$out" | grep -qF -- "$pattern"; then
        ok "$desc"
    else
        notok "$desc" "status $status (want $want_status)" "output: $(printf '%s' "$out" | head -5)"
    fi
}

# same TEXT FILE1 FILE2: the two files are identical
same() {
    if cmp -s "$2" "$3"; then ok "$1"; else notok "$1" "$(diff "$2" "$3" | head -10)"; fi
}
