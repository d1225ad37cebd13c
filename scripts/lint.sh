#!/usr/bin/env bash
# lint.sh: the project's code analysis (`./sbt lint`; docs/analysis.md).
#
#   scripts/lint.sh [--write-doc] [--pending] [--write-pending] [PATH...]
#
# Runs semgrep with the rules in lint/semgrep.yml over the Scala sources and applies the project's
# suppression rules (lint/lint.py). Prints each finding as PATH:LINE:COLUMN: RULE: message and
# exits 1 if any is left, or if docs/analysis.md's generated list is out of date (--write-doc
# rewrites it). --pending lists the findings that wait in lint/pending.txt; --write-pending rewrites
# that list from the open findings under its owners' paths (when merging their work). With PATHs it checks
# only those (and not the doc).
#
# semgrep comes from PyPI, pinned, into a virtual environment of its own made on first use in
# $TRACER_LINT_CACHE (default ~/.cache/tracer-lint); it runs offline, with only our rules.
set -euo pipefail

readonly SEMGREP_VERSION=1.185.0
home=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cache=${TRACER_LINT_CACHE:-"${XDG_CACHE_HOME:-$HOME/.cache}/tracer-lint"}
venv="$cache/semgrep-$SEMGREP_VERSION"
semgrep="$venv/bin/semgrep"

# A virtual environment's scripts name its directory, so it is made in place; .installed marks
# one that is whole.
if [ ! -f "$venv/.installed" ]; then
  command -v python3 >/dev/null || { echo "lint.sh: needs python3 (apt-get install python3 python3-venv)" >&2; exit 1; }
  echo "lint.sh: installing semgrep $SEMGREP_VERSION into $venv (first use)" >&2
  rm -rf "$venv"
  mkdir -p "$cache"
  { python3 -m venv "$venv" &&
    "$venv/bin/pip" install --quiet --disable-pip-version-check "semgrep==$SEMGREP_VERSION" >&2; } || {
    rm -rf "$venv"
    echo "lint.sh: could not install semgrep $SEMGREP_VERSION (needs python3-venv and PyPI)" >&2
    exit 1
  }
  touch "$venv/.installed"
fi

# semgrep keeps its settings and log under HOME; keep them in the cache, away from the user's.
export SEMGREP_SETTINGS_FILE="$cache/settings.yml" SEMGREP_LOG_FILE="$cache/semgrep.log"
export SEMGREP_ENABLE_VERSION_CHECK=0 SEMGREP_SEND_METRICS=off
exec python3 "$home/lint/lint.py" "$semgrep" --root "$home" "$@"
