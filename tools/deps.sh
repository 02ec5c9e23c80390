#!/bin/sh
# deps.sh: install the Debian packages vroc needs that this machine lacks.
# `deps.sh fuzz` (make fuzz) also wants AFL++ (afl++), and `deps.sh bench` (make
# bench) assimp-utils, the peer the mesh readers are measured against.
# Checks with pkg-config and command -v first; on a ready machine it installs
# nothing and prints one line.  Runs apt-get directly as root, through sudo
# otherwise.  Used by `make deps`, itself a prerequisite of check, bench, demo.
set -u

missing=""
add() { # Debian package, once
    case " $missing " in *" $1 "*) ;; *) missing="$missing $1" ;; esac
}
need_pkg() { # pkg-config module, Debian package
    pkg-config --exists "$1" 2>/dev/null || add "$2"
}
need_cmd() { # command, Debian package
    command -v "$1" >/dev/null 2>&1 || add "$2"
}

need_cmd pkg-config pkg-config
need_cmd cc gcc
need_cmd c++ g++
if command -v pkg-config >/dev/null 2>&1; then
    need_pkg readline libreadline-dev
    need_pkg osmesa libosmesa6-dev
    need_pkg libpng libpng-dev
    need_pkg qhull_r libqhull-dev
    need_pkg sndfile libsndfile1-dev
    need_pkg samplerate libsamplerate0-dev
    need_pkg libpulse-simple libpulse-dev
    need_pkg nettle nettle-dev # the SHA-256 save writes of a polyhedron's file
    need_pkg sdl2 libsdl2-dev # the live window (its headers: it is loaded with dlopen)
    need_pkg cmocka libcmocka-dev
    need_pkg bullet libbullet-dev # the peer of the gas benchmark (make bench)
else
    missing="$missing libreadline-dev libosmesa6-dev libpng-dev libqhull-dev libsndfile1-dev"
    missing="$missing libsamplerate0-dev libpulse-dev nettle-dev libcmocka-dev libbullet-dev"
    missing="$missing libsdl2-dev"
fi
need_cmd tmux tmux
need_cmd mandoc mandoc
need_cmd valgrind valgrind
# movies: the ffmpeg program (and ffprobe, which the tests read movies with)
need_cmd ffmpeg ffmpeg
need_cmd ffprobe ffmpeg
# plot: the gnuplot program (its pngcairo terminal; -nox: no X needed)
need_cmd gnuplot gnuplot-nox
# the live sound test: a PulseAudio server of its own, parecord (and pactl,
# pacat), and pgrep, which counts the servers
need_cmd pulseaudio pulseaudio
need_cmd parecord pulseaudio-utils
need_cmd pgrep procps
# the window's tests: an X server of their own (Xvfb), xdotool for keys and the
# mouse, and xwd for screenshots of the window
need_cmd Xvfb xvfb
need_cmd xdotool xdotool
need_cmd xwd x11-apps
need_cmd xdpyinfo x11-utils
if [ "${1:-}" = fuzz ]; then need_cmd afl-fuzz afl++; fi
# make bench measures the mesh readers against assimp's `assimp info`
if [ "${1:-}" = bench ]; then need_cmd assimp assimp-utils; fi

if [ -z "$missing" ]; then
    echo "deps: all present"
    exit 0
fi

echo "deps: installing$missing"
if [ "$(id -u)" -eq 0 ]; then
    SUDO=""
elif command -v sudo >/dev/null 2>&1; then
    SUDO="sudo"
else
    echo "deps: not root and no sudo: install these by hand:$missing" >&2
    exit 1
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q >/dev/null || { echo "deps: apt-get update failed" >&2; exit 1; }
# shellcheck disable=SC2086
$SUDO apt-get install -y -q --no-install-recommends $missing >/dev/null ||
    { echo "deps: apt-get install failed:$missing" >&2; exit 1; }
echo "deps: installed$missing"
