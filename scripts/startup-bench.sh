#!/usr/bin/env bash
# startup-bench.sh: the start-up set-ups of the launcher compared, whole process, paired runs.
#
#   scripts/startup-bench.sh [--runs N] [SCENE:WxH ...]
#
# For each row (a benchmark scene and a picture size; default the five rows of docs/performance.md,
# "Start-up: JDK and cache") it runs every set-up below once per round, N rounds (default 5), one
# after the other, so that each round meets the same machine, and prints a Markdown table of the
# median wall time of each in seconds (bash's `time`, whole `java` process, -p 2). The set-ups:
#
#   17 cds        JDK 17 with the AppCDS archive of the launcher's training run (the launcher's
#                 choice for JDK 17 to 24)
#   25 none       JDK 25, no cache (TRACER_CACHE=off)
#   25 cds        JDK 25 with an AppCDS archive of the same training (TRACER_CACHE=cds)
#   25 aot-one    JDK 25, AOT cache trained on one 48x27 render of the showcase scene (round 3's)
#   25 aot-64     JDK 25, AOT cache trained on the launcher's training batch at 64 pixels wide
#   25 aot        JDK 25, AOT cache trained on the launcher's batch at 320 wide (the launcher's)
#   25 aot+coh    the same with compact object headers (-XX:+UseCompactObjectHeaders)
#
# The caches are made in a scratch directory from the built jar; the JVM options are the
# launcher's default (tracer_default_jvm in launcher/launcher.sh, and
# --sun-misc-unsafe-memory-access=allow on JDK 25).
# JDK17 and JDK25 name the two Javas (defaults: the Debian and Temurin paths of this project's
# machines). The scenes are tracer.demo.BenchScenes' (scenes/bench/, generated on first use, as
# scripts/bench.sh does) and triangles-20000.xml, the 20,000-triangle terrain written as
# <triangle> elements (5.9 MB), made here from mesh-20000.obj.
set -euo pipefail

home=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
runs=5
rows=()
while [ $# -gt 0 ]; do
  case "$1" in
    --runs) runs=$2; shift ;;
    *:*x*) rows+=("$1") ;;
    *) echo "usage: startup-bench.sh [--runs N] [SCENE:WxH ...]" >&2; exit 2 ;;
  esac
  shift
done
if [ ${#rows[@]} -eq 0 ]; then
  rows=(few:1280x720 spheres:1280x720 triangles-20000:1280x720 few:32x24 triangles-20000:32x18)
fi
j17=${JDK17:-/usr/lib/jvm/java-17-openjdk-amd64}/bin/java
j25=${JDK25:-/usr/lib/jvm/temurin-25-jdk-amd64}/bin/java
for j in "$j17" "$j25"; do [ -x "$j" ] || { echo "startup-bench.sh: no $j" >&2; exit 1; }; done

"$home/tracer" --help >/dev/null # builds the jar if needed, outside the timings
dir="$home/scenes/bench"
if [ ! -f "$dir/mesh-20000.obj" ]; then
  echo "startup-bench.sh: generating the benchmark scenes in $dir" >&2
  "$home/scripts/demo.sh" tracer.demo.BenchScenes "$dir"
fi
if [ ! -f "$dir/triangles-20000.xml" ]; then
  # The OBJ terrain's faces as <triangle> elements, in mesh-20000.xml's frame and surface.
  awk '
    FNR == NR { if ($1 == "v") v[++n] = $2 " " $3 " " $4; if ($1 == "f") f[++m] = $2 " " $3 " " $4; next }
    /<mesh / {
      for (i = 1; i <= m; i++) {
        split(f[i], k, " "); line = "  <triangle>"
        for (c = 1; c <= 3; c++) { split(v[k[c] + 0], p, " "); line = line "<corner x=\"" p[1] "\" y=\"" p[2] "\" z=\"" p[3] "\"/>" }
        print line "<surface diffuse=\"0.9\" reflection=\"0.1\"><colour r=\"0.75\" g=\"0.6\" b=\"0.35\"/></surface></triangle>"
      }
      next
    }
    { print }
  ' "$dir/mesh-20000.obj" "$dir/mesh-20000.xml" >"$dir/triangles-20000.xml.partial"
  mv "$dir/triangles-20000.xml.partial" "$dir/triangles-20000.xml"
fi

work=$(mktemp -d "${TMPDIR:-/tmp}/startup-bench.XXXXXX")
trap 'rm -rf "$work"' EXIT
jar="$work/tracer.jar"
cp "$home/target/scala-3.8.3/tracer.jar" "$jar"
# shellcheck source=launcher/launcher.sh
. "$home/launcher/launcher.sh"
read -r -a jvm <<<"$tracer_default_jvm"
unsafe=--sun-misc-unsafe-memory-access=allow
quiet=(-Xlog:cds=off -Xlog:aot*=off)

# The launcher's training batch: the gallery and launcher/training, each to a picture in $work.
: >"$work/batch"
for scene in "$home"/scenes/*.xml "$home"/launcher/training/*.xml; do
  printf '%s\t%s\n' "$scene" "$work/train-$(basename "$scene" .xml).png" >>"$work/batch"
done
echo "startup-bench.sh: making the caches" >&2
trap 'echo "startup-bench.sh: failed at line $LINENO" >&2' ERR
# batch WIDTH JAVA OPTION...: the training batch at WIDTH pixels wide.
batch() { "${@:2}" -jar "$jar" -x "$1" -p 2 --batch "$work/batch" >/dev/null 2>&1; }
batch 64 "$j17" "${jvm[@]}" -XX:DumpLoadedClassList="$work/17.classes"
"$j17" "${jvm[@]}" -Xshare:dump -XX:SharedClassListFile="$work/17.classes" \
  -XX:SharedArchiveFile="$work/17.jsa" -Xlog:cds=off -cp "$jar" >/dev/null 2>&1
batch 64 "$j25" "${jvm[@]}" "$unsafe" -XX:DumpLoadedClassList="$work/25.classes"
"$j25" "${jvm[@]}" "$unsafe" -Xshare:dump -XX:SharedClassListFile="$work/25.classes" \
  -XX:SharedArchiveFile="$work/25.jsa" "${quiet[@]}" -cp "$jar" >/dev/null 2>&1
(cd "$home/scenes" && "$j25" "${jvm[@]}" "$unsafe" -XX:AOTCacheOutput="$work/one.aot" \
  -jar "$jar" -x 48 -y 27 -a 2 -p 2 "$work/one.png" <showcase.xml >/dev/null 2>&1)
batch 64 "$j25" "${jvm[@]}" "$unsafe" -XX:AOTCacheOutput="$work/64.aot"
batch 320 "$j25" "${jvm[@]}" "$unsafe" -XX:AOTCacheOutput="$work/320.aot"
batch 320 "$j25" "${jvm[@]}" "$unsafe" -XX:+UseCompactObjectHeaders -XX:AOTCacheOutput="$work/320c.aot"

names=("17 cds" "25 none" "25 cds" "25 aot-one" "25 aot-64" "25 aot" "25 aot+coh")
setups=(
  "$j17 ${jvm[*]} -XX:SharedArchiveFile=$work/17.jsa -Xshare:auto -Xlog:cds=off"
  "$j25 ${jvm[*]} $unsafe"
  "$j25 ${jvm[*]} $unsafe -XX:SharedArchiveFile=$work/25.jsa ${quiet[*]}"
  "$j25 ${jvm[*]} $unsafe -XX:AOTCache=$work/one.aot ${quiet[*]}"
  "$j25 ${jvm[*]} $unsafe -XX:AOTCache=$work/64.aot ${quiet[*]}"
  "$j25 ${jvm[*]} $unsafe -XX:AOTCache=$work/320.aot ${quiet[*]}"
  "$j25 ${jvm[*]} $unsafe -XX:+UseCompactObjectHeaders -XX:AOTCache=$work/320c.aot ${quiet[*]}"
)

median() { printf '%s\n' "$@" | sort -n | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }'; }

header="| row |"
rule="|---|"
for name in "${names[@]}"; do header="$header $name |"; rule="$rule---|"; done
echo "$header"
echo "$rule"
TIMEFORMAT=%R
for row in "${rows[@]}"; do
  scene=${row%%:*} size=${row#*:}
  declare -a times=()
  for ((r = 0; r < runs; r++)); do
    for i in "${!setups[@]}"; do
      # shellcheck disable=SC2086 # each set-up is a command line of words without spaces
      t=$( { time ${setups[$i]} -jar "$jar" -p 2 -x "${size%x*}" -y "${size#*x}" \
        -i "$dir/$scene.xml" "$work/out.png" >/dev/null 2>"$work/err"; } 2>&1)
      if [ -s "$work/err" ]; then echo "startup-bench.sh: ${names[$i]} wrote on stderr:" >&2; head -3 "$work/err" >&2; fi
      times[i]="${times[i]:-} $t"
    done
  done
  line="| $scene $size |"
  for i in "${!setups[@]}"; do
    # shellcheck disable=SC2086 # the list of times, split into words
    line="$line $(median ${times[i]}) |"
  done
  echo "$line"
  unset times
done
