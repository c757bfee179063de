"""`caisson design --life-range` shards joined by `caisson merge` against the same shards simulated
in Python: `Design.statistics` is the merged `design.json` key for key, bit for bit (warnings
too), and the lives are the merged `lives.csv` row for row. And what `Design.statistics` refuses."""

from __future__ import annotations

import json
import re

import numpy as np
import pandas as pd
import pytest

import caisson
from conftest import ROOT, assert_same_json, cli, read_csv_exact

LIVES = 12
# Out of order and of unequal sizes: 0..5, 5..9, 9..12.
RANGES = [(5, 9), (0, 5), (9, 12)]

# The small design of the CLI's design tests (crates/caisson/tests/data/small_design.toml: 12
# lives of 5 years, about 0.1 s), with a failure limit of 2 mm so that most lives fail: the merged
# design.json has warnings.
DESIGN = (ROOT / "crates/caisson/tests/data/small_design.toml").read_text() + "failure_sliding_m = 0.002\n"
assert f"\nlives = {LIVES}\n" in DESIGN and DESIGN.rstrip().endswith("failure_sliding_m = 0.002")


@pytest.fixture
def design_file(tmp_path):
    p = tmp_path / "design_small.toml"
    p.write_text(DESIGN)
    return p


def test_cli_shards_merged_equal_python_shards_bit_for_bit(tmp_path, design_file):
    shard_dirs = []
    for a, b in RANGES:
        d = tmp_path / f"shard_{a}_{b}"
        cli("design", design_file, "--life-range", f"{a}..{b}", "--out", d)
        shard_dirs.append(d)
    merged = tmp_path / "merged"
    cli("merge", design_file, *shard_dirs[::-1], "--out", merged)
    want = json.loads((merged / "design.json").read_text())
    want_lives = read_csv_exact(merged / "lives.csv")
    assert len(want_lives) == LIVES and list(want_lives["life"]) == list(range(LIVES))

    design = caisson.Design(caisson.Scenario.from_toml(design_file))
    parts = [design.simulate_lives(range(a, b)) for a, b in RANGES]
    # Each Python shard is the CLI shard's lives.csv.
    for (a, b), part, d in zip(RANGES, parts, shard_dirs):
        pd.testing.assert_frame_equal(part, read_csv_exact(d / "lives.csv"), check_exact=True, check_dtype=False)

    got = design.statistics(parts).report
    compared = assert_same_json(got, want)
    assert compared > 70, compared  # design.json has 79 values here: all of them, not a handful
    assert got["lives"] == LIVES
    codes = [w["code"] for w in want["warnings"]]
    assert "failed-lives" in codes, codes  # the warnings are compared, not two empty lists
    assert got["warnings"] == want["warnings"]

    lives = pd.concat(parts, ignore_index=True).sort_values("life", ignore_index=True)
    assert list(lives.columns) == list(want_lives.columns)
    rows = 0
    for got_row, want_row in zip(lives.itertuples(index=False), want_lives.itertuples(index=False)):
        assert tuple(got_row) == tuple(want_row), (got_row, want_row)  # exact: floats parsed exactly
        rows += 1
    assert rows == LIVES


def test_statistics_refuses_repeated_lives_missing_columns_and_bad_values(design_file):
    design = caisson.Design(caisson.Scenario.from_toml(design_file))
    part = design.simulate_lives(range(3))
    ok = design.statistics(part)
    assert ok["lives"] == 3
    with pytest.raises(ValueError, match=r"^life 1 appears more than once$"):
        design.statistics([part, part.iloc[1:2]])
    with pytest.raises(ValueError, match=r"^the lives have no column 'waves' \(the lives need life, sliding_m, "):
        design.statistics(part.drop(columns="waves"))
    with pytest.raises(ValueError, match=r"^shard 1 \(of 2\) has no column 'life'"):
        design.statistics([part, part.drop(columns="life")])
    with pytest.raises(ValueError, match=r"^no lives given"):
        design.statistics([])
    with pytest.raises(ValueError, match=r"^no lives given"):
        design.statistics(part.iloc[0:0])
    bad = part.astype({"waves": "int64"})
    bad.loc[2, "waves"] = -1
    with pytest.raises(ValueError, match=r"^column 'waves' = -1 in row 2 \(life 2\): must be a whole number ≥ 0$"):
        design.statistics(bad)
    bad = part.astype({"rocking_waves": "float64"})
    bad.loc[0, "rocking_waves"] = 2.5
    with pytest.raises(ValueError, match=r"^column 'rocking_waves' = 2.5 in row 0 \(life 0\): must be a whole number"):
        design.statistics(bad)
    bad = part.copy()
    bad.loc[1, "sliding_m"] = np.nan
    with pytest.raises(ValueError, match=r"^column 'sliding_m' = nan in row 1 \(life 1\): must be a finite number \(m\)$"):
        design.statistics(bad)
    bad = part.copy()
    bad.loc[0, "max_rotation_rad"] = np.inf
    with pytest.raises(ValueError, match=r"^column 'max_rotation_rad' = inf in row 0 \(life 0\): must be a finite number \(rad\)$"):
        design.statistics(bad)
    with pytest.raises(TypeError, match="DataFrames"):
        design.statistics([part, {"life": [3]}])
    # A whole-number column stored as floats (e.g. after a join) is accepted unchanged.
    assert design.statistics(part.astype({"waves": "float64"})) == ok


@pytest.mark.parametrize(
    "line, key",
    [
        ("failure_rotation_rad = 0.0", "[design] failure_rotation_rad"),
        ("failure_rotation_rad = 0.2", "[design] failure_rotation_rad"),
        ("continue_after_failure = 1", "continue_after_failure"),
        ("allowable_heel_pressure_kpa = 5.0", "[design] allowable_heel_pressure_kpa"),
        ("failure_heel_pressure_kpa = -1.0", "[design] failure_heel_pressure_kpa"),
    ],
)
def test_the_failure_keys_are_refused_out_of_range_as_in_the_cli(tmp_path, line, key):
    p = tmp_path / "bad.toml"
    p.write_text(DESIGN + line + "\n")
    with pytest.raises(caisson.ScenarioError, match=re.escape(key)):
        caisson.Design(caisson.Scenario.from_toml(p))


def test_a_failed_life_ends_and_counts_at_the_limit(tmp_path):
    """The lives of a 3 cm limit (half of them fail): the headline E|S| counts each failed life at
    the limit, the uncapped mean is that of the lives as simulated (each run to its end), and the
    failure modes are those of each life's failing wave (its columns)."""
    p = tmp_path / "limit_3cm.toml"
    p.write_text(DESIGN.replace("failure_sliding_m = 0.002", "failure_sliding_m = 0.03"))
    design = caisson.Design(caisson.Scenario.from_toml(p))
    lives = design.simulate_lives()
    s = design.statistics(lives)["dynamic"]
    failed = (lives["max_excursion_m"] > 0.03) | (lives["max_rotation_rad"] > 0.01)
    assert 0 < failed.sum() < LIVES
    # A life beyond a limit failed, and records the year of its failing wave.
    assert (failed == (lives["failure_year"] > 0)).all()
    assert (failed == ((lives["failed_by_sliding"] + lives["failed_by_rotation"]) > 0)).all()
    capped = np.where(failed, 0.03, lives["sliding_m"].abs())
    assert s["expected_sliding_m"] == pytest.approx(capped.mean(), rel=1e-12)
    assert s["expected_sliding_m"] <= 0.03 < s["expected_sliding_uncapped_m"]
    assert s["expected_sliding_uncapped_m"] == pytest.approx(lives["sliding_m"].abs().mean(), rel=1e-12)
    assert s["failure"]["lives"] == failed.sum()
    assert s["failure"]["by_sliding"]["lives"] == lives["failed_by_sliding"].sum()
    assert s["failure"]["by_rotation"]["lives"] == lives["failed_by_rotation"].sum()
