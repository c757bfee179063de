"""Python ↔ CLI equivalence on absurd-but-valid input: the scenarios a front-end that assembles its
own report would get wrong. Each pair must agree key for key and bit for bit (warnings included),
or refuse the same way: a load that warns in `spectrum`, the loads on a soft foundation, a gap
between shards of a design, sizing candidates whose Goda check has no value."""

from __future__ import annotations

import json

import pytest

import math

import caisson
from conftest import EXAMPLES, assert_replace_error_is_the_clis, assert_same_json, cli, cli_json, short_design_toml, short_size_toml


def heavy_triangle(tmp_path):
    """examples/table5_triangle.toml with a peak force of 121 W': valid (below 10³ W'), but a
    force in N written as kN would look like it, so every report of it warns `implausible-load`."""
    text = (EXAMPLES / "table5_triangle.toml").read_text()
    assert "peak_horizontal_kn = 12.0" in text
    p = tmp_path / "heavy_triangle.toml"
    p.write_text(text.replace("peak_horizontal_kn = 12.0", "peak_horizontal_kn = 1000.0"))
    return p


def codes(report: dict) -> list:
    return [w["code"] for w in report["warnings"]]


def test_spectrum_of_a_load_that_warns_has_the_cli_warnings(tmp_path):
    p = heavy_triangle(tmp_path)
    want = cli_json("spectrum", p, "--tr-over-t0", "0.1:2:3")
    assert "implausible-load" in codes(want)
    frame = caisson.spectrum(caisson.Scenario.from_toml(p), [p_["tr_over_t0"] for p_ in want["points"]])
    head = {k: v for k, v in want.items() if k != "points"}
    assert assert_same_json(dict(frame.attrs), head) >= 8
    assert assert_same_json(frame.to_dict("records"), want["points"]) == 3 * 8


def test_run_of_a_load_that_warns_has_the_cli_warnings(tmp_path):
    p = heavy_triangle(tmp_path)
    want = cli_json("run", p)
    assert "implausible-load" in codes(want)
    got = caisson.run(caisson.Scenario.from_toml(p), history=False).summary
    assert assert_same_json(got, want) > 20


def test_loads_on_a_soft_foundation_are_the_cli_loads_with_its_warnings(tmp_path):
    # The design example on a foundation of E100 = 10 kPa (35 000 times softer): valid, and the
    # structure's warnings (settlement, natural period) are in both reports.
    sc = caisson.Scenario.from_toml(EXAMPLES / "design_breakwater.toml").replace(foundation={"e100_kpa": 10.0})
    p = tmp_path / "soft.toml"
    p.write_text(sc.to_toml())
    want = cli_json("loads", p)
    assert codes(want) == ["implausible-settlement", "implausible-natural-period"]
    got = caisson.loads.report(caisson.Scenario.from_toml(p))
    assert assert_same_json(got, want) > 50


def test_design_statistics_refuse_a_gap_between_shards_as_caisson_merge_does(tmp_path):
    p = short_design_toml(tmp_path, lives=12, years=5)
    # Two CLI shards with a gap (lives 4..6 in none): merge refuses it.
    for r in ("0..4", "6..12"):
        cli("design", p, "--life-range", r, "--out", tmp_path / r)
    refused = cli("merge", p, tmp_path / "0..4", tmp_path / "6..12", "--out", tmp_path / "m", check=False)
    assert refused.returncode == 2 and "lives 4..6 are in no shard" in refused.stderr
    # The same shards in Python: refused too, naming the same lives.
    d = caisson.Design(caisson.Scenario.from_toml(p))
    parts = [d.simulate_lives(range(0, 4)), d.simulate_lives(range(6, 12))]
    with pytest.raises(ValueError, match=r"^lives 4\.\.6 are missing \(2 lives\)"):
        d.statistics(parts)
    # Filled, both join into what one run of 12 lives reports.
    merged = cli("merge", p, tmp_path / "0..4", tmp_path / "6..12", tmp_path / "4..6", "--out", tmp_path / "m", check=False)
    assert merged.returncode == 2  # the shard 4..6 is not run yet: no such checkpoint
    cli("design", p, "--life-range", "4..6", "--out", tmp_path / "4..6")
    cli("merge", p, tmp_path / "0..4", tmp_path / "6..12", tmp_path / "4..6", "--out", tmp_path / "m")
    want = json.loads((tmp_path / "m" / "design.json").read_text())
    got = d.statistics(parts + [d.simulate_lives(range(4, 6))]).report
    assert assert_same_json(got, want) > 40


def test_size_candidates_without_a_goda_value_are_the_clis_nulls_and_empty_cells(tmp_path):
    # The sizing example searched down to 3 m: the narrow candidates tip about the heel under the
    # design wave (Goda's overturning safety factor below 1), so their heel pressure does not exist
    # (no resultant inside the base): `null` in size.json, an empty cell in candidates.csv, and in
    # Python None in the report and NaN in the frame. A front-end that turned it into a number (an
    # infinity, a 0) or dropped the candidate would drift here.
    p = short_size_toml(tmp_path, range_m=(3.0, 30.0))
    out = tmp_path / "out"
    cli("size", p, "--out", out)
    want = json.loads((out / "size.json").read_text())
    tipping = [c["width_m"] for c in want["candidates"] if c["goda_heel_pressure_kpa"] is None]
    assert len(tipping) >= 3 and min(tipping) == 3.0
    assert all(c["goda_overturning_safety_factor"] < 1.0 for c in want["candidates"] if c["width_m"] in tipping)
    got = caisson.size(caisson.Scenario.from_toml(p))
    assert assert_same_json(got.report, want) > 100
    frame = got.candidates
    nan_widths = [w for w, v in zip(frame["width_m"], frame["goda_heel_pressure_kpa"]) if math.isnan(v)]
    assert nan_widths == tipping
    rows = (out / "candidates.csv").read_text().splitlines()
    header = rows[0].split(",")
    # The frame holds every column of the CSV (but the precision's two, empty with a fixed number
    # of lives), the intervals of the impulsive shares among them.
    missing = set(header) - {"precision_lives", "precision_met"} - set(frame.columns)
    assert not missing and len(header) == 68, (missing, len(header))
    assert "dynamic_impulsive_share_of_failures_ci95_high" in frame.columns
    col = header.index("goda_heel_pressure_kpa")
    empty = [float(r.split(",")[0]) for r in rows[1:] if r.split(",")[col] == ""]
    assert empty == tipping


@pytest.mark.parametrize("rule", ["cuomo-2010", "goda-takahashi", "none"])
def test_the_breaking_load_gives_the_clis_loads_and_design(tmp_path, rule):
    # The 15 m site of the study (a berm: Goda's check with α_I; impulsive waves under both
    # rules with a peak) under each `[waves] breaking_load`, through `Scenario.replace`: the loads
    # report and a short design are the CLI's key for key and bit for bit (warnings included),
    # and each records the rule.
    sc = caisson.Scenario.from_toml(EXAMPLES / "study" / "site_15m.toml").replace(
        waves={"breaking_load": rule}, design={"lives": 6, "life_years": 10}
    )
    p = tmp_path / "site.toml"
    p.write_text(sc.to_toml())
    want = cli_json("loads", p)
    got = caisson.loads.report(sc)
    assert got["breaking_load"]["rule"] == rule
    assert assert_same_json(got, want) > 80
    table = caisson.loads.evaluate(sc, [3.0, 6.0, 9.0])
    assert list(table["breaking_load.rule"]) == [rule] * 3
    want = cli_json("design", p)
    got = caisson.Design(sc).run()[0].report
    assert got["model"]["breaking_load"] == rule
    assert assert_same_json(got, want) > 40


def test_goda_takahashi_without_the_berm_raises_the_clis_error(tmp_path):
    # `breaking_load = "goda-takahashi"` needs `[water] berm_width_m` (Takahashi's α_I): Python
    # raises the words the CLI prints for the same file, naming the key.
    sc = caisson.Scenario.from_toml(EXAMPLES / "design_breakwater.toml")
    with pytest.raises(caisson.ScenarioError) as err:
        sc.replace(waves={"breaking_load": "goda-takahashi"})
    assert err.value.key == "[water] berm_width_m"
    d = sc.to_dict()
    d["waves"] = {**d["waves"], "breaking_load": "goda-takahashi"}
    bad = tmp_path / "scenario.toml"
    bad.write_text(caisson._toml.dumps(d))
    for command in ("loads", "design"):
        r = cli(command, bad, check=False)
        assert r.returncode == 2 and "[water] berm_width_m" in r.stderr
        assert_replace_error_is_the_clis(err.value, "waves", r.stderr)
    # With the berm given it is accepted.
    assert sc.replace(water={"berm_width_m": 10.0}, waves={"breaking_load": "goda-takahashi"}) is not None


def test_the_breaking_site_design_is_the_clis_with_its_impulsive_shares_heel_pressures_and_warnings(tmp_path):
    # examples/breaking_site_15m.toml (issue 33's 15 m breaking-wave site) under the seed's impact
    # (`cuomo-2010`: impulsive waves make most of the answer), 60 lives of 20 years, with a failure
    # heel pressure of 380 kPa (a mode of its own): the impulsive groups, the heel exceedance, both
    # E|S| and their standard errors, the failure by heel pressure and the warnings, key for key
    # and bit for bit, Python against `caisson design --json`.
    sc = caisson.Scenario.from_toml(EXAMPLES / "breaking_site_15m.toml").replace(
        waves={"breaking_load": "cuomo-2010"},
        design={"lives": 60, "life_years": 20, "failure_heel_pressure_kpa": 380.0},
    )
    p = tmp_path / "breaking.toml"
    p.write_text(sc.to_toml())
    want = cli_json("design", p)
    design = caisson.Design(caisson.Scenario.from_toml(p))
    got = design.statistics(design.simulate_lives())
    assert assert_same_json(got.report, want) > 100
    assert "impulsive-share" in codes(want)
    for model in ("dynamic", "rigid_block"):
        i = want[model]["impulsive"]
        assert set(i) == {
            "waves",
            "sliding_m",
            "share_of_expected_sliding",
            "share_of_expected_sliding_ci95",
            "share_of_failures",
            "share_of_failures_ci95",
            "failures",
        }
        for share in ("share_of_expected_sliding", "share_of_failures"):
            low, high = i[f"{share}_ci95"]
            assert low <= i[share] <= high, (model, share, i)
    h = want["dynamic"]["heel_pressure_exceedance"]
    assert (h["allowable_kpa"], h["exact_from_kpa"]) == (400.0, 380.0)
    assert want["failure_heel_pressure_kpa"] == 380.0 and "by_heel_pressure" in want["dynamic"]["failure"]


def test_a_size_by_the_as_simulated_expected_sliding_is_the_clis(tmp_path):
    # The short sizing example with `expected_sliding = "as-simulated"`: both statistics, the
    # impulsive groups and the heel exceedance of every candidate, and the answer, bit for bit.
    sc = caisson.Scenario.from_toml(short_size_toml(tmp_path)).replace(size={"expected_sliding": "as-simulated"})
    p = tmp_path / "as_simulated.toml"
    p.write_text(sc.to_toml())
    out = tmp_path / "out"
    cli("size", p, "--out", out)
    want = json.loads((out / "size.json").read_text())
    got = caisson.size(caisson.Scenario.from_toml(p))
    assert assert_same_json(got.report, want) > 100
    assert want["criteria"]["expected_sliding"] == "as-simulated"
    for c in want["candidates"]:
        assert c["dynamic"]["expected_sliding_uncapped_standard_error_m"] >= 0.0 and "impulsive" in c["rigid_block"]
        assert 0.0 <= c["heel_pressure_exceedance"]["probability"] <= 1.0
