#!/usr/bin/env bash
# render-frames.sh: renders a chunk of a movie's frames in one tracer process (tracer --batch), for
# scripts/movie.sh, which runs it directly or, across cores and machines, through GNU parallel.
#
#   render-frames.sh TRACER COUNT N SCENE FRAME [N SCENE FRAME ...]
#
# Runs TRACER -t $TRACER_OPTS --batch LIST from the first scene's directory, LIST naming each SCENE
# with its FRAME (the tracer reads each scene as -i SCENE, so its relative paths resolve against
# its own directory, and writes each FRAME whole or not at all). As each frame finishes, its
# Tracetime figure goes to FRAME without .png plus .time and a progress line to stderr, so frames
# finished before an interruption count as done. A frame that fails is named and the others go on;
# the status is then 1.
set -uo pipefail

usage() { echo "usage: render-frames.sh TRACER COUNT N SCENE FRAME [N SCENE FRAME ...]" >&2; exit 2; }
[ $# -ge 5 ] && [ $((($# - 2) % 3)) -eq 0 ] || usage
tracer=$1; count=$2; shift 2

list=$(mktemp "${TMPDIR:-/tmp}/tracer-batch.XXXXXX") || { echo "movie.sh: cannot make a batch list" >&2; exit 1; }
trap 'rm -f "$list"' EXIT
numbers=(); scenes=(); frames=()
while [ $# -gt 0 ]; do
  numbers+=("$1"); scenes+=("$2"); frames+=("$3")
  printf '%s\t%s\n' "$2" "$3" >> "$list"
  shift 3
done

# Each "Tracetime: N ms FRAME" line marks FRAME done: its time is written beside it, then renamed,
# so a frame counts as done only with its time, and never half-written.
# shellcheck disable=SC2086 # TRACER_OPTS is a list of options: split it into words.
(cd "$(dirname "${scenes[0]}")" && "$tracer" -t ${TRACER_OPTS:-} --batch "$list") |
  while IFS= read -r line; do
    ms=${line#Tracetime: }; ms=${ms%% ms *}
    frame=${line#Tracetime: * ms }
    case "$ms" in '' | *[!0-9]*) continue ;; esac
    for i in "${!frames[@]}"; do
      [ "${frames[$i]}" = "$frame" ] || continue
      time_file="${frame%.png}.time"
      partial="$time_file.$(hostname 2>/dev/null || echo host).$$.partial"
      printf '%s\n' "$ms" > "$partial" && mv -f "$partial" "$time_file"
      echo "frame ${numbers[$i]}/$count: ${scenes[$i]} ($ms ms)" >&2
    done
  done

status=0
for i in "${!frames[@]}"; do
  if [ ! -f "${frames[$i]%.png}.time" ] || [ "${scenes[$i]}" -nt "${frames[$i]}" ]; then
    echo "movie.sh: frame ${numbers[$i]} failed: ${scenes[$i]}" >&2
    status=1
  fi
done
exit "$status"
