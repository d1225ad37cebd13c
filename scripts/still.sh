#!/usr/bin/env bash
# still.sh: renders one picture in horizontal bands — on this machine's cores and on other machines
# through GNU parallel — and joins the bands into the picture a single run would make.
#
#   scripts/still.sh TRACER SCENE OUTPUT
#
# TRACER  the full path of the ray tracer program
# SCENE   the scene file; it is rendered from its own directory, so relative texture and mesh
#         paths work (as movie.sh renders frames)
# OUTPUT  the picture: PNG for .png (any case), floating point for .pfm or .exr (any case; the
#         bands are then .pfm), binary PPM otherwise, written whole or not at all
#
# Each band is rendered by TRACER -t $TRACER_OPTS as -R a:b, in batches (many bands in one tracer
# process: tracer --batch), and kept, with its Tracetime, in
# NAME-bands/ beside OUTPUT (NAME.EXT), so a second run after a failure renders only the bands
# that are missing; bands of an older scene or of other TRACER_OPTS are thrown away first. When
# every band is rendered the script prints "Total tracetime: N ms" (the sum of the bands' figures)
# on stdout and writes OUTPUT with TRACER --stack. Progress, one line a band, goes to stderr.
#
# Environment: TRACER_OPTS (tracer options for every band, e.g. "-x 3840 -a 3"; not -R or -i),
# FARM_JOBS (bands rendered at once on this machine, default 1), FARM_HOSTS (a GNU parallel
# sshlogin file: render on those machines too, which must see TRACER, the scene and OUTPUT's
# directory at the same paths), FARM_BANDS (how many bands; default 4 for each slot, so that fast
# and slow hosts finish together, and never more than the picture's rows).
# Exit status: 0 success, 1 a band or the joining failed, 2 a usage error (TRACER_OPTS's too).
set -uo pipefail

usage() { echo "usage: still.sh TRACER SCENE OUTPUT" >&2; exit 2; }
die() { echo "still.sh: $1" >&2; exit "${2:-1}"; }
whole() { case "$2" in '' | *[!0-9]* | 0) die "$1 must be a positive whole number, got '$2'" 2 ;; esac; }

[ $# -eq 3 ] || usage
tracer=$1
scene=$2
output=$3
jobs=${FARM_JOBS:-1}
hosts=${FARM_HOSTS:-}

[ -x "$tracer" ] && [ ! -d "$tracer" ] || die "TRACER '$tracer' is not an executable program" 2
[ -f "$scene" ] && [ -r "$scene" ] || die "SCENE '$scene' is not a readable file" 2
whole FARM_JOBS "$jobs"
[ -z "${FARM_BANDS:-}" ] || whole FARM_BANDS "$FARM_BANDS"
if [ -n "$hosts" ] && [ ! -r "$hosts" ]; then die "FARM_HOSTS '$hosts' is not a readable sshlogin file" 2; fi
if { [ "$jobs" -gt 1 ] || [ -n "$hosts" ]; } && ! command -v parallel >/dev/null 2>&1; then
  die "FARM_JOBS and FARM_HOSTS need GNU parallel: install it (Debian/Ubuntu: sudo apt-get install parallel; macOS: brew install parallel)"
fi
if [ -n "$hosts" ] && ! command -v ssh >/dev/null 2>&1; then
  die "FARM_HOSTS needs ssh: install it (Debian/Ubuntu: sudo apt-get install openssh-client)"
fi
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

absolute() { case "$1" in /*) printf '%s\n' "$1" ;; *) printf '%s/%s\n' "$PWD" "$1" ;; esac; }
tracer=$(absolute "$tracer")
scene=$(absolute "$scene")
output=$(absolute "$output")
out_dir=$(dirname "$output")
[ -d "$out_dir" ] || die "the directory of OUTPUT '$out_dir' does not exist" 2
name=$(basename "$output")
bands_dir="$out_dir/${name%.*}-bands"
# Bands are 8-bit PPM for an 8-bit picture, 32-bit float PFM for a .pfm or .exr one: --stack joins
# bands of one kind, and the float bands keep path mode's unclamped mean.
case "$name" in *.[pP][fF][mM] | *.[eE][xX][rR]) kind=pfm ;; *) kind=ppm ;; esac
export TRACER_OPTS="${TRACER_OPTS:-}"

# The picture's size, as the tracer resolves it from the scene and the options.
# shellcheck disable=SC2086 # TRACER_OPTS is a list of options: split it into words.
size=$(cd "$(dirname "$scene")" && "$tracer" --size $TRACER_OPTS < "$scene")
case $? in
  0) ;;
  2) die "the tracer refused TRACER_OPTS='$TRACER_OPTS' (its message is above)" 2 ;;
  *) die "the tracer cannot render '$scene' with TRACER_OPTS='$TRACER_OPTS' (its message is above)" ;;
esac
read -r width height <<< "$size"
whole "the picture's height" "$height"

# More bands than slots, so that a fast host takes more of them than a slow one.
slots=$jobs
if [ -n "$hosts" ]; then
  slots=0
  while read -r login _; do
    case "$login" in '' | '#'*) continue ;; */*) slots=$((slots + ${login%%/*})) ;; *) slots=$((slots + jobs)) ;; esac
  done < "$hosts"
  [ "$slots" -gt 0 ] || die "FARM_HOSTS '$hosts' names no hosts" 2
fi
bands=${FARM_BANDS:-$((4 * slots))}
[ "$bands" -le "$height" ] || bands=$height

# Finished bands are kept only for the same scene, picture and options.
key="$width $height $bands $kind $TRACER_OPTS"
mkdir -p "$bands_dir" || die "cannot create '$bands_dir'"
if [ "$(cat "$bands_dir/bands.key" 2>/dev/null)" != "$key" ] || [ "$scene" -nt "$bands_dir/bands.key" ]; then
  rm -f "$bands_dir"/band-*.ppm "$bands_dir"/band-*.pfm "$bands_dir"/band-*.time
  printf '%s\n' "$key" > "$bands_dir/bands.key" || die "cannot write '$bands_dir/bands.key'"
fi

# Band k holds rows ⌊k·Y/bands⌋ up to ⌊(k + 1)·Y/bands⌋.
files=()
todo=()
for ((k = 0; k < bands; k++)); do
  a=$((k * height / bands))
  b=$(((k + 1) * height / bands))
  band=$(printf '%s/band-%04d.%s' "$bands_dir" "$((k + 1))" "$kind")
  files+=("$band")
  if [ -f "$band" ] && [ -f "${band%.*}.time" ]; then
    echo "band $((k + 1))/$bands: rows $a:$b (done before, $(cat "${band%.*}.time") ms)" >&2
  else
    todo+=("$((k + 1))"$'\t'"$scene"$'\t'"$band"$'\t'"$a:$b")
  fi
done

# The bands are rendered in batches, as movie.sh renders frames: one tracer process renders a
# chunk of bands (render-frames.sh, tracer --batch), so the JVM starts, and compiles the tracer's
# code, once a chunk rather than once a band. Serially all the bands are one chunk; through GNU
# parallel each chunk is about half a slot's share, so that the bands still even out the slots.
if [ ${#todo[@]} -gt 0 ]; then
  farm=false
  if [ "$jobs" -gt 1 ] || [ -n "$hosts" ]; then farm=true; fi
  if $farm; then chunk=$(((${#todo[@]} + 2 * slots - 1) / (2 * slots))); else chunk=${#todo[@]}; fi
  # shellcheck source=scripts/batches.sh
  . "$here/batches.sh"
  render_batches "$tracer" "$bands" band "$jobs" "$hosts" "$chunk" "${todo[@]}" || {
    status=$?
    [ "$status" -ne 2 ] || exit 2 # the tracer refused TRACER_OPTS, as render-frames.sh said
    if $farm; then die "the picture stopped because a band failed; run again to render what is missing"; fi
    exit 1
  }
fi

# The total: every band's figure, wherever and whenever it was rendered.
total=0
stack=()
for band in "${files[@]}"; do
  ms=$(cat "${band%.*}.time" 2>/dev/null) || die "band $band has no time"
  total=$((total + ms))
  stack+=(--stack "$band")
done
echo "Total tracetime: $total ms"

"$tracer" "${stack[@]}" "$output" || die "cannot join the bands into '$output'"
echo "still.sh: wrote $output ($width×$height, $bands bands)" >&2
