#!/usr/bin/env bash
# ab.sh: a steady-state A/B comparison of tracer jars on one scene (docs/performance.md, round 12).
#
#   scripts/ab.sh [--runs N] [--frames N] [--threads N] SCENE.xml JAR... [-- TRACER-OPTIONS...]
#
# Each run starts every JAR in turn (alternating, so a slow spell of the machine hits them all)
# and has it render SCENE --frames times (default 4) in one JVM (`--batch`), on --threads threads
# (default 1); the run's figure is the best Tracetime of the frames after the first, so the JIT's
# warm-up and start-up are left out and what is compared is the compiled code. Prints one line
# per jar: its Tracetime in ms, a figure per run (default 3 runs). TRACER-OPTIONS go to every
# render (e.g. -x 1280 -y 720 -g srgb). The Java is $JAVA (default: java on PATH), started as
# `java OPTIONS -jar JAR`, OPTIONS the launcher's default (tracer_default_jvm in
# launcher/launcher.sh; with --sun-misc-unsafe-memory-access=allow on 23+).
# The pictures go to a temporary directory, removed at the end; with --keep DIR they go to DIR
# (frame f of the i-th jar, from 0, as i-f.png), to compare the jars' pictures with cmp.
set -euo pipefail

runs=3 frames=4 threads=1 keep=
while [ $# -gt 0 ]; do
  case "$1" in
    --runs) runs=${2:-}; shift $(( $# > 1 ? 2 : 1 )) ;;
    --frames) frames=${2:-}; shift $(( $# > 1 ? 2 : 1 )) ;;
    --threads) threads=${2:-}; shift $(( $# > 1 ? 2 : 1 )) ;;
    --keep) keep=${2:-}; shift $(( $# > 1 ? 2 : 1 )) ;;
    *) break ;;
  esac
done
if [ $# -lt 2 ]; then
  echo "usage: ab.sh [--runs N] [--frames N] [--threads N] [--keep DIR] SCENE.xml JAR... [-- OPTIONS...]" >&2
  exit 2
fi
for n in "$runs" "$frames" "$threads"; do
  case "$n" in '' | *[!0-9]*) echo "ab.sh: --runs, --frames and --threads take whole numbers" >&2; exit 2 ;; esac
done
(( frames >= 2 && runs >= 1 && threads >= 1 )) || { echo "ab.sh: needs --frames ≥ 2, --runs ≥ 1, --threads ≥ 1" >&2; exit 2; }
scene=$1; shift
jars=()
while [ $# -gt 0 ] && [ "$1" != -- ]; do jars+=("$1"); shift; done
[ $# -gt 0 ] && shift
[ -f "$scene" ] || { echo "ab.sh: no scene '$scene'" >&2; exit 1; }
for jar in "${jars[@]}"; do [ -f "$jar" ] || { echo "ab.sh: no jar '$jar'" >&2; exit 1; }; done

java=${JAVA:-java}
# The launcher's default JVM options (sourcing it defines its functions and constants, nothing runs).
# shellcheck source=launcher/launcher.sh
. "$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/launcher/launcher.sh"
read -r -a flags <<<"$tracer_default_jvm"
if "$java" --sun-misc-unsafe-memory-access=allow -version >/dev/null 2>&1; then
  flags+=(--sun-misc-unsafe-memory-access=allow)
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
out=${keep:-$work}
mkdir -p "$out"
scene=$(cd "$(dirname "$scene")" && pwd)/$(basename "$scene")

declare -a figures
for ((r = 1; r <= runs; r++)); do
  for i in "${!jars[@]}"; do
    list=$work/list-$i
    : >"$list"
    for ((f = 1; f <= frames; f++)); do printf '%s\t%s\n' "$scene" "$out/$i-$f.png" >>"$list"; done
    times=$("$java" "${flags[@]}" -jar "${jars[$i]}" -t -p "$threads" "$@" --batch "$list") || {
      echo "ab.sh: ${jars[$i]} failed on $scene" >&2
      exit 1
    }
    best=$(printf '%s\n' "$times" | sed -n 's/^Tracetime: \([0-9]*\) ms.*/\1/p' | tail -n +2 | sort -n | head -1)
    figures[$i]="${figures[$i]:-} $best"
  done
done
for i in "${!jars[@]}"; do
  echo "${jars[$i]}:${figures[$i]}"
done
