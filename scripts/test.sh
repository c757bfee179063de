#!/usr/bin/env bash
# Every test of the project: the Rust workspace (unit, verification, golden and CLI tests) and the
# Python package (pytest against the CLI, Dask and Ray shards, the examples).
#
# Creates .venv (Python 3.9+, `python3` or $PYTHON) if missing, installs the pinned Python
# requirements, builds the `caisson` package into it (maturin develop --release), then runs
# `cargo test --release --workspace` and pytest. Exits non-zero if pytest collects no test.
set -euo pipefail
cd "$(dirname "$0")/.."
PYTHON=${PYTHON:-python3}
# Each phase says what it does and, when it ends, how long it took (the whole run: about 5 min of
# CPU on an idle 2-core machine once the Rust and Python dependencies are built; the first run
# builds them and installs the Python requirements, about 10 more minutes).
start=$SECONDS
phase_start=$SECONDS
phase() {
    if [ -n "${phase_name:-}" ]; then
        echo "== ${phase_name}: done in $((SECONDS - phase_start)) s"
    fi
    phase_name=$1
    phase_start=$SECONDS
    [ -n "$phase_name" ] && echo "== ${phase_name} ..."
    return 0
}
phase "Python environment: .venv with the pinned requirements (crates/caisson-py/requirements.txt)"
if [ ! -x .venv/bin/python ]; then
    "$PYTHON" -m venv .venv
fi
# shellcheck disable=SC1091
. .venv/bin/activate
python -m pip install -q --disable-pip-version-check -r crates/caisson-py/requirements.txt \
    | { grep -v "^Requirement already satisfied" || true; }
phase "Python package: maturin develop --release (builds the caisson extension into .venv)"
# Its build output is kept to itself unless it fails (then it is printed whole).
maturin_log=$(mktemp)
if ! (cd crates/caisson-py && maturin develop --release --quiet) >"$maturin_log" 2>&1; then
    cat "$maturin_log" >&2
    rm -f "$maturin_log"
    echo "maturin develop failed (its output above)" >&2
    exit 1
fi
rm -f "$maturin_log"

phase "Rust tests: cargo test --release --workspace (unit, verification, golden, CLI, fuzz)"
cargo test --release --workspace
# The CLI the Python tests compare against (built by the tests above; this is a no-op check).
cargo build --release -p caisson-cli

phase "Python tests: pytest crates/caisson-py/tests (against the CLI, Dask and Ray shards, examples)"
status=0
python -m pytest -q crates/caisson-py/tests || status=$?
phase ""
echo "== all tests: $((SECONDS - start)) s"
if [ "$status" -eq 5 ]; then
    echo "pytest collected no tests: failing" >&2
    exit 1
fi
exit "$status"
