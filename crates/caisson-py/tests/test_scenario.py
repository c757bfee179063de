"""Scenario: construction, validation errors with the CLI's words and keys, dicts, replace, pickling."""

from __future__ import annotations

import pickle

import pytest

import caisson
from conftest import EXAMPLES, assert_replace_error_is_the_clis, cli


def test_every_example_loads_and_round_trips_through_a_dict():
    n = 0
    for p in sorted(EXAMPLES.glob("*.toml")):
        sc = caisson.Scenario.from_toml(p)
        d = sc.to_dict()
        again = caisson.Scenario.from_dict(d, base_dir=EXAMPLES)
        assert again.to_dict() == d, p
        n += 1
    assert n >= 9


def test_from_toml_text_and_path_agree():
    p = EXAMPLES / "table5_triangle.toml"
    a = caisson.Scenario.from_toml(p)
    b = caisson.Scenario.from_toml(p.read_text(), base_dir=EXAMPLES)
    assert a == b and a.has_load and not a.has_waves and a.duration_s == 0.6


@pytest.mark.parametrize(
    "table, change, key, value",
    [
        ("caisson", {"width_m": -0.78}, "[caisson] width_m", "-0.78"),
        ("caisson", {"weight_in_water_kn": float("nan")}, "[caisson] weight_in_water_kn", "NaN"),
        ("foundation", {"springs": 1}, "[foundation] springs", "1"),
        ("foundation", {"mu_static": 0.3, "mu_dynamic": 0.5}, None, None),
        ("solver", {"dt_s": 2.0}, "[solver] dt_s", "2"),
        ("load", {"kind": "square"}, "[load] kind", None),
    ],
)
def test_bad_input_raises_scenario_error_with_the_cli_message(tmp_path, table, change, key, value):
    sc = caisson.Scenario.from_toml(EXAMPLES / "table5_triangle.toml")
    with pytest.raises(caisson.ScenarioError) as err:
        sc.replace(**{table: change})
    e = err.value
    assert isinstance(e, ValueError)
    if key is not None:
        assert e.key == key
    if value is not None:
        assert e.value == value
    # The CLI says the same words about the same file.
    d = sc.to_dict()
    d[table] = {**d.get(table, {}), **change}
    bad = tmp_path / "scenario.toml"
    bad.write_text(caisson._toml.dumps(d))
    r = cli("run", bad, check=False)
    assert r.returncode == 2
    assert_replace_error_is_the_clis(e, table, r.stderr)


def test_unknown_key_names_the_table_and_key():
    with pytest.raises(caisson.ScenarioError) as err:
        caisson.Scenario.from_toml(EXAMPLES / "table5_triangle.toml").replace(caisson={"widht_m": 1.0})
    assert err.value.key == "[caisson] widht_m"
    assert str(err.value).startswith("replace(caisson={'widht_m': 1.0}): unknown key `widht_m`, expected one of `width_m`")


def test_a_value_of_the_wrong_kind_names_the_key_and_the_kind(tmp_path):
    sc = caisson.Scenario.from_toml(EXAMPLES / "table5_triangle.toml")
    with pytest.raises(caisson.ScenarioError) as err:
        sc.replace(caisson={"width_m": "20"})
    e = err.value
    assert (e.key, e.value, e.allowed) == ("[caisson] width_m", '"20"', "must be a number (m)")
    assert str(e).endswith('`[caisson] width_m` must be a number (m), got the string "20"')
    with pytest.raises(caisson.ScenarioError) as err:
        sc.replace(foundation={"springs": 2.5})
    assert (err.value.key, err.value.value, err.value.allowed) == ("[foundation] springs", "2.5", "must be a whole number")


def test_missing_table_names_it():
    with pytest.raises(caisson.ScenarioError) as err:
        caisson.Design(caisson.Scenario.from_toml(EXAMPLES / "table5_triangle.toml"))
    assert err.value.key == "[design]"


def test_replace_changes_only_the_given_keys_and_none_removes():
    sc = caisson.Scenario.from_toml(EXAMPLES / "table5_triangle.toml")
    wider = sc.replace(caisson={"width_m": 0.9}, load={"peak_uplift_kn": None})
    d0, d1 = sc.to_dict(), wider.to_dict()
    assert d1["caisson"]["width_m"] == 0.9 and "peak_uplift_kn" not in d1["load"]
    d0["caisson"].pop("width_m"), d1["caisson"].pop("width_m")
    d0["load"].pop("peak_uplift_kn")
    assert d0 == d1
    assert sc.to_dict()["caisson"]["width_m"] == 0.78  # the original is unchanged


def test_objects_are_immutable():
    sc = caisson.Scenario.from_toml(EXAMPLES / "table5_triangle.toml")
    with pytest.raises(AttributeError):
        sc._text = "x"
    with pytest.raises(AttributeError):
        caisson.Design(caisson.Scenario.from_toml(EXAMPLES / "design_breakwater.toml")).x = 1


def test_pickling_round_trips():
    sc = caisson.Scenario.from_toml(EXAMPLES / "table5_series.toml")
    again = pickle.loads(pickle.dumps(sc))
    assert again == sc and again.path == sc.path and again.base_dir == sc.base_dir
    assert caisson.run(again).summary == caisson.run(sc).summary
    d = caisson.Design(caisson.Scenario.from_toml(EXAMPLES / "design_breakwater.toml"), lives=7)
    d2 = pickle.loads(pickle.dumps(d))
    assert d2.lives == 7 and d2.fingerprint == d.fingerprint
    f = caisson.Fragility(caisson.Scenario.from_toml(EXAMPLES / "fragility.toml"))
    assert pickle.loads(pickle.dumps(f)).scenario == f.scenario
    try:
        sc.replace(caisson={"width_m": -1.0})
    except caisson.ScenarioError as e:
        e2 = pickle.loads(pickle.dumps(e))
        assert (type(e2), str(e2), e2.key, e2.value, e2.allowed) == (type(e), str(e), e.key, e.value, e.allowed)
    else:
        pytest.fail("no error")


@pytest.mark.parametrize(
    "key, value",
    [
        ("sliding_safety_factor", 0.9),
        ("overturning_safety_factor", 11.0),
        ("allowable_heel_pressure_kpa", 5.0),
    ],
)
def test_bad_conventional_design_keys_are_refused_as_by_the_cli(tmp_path, key, value):
    """Goda's conventional width keys of ``[size]`` are validated by the library, in Python as in
    the CLI: the same key, the same words. As `caisson size` refuses them (and `caisson run` of the
    same file does not read ``[size]``), ``caisson.size`` does, before any work."""
    sc = caisson.Scenario.from_toml(EXAMPLES / "size_breakwater.toml").replace(size={key: value})
    with pytest.raises(caisson.ScenarioError) as err:
        caisson.size(sc)
    assert err.value.key == f"[size] {key}"
    bad = tmp_path / "scenario.toml"
    bad.write_text(sc.to_toml())
    r = cli("size", bad, check=False)
    assert r.returncode == 2
    assert str(err.value) == r.stderr.strip().removeprefix("Error: ")
