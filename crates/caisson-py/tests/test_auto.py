"""`[design] lives = "auto"` from Python (issue 35, item 2): `Design.simulate_auto` runs the lives
`caisson design` runs (the same on 1 and 2 threads), `Design.statistics` of them is its
design.json bit for bit with the `precision` verdict, shards of `simulate_lives` stop at the same
life (the rule of `caisson merge`) or are refused when short of it, and bad keys are refused
naming the key."""

from __future__ import annotations

import json

import pandas as pd
import pytest

import caisson
from conftest import ROOT, assert_same_json, cli

SMALL = (ROOT / "crates/caisson/tests/data/small_design.toml").read_text()
assert "\nlives = 12\n" in SMALL


def auto_text(extra: str) -> str:
    return SMALL.replace("\nlives = 12\n", f'\nlives = "auto"\n{extra}\n')


@pytest.fixture
def auto_file(tmp_path):
    p = tmp_path / "auto.toml"
    # Target 0.03 within 4000 lives: the small design's frequent failures stop it at 2000.
    p.write_text(auto_text("target_relative_error = 0.03\nmax_lives = 4000"))
    return p


def test_simulate_auto_is_the_clis_run_on_any_thread_count_and_from_shards(tmp_path, auto_file):
    design = caisson.Design(caisson.Scenario.from_toml(auto_file))
    assert (design.auto, design.lives) == (0.03, 4000)
    one = design.simulate_auto(threads=1)
    two = design.simulate_auto(threads=2)
    pd.testing.assert_frame_equal(one, two, check_exact=True)
    k = len(one)
    assert list(one["life"]) == list(range(k)) and k % 500 == 0 and 500 < k < 4000, k

    stats = design.statistics(one)
    out = tmp_path / "cli"
    cli("design", auto_file, "--out", out)
    want = json.loads((out / "design.json").read_text())
    assert assert_same_json(stats.report, want) > 70
    p = stats.precision
    assert p == want["precision"] and p["lives"] == k and p["met"] is True
    assert p["expected_sliding_relative_error"] <= 0.03 and p["failure_relative_error"] <= 0.03

    # Shards past the stopping point stop at k; shards short of it are refused.
    parts = [design.simulate_lives(range(0, 1200)), design.simulate_lives(range(1200, 2500))]
    assert assert_same_json(design.statistics(parts).report, want) > 70
    with pytest.raises(ValueError, match=r"do not reach the stopping point"):
        design.statistics(parts[0])


def test_stratified_simulate_auto_is_the_clis_run(tmp_path):
    # Target 0.2 within 6000 lives of the pool, stratified: the CLI stops at 3000
    # (tests/cli_design_auto.rs); the lives are the sample's of 0..k, not 0..k.
    f = tmp_path / "strat.toml"
    f.write_text(auto_text('target_relative_error = 0.2\nmax_lives = 6000\nsampling = "stratified"'))
    design = caisson.Design(caisson.Scenario.from_toml(f))
    one = design.simulate_auto(threads=1)
    two = design.simulate_auto(threads=2)
    pd.testing.assert_frame_equal(one, two, check_exact=True)
    out = tmp_path / "cli"
    cli("design", f, "--out", out)
    want = json.loads((out / "design.json").read_text())
    k = want["precision"]["lives"]
    sample = [i for i in design.sample() if i < k]
    assert list(one["life"]) == sample and len(sample) < k / 5, (len(sample), k)
    stats = design.statistics(one)
    assert assert_same_json(stats.report, want) > 70
    assert stats.precision == want["precision"] and want["precision"]["met"] is True
    # Shards of the sample past the stopping point stop at k; short of it, refused.
    parts = [design.simulate_lives([i for i in sample if i < 1000]), design.simulate_lives([i for i in design.sample() if 1000 <= i < k + 500])]
    assert assert_same_json(design.statistics(parts).report, want) > 70
    with pytest.raises(ValueError, match=r"do not reach the stopping point"):
        design.statistics(parts[0])


def test_bad_auto_keys_are_refused_naming_the_key(tmp_path):
    cases = [
        (SMALL.replace("\nlives = 12\n", '\nlives = "many"\n'), "[design] lives"),
        (auto_text("target_relative_error = 0"), "[design] target_relative_error"),
    ]
    for k, (text, key) in enumerate(cases):
        f = tmp_path / f"bad{k}.toml"
        f.write_text(text)
        with pytest.raises(caisson.ScenarioError) as e:
            caisson.Scenario.from_toml(f)
        assert key in str(e.value), str(e.value)
    # A number of lives: simulate_auto refuses, naming the key's value.
    f = tmp_path / "fixed.toml"
    f.write_text(SMALL)
    with pytest.raises(ValueError, match=r'needs `lives = "auto"`'):
        caisson.Design(caisson.Scenario.from_toml(f)).simulate_auto()
