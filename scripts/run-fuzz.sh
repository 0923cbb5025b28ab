#!/usr/bin/env bash
# Runs the libFuzzer targets built by `make fuzz` one after the other, each for
# FUZZ_SECONDS seconds (default 60), and lists the findings.
#
# libFuzzer runs in fork mode and keeps going after a crash, a timeout (an
# execution over 10 s) or an out-of-memory, so one bounded run collects every
# finding it meets instead of stopping at the first. New corpus entries go to
# BUILD/corpus/NAME (the committed seeds in fuzz/corpus/NAME are only read),
# findings to BUILD/findings/NAME/, logs to BUILD/NAME.log (NAME: parser or
# build). Findings already there before this run (of earlier runs, kept until
# removed) are listed apart as old; the exit status is 1 only when this run
# added a finding (one it finds again is old: libFuzzer names an artifact by a
# hash of its input).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build-fuzz}
seconds=${FUZZ_SECONDS:-60}
# libFuzzer reads -max_total_time=0 as "no limit": the run must stay bounded.
if ! [[ $seconds =~ ^[1-9][0-9]*$ ]]; then
    echo "run-fuzz.sh: FUZZ_SECONDS must be a positive number of seconds, found '$seconds'" >&2
    exit 2
fi
# Symbolized stack traces; every UBSan report stops the execution (a finding).
export ASAN_SYMBOLIZER_PATH=/usr/lib/llvm-14/bin/llvm-symbolizer
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

# The findings of target NAME, one path a line, sorted (none before its first run).
list_findings() {
    [ -d "$build/findings/$1" ] || return 0
    find "$build/findings/$1" -type f | LC_ALL=C sort
}
declare -A old_findings
for name in parser build; do
    old_findings[$name]=$(list_findings "$name")
done

run_target() {
    local name=$1 target=$2 max_len=$3
    local corpus=$build/corpus/$name findings=$build/findings/$name
    mkdir -p "$corpus" "$findings"
    echo "== $target: $seconds s (log: $build/$name.log)"
    "$build/$target" -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
        -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len="$max_len" \
        -dict=fuzz/ell.dict -artifact_prefix="$findings/" -print_final_stats=1 \
        "$corpus" "fuzz/corpus/$name" >"$build/$name.log" 2>&1 || true
    grep -E '^#[0-9]+: cov' "$build/$name.log" | tail -n 1 || true
}

# The parser target takes long lines (tokens beyond the 4096-bit cap); the
# build target ignores inputs over 512 bytes anyway.
run_target parser fuzz_site_parser 12000
run_target build fuzz_build 512

status=0
for name in parser build; do
    mapfile -t new < <(LC_ALL=C comm -13 <(printf '%s\n' "${old_findings[$name]}" | sed '/^$/d') <(list_findings "$name"))
    mapfile -t old < <(printf '%s\n' "${old_findings[$name]}" | sed '/^$/d')
    echo "$name: ${#new[@]} new finding(s) in this run"
    for f in "${new[@]}"; do echo "  $f"; done
    if [ ${#old[@]} -gt 0 ]; then
        echo "$name: ${#old[@]} old finding(s), there before this run (not counted; remove each once fixed)"
        for f in "${old[@]}"; do echo "  $f"; done
    fi
    [ ${#new[@]} -eq 0 ] || status=1
done
exit "$status"
