#!/usr/bin/env bash
# Run the README's test command RUNS times in a row with BUSY busy loops beside it (default 100
# runs, 2 loops: a 2-core machine with both cores already loaded), and stop at the first failure.
# A test that fails here fails by chance: a defect to fix, not to retry.
#
#   scripts/stress-tests.sh [RUNS] [BUSY]
set -uo pipefail
runs=${1:-100}
busy=${2:-2}
cd "$(dirname "$0")/.."
cargo test --release --workspace --no-run -q 2>/dev/null || { echo "the tests do not build"; exit 1; }
pids=()
for _ in $(seq "$busy"); do
    (while :; do :; done) &
    pids+=($!)
done
trap 'kill "${pids[@]}" 2>/dev/null' EXIT
log=$(mktemp)
start=$(date +%s)
for i in $(seq "$runs"); do
    if ! cargo test --release --workspace >"$log" 2>&1; then
        echo "run $i of $runs FAILED after $(( $(date +%s) - start )) s:"
        grep -E "FAILED|panicked|failed" "$log" | head -n 20
        exit 1
    fi
    echo "run $i: $(grep -c 'test result: ok' "$log") test binaries ok ($(( $(date +%s) - start )) s)"
done
echo "$runs runs of the README's test command passed with $busy busy loops beside them"
