#!/bin/sh
# Usage: library_loaded.sh LUMEN LIBRARY yes|no SCENE SWITCH
# Runs LUMEN with SWITCH (--version, --help, or an output type for a tiny render of SCENE) and
# checks, with the dynamic loader's own log, whether the shared library whose name starts with
# LIBRARY (e.g. libOpenImageIO) was loaded.
set -eu
lumen=$1 library=$2 expect=$3 scene=$4 switch=$5
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
case $switch in
    --*) set -- "$switch" ;;
    *) mkdir "$work/img"; set -- "$scene" +W8 +H6 -A "$switch" "+O$work/img/" ;;
esac
LD_DEBUG=libs LD_DEBUG_OUTPUT="$work/ld" "$lumen" "$@" >"$work/stdout" 2>"$work/stderr" || {
    echo "lumen $* failed:"; cat "$work/stderr"; exit 1; }
if cat "$work"/ld.* | grep -q "/$library\.so"; then loaded=yes; else loaded=no; fi
case $switch in
    --*) ;;
    *) [ -n "$(ls "$work/img")" ] || { echo "no image written for $switch"; exit 1; } ;;
esac
if [ "$loaded" != "$expect" ]; then
    echo "lumen $*: $library loaded: $loaded, expected: $expect"
    exit 1
fi
echo "lumen $*: $library loaded: $loaded (as expected)"
