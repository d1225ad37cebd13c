#!/usr/bin/env bash
# movie.sh: renders the frames of a movie with the ray tracer, then encodes them with ffmpeg.
#
#   scripts/movie.sh TRACER FRAMES [OUTPUT]
#
# TRACER  the full path of the ray tracer program (called as: TRACER -t $TRACER_OPTS --batch LIST,
#         LIST naming SCENE<TAB>FRAME.png a line)
# FRAMES  a file naming the frames' scene files, one a line, in order; relative names are relative
#         to the directory FRAMES is in; blank lines and lines starting with # are skipped
# OUTPUT  the movie: .mpg (MPEG-1, the default movie.mpg) or .mp4 (H.264, plays in browsers)
#
# Each scene is read as the tracer's -i SCENE, so its relative texture paths resolve against its
# own directory; frames are rendered in batches, many in one tracer process (tracer --batch). The frames
# are kept as PNG (compressed) in OUTPUT's directory, in NAME-frames/ for a movie NAME.EXT, each with
# its Tracetime beside it; a second run renders only frames that are missing or older than their
# scene. When every frame is rendered the script prints "Total tracetime: N ms" (the sum of every
# frame's figure) on stdout, then encodes. Progress, one line a frame, goes to stderr.
#
# Environment: TRACER_OPTS (extra tracer options, e.g. "-x 640 -a 2"), MOVIE_FPS (default 25),
# MOVIE_JOBS (frames rendered at once on this machine, default 1) and MOVIE_HOSTS (a GNU parallel
# sshlogin file: render on those machines too, which must see TRACER, the scenes and the frame
# directory at the same paths). Either of the last two renders through GNU parallel. FARM_JOBS and
# FARM_HOSTS, as scripts/still.sh reads them, stand in for MOVIE_JOBS and MOVIE_HOSTS when those
# are not set. MOVIE_CHUNK sets how many frames one tracer process renders (default: all of them
# serially, up to 8 a job through GNU parallel).
# Exit status: 0 success, 1 a frame or the encoding failed, 2 a usage error (TRACER_OPTS's too).
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
jobs=${MOVIE_JOBS:-${FARM_JOBS:-1}}
hosts=${MOVIE_HOSTS:-${FARM_HOSTS:-}}
case "$jobs" in '' | *[!0-9]* | 0) die "MOVIE_JOBS (or FARM_JOBS) must be a positive whole number, got '$jobs'" 2 ;; esac
if [ -n "$hosts" ] && [ ! -r "$hosts" ]; then die "MOVIE_HOSTS (or FARM_HOSTS) '$hosts' is not a readable sshlogin file" 2; fi
if { [ "$jobs" -gt 1 ] || [ -n "$hosts" ]; } && ! command -v parallel >/dev/null 2>&1; then
  die "MOVIE_JOBS and MOVIE_HOSTS need GNU parallel: install it (Debian/Ubuntu: sudo apt-get install parallel; macOS: brew install parallel)"
fi
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

absolute() { case "$1" in /*) printf '%s\n' "$1" ;; *) printf '%s/%s\n' "$PWD" "$1" ;; esac; }
tracer=$(absolute "$tracer")
frames_dir_of_list=$(cd "$(dirname "$frames_file")" && pwd) || die "cannot enter the directory of '$frames_file'"
output=$(absolute "$output")
out_dir=$(dirname "$output")
[ -d "$out_dir" ] || die "the directory of OUTPUT '$out_dir' does not exist" 2
name=$(basename "$output")
frames_dir="$out_dir/${name%.*}-frames"
tmp_movie="$out_dir/.${name}.$$.partial.${name##*.}"
# A frames directory this run makes goes again if the run ends with nothing in it (a refused
# TRACER_OPTS, a list without scenes): rmdir leaves a directory holding frames alone.
made_frames_dir=false
[ -d "$frames_dir" ] || made_frames_dir=true
trap 'rm -f "$tmp_movie"; if $made_frames_dir; then rmdir "$frames_dir" 2>/dev/null; fi' EXIT
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

# The frames still to render: those missing, without their time, or older than their scene.
todo=()
for i in "${!scenes[@]}"; do
  n=$((i + 1))
  scene=${scenes[$i]}
  frame=$(printf '%s/frame-%06d.png' "$frames_dir" "$n")
  if [ -f "$frame" ] && [ -f "${frame%.png}.time" ] && [ ! "$scene" -nt "$frame" ]; then
    echo "frame $n/$count: $scene (done before, $(cat "${frame%.png}.time") ms)" >&2
  else
    todo+=("$n"$'\t'"$scene"$'\t'"$frame"$'\t'-)
  fi
done

# The frames are rendered in batches: one tracer process renders a chunk of frames
# (render-frames.sh, tracer --batch), so the JVM starts once a chunk and the later frames run on
# code the JIT has already compiled. Serially everything is one chunk; through GNU parallel the
# chunks are small enough to keep every job busy. MOVIE_CHUNK sets the frames a process.
export TRACER_OPTS="${TRACER_OPTS:-}"
if [ ${#todo[@]} -gt 0 ]; then
  farm=false
  if [ "$jobs" -gt 1 ] || [ -n "$hosts" ]; then farm=true; fi
  if [ -n "${MOVIE_CHUNK:-}" ]; then chunk=$MOVIE_CHUNK
  elif $farm; then chunk=$(((${#todo[@]} + 2 * jobs - 1) / (2 * jobs))); [ "$chunk" -le 8 ] || chunk=8
  else chunk=${#todo[@]}; fi
  case "$chunk" in '' | *[!0-9]* | 0) die "MOVIE_CHUNK must be a positive whole number, got '$chunk'" 2 ;; esac
  # shellcheck source=scripts/batches.sh
  . "$here/batches.sh"
  render_batches "$tracer" "$count" frame "$jobs" "$hosts" "$chunk" "${todo[@]}" || {
    status=$?
    [ "$status" -ne 2 ] || exit 2 # the tracer refused TRACER_OPTS, as render-frames.sh said
    if $farm; then die "the movie stopped because a frame failed; run again to render what is missing"; fi
    exit 1
  }
fi

# The total: every frame's figure, wherever and whenever it was rendered.
total=0
for i in "${!scenes[@]}"; do
  time_file=$(printf '%s/frame-%06d.time' "$frames_dir" "$((i + 1))")
  ms=$(cat "$time_file" 2>/dev/null) || die "frame $((i + 1)) has no time: $time_file"
  total=$((total + ms))
done

echo "Total tracetime: $total ms"

command -v ffmpeg >/dev/null 2>&1 ||
  die "ffmpeg is not installed, so the frames in '$frames_dir' were not encoded: install it (Debian/Ubuntu: sudo apt-get install ffmpeg; macOS: brew install ffmpeg) and run this again"

# Frames of odd width or height are padded by one pixel: the encoders need even sizes.
if ! ffmpeg -hide_banner -loglevel error -y -framerate "$fps" -i "$frames_dir/frame-%06d.png" -frames:v "$count" \
  -vf "pad=ceil(iw/2)*2:ceil(ih/2)*2" -r "$fps" "${codec[@]}" "$tmp_movie" </dev/null; then
  die "ffmpeg could not encode '$output'"
fi
mv "$tmp_movie" "$output" || die "cannot write '$output'"
echo "movie.sh: wrote $output ($count frames, $fps frames a second)" >&2
