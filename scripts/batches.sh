#!/usr/bin/env bash
# batches.sh: sourced by movie.sh and still.sh; renders their frames or bands in batches.
#
#   render_batches TRACER COUNT KIND JOBS HOSTS CHUNK ITEM...
#
# Each ITEM is "N<TAB>SCENE<TAB>OUTPUT<TAB>ROWS" (ROWS a:b, or - for the whole picture). The items
# go in chunks of CHUNK to scripts/render-frames.sh, one tracer process (tracer --batch) a chunk:
# one after the other here, or — with JOBS > 1 or a HOSTS sshlogin file — through GNU parallel,
# each column of a chunk's line one argument. A failure stops new chunks from starting and those
# in flight finish; on hosts, a failed chunk is tried again (elsewhere, if another host is free)
# up to three times. Returns 1 when anything failed (render-frames.sh has named it), 2 when the
# tracer refused TRACER_OPTS.

render_batches() {
  local tracer=$1 count=$2 kind=$3 jobs=$4 hosts=$5 chunk=$6
  shift 6
  local render
  render="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/render-frames.sh"
  local items=("$@") chunks=() line i
  for ((i = 0; i < ${#items[@]}; i += chunk)); do
    line=$(printf '%s\t' "${items[@]:i:chunk}")
    chunks+=("${line%$'\t'}")
  done
  if [ "$jobs" -gt 1 ] || [ -n "$hosts" ]; then
    local options=(--will-cite --colsep '\t' --halt soon,fail=1 --jobs "$jobs" --env TRACER_OPTS)
    if [ -n "$hosts" ]; then options+=(--sshloginfile "$hosts" --retries 3); fi
    printf '%s\n' "${chunks[@]}" | parallel "${options[@]}" -q "$render" "$tracer" "$count" "$kind"
    # With --halt, parallel's status is the failed job's: 2 when the tracer refused its options.
    local status=$?
    [ "$status" -eq 0 ] || return "$((status == 2 ? 2 : 1))"
  else
    local job
    for line in "${chunks[@]}"; do
      IFS=$'\t' read -r -a job <<< "$line"
      "$render" "$tracer" "$count" "$kind" "${job[@]}" || return "$(($? == 2 ? 2 : 1))"
    done
  fi
}
