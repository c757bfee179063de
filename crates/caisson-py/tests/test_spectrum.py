"""caisson.spectrum against `caisson spectrum --json` and spectrum.csv bit for bit; order, threads
and progress; bad ratios and scenarios refused as the CLI refuses them."""

from __future__ import annotations

import json

import numpy as np
import pytest

import caisson
from conftest import EXAMPLES, assert_same_json, cli, read_csv_exact

TRIANGLE = EXAMPLES / "table5_triangle.toml"


def test_spectrum_matches_the_cli_bit_for_bit(tmp_path):
    out = tmp_path / "out"
    want = json.loads(cli("spectrum", TRIANGLE, "--tr-over-t0", "0.05:5:12", "--json", "--out", out).stdout)
    csv = read_csv_exact(out / "spectrum.csv")
    # The CLI's ratios (log-spaced: 0.05 is 5.000000000000001e-2) as a numpy array.
    ratios = np.array([p["tr_over_t0"] for p in want["points"]])
    assert len(ratios) == 12
    calls = []
    frame = caisson.spectrum(caisson.Scenario.from_toml(TRIANGLE), ratios, threads=2, progress=lambda a, b: calls.append((a, b)))
    assert calls[-1] == (12, 12)
    assert list(frame.columns) == list(csv.columns)  # the order of spectrum.csv
    n = assert_same_json(frame.to_dict("records"), want["points"])
    assert n == 12 * 8
    head = {k: v for k, v in want.items() if k != "points"}
    assert assert_same_json(dict(frame.attrs), head) >= 6
    assert np.array_equal(frame.to_numpy(), csv.to_numpy())  # exact
    # Not a flat table: the spectrum has a peak of Ψ and sliding that grows with the rise time.
    assert frame["psi"].max() > 1.0 and frame["permanent_sliding_m"].iloc[-1] > 0.0


def test_spectrum_rows_follow_the_ratios_in_any_order_on_any_thread_count():
    sc = caisson.Scenario.from_toml(TRIANGLE)
    ratios = np.array([2.0, 0.1, 0.7, 0.3])
    one = caisson.spectrum(sc, ratios)
    assert list(one["tr_over_t0"]) == list(ratios)
    two = caisson.spectrum(sc, ratios[::-1].copy(), threads=2)
    assert np.array_equal(two.to_numpy()[::-1], one.to_numpy())
    single = caisson.spectrum(sc, 0.7)  # a scalar is one ratio
    assert len(single) == 1 and np.array_equal(single.to_numpy()[0], one.to_numpy()[2])


def test_spectrum_refuses_bad_ratios_like_the_cli():
    sc = caisson.Scenario.from_toml(TRIANGLE)
    checked = 0
    for ratios, value in (([0.5, 0.0009], "0.0009"), ([1001.0], "1001"), ([np.nan], "NaN"), ([0.5, -1.0], "-1")):
        with pytest.raises(caisson.ScenarioError) as e:
            caisson.spectrum(sc, np.array(ratios))
        assert isinstance(e.value, ValueError)
        assert e.value.key == "tr_over_t0" and e.value.value == value, (e.value.key, e.value.value)
        assert "from 0.001 to 1000" in str(e.value) and e.value.allowed.startswith("finite numbers from 0.001 to 1000")
        checked += 1
    assert checked == 4
    # The CLI draws the same line.
    for arg in ("0.0009:1:3", "1:1001:3"):
        r = cli("spectrum", TRIANGLE, "--tr-over-t0", arg, check=False)
        assert r.returncode == 2 and "0.001 ≤ FROM < TO ≤ 1000" in r.stderr, r.stderr
    with pytest.raises(caisson.ScenarioError, match="is empty") as e:
        caisson.spectrum(sc, np.array([]))
    assert e.value.key == "tr_over_t0"
    with pytest.raises(caisson.ScenarioError, match="one-dimensional"):
        caisson.spectrum(sc, np.ones((2, 2)))
    # Work over the limit (10⁸ steps): about 2·10⁵ steps per point at t_r/T0 = 0.001.
    with pytest.raises(caisson.ScenarioError, match=r"about 2\.\d+e8 time steps .* at most 1e8") as e:
        caisson.spectrum(sc, np.full(1000, 0.001))
    assert e.value.key == "tr_over_t0"


def test_spectrum_needs_a_triangular_load():
    with pytest.raises(caisson.ScenarioError, match=r'needs `\[load\] kind = "triangle"`') as e:
        caisson.spectrum(caisson.Scenario.from_toml(EXAMPLES / "table5_series.toml"), [1.0])
    assert (e.value.key, e.value.value) == ("[load] kind", '"series"')
    with pytest.raises(caisson.ScenarioError, match="triangle") as e:
        caisson.spectrum(caisson.Scenario.from_toml(EXAMPLES / "pari_breaking_loads.toml"), [1.0])
    assert e.value.key == "[load]" and e.value.value is None
    r = cli("spectrum", EXAMPLES / "table5_series.toml", check=False)
    assert r.returncode == 2 and 'needs `[load] kind = "triangle"`' in r.stderr
