"""campaign, Design, Fragility and fit_lognormal against `caisson campaign|design|fragility` bit
for bit; threads and shards do not change a number."""

from __future__ import annotations

import json
import random

import numpy as np
import pandas as pd
import pytest

import caisson
from conftest import EXAMPLES, cli, cli_json, read_csv_exact, short_design_toml


@pytest.mark.parametrize("name", ["pari_nonbreaking_campaign.toml", "pari_breaking_campaign.toml"])
def test_campaign_matches_campaign_json(tmp_path, name):
    p = EXAMPLES / name
    cli("campaign", p, "--out", tmp_path)
    want = json.loads((tmp_path / "campaign.json").read_text())
    ds = caisson.campaign(caisson.Scenario.from_toml(p), threads=2)
    assert json.loads(ds.attrs["report_json"]) == want
    conds = want["conditions"]
    assert ds.sizes["condition"] == len(conds)
    for i, c in enumerate(conds):
        assert list(ds["sliding_m"].values[i]) == c["realization_sliding_m"]
        assert ds["height_m"].values[i] == c["height_m"]
        assert ds["sliding_mean_m"].values[i] == c["sliding_m"]["mean"]
        assert ds["regime"].values[i] == c["regime"]
        assert list(ds["max_horizontal_reaction_kn"].values[i]) == [r["max_horizontal_reaction_kn"] for r in c["realizations"]]


def test_campaign_damping_mode_matches_the_cli_option(tmp_path):
    p = EXAMPLES / "pari_nonbreaking_campaign.toml"
    cli("campaign", p, "--damping-mode", "elastic", "--out", tmp_path)
    ds = caisson.campaign(caisson.Scenario.from_toml(p), damping_mode="elastic")
    assert json.loads(ds.attrs["report_json"]) == json.loads((tmp_path / "campaign.json").read_text())
    with pytest.raises(caisson.ScenarioError):
        caisson.campaign(caisson.Scenario.from_toml(p), damping_mode="both")


def test_design_matches_caisson_design(tmp_path):
    p = short_design_toml(tmp_path)
    out = tmp_path / "out"
    cli("design", p, "--out", out)
    want = json.loads((out / "design.json").read_text())
    lives_csv = read_csv_exact(out / "lives.csv")
    d = caisson.Design(caisson.Scenario.from_toml(p))
    assert d.lives == 40
    calls = []
    lives = d.simulate_lives(threads=2, progress=lambda a, b: calls.append((a, b)))
    assert calls[-1] == (40, 40)
    assert d.statistics(lives) == want
    pd.testing.assert_frame_equal(lives, lives_csv, check_exact=True, check_dtype=False)
    stats, again = d.run()
    assert stats == want and again.equals(lives)


def test_design_lives_in_any_order_and_split_give_the_same_statistics(tmp_path):
    p = short_design_toml(tmp_path)
    want = cli_json("design", p)
    d = caisson.Design(caisson.Scenario.from_toml(p))
    idx = list(range(40))
    random.Random(3).shuffle(idx)
    shards = [d.simulate_lives(idx[k : k + 7]) for k in range(0, 40, 7)]
    assert d.statistics(shards[::-1]) == want
    with pytest.raises(ValueError, match="more than once"):
        d.statistics(shards + shards[:1])


def test_design_lives_option_equals_cli_lives(tmp_path):
    p = short_design_toml(tmp_path)
    want = cli_json("design", p, "--lives", "13")
    d = caisson.Design(caisson.Scenario.from_toml(p), lives=13)
    assert d.statistics(d.simulate_lives()) == want


def test_fragility_matches_caisson_fragility_and_fit_lognormal_its_fits(tmp_path):
    sc = caisson.Scenario.from_toml(EXAMPLES / "fragility.toml").replace(
        fragility={"storms": 12, "significant_heights_m": [8.0, 9.0, 10.0, 11.0], "storm_duration_h": 0.5}
    )
    p = tmp_path / "fragility_short.toml"
    p.write_text(sc.to_toml())
    want = cli_json("fragility", p)
    r = caisson.Fragility(caisson.Scenario.from_toml(p)).run(threads=2)
    assert r.summary == want
    assert len(r.storms) == 4 * 12 and list(r.levels["significant_height_m"]) == [8.0, 9.0, 10.0, 11.0]
    im = [lv["significant_height_m"] for lv in want["levels"]]
    n = [lv["storms"] for lv in want["levels"]]
    checked = 0
    for j, f in enumerate(want["fits"]):
        for model in ("dynamic", "rigid_block"):
            k = [lv["exceedance"][j][f"{model}_count"] for lv in want["levels"]]
            if f[model]["fitted"]:
                got = caisson.fit_lognormal(im, k, n)
                assert got["median"] == f[model]["median_m"] and got["beta"] == f[model]["beta"]
                assert got["log_likelihood"] == f[model]["log_likelihood"]
                # The 95 % profile-likelihood intervals, bit for bit, around the estimates.
                assert got["median_ci95"] == f[model]["median_ci95_m"] and got["beta_ci95"] == f[model]["beta_ci95"]
                lo, hi = got["median_ci95"]
                assert (lo is None or lo < got["median"]) and (hi is None or got["median"] < hi)
            else:
                with pytest.raises(caisson.FitError) as e:
                    caisson.fit_lognormal(im, k, n)
                assert e.value.reason == f[model]["reason"] and str(e.value) == f[model]["message"]
            checked += 1
    assert checked == 2 * len(want["fits"])


def test_fit_lognormal_recovers_a_known_curve_and_refuses_separated_counts():
    from math import erf, log, sqrt

    im = np.array([1.0, 1.5, 2.0, 2.5, 3.0, 4.0])
    n = np.full(6, 100000)
    p = [0.5 * (1 + erf((log(x) - log(2.2)) / (0.4 * sqrt(2)))) for x in im]
    k = np.round(n * np.array(p)).astype(int)
    f = caisson.fit_lognormal(im, k, n)
    assert abs(f["median"] / 2.2 - 1) < 5e-3 and abs(f["beta"] / 0.4 - 1) < 1e-2
    with pytest.raises(caisson.FitError) as e:
        caisson.fit_lognormal([1.0, 2.0], [0, 10], [10, 10])
    assert e.value.reason == "separated"
