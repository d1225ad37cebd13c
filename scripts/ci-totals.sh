#!/usr/bin/env bash
# ci-totals.sh LOG STATUS: prints the plain line "N passed, M failed" for an sbt log, alone at the
# start of a line and free of escape sequences (.ci/run's closing line).
#
# sbt prints "Passed: Total T, Failed F, Errors E, Passed P" (or "Failed: Total …") per test run;
# errors count as failures, and a failing run (STATUS ≠ 0) with no failed test counts as one.
set -euo pipefail
log=$1
status=$2

clean=$(sed 's/\x1b\[[0-9;?]*[A-Za-z]//g' "$log")
passed=$(printf '%s\n' "$clean" | sed -n 's/.*Total [0-9]*, Failed [0-9]*, Errors [0-9]*, Passed \([0-9]*\).*/\1/p' | awk '{s+=$1} END {print s+0}')
failed=$(printf '%s\n' "$clean" | sed -n 's/.*Total [0-9]*, Failed \([0-9]*\), Errors \([0-9]*\), Passed.*/\1 \2/p' | awk '{s+=$1+$2} END {print s+0}')
if [ "$status" -ne 0 ] && [ "$failed" -eq 0 ]; then failed=1; fi
# Start a line of our own if the log's last line was left open (a terminal clean-up sequence).
if [ -s "$log" ] && [ -n "$(tail -c 1 "$log")" ]; then echo; fi
echo "$passed passed, $failed failed"
