"""caisson.run against `caisson run` (summary.json, history.csv, springs.csv) bit for bit; force
series from numpy; wave trains; threads, progress and the GIL."""

from __future__ import annotations

import json

import numpy as np
import pandas as pd
import pytest

import caisson
from conftest import EXAMPLES, cli, cli_json, read_csv_exact, turns_while


@pytest.mark.parametrize("name", ["table5_triangle.toml", "table5_series.toml", "fifteen_waves.toml"])
def test_run_matches_the_cli_bit_for_bit(tmp_path, name):
    out = tmp_path / "out"
    cli("run", EXAMPLES / name, "--out", out)
    r = caisson.run(caisson.Scenario.from_toml(EXAMPLES / name))
    assert r.summary == json.loads((out / "summary.json").read_text())
    h = read_csv_exact(out / "history.csv")
    assert list(r.history.columns) == list(h.columns)
    pd.testing.assert_frame_equal(r.history, h, check_exact=True, check_dtype=False)
    s = read_csv_exact(out / "springs.csv")
    n = r.springs.sizes["spring"]
    assert np.array_equal(r.springs["normal_kn"].values, s[[f"normal_{i}_kn" for i in range(1, n + 1)]].values)
    assert np.array_equal(r.springs["shear_kn"].values, s[[f"shear_{i}_kn" for i in range(1, n + 1)]].values)
    assert np.array_equal(r.springs["uy_m"].values, s[[f"uy_{i}_m" for i in range(1, n + 1)]].values)
    assert np.array_equal(r.springs["x_m"].values, r.summary["spring_positions_m"])


def test_a_numpy_force_series_equals_the_same_series_from_a_file():
    csv = read_csv_exact(EXAMPLES / "forces_example.csv")
    sc = caisson.Scenario.from_toml(EXAMPLES / "table5_series.toml")
    from_file = caisson.run(sc)
    # The numpy series overrides the scenario's [load] (here the same CSV): the same numbers.
    r = caisson.run(
        sc,
        t_s=csv["time_s"].to_numpy(),
        fx_kn=csv["fx_kn"].to_numpy(),
        fy_kn=csv["fy_kn"].to_numpy(),
        moment_knm=csv["moment_knm"].to_numpy(),
    )
    assert r.summary == from_file.summary
    pd.testing.assert_frame_equal(r.history, from_file.history, check_exact=True)


def test_bad_force_series_is_refused_with_its_key():
    sc = caisson.Scenario.from_toml(EXAMPLES / "table5_triangle.toml")
    with pytest.raises(caisson.ScenarioError) as e:
        caisson.run(sc, t_s=[0.0, 0.1, 0.1], fx_kn=[0.0, 1.0, 0.0])
    assert e.value.key == "t_s"
    with pytest.raises(caisson.ScenarioError) as e:
        caisson.run(sc, t_s=[0.0, 0.1, 0.2], fx_kn=[0.0, np.nan, 0.0])
    assert e.value.key == "fx_kn"
    with pytest.raises(caisson.ScenarioError) as e:
        caisson.run(sc, t_s=[0.0, 0.1], fx_kn=[0.0, 1.0, 2.0])
    assert e.value.key == "fx_kn"


def test_wave_trains_match_the_cli_and_do_not_depend_on_threads():
    p = EXAMPLES / "pari_breaking_loads.toml"
    sc = caisson.Scenario.from_toml(p)
    calls = []
    one = caisson.run(sc, threads=1, progress=lambda done, total: calls.append((done, total)))
    two = caisson.run(sc, threads=2)
    assert one.summary == cli_json("run", p) == two.summary
    n = one.summary["waves"]["realizations"]
    assert calls and calls[-1] == (n, n) and all(a <= b for (a, _), (b, _) in zip(calls, calls[1:]))
    assert len(one.waves) == n * one.summary["waves"]["waves"]
    # Per-wave slides add up to the total (differences of the permanent sliding: rounding only).
    assert np.allclose(
        one.waves.groupby("realization")["sliding_m"].sum().values,
        [r["sliding_m"] for r in one.summary["realizations"]],
        rtol=1e-9,
        atol=1e-12,
    )


def test_runs_release_the_gil():
    sc = caisson.Scenario.from_toml(EXAMPLES / "design_breakwater.toml")
    d = caisson.Design(sc, lives=60)
    count = turns_while(d.simulate_lives)
    # With the GIL held by the run, this loop could not have turned while the lives ran.
    assert count > 1000, count


def test_a_failing_progress_callback_stops_with_its_error():
    sc = caisson.Scenario.from_toml(EXAMPLES / "pari_breaking_loads.toml")

    def boom(done, total):
        raise KeyError("from progress")

    with pytest.raises(KeyError):
        caisson.run(sc, progress=boom)
