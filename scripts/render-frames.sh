#!/usr/bin/env bash
# render-frames.sh: renders a chunk of a movie's frames (for scripts/movie.sh) or of a picture's
# bands (for scripts/still.sh) in one tracer process (tracer --batch); the scripts run it directly
# or, across cores and machines, through GNU parallel.
#
#   render-frames.sh TRACER COUNT KIND N SCENE OUTPUT ROWS [N SCENE OUTPUT ROWS ...]
#
# KIND is "frame" or "band"; COUNT how many there are in all (for the progress lines); ROWS the
# band's rows a:b (-R a:b), or - for the whole picture. Runs TRACER -t $TRACER_OPTS --batch LIST
# from the first scene's directory, LIST naming each SCENE with its OUTPUT (and rows): the tracer
# reads each scene as -i SCENE, so its relative paths resolve against its own directory, and
# writes each OUTPUT whole or not at all. As each one finishes, its Tracetime figure goes to OUTPUT
# without its extension plus .time and a progress line to stderr, so what finished before an
# interruption counts as done. One that fails is named and the others go on; the status is then 1.
# When the tracer refuses its options (TRACER_OPTS; its status 2, nothing rendered) that is said
# once, after the tracer's own message, and the status is 2.
set -uo pipefail

usage() { echo "usage: render-frames.sh TRACER COUNT KIND N SCENE OUTPUT ROWS [N SCENE OUTPUT ROWS ...]" >&2; exit 2; }
[ $# -ge 7 ] && [ $((($# - 3) % 4)) -eq 0 ] || usage
tracer=$1; count=$2; kind=$3; shift 3
script=$([ "$kind" = band ] && echo still.sh || echo movie.sh)

list=$(mktemp "${TMPDIR:-/tmp}/tracer-batch.XXXXXX") || { echo "$script: cannot make a batch list" >&2; exit 1; }
trap 'rm -f "$list"' EXIT
numbers=(); scenes=(); outputs=(); rows=()
while [ $# -gt 0 ]; do
  numbers+=("$1"); scenes+=("$2"); outputs+=("$3"); rows+=("$4")
  if [ "$4" = - ]; then printf '%s\t%s\n' "$2" "$3"; else printf '%s\t%s\t%s\n' "$2" "$3" "$4"; fi >> "$list"
  shift 4
done

# Each "Tracetime: N ms OUTPUT" line marks OUTPUT done: its time is written beside it, then
# renamed, so an output counts as done only with its time, and never half-written.
# shellcheck disable=SC2086 # TRACER_OPTS is a list of options: split it into words.
(cd "$(dirname "${scenes[0]}")" && "$tracer" -t ${TRACER_OPTS:-} --batch "$list") |
  while IFS= read -r line; do
    ms=${line#Tracetime: }; ms=${ms%% ms *}
    output=${line#Tracetime: * ms }
    case "$ms" in '' | *[!0-9]*) continue ;; esac
    for i in "${!outputs[@]}"; do
      [ "${outputs[$i]}" = "$output" ] || continue
      time_file="${output%.*}.time"
      partial="$time_file.$(hostname 2>/dev/null || echo host).$$.partial"
      printf '%s\n' "$ms" > "$partial" && mv -f "$partial" "$time_file"
      where=${scenes[$i]}; [ "${rows[$i]}" = - ] || where="$where -R ${rows[$i]}"
      echo "$kind ${numbers[$i]}/$count: $where ($ms ms)" >&2
    done
  done
traced=${PIPESTATUS[0]}
if [ "$traced" -eq 2 ]; then
  echo "$script: the tracer refused TRACER_OPTS='${TRACER_OPTS:-}' (its message is above)" >&2
  exit 2
fi

status=0
for i in "${!outputs[@]}"; do
  if [ ! -f "${outputs[$i]%.*}.time" ] || [ "${scenes[$i]}" -nt "${outputs[$i]}" ]; then
    where=${scenes[$i]}; [ "${rows[$i]}" = - ] || where="$where (-R ${rows[$i]})"
    echo "$script: $kind ${numbers[$i]} failed: $where" >&2
    status=1
  fi
done
exit "$status"
