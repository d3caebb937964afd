#!/bin/sh
# Usage: oiio_loaded.sh LUMEN yes|no SCENE SWITCH
# Runs LUMEN with SWITCH (--version, --help, or an output type for a tiny render of SCENE) and
# checks, with the dynamic loader's own log, whether libOpenImageIO was loaded.
set -eu
lumen=$1 expect=$2 scene=$3 switch=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
case $switch in
    --*) set -- "$switch" ;;
    *) mkdir "$work/img"; set -- "$scene" +W8 +H6 -A "$switch" "+O$work/img/" ;;
esac
LD_DEBUG=libs LD_DEBUG_OUTPUT="$work/ld" "$lumen" "$@" >"$work/stdout" 2>"$work/stderr" || {
    echo "lumen $* failed:"; cat "$work/stderr"; exit 1; }
if cat "$work"/ld.* | grep -q 'libOpenImageIO\.so'; then loaded=yes; else loaded=no; fi
case $switch in
    --*) ;;
    *) [ -n "$(ls "$work/img")" ] || { echo "no image written for $switch"; exit 1; } ;;
esac
if [ "$loaded" != "$expect" ]; then
    echo "lumen $*: OpenImageIO loaded: $loaded, expected: $expect"
    exit 1
fi
echo "lumen $*: OpenImageIO loaded: $loaded (as expected)"
