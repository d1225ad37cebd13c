#!/usr/bin/env bash
# alternate.sh: whole runs of two or more checkouts of the tracer, alternating (docs/performance.md,
# round 21).
#
#   scripts/alternate.sh [--runs N] SCENE.xml CHECKOUT... [-- TRACER-OPTIONS...]
#
# Each round runs every CHECKOUT's own ./tracer (its launcher, its jar, its start-up cache) on
# SCENE in turn, from the scene's directory (where its meshes and textures are found), with -t
# and TRACER-OPTIONS (e.g. -p 2 -x 1280 -y 720), so that a slow spell of the machine falls on
# all of them; N rounds (default 5). Prints one line per checkout: the wall time in ms of each
# round with its Tracetime in brackets, then the median wall time. Each
# checkout renders the scene once at 8x8 first, outside the timings, so its jar is built and its
# start-up cache trained before the first round. The pictures of the last round are compared
# pixel by pixel (each read back by the first checkout's `tracer --stack` into a PPM), so a
# change of the PNG's encoding alone is no difference; a difference is reported on standard
# error (the exit status stays 0: a difference may be the point of the comparison).
#
# The start-up cache is part of what is compared: each checkout's is trained once, and its
# profiles carry a bias of their own (round 21 measured medians moving by 10% when the caches
# were trained again). Delete the caches (target/scala-3.8.3/*.aot) and run again before trusting
# a small difference.
set -euo pipefail

runs=5
while [ $# -gt 0 ]; do
  case "$1" in
    --runs) runs=${2:-}; shift $(( $# > 1 ? 2 : 1 )) ;;
    *) break ;;
  esac
done
usage() {
  echo "usage: alternate.sh [--runs N] SCENE.xml CHECKOUT... [-- TRACER-OPTIONS...]" >&2
  exit 2
}
case "$runs" in '' | *[!0-9]* | 0) echo "alternate.sh: --runs takes a whole number from 1" >&2; exit 2 ;; esac
[ $# -ge 2 ] || usage
scene=$1; shift
checkouts=()
while [ $# -gt 0 ] && [ "$1" != -- ]; do checkouts+=("$1"); shift; done
[ $# -gt 0 ] && shift
[ ${#checkouts[@]} -ge 1 ] || usage
[ -f "$scene" ] || { echo "alternate.sh: no scene '$scene'" >&2; exit 1; }
for c in "${checkouts[@]}"; do
  [ -x "$c/tracer" ] || { echo "alternate.sh: '$c' has no ./tracer" >&2; exit 2; }
done
# Every run starts in the scene's directory (its meshes and textures are relative to it), so the
# checkouts are found by their full paths.
homes=()
for c in "${checkouts[@]}"; do homes+=("$(cd "$c" && pwd)"); done
cd "$(dirname "$scene")"
scene=$PWD/${scene##*/}

out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

# render I CHECKOUT OPTIONS...: one run of checkout number I; prints "wall(Tracetime)".
render() {
  local i=$1 checkout=$2 start end trace
  shift 2
  start=$(date +%s%N)
  if ! trace=$("${homes[$i]}/tracer" -t "$@" "$out/$i.png" < "$scene"); then
    echo "alternate.sh: $checkout failed" >&2
    exit 1
  fi
  end=$(date +%s%N)
  trace=$(sed -n 's/^Tracetime: \([0-9]*\) ms$/\1/p' <<< "$trace")
  echo "$(( (end - start) / 1000000 ))(${trace:--})"
}

for i in "${!checkouts[@]}"; do
  "${homes[$i]}/tracer" -x 8 -y 8 "$out/warm-$i.png" < "$scene" > /dev/null ||
    { echo "alternate.sh: ${checkouts[$i]} failed" >&2; exit 1; }
done
# same_pixels A.png B.png: whether the two pictures hold the same pixels, whatever their encoding.
same_pixels() {
  "${homes[0]}/tracer" --stack "$1" "$1.ppm" > /dev/null &&
    "${homes[0]}/tracer" --stack "$2" "$2.ppm" > /dev/null &&
    cmp -s "$1.ppm" "$2.ppm"
}

results=()
for ((round = 0; round < runs; round++)); do
  for i in "${!checkouts[@]}"; do
    run=$(render "$i" "${checkouts[$i]}" "$@") || exit 1
    results[i]="${results[i]:-} $run"
  done
done
for i in "${!checkouts[@]}"; do
  # The median of the wall times (the lower middle one for an even count).
  median=$(tr ' ' '\n' <<< "${results[i]}" | sed -n 's/^\([0-9]*\)(.*/\1/p' | sort -n |
    awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }')
  echo "${checkouts[$i]}:${results[i]} median $median"
  if [ "$i" -gt 0 ] && ! same_pixels "$out/0.png" "$out/$i.png"; then
    echo "alternate.sh: ${checkouts[$i]}'s picture differs from ${checkouts[0]}'s" >&2
  fi
done
