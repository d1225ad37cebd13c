#!/usr/bin/env bash
# movie.sh: renders the frames of a movie with the ray tracer, then encodes them with ffmpeg.
#
#   scripts/movie.sh TRACER FRAMES [OUTPUT]
#
# TRACER  the full path of the ray tracer program (called as: TRACER -t $TRACER_OPTS FRAME.png < SCENE)
# FRAMES  a file naming the frames' scene files, one a line, in order; relative names are relative
#         to the directory FRAMES is in; blank lines and lines starting with # are skipped
# OUTPUT  the movie: .mpg (MPEG-1, the default movie.mpg) or .mp4 (H.264, plays in browsers)
#
# Each scene is rendered from its own directory, so its relative texture paths work. The frames
# are kept as PNG (compressed) in OUTPUT's directory, in NAME-frames/ for a movie NAME.EXT, each with
# its Tracetime beside it; a second run renders only frames that are missing or older than their
# scene. When every frame is rendered the script prints "Total tracetime: N ms" (the sum of every
# frame's figure) on stdout, then encodes. Progress, one line a frame, goes to stderr.
#
# Environment: TRACER_OPTS (extra tracer options, e.g. "-x 640 -a 2"), MOVIE_FPS (default 25).
# Exit status: 0 success, 1 a frame or the encoding failed, 2 a usage error.
set -uo pipefail

usage() { echo "usage: movie.sh TRACER FRAMES [OUTPUT]" >&2; exit 2; }
die() { echo "movie.sh: $1" >&2; exit "${2:-1}"; }

[ $# -ge 2 ] && [ $# -le 3 ] || usage
tracer=$1
frames_file=$2
output=${3:-movie.mpg}
fps=${MOVIE_FPS:-25}

[ -x "$tracer" ] && [ ! -d "$tracer" ] || die "TRACER '$tracer' is not an executable program" 2
[ -f "$frames_file" ] && [ -r "$frames_file" ] || die "FRAMES '$frames_file' is not a readable file" 2
case "$output" in
  *.mpg | *.mpeg | *.MPG | *.MPEG) codec=(-c:v mpeg1video -q:v 2) ;;
  *.mp4 | *.MP4) codec=(-c:v libx264 -preset medium -crf 20 -pix_fmt yuv420p -movflags +faststart) ;;
  *) die "OUTPUT '$output' must end in .mpg (MPEG-1) or .mp4 (H.264)" 2 ;;
esac
case "$fps" in '' | *[!0-9]* | 0) die "MOVIE_FPS must be a positive whole number, got '$fps'" 2 ;; esac

absolute() { case "$1" in /*) printf '%s\n' "$1" ;; *) printf '%s/%s\n' "$PWD" "$1" ;; esac; }
tracer=$(absolute "$tracer")
frames_dir_of_list=$(cd "$(dirname "$frames_file")" && pwd) || die "cannot enter the directory of '$frames_file'"
output=$(absolute "$output")
out_dir=$(dirname "$output")
[ -d "$out_dir" ] || die "the directory of OUTPUT '$out_dir' does not exist" 2
name=$(basename "$output")
frames_dir="$out_dir/${name%.*}-frames"
mkdir -p "$frames_dir" || die "cannot create '$frames_dir'"

# The scene files, in order, as absolute paths.
scenes=()
while IFS= read -r line || [ -n "$line" ]; do
  line=${line%$'\r'}
  case "$line" in '' | '#'*) continue ;; esac
  case "$line" in /*) scenes+=("$line") ;; *) scenes+=("$frames_dir_of_list/$line") ;; esac
done < "$frames_file"
count=${#scenes[@]}
[ "$count" -gt 0 ] || die "FRAMES '$frames_file' names no scene files"

# Render each frame unless it is already there and newer than its scene.
total=0
for i in "${!scenes[@]}"; do
  n=$((i + 1))
  scene=${scenes[$i]}
  frame=$(printf '%s/frame-%06d.png' "$frames_dir" "$n")
  time_file="${frame%.png}.time"
  [ -f "$scene" ] || die "frame $n: scene file '$scene' does not exist"
  if [ -f "$frame" ] && [ -f "$time_file" ] && [ ! "$scene" -nt "$frame" ]; then
    ms=$(cat "$time_file")
    echo "frame $n/$count: $scene (done before, $ms ms)" >&2
  else
    # shellcheck disable=SC2086 # TRACER_OPTS is a list of options: split it into words.
    if ! result=$(cd "$(dirname "$scene")" && "$tracer" -t ${TRACER_OPTS:-} "$frame" < "$scene"); then
      die "frame $n failed: $scene"
    fi
    ms=$(printf '%s\n' "$result" | sed -n 's/^Tracetime: \([0-9][0-9]*\) ms$/\1/p')
    [ -n "$ms" ] || die "frame $n: the tracer printed no 'Tracetime: N ms' for $scene"
    printf '%s\n' "$ms" > "$time_file.partial" && mv "$time_file.partial" "$time_file" ||
      die "frame $n: cannot write '$time_file'"
    echo "frame $n/$count: $scene ($ms ms)" >&2
  fi
  total=$((total + ms))
done

echo "Total tracetime: $total ms"

command -v ffmpeg >/dev/null 2>&1 ||
  die "ffmpeg is not installed, so the frames in '$frames_dir' were not encoded: install it (Debian/Ubuntu: sudo apt-get install ffmpeg; macOS: brew install ffmpeg) and run this again"

# Frames of odd width or height are padded by one pixel: the encoders need even sizes.
tmp_movie="$out_dir/.${name}.$$.partial.${name##*.}"
trap 'rm -f "$tmp_movie"' EXIT
if ! ffmpeg -hide_banner -loglevel error -y -framerate "$fps" -i "$frames_dir/frame-%06d.png" -frames:v "$count" \
  -vf "pad=ceil(iw/2)*2:ceil(ih/2)*2" -r "$fps" "${codec[@]}" "$tmp_movie" </dev/null; then
  die "ffmpeg could not encode '$output'"
fi
mv "$tmp_movie" "$output" || die "cannot write '$output'"
echo "movie.sh: wrote $output ($count frames, $fps frames a second)" >&2
