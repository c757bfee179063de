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
if [ ! -x .venv/bin/python ]; then
    "$PYTHON" -m venv .venv
fi
# shellcheck disable=SC1091
. .venv/bin/activate
python -m pip install -q --disable-pip-version-check -r crates/caisson-py/requirements.txt
(cd crates/caisson-py && maturin develop --release --quiet)

cargo test --release --workspace
# The CLI the Python tests compare against (built by the tests above; this is a no-op check).
cargo build --release -p caisson-cli

status=0
python -m pytest -q crates/caisson-py/tests || status=$?
if [ "$status" -eq 5 ]; then
    echo "pytest collected no tests: failing" >&2
    exit 1
fi
exit "$status"
