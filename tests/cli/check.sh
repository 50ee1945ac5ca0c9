#!/bin/sh
# Runs a command and checks its exit status (a number, or "nonzero") and that
# its combined output matches an extended regular expression.
# Usage: check.sh STATUS REGEX COMMAND [ARGS...]
expected=$1; regex=$2; shift 2
out=$("$@" 2>&1); status=$?
printf '%s\n' "$out"
if [ "$expected" = nonzero ]; then
  [ "$status" -ne 0 ] || { echo "check: expected a non-zero exit status, got 0"; exit 1; }
else
  [ "$status" -eq "$expected" ] || { echo "check: expected exit status $expected, got $status"; exit 1; }
fi
printf '%s\n' "$out" | grep -E -q -- "$regex" || { echo "check: output does not match: $regex"; exit 1; }
