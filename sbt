#!/usr/bin/env bash
# sbt launcher bootstrap: needs only a JDK 17+ and curl (or wget).
# On first use it downloads the pinned sbt launcher jar from Maven Central, checks its SHA-256,
# and caches it outside git (in $SBT_LAUNCHER_CACHE, default ~/.cache/tracer-sbt).
set -euo pipefail

readonly SBT_LAUNCHER_VERSION=1.12.14
readonly SBT_LAUNCHER_SHA256=1750c8fb61c2d2f82da40b2cd9014f4d8a1bd49a361402ea5b1cec061ed66578
readonly SBT_LAUNCHER_URL="https://repo1.maven.org/maven2/org/scala-sbt/sbt-launch/${SBT_LAUNCHER_VERSION}/sbt-launch-${SBT_LAUNCHER_VERSION}.jar"

cache_dir=${SBT_LAUNCHER_CACHE:-"${XDG_CACHE_HOME:-$HOME/.cache}/tracer-sbt"}
jar="$cache_dir/sbt-launch-${SBT_LAUNCHER_VERSION}.jar"

sha256_of() {
  if command -v sha256sum >/dev/null 2>&1; then sha256sum "$1" | cut -d' ' -f1
  else shasum -a 256 "$1" | cut -d' ' -f1; fi
}

download() {
  if command -v curl >/dev/null 2>&1; then curl -fsSL --retry 3 -o "$2" "$1"
  elif command -v wget >/dev/null 2>&1; then wget -q -O "$2" "$1"
  else echo "sbt: need curl or wget to download the sbt launcher" >&2; exit 1; fi
}

if [ ! -f "$jar" ]; then
  mkdir -p "$cache_dir"
  tmp=$(mktemp "$cache_dir/sbt-launch.XXXXXX")
  trap 'rm -f "$tmp"' EXIT
  echo "sbt: downloading sbt launcher $SBT_LAUNCHER_VERSION" >&2
  download "$SBT_LAUNCHER_URL" "$tmp"
  actual=$(sha256_of "$tmp")
  if [ "$actual" != "$SBT_LAUNCHER_SHA256" ]; then
    echo "sbt: launcher checksum mismatch (expected $SBT_LAUNCHER_SHA256, got $actual)" >&2
    exit 1
  fi
  mv "$tmp" "$jar"
  trap - EXIT
fi

cd "$(dirname "${BASH_SOURCE[0]}")"
batch=()
# Without a terminal (CI, scripts) sbt must not wait for input, and must not colour its log or
# redraw it with the super shell's escape sequences.
if [ ! -t 0 ] || [ -n "${CI:-}" ]; then
  batch=(-Dsbt.batch=true -Dsbt.supershell=false -Dsbt.color=false -Dsbt.ci=true)
fi
exec java -Xss4m -Xmx3g ${batch[@]+"${batch[@]}"} ${SBT_JAVA_OPTS:-} -jar "$jar" "$@"
