"""caisson.loads and caisson.waves against `caisson loads --json`, broadcasting, vectorisation."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest

import caisson
from conftest import EXAMPLES, cli_json, turns_while

LOAD_EXAMPLES = ["pari_breaking_loads.toml", "pari_nonbreaking_loads.toml", "design_breakwater.toml", "fragility.toml"]


def flatten(d: dict, prefix: str = "") -> dict:
    out = {}
    for k, v in d.items():
        key = f"{prefix}{k}"
        if isinstance(v, dict):
            out.update(flatten(v, key + "."))
        else:
            out[key] = v
    return out


@pytest.mark.parametrize("name", LOAD_EXAMPLES)
def test_report_and_evaluate_match_caisson_loads_json(name):
    p = EXAMPLES / name
    sc = caisson.Scenario.from_toml(p)
    want = cli_json("loads", p)
    assert caisson.loads.report(sc) == want
    flat = flatten(want)
    # The scenario's own height: H of a regular wave, H1/3 of an irregular sea (whose design wave
    # is H_max, docs/model.md §1.3).
    height = want["design_wave"]["significant_height_m"] or want["wave"]["incident_height_m"]
    frame = caisson.loads.evaluate(sc, [height])
    assert frame.attrs == {"caisson_version": want["caisson_version"], "results_version": want["results_version"]}
    row = frame.iloc[0].to_dict()
    flat.pop("caisson_version"), flat.pop("results_version")
    assert sorted(row) == sorted(flat)  # the CLI sorts the keys; the frame keeps the struct order
    for k, v in flat.items():
        if v is None:
            assert row[k] is None or (isinstance(row[k], float) and math.isnan(row[k])), k
        else:
            assert row[k] == v, k  # exact


def test_evaluate_is_the_report_of_each_height():
    p = EXAMPLES / "pari_breaking_loads.toml"
    sc = caisson.Scenario.from_toml(p)
    heights = np.linspace(0.05, 0.5, 7)
    frame = caisson.loads.evaluate(sc, heights)
    assert len(frame) == 7 and np.array_equal(frame["wave.incident_height_m"].to_numpy(), heights)
    for i, h in enumerate(heights):
        one = caisson.loads.report(sc.replace(waves={"height_m": float(h)}))
        assert frame["goda.horizontal_force_kn_per_m"][i] == one["goda"]["horizontal_force_kn_per_m"]
        assert frame["regime.regime"][i] == one["regime"]["regime"]
    # Regimes change along the heights (the example has both).
    assert set(frame["regime.regime"]) == {"breaking", "non-breaking"}


def test_every_column_of_every_row_is_the_report_of_its_height():
    """The columns hold every key of each height's `caisson loads --json`, exactly, in the JSON's
    order, including the keys that are null for some heights and numbers for others."""
    sc = caisson.Scenario.from_toml(EXAMPLES / "pari_breaking_loads.toml")
    # The first wave (2 m: breaking, no rise-time distribution, no heel pressure) has nulls where
    # later waves have numbers; both regimes.
    heights = np.array([2.0, 0.45, 0.05, 0.5, 0.3])
    frame = caisson.loads.evaluate(sc, heights)
    assert set(frame["regime.regime"]) == {"breaking", "non-breaking"}
    checked = widened = 0
    first = flatten(caisson.loads.report(sc.replace(waves={"height_m": float(heights[0])})))
    for i, h in enumerate(heights):
        flat = flatten(caisson.loads.report(sc.replace(waves={"height_m": float(h)})))
        flat.pop("caisson_version"), flat.pop("results_version")
        # Warnings are not columns: the 2 m wave would tip the flume caisson (Goda's overturning
        # factor below 1), so its report warns; the table has no warnings column.
        warnings = flat.pop("warnings", [])
        assert [w["code"] for w in warnings] == (["overturning-under-design-wave"] if h == 2.0 else []), (h, warnings)
        assert sorted(frame.columns) == sorted(flat)
        for k, v in flat.items():
            got = frame[k].iloc[i]
            if v is None:
                assert got is None or (isinstance(got, float) and math.isnan(got)), (h, k, got)
            else:
                assert got == v and type(v)(got) == v, (h, k, got, v)  # exact
                widened += first[k] is None
            checked += 1
    assert checked == len(heights) * len(frame.columns)
    assert widened > 0  # some column was null in the first row and has values later
    order = [k for k in first if k not in ("caisson_version", "results_version", "warnings")]
    assert list(frame.columns) == order  # the struct order of the JSON
    kinds = {str(frame[k].dtype) for k in frame.columns}
    assert kinds == {"float64", "bool", "category"}, kinds
    texts = [k for k in frame.columns if str(frame[k].dtype) == "category"]
    assert texts == [
        "wave.kind",
        "design_wave.rule",
        "regime.regime",
        "regime.breaker_criterion",
        "breaking_load.rule",
        "rise_time.model",
        "time_history.load_shape",
    ]


def test_evaluate_is_the_same_on_any_number_of_threads():
    """Blocks of rows on a local pool: the table (numbers, flags, and the text columns' codes and
    categories, in order of first appearance) is the one of one thread; an error is the first
    row's."""
    sc = caisson.Scenario.from_toml(EXAMPLES / "pari_breaking_loads.toml")
    # 12 000 waves in blocks of 2048 rows: the first blocks break, the last ones do not, so the
    # codes of the later blocks are renumbered.
    heights = np.concatenate([np.linspace(0.6, 0.4, 6000), np.linspace(0.3, 0.05, 6000)])
    one = caisson.loads.evaluate(sc, heights)
    assert list(one["regime.regime"].cat.categories) == ["breaking", "non-breaking"]
    assert one["regime.regime"].iloc[0] == "breaking" and one["regime.regime"].iloc[-1] == "non-breaking"
    for threads in (2, 3, 0):
        many = caisson.loads.evaluate(sc, heights, threads=threads)
        pd.testing.assert_frame_equal(many, one, check_exact=True)
        assert many.attrs == one.attrs
    # A wave that cannot be non-breaking (H ≥ H_br) at rows 7000 and 11 000: the error of row 7000.
    forced = sc.replace(waves={"regime": "non-breaking", "height_m": 0.1})
    h = np.full(12_000, 0.1)
    h[7000], h[11_000] = 0.5, 0.55
    messages = set()
    for threads in (1, 2, 3):
        with pytest.raises(caisson.ScenarioError) as e:
            caisson.loads.evaluate(forced, h, threads=threads)
        messages.add(str(e.value))
    assert len(messages) == 1 and "0.5" in messages.pop()


def test_evaluate_releases_the_gil():
    sc = caisson.Scenario.from_toml(EXAMPLES / "pari_breaking_loads.toml")
    heights = np.linspace(0.05, 0.5, 400_000)
    count = turns_while(caisson.loads.evaluate, sc, heights)
    # With the GIL held while the waves are evaluated, this loop could not have turned.
    assert count > 1000, count


def test_evaluate_broadcasts_heights_and_periods():
    sc = caisson.Scenario.from_toml(EXAMPLES / "pari_breaking_loads.toml")
    h = np.array([[0.1], [0.2]])
    t = np.array([2.0, 3.0, 4.0])
    f = caisson.loads.evaluate(sc, h, t)
    assert len(f) == 6
    assert list(f["wave.period_s"]) == [2.0, 3.0, 4.0] * 2
    assert list(f["wave.incident_height_m"]) == [0.1] * 3 + [0.2] * 3


def test_evaluate_refuses_bad_heights():
    sc = caisson.Scenario.from_toml(EXAMPLES / "pari_breaking_loads.toml")
    with pytest.raises(caisson.ScenarioError) as e:
        caisson.loads.evaluate(sc, [0.1, -0.2])
    assert e.value.key == "heights_m"


def test_wave_functions_match_the_loads_report_and_broadcast():
    p = EXAMPLES / "pari_breaking_loads.toml"
    rep = cli_json("loads", p)
    t, hs, d = rep["wave"]["period_s"], rep["site"]["depth_at_toe_m"], rep["site"]["depth_at_wall_m"]
    assert caisson.waves.wavelength_m(t, hs) == rep["wave"]["toe_wavelength_m"]
    assert caisson.waves.breaker_height_m(d, t) == rep["regime"]["breaker_height_at_wall_m"]
    assert caisson.waves.breaker_height_m(hs, t) == rep["wave"]["toe_breaker_height_m"] or math.isclose(
        caisson.waves.breaker_height_m(hs, t), rep["wave"]["toe_breaker_height_m"], rel_tol=1e-12
    )
    # Deep water: L0 = g T² / 2π.
    assert math.isclose(caisson.waves.wavelength_m(10.0, 1e4), 9.81 * 100 / (2 * math.pi), rel_tol=1e-12)
    grid = caisson.waves.wavelength_m(np.array([[4.0], [8.0]]), np.array([5.0, 10.0, 20.0]))
    assert grid.shape == (2, 3) and grid[1, 2] == caisson.waves.wavelength_m(8.0, 20.0)
    assert np.all(np.diff(grid, axis=1) > 0)  # longer in deeper water
    assert caisson.waves.breaker_height_m(2.0, 8.0, "mccowan") == 0.78 * 2.0
    g = caisson.waves.breaker_height_m(np.array([1.0, 2.0]), 8.0, "goda", slope=0.01)
    assert g.shape == (2,) and g[1] > g[0]
    with pytest.raises(ValueError):
        caisson.waves.breaker_height_m(1.0, 8.0, "oumeraci")


def test_surf_zone_heights_are_goda_s_and_broadcast():
    h13, hmax = caisson.waves.surf_zone_heights(np.array([3.0, 6.0, 9.0]), 12.8, 20.0, 0.01)
    assert h13.shape == (3,) and np.all(hmax > h13) and np.all(np.diff(h13) > 0)
    # Outside the surf zone (h/L0 ≥ 0.2) H_max = 1.8 H1/3 (docs/model.md §3.3).
    a, b = caisson.waves.surf_zone_heights(2.0, 6.0, 20.0, 0.01)
    assert b == 1.8 * a
    # Deep inside it the depth limits H1/3 (β0 H0' + β1 h < K_s H0').
    a, _ = caisson.waves.surf_zone_heights(8.0, 12.0, 4.0, 0.0)
    assert a < 0.6 * 8.0


def test_an_irregular_sea_is_checked_under_its_hmax():
    """Python's loads, like ``caisson loads``, check an irregular sea under Goda's H_max (13.451 m
    for the sizing example's H1/3 = 7.5 m, tests/verify_goda_design.rs), not under H1/3."""
    sc = caisson.Scenario.from_toml(EXAMPLES / "size_breakwater.toml")
    r = caisson.loads.report(sc)
    assert r["wave"]["kind"] == "irregular"
    assert r["design_wave"]["rule"] == "goda-breaking-limited"
    assert abs(r["goda"]["design_height_m"] - 13.451) < 1e-3
    frame = caisson.loads.evaluate(sc, [7.5, 3.0])
    assert frame["goda.design_height_m"].iloc[0] == r["goda"]["design_height_m"]
    assert frame["safety.sliding"].iloc[0] == r["safety"]["sliding"]
    assert frame["goda.design_height_m"].iloc[1] < 1.8 * 3.0 + 1e-9
