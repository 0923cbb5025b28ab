#!/usr/bin/env bash
# Runs the Catch2 test binary and ends with the line "N passed, M failed"
# (test cases), which CI reads; the exit status is the binary's.
set -u
binary=$1; shift
log=$(mktemp)
"$binary" "$@" 2>&1 | tee "$log"
status=${PIPESTATUS[0]}
summary=$(grep -E '^(All tests passed|test cases:)' "$log" | tail -n 1)
rm -f "$log"
if [[ $summary =~ ^All\ tests\ passed.*in\ ([0-9]+)\ test\ case ]]; then
    echo "${BASH_REMATCH[1]} passed, 0 failed"
elif [[ $summary =~ test\ cases:\ +([0-9]+)\ \|\ +([0-9]+)\ passed\ \|\ +([0-9]+)\ failed ]]; then
    echo "${BASH_REMATCH[2]} passed, ${BASH_REMATCH[3]} failed"
elif [[ $summary =~ test\ cases:\ +([0-9]+)\ \|\ +([0-9]+)\ failed ]]; then
    echo "0 passed, ${BASH_REMATCH[2]} failed"
else
    echo "0 passed, 1 failed"
    [ "$status" -eq 0 ] && status=1
fi
exit "$status"
