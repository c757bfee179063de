"""Typed results: the same name for the same quantity in every kind of result and in the CLI's
JSON, numbers as the numbers they equal, a clean namespace."""

from __future__ import annotations

import caisson
import pytest

from conftest import EXAMPLES, cli_json, short_design_toml


def test_both_kinds_of_run_name_their_sliding_permanent_sliding_m():
    load = caisson.run(caisson.Scenario.from_toml(EXAMPLES / "table5_triangle.toml"))
    waves = caisson.run(caisson.Scenario.from_toml(EXAMPLES / "pari_breaking_loads.toml"))
    assert (load.kind, waves.kind) == ("load", "waves")
    # A [load] run: the summary's keys; a [waves] run: the means over its realizations.
    assert load.permanent_sliding_m == load.summary["permanent_sliding_m"]
    assert load.max_horizontal_reaction_kn == load.summary["max_horizontal_reaction_kn"]
    assert load.rigid_block_sliding_m is None and load.realizations is None
    per = [r["sliding_m"] for r in waves.summary["realizations"]]
    assert len(per) == len(waves.realizations) == waves.summary["waves"]["realizations"] > 1
    assert waves.permanent_sliding_m == pytest.approx(sum(per) / len(per), rel=1e-12)
    assert list(waves.realizations["sliding_m"]) == per
    assert waves.max_horizontal_reaction_kn == max(r["max_horizontal_reaction_kn"] for r in waves.summary["realizations"])
    # The seed's Table 5 run warns twice (README); the warnings are typed, codes first.
    assert [w.code for w in load.warnings] == [w["code"] for w in load.summary["warnings"]] and len(load.warnings) == 2


def test_design_statistics_are_typed_and_read_as_design_json(tmp_path):
    p = short_design_toml(tmp_path, lives=30, years=20)
    want = cli_json("design", p)
    d = caisson.Design(caisson.Scenario.from_toml(p))
    stats = d.statistics(d.simulate_lives())
    assert stats == want and stats.report == want and stats["dynamic"] == want["dynamic"]
    dyn = want["dynamic"]
    assert stats.dynamic.failure_probability == dyn["failure"]["probability"]
    assert stats.dynamic.failure_lives == dyn["failure"]["lives"]
    assert stats.dynamic.expected_sliding_m == dyn["expected_sliding_m"]
    assert stats.rigid_block.expected_sliding_m == want["rigid_block"]["expected_sliding_m"]
    assert stats.dynamic.exceedance_probability == {e["threshold_m"]: e["probability"] for e in dyn["exceedance_probability"]}
    assert len(stats.dynamic.exceedance_probability) == len(dyn["exceedance_probability"]) > 0
    assert (stats.lives, stats.life_years) == (30, 20)
    assert [w.code for w in stats.warnings] == [w["code"] for w in want["warnings"]]
    # Every estimate with its 95 % interval, typed as (low, high) tuples (docs/design.md,
    # Intervals): the JSON's numbers, and each interval around its estimate.
    checked = 0
    for model in ("dynamic", "rigid_block"):
        typed, m = getattr(stats, model), want[model]
        for key in ("expected_sliding", "expected_sliding_uncapped", "expected_sliding_per_year"):
            ci = getattr(typed, f"{key}_ci95_m")
            assert ci == tuple(m[f"{key}_ci95_m"]) and ci[0] <= getattr(typed, f"{key}_m") <= ci[1]
            checked += 1
        assert typed.expected_sliding_per_year_standard_error_m == m["expected_sliding_per_year_standard_error_m"]
        assert typed.failure_probability_ci95 == tuple(m["failure"]["probability_ci95"])
        assert typed.failure_probability_ci95[0] <= typed.failure_probability <= typed.failure_probability_ci95[1]
        assert typed.exceedance_ci95 == {e["threshold_m"]: tuple(e["ci95"]) for e in m["exceedance_probability"]}
        assert typed.percentiles_ci95_m == {k: tuple(v) for k, v in m["percentiles_ci95_m"].items()}
        assert typed.surviving_expected_sliding_ci95_m == tuple(m["surviving"]["expected_sliding_ci95_m"])
        checked += 1
    assert checked == 8


def test_a_whole_float_is_the_whole_number_it_equals():
    sc = caisson.Scenario.from_toml(EXAMPLES / "design_breakwater.toml")
    assert caisson.Design(sc.replace(design={"lives": 10.0})).lives == 10
    with pytest.raises(caisson.ScenarioError) as err:
        sc.replace(design={"lives": 10.5})
    assert str(err.value) == "replace(design={'lives': 10.5}): `[design] lives` must be a whole number (or \"auto\": lives to `target_relative_error`), got 10.5"
    # A real-valued key reads a whole float exactly (22.0 written as 22).
    assert sc.replace(caisson={"width_m": 22.0}).to_dict()["caisson"]["width_m"] == 22


def test_the_namespace_lists_the_package_and_nothing_it_imports():
    names = dir(caisson)
    assert names == sorted(caisson.__all__)
    for leaked in ("Any", "Optional", "Path", "dataclass", "np", "pd", "json", "os", "sys", "re"):
        assert leaked not in names
    for public in ("Scenario", "run", "Design", "DesignStatistics", "RunResult", "FragilityResult", "ResultWarning"):
        assert public in names
