# Sourced by the benchmarks that time lumen against POV-Ray with /usr/bin/time: checks both
# are there and makes $work, a scratch folder removed on exit.
command -v povray >/dev/null || { echo "povray missing: tools/install-deps.sh" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "/usr/bin/time missing (package time)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
