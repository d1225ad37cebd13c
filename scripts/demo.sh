#!/usr/bin/env bash
# demo.sh: runs a main of the demo module (tracer.demo) with only its own output on stdout.
#
#   scripts/demo.sh tracer.demo.PovRay scenes/materials.xml > materials.pov
#   scripts/demo.sh tracer.demo.BenchScenes scenes/bench
#
# The demo module (demo/: the animation, the benchmark scenes, the model and texture generators,
# the POV-Ray export) is not in tracer.jar. This runs it from its own jar beside tracer.jar, both
# built by sbt when missing or older than their sources; sbt's log goes to stderr, so a command
# that writes to stdout (PovRay) can be redirected to a file cleanly. Works from any directory.
set -euo pipefail

home=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
jar="$home/target/scala-3.8.3/tracer.jar"
demo_jar="$home/demo/target/tracer-demo.jar"
[ $# -gt 0 ] || { echo "usage: demo.sh MAIN-CLASS [ARGUMENT...]" >&2; exit 2; }

stale() { [ ! -f "$1" ] || [ -n "$(find "${@:2}" -newer "$1" -print -quit 2>/dev/null)" ]; }
if stale "$jar" "$home/src/main" "$home/build.sbt" || stale "$demo_jar" "$home/demo/src/main" "$home/build.sbt"; then
  echo "demo.sh: building tracer.jar and the demo's jar" >&2
  (cd "$home" && ./sbt -Dsbt.supershell=false assembly demo/package </dev/null >&2) || {
    echo "demo.sh: the build failed" >&2
    exit 1
  }
  touch "$jar" "$demo_jar"
fi
exec java -cp "$jar:$demo_jar" "$@"
