#!/usr/bin/env bash
# Runs the Catch2 test binary and, with --pytest DIR, then the Python suite
# under DIR ($PYTHON -m pytest; the environment gives PYTHONPATH and
# ELLVOR_BINARY). Ends with one line "N passed, M failed" (Catch2 test cases
# plus pytest tests), which CI reads; the exit status is non-zero when either
# suite failed.
#   tests/run_suite.sh BINARY [--pytest DIR] [CATCH2 ARGS...]
set -u
binary=$1; shift
pytest_dir=""
if [ "${1:-}" = "--pytest" ]; then
    pytest_dir=$2; shift 2
fi
log=$(mktemp)
trap 'rm -f "$log"' EXIT

"$binary" "$@" 2>&1 | tee "$log"
status=${PIPESTATUS[0]}
summary=$(grep -E '^(All tests passed|test cases:)' "$log" | tail -n 1)
if [[ $summary =~ ^All\ tests\ passed.*in\ ([0-9]+)\ test\ case ]]; then
    passed=${BASH_REMATCH[1]} failed=0
elif [[ $summary =~ test\ cases:\ +([0-9]+)\ \|\ +([0-9]+)\ passed\ \|\ +([0-9]+)\ failed ]]; then
    passed=${BASH_REMATCH[2]} failed=${BASH_REMATCH[3]}
elif [[ $summary =~ test\ cases:\ +([0-9]+)\ \|\ +([0-9]+)\ failed ]]; then
    passed=0 failed=${BASH_REMATCH[2]}
else
    passed=0 failed=1
    [ "$status" -eq 0 ] && status=1
fi

if [ -n "$pytest_dir" ]; then
    echo "== Python suite ($pytest_dir)"
    start=$(date +%s)
    # Agg: no display; no cache or bytecode files in the source tree.
    MPLBACKEND=Agg PYTHONDONTWRITEBYTECODE=1 "${PYTHON:-/usr/bin/python3}" -m pytest -q -p no:cacheprovider \
        "$pytest_dir" 2>&1 | tee "$log"
    py_status=${PIPESTATUS[0]}
    echo "Python suite: $(( $(date +%s) - start )) s"
    # pytest's last line: "== 3 failed, 40 passed, 1 error in 12.3s ==" (any order, any subset).
    py_summary=$(grep -E '(passed|failed|error|no tests ran)' "$log" | tail -n 1)
    count() { [[ $py_summary =~ ([0-9]+)\ $1 ]] && echo "${BASH_REMATCH[1]}" || echo 0; }
    py_passed=$(count passed)
    py_failed=$(( $(count failed) + $(count error) ))
    # Exit 5 is "no tests collected": a broken suite, not a pass.
    if [ "$py_status" -ne 0 ] && [ "$py_failed" -eq 0 ]; then py_failed=1; fi
    passed=$(( passed + py_passed )) failed=$(( failed + py_failed ))
    [ "$py_status" -ne 0 ] && [ "$status" -eq 0 ] && status=$py_status
fi
echo "$passed passed, $failed failed"
exit "$status"
