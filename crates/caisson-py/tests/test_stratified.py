"""`[design] sampling = "stratified"` from Python (issue 35, item 3): `Design.sample()` lists the
lives `caisson design` simulates, `simulate_lives()` runs them (the same on 1 and 2 threads),
and `Design.statistics` of them is its design.json, from one frame or from shards; a sample with
a life missing is refused."""

from __future__ import annotations

import json

import pandas as pd
import pytest

import caisson
from conftest import ROOT, assert_same_json, cli

SMALL = (ROOT / "crates/caisson/tests/data/small_design.toml").read_text()
assert "\nlives = 12\n" in SMALL


@pytest.fixture
def stratified_file(tmp_path):
    p = tmp_path / "stratified.toml"
    p.write_text(SMALL.replace("\nlives = 12\n", '\nlives = 3000\nsampling = "stratified"\n'))
    return p


def test_the_stratified_sample_is_the_clis_run(tmp_path, stratified_file):
    design = caisson.Design(caisson.Scenario.from_toml(stratified_file))
    sample = design.sample()
    # About 4.7 % of the 3000 lives (141), ascending, each once.
    assert 100 < len(sample) < 200 and sample == sorted(set(sample)), len(sample)
    assert design.sample(threads=2) == sample
    one = design.simulate_lives(threads=1)
    two = design.simulate_lives(threads=2)
    pd.testing.assert_frame_equal(one, two, check_exact=True)
    assert list(one["life"]) == sample

    stats = design.statistics(one)
    out = tmp_path / "cli"
    cli("design", stratified_file, "--out", out)
    want = json.loads((out / "design.json").read_text())
    assert assert_same_json(stats.report, want) > 70
    assert stats.sampling == want["sampling"] and stats.sampling["simulated_lives"] == len(sample)
    assert stats.lives == 3000

    # Shards in any order give the same; a missing life of the sample is refused.
    half = len(sample) // 2
    parts = [design.simulate_lives(sample[half:]), design.simulate_lives(sample[:half])]
    assert assert_same_json(design.statistics(parts).report, want) > 70
    with pytest.raises(ValueError, match=r"of the stratified sample is missing"):
        design.statistics(parts[0])
