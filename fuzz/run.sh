#!/usr/bin/env bash
# Runs the scene-language fuzzer for SECONDS (default 60) from the seeds (fuzz/seeds, the example
# scenes, the inputs that once crashed it) and fails on any crash, hang (> 10 s per input),
# memory blow-up (> 2 GiB) or sanitizer report. New inputs accumulate in the fuzzer's build
# directory (corpus/), found problems in artifacts/.
#   fuzz/run.sh build-fuzz/parse_fuzzer [SECONDS]
set -euo pipefail
fuzzer=$1
seconds=${2:-60}
here=$(cd "$(dirname "$0")" && pwd)
work=$(dirname "$fuzzer")
mkdir -p "$work/corpus" "$work/artifacts"
"$fuzzer" -dict="$here/scene.dict" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -max_len=8192 -print_final_stats=1 -artifact_prefix="$work/artifacts/" \
    "$work/corpus" "$here/seeds" "$here/../examples/scenes" "$here/../tests/dsl/fuzz_regressions" \
    >"$work/fuzz.log" 2>&1 || {
    status=$?
    grep -E -A30 "ERROR|runtime error|deadly|timeout|out-of-memory" "$work/fuzz.log" | head -60
    echo "fuzz/run.sh: the fuzzer failed (exit status $status); full log in $work/fuzz.log, input in $work/artifacts/"
    exit 1
}
grep -E "^#[0-9]+[[:space:]]+DONE|stat::number_of_executed_units" "$work/fuzz.log"
