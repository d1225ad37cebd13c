#!/usr/bin/env bash
# render-frame.sh: renders one frame of a movie for scripts/movie.sh, or one band of a picture for
# scripts/still.sh, which run it directly or, across cores and machines, through GNU parallel.
#
#   render-frame.sh TRACER SCENE FRAME N COUNT [KIND [ARGS...]]
#
# Runs TRACER -t $TRACER_OPTS ARGS FRAME < SCENE from SCENE's directory (the tracer writes FRAME
# whole or not at all), then writes the Tracetime figure to FRAME without its extension plus .time,
# and prints one progress line on stderr. KIND is "frame" (the default, for movie.sh) or "band"
# (for still.sh, with ARGS such as -R a:b). On failure it names the frame or band and exits 1.
set -uo pipefail

[ $# -ge 5 ] || { echo "usage: render-frame.sh TRACER SCENE FRAME N COUNT [KIND [ARGS...]]" >&2; exit 2; }
tracer=$1; scene=$2; frame=$3; n=$4; count=$5; kind=${6:-frame}
shift $(($# < 6 ? $# : 6))
time_file="${frame%.*}.time"
script=$([ "$kind" = band ] && echo still.sh || echo movie.sh)

fail() { echo "$script: $kind $n failed: $scene${*:+ ($*)}" >&2; exit 1; }

[ -f "$scene" ] || fail "no such scene file"
# shellcheck disable=SC2086 # TRACER_OPTS is a list of options: split it into words.
result=$(cd "$(dirname "$scene")" && "$tracer" -t ${TRACER_OPTS:-} "$@" "$frame" < "$scene") || fail "$@"
ms=$(printf '%s\n' "$result" | sed -n 's/^Tracetime: \([0-9][0-9]*\) ms$/\1/p')
[ -n "$ms" ] || fail "the tracer printed no 'Tracetime: N ms'"
# Written beside, then renamed: a frame counts as done only with its time, and never half-written.
partial="$time_file.$(hostname 2>/dev/null || echo host).$$.partial"
{ printf '%s\n' "$ms" > "$partial" && mv -f "$partial" "$time_file"; } || fail "cannot write $time_file"
echo "$kind $n/$count: $scene${*:+ $*} ($ms ms)" >&2
