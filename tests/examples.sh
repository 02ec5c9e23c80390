#!/bin/sh
# examples.sh: every command page's example (commands/NAME, after "example:")
# runs as a script: `vroc -b -q` on it in an empty folder, with the scenes folder
# at hand (VROC_SCENES) and VROC_SANDBOX=1, must end with status 0 and print no
# error or warning, so that what help and the manual show stays true.  Examples
# that need a terminal (none yet) are listed in NEEDS_TTY and skipped; those that
# open a window (NEEDS_DISPLAY) run under an X server of the test's own (Xvfb),
# and only they see it.
. "$(dirname "$0")/lib.sh"
ROOT=$(cd "$(dirname "$0")/.." && pwd)
NEEDS_TTY=""
NEEDS_DISPLAY="window"
trap 'xvfb_stop; rm -rf "$TMP"' EXIT
NO_DISPLAY=""
xvfb_start || { NO_DISPLAY=$NEEDS_DISPLAY; NEEDS_DISPLAY=""; }
SHOWN=${DISPLAY:-}
unset DISPLAY
for f in "$ROOT"/commands/*; do
    name=$(basename "$f")
    case " $NEEDS_TTY " in *" $name "*) ok "example of $name # SKIP needs a terminal"; continue ;; esac
    case " $NO_DISPLAY " in *" $name "*) ok "example of $name # SKIP needs an X server"; continue ;; esac
    mkdir -p "$TMP/ex/$name"
    sed -n '/^example:$/,$p' "$f" | sed 1d > "$TMP/ex/$name.vroc"
    if [ ! -s "$TMP/ex/$name.vroc" ]; then notok "$name has an example"; continue; fi
    shown=
    case " $NEEDS_DISPLAY " in *" $name "*) shown=$SHOWN ;; esac
    out=$(cd "$TMP/ex/$name" && DISPLAY=$shown VROC_SCENES="$ROOT/scenes" VROC_SANDBOX=1 "$VROC" -b -q "../$name.vroc" 2>&1 >/dev/null)
    status=$?
    if [ $status -eq 0 ] && ! printf '%s' "$out" | grep -qE '(error|warning):'; then
        ok "the example of $name runs as a script"
    else
        notok "the example of $name runs as a script" "status $status" "$(printf '%s' "$out" | head -3)"
    fi
done
exit 0
