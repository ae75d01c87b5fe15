#!/usr/bin/env bash
# Passes only when a command exits with the expected status AND its output matches an
# extended regular expression: CTest's PASS_REGULAR_EXPRESSION alone ignores the exit status,
# so a crash after printing the right words would pass. The whole output is one
# string to the regex (grep -z), so ".*" spans lines.
# Usage: expect_output.sh <expected exit status> <regex> <command> [args...]
set -uo pipefail
want=$1
regex=$2
shift 2
out=$("$@" 2>&1)
rc=$?
printf '%s\n' "$out"
if [ "$rc" -ne "$want" ]; then
  echo "FAILED: exit status $rc, expected $want"
  exit 1
fi
if ! printf '%s\n' "$out" | grep -Ezq -e "$regex"; then
  echo "FAILED: the output does not match: $regex"
  exit 1
fi
echo "PASSED: exit status $rc and the output matches: $regex"
