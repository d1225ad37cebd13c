#!/usr/bin/env bash
# render-frame.sh: renders one frame of a movie for scripts/movie.sh, which runs it directly or,
# across cores and machines, through GNU parallel.
#
#   render-frame.sh TRACER SCENE FRAME N COUNT
#
# Runs TRACER -t $TRACER_OPTS FRAME < SCENE from SCENE's directory (the tracer writes FRAME whole or
# not at all), then writes the frame's Tracetime figure to FRAME without .png plus .time, and prints
# one progress line on stderr. On failure it names the frame and exits 1.
set -uo pipefail

[ $# -eq 5 ] || { echo "usage: render-frame.sh TRACER SCENE FRAME N COUNT" >&2; exit 2; }
tracer=$1; scene=$2; frame=$3; n=$4; count=$5
time_file="${frame%.png}.time"

fail() { echo "movie.sh: frame $n failed: $scene${1:+ ($1)}" >&2; exit 1; }

[ -f "$scene" ] || fail "no such scene file"
# shellcheck disable=SC2086 # TRACER_OPTS is a list of options: split it into words.
result=$(cd "$(dirname "$scene")" && "$tracer" -t ${TRACER_OPTS:-} "$frame" < "$scene") || fail
ms=$(printf '%s\n' "$result" | sed -n 's/^Tracetime: \([0-9][0-9]*\) ms$/\1/p')
[ -n "$ms" ] || fail "the tracer printed no 'Tracetime: N ms'"
# Written beside, then renamed: a frame counts as done only with its time, and never half-written.
partial="$time_file.$(hostname 2>/dev/null || echo host).$$.partial"
{ printf '%s\n' "$ms" > "$partial" && mv -f "$partial" "$time_file"; } || fail "cannot write $time_file"
echo "frame $n/$count: $scene ($ms ms)" >&2
