"""Shared fixtures: the repository root, the `caisson` CLI (built by scripts/test.sh before pytest)
and helpers to run it."""

from __future__ import annotations

import json
import os
import re
import subprocess
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[3]
EXAMPLES = ROOT / "examples"


def cli_path() -> Path:
    """$CAISSON_BIN, or the release build in $CARGO_TARGET_DIR (default: target/)."""
    target = ROOT / os.environ.get("CARGO_TARGET_DIR", "target")
    p = Path(os.environ.get("CAISSON_BIN", target / "release" / "caisson"))
    if not p.exists():
        pytest.fail(f"the caisson CLI is not built at {p}: run `cargo build --release -p caisson-cli` (scripts/test.sh does)")
    return p


def turns_while(f, *args) -> int:
    """How many times a loop in this thread turned while `f(*args)` ran in another thread: a few
    when `f` holds the GIL, many when it releases it."""
    import threading

    t = threading.Thread(target=f, args=args)
    count = 0
    t.start()
    while t.is_alive():
        count += 1
    t.join()
    return count


def cli(*args: str, check: bool = True) -> subprocess.CompletedProcess:
    r = subprocess.run([str(cli_path()), *map(str, args)], capture_output=True, text=True, cwd=ROOT)
    if check and r.returncode != 0:
        raise AssertionError(f"caisson {' '.join(map(str, args))} failed ({r.returncode}): {r.stderr}")
    return r


def cli_json(*args: str) -> dict:
    return json.loads(cli(*args, "--json").stdout)


@pytest.fixture
def examples() -> Path:
    return EXAMPLES


def read_csv_exact(path) -> "pd.DataFrame":
    """A CSV of the CLI with every number parsed by Python's float (exact: the CLI writes the
    shortest text that reads back to the same double); whole-number columns as int64."""
    import csv

    import pandas as pd

    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    cols = {}
    for j, name in enumerate(rows[0]):
        text = [r[j] for r in rows[1:]]
        try:
            cols[name] = [int(t) for t in text]
        except ValueError:
            cols[name] = [float(t) for t in text]
    return pd.DataFrame(cols)


def assert_same_json(got, want, path: str = "") -> int:
    """`got` == `want` with the same keys, list lengths and JSON types (an int is not a float),
    numbers bit for bit (a float by its 8 bytes); returns how many numbers, strings and booleans were compared."""
    assert type(got) is type(want), f"{path}: {type(got).__name__} != {type(want).__name__}"
    if isinstance(want, dict):
        assert list(sorted(got)) == list(sorted(want)), f"{path}: keys differ: {sorted(set(got) ^ set(want))}"
        return sum(assert_same_json(got[k], want[k], f"{path}.{k}") for k in want)
    if isinstance(want, list):
        assert len(got) == len(want), f"{path}: {len(got)} items != {len(want)}"
        return sum(assert_same_json(g, w, f"{path}[{i}]") for i, (g, w) in enumerate(zip(got, want)))
    if isinstance(want, float):
        assert np.float64(got).tobytes() == np.float64(want).tobytes(), f"{path}: {got!r} != {want!r}"
    else:
        assert got == want, f"{path}: {got!r} != {want!r}"
    return 1


def assert_replace_error_is_the_clis(err, table: str, stderr: str) -> None:
    """A `Scenario.replace` error says what the CLI says of the same scenario written to a file
    (its words after `Error: `), without the file's place (`scenario.toml line 7, column 1: `,
    a line of TOML the user never wrote), after the change it comes from (`replace(caisson=...)`)."""
    words = re.sub(r"^\S+ line \d+(, column \d+)?: ", "", stderr.strip().removeprefix("Error: "))
    words = re.sub(r" \(in `[^`]*`\)$", "", words).replace("unknown field", "unknown key", 1)
    message = str(err)
    assert message.startswith(f"replace({table}=") and message.endswith(words), (message, words)
    assert not re.search(r"line \d+", message), message


def short_design_toml(tmp_path: Path, lives: int = 40, years: int = 20) -> Path:
    """A short copy of examples/design_breakwater.toml (few lives and years: seconds)."""
    import caisson

    sc = caisson.Scenario.from_toml(EXAMPLES / "design_breakwater.toml").replace(design={"lives": lives, "life_years": years})
    p = tmp_path / "design_short.toml"
    p.write_text(sc.to_toml())
    return p


def short_size_toml(tmp_path: Path, range_m=(8.0, 30.0)) -> Path:
    """examples/size_breakwater.toml with short lives, few of them and a coarse search over
    `range_m` (seconds)."""
    import caisson

    sc = caisson.Scenario.from_toml(EXAMPLES / "size_breakwater.toml").replace(
        design={"life_years": 5, "storm_duration_h": 0.2, "storm_location_m": 7.5, "storm_scale_m": 1.5},
        size={"lives": 12, "curve_points": 4, "tolerance_m": 0.5, "range_m": list(range_m)},
    )
    p = tmp_path / f"size_short_{range_m[0]:g}.toml"
    p.write_text(sc.to_toml())
    return p
