#!/usr/bin/env bash
# mitsuba.sh: runs a Python program with Mitsuba 3 (the oracle of path mode; docs/mitsuba.md).
#
#   scripts/mitsuba.sh PROGRAM.py [ARGUMENT...]
#   scripts/mitsuba.sh --install          (only make sure Mitsuba is installed)
#   scripts/mitsuba.sh --python           (print the Python that has it, installing it first)
#
# Mitsuba comes from PyPI, pinned, into a virtual environment of its own made on first use in
# $TRACER_MITSUBA_CACHE (default ~/.cache/tracer-mitsuba). The programs that the twin writer
# (tracer.demo.Mitsuba) makes choose their variant themselves: `scalar_rgb`, or `llvm_ad_rgb`,
# which needs a libLLVM of version 16 or newer; this script names Debian's libllvm19 for it
# (DRJIT_LIBLLVM_PATH) when the variable is unset and the library is there.
set -euo pipefail

readonly MITSUBA_VERSION=3.9.1
cache=${TRACER_MITSUBA_CACHE:-"${XDG_CACHE_HOME:-$HOME/.cache}/tracer-mitsuba"}
venv="$cache/mitsuba-$MITSUBA_VERSION"
python="$venv/bin/python"

[ $# -gt 0 ] || { echo "usage: mitsuba.sh PROGRAM.py [ARGUMENT...] | --install | --python" >&2; exit 2; }

# A virtual environment's scripts name its directory, so it is made in place; .installed marks
# one that is whole.
if [ ! -f "$venv/.installed" ]; then
  command -v python3 >/dev/null || { echo "mitsuba.sh: needs python3 (apt-get install python3 python3-venv)" >&2; exit 1; }
  echo "mitsuba.sh: installing mitsuba $MITSUBA_VERSION into $venv (first use)" >&2
  rm -rf "$venv"
  mkdir -p "$cache"
  { python3 -m venv "$venv" &&
    "$venv/bin/pip" install --quiet --disable-pip-version-check "mitsuba==$MITSUBA_VERSION" >&2 &&
    "$python" -c 'import mitsuba; mitsuba.set_variant("scalar_rgb")'; } || {
    rm -rf "$venv"
    echo "mitsuba.sh: could not install mitsuba $MITSUBA_VERSION (needs python3-venv and PyPI)" >&2
    exit 1
  }
  touch "$venv/.installed"
fi

case "$1" in
  --install) exit 0 ;;
  --python) echo "$python"; exit 0 ;;
esac
[ -f "$1" ] || { echo "mitsuba.sh: no such program: $1" >&2; exit 2; }

llvm=/usr/lib/x86_64-linux-gnu/libLLVM-19.so
if [ -z "${DRJIT_LIBLLVM_PATH:-}" ] && [ -f "$llvm" ]; then export DRJIT_LIBLLVM_PATH=$llvm; fi
exec "$python" "$@"
