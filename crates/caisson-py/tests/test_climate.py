"""The climate keys of [design] and [fragility] through Python's Scenario (docs/design.md,
"Climate"): the same numbers and the same record as the CLI, and the same refusals."""

import caisson
import pytest
from conftest import EXAMPLES, cli_json


def test_the_climate_example_through_python_is_the_cli(tmp_path):
    sc = caisson.Scenario.from_toml(EXAMPLES / "design_climate.toml").replace(design={"life_years": 20})
    p = tmp_path / "climate.toml"
    p.write_text(sc.to_toml())
    want = cli_json("design", p, "--lives", "12")
    stats, lives = caisson.Design(caisson.Scenario.from_toml(p), lives=12).run(threads=2)
    assert stats == want
    assert len(lives) == 12
    c = stats["climate"]
    assert c["storms"] == {"kind": "peaks-over-threshold", "rate_per_year": 3.0, "threshold_m": 4.0}
    assert c["wave_direction"]["kind"] == "normal"
    assert c["sea_level_rise"] == {"kind": "linear", "rise_m": 0.5, "life_years": 20.0}


def test_climate_keys_change_the_lives_and_the_defaults_do_not():
    sc = caisson.Scenario.from_toml(EXAMPLES / "design_breakwater.toml").replace(design={"life_years": 5})
    base = caisson.Design(sc, lives=6).simulate_lives()
    same = caisson.Design(sc.replace(design={"storm_model": "annual-maxima", "error_scope": "storm"}), lives=6)
    assert same.simulate_lives().equals(base)
    pot = caisson.Design(
        sc.replace(design={"storm_model": "peaks-over-threshold", "storm_rate_per_year": 3.0, "storm_threshold_m": 4.5}),
        lives=6,
    ).simulate_lives()
    # About three times the storms, so about three times the waves.
    assert pot["waves"].sum() > 2 * base["waves"].sum()


@pytest.mark.parametrize(
    "table, keys, named",
    [
        ("design", {"storm_model": "peaks-over-threshold", "storm_threshold_m": 4.0}, "[design] storm_rate_per_year"),
        ("design", {"storm_duration_model": "lognormal", "storm_duration_cov": 3.0}, "[design] storm_duration_cov"),
        ("design", {"sea_level_rise_m": 9.0}, "[design] sea_level_rise_m"),
        ("design", {"wave_direction": "uniform", "wave_direction_spread_deg": 90.0}, "[design] wave_direction_spread_deg"),
        ("design", {"error_scope": "year"}, "[design] error_scope"),
        ("design", {"impact_force_cov": -0.1}, "[design] impact_force_cov"),
        ("design", {"wave_periods": "longuet-higgins", "period_spectral_width": 0.9}, "[design] period_spectral_width"),
        ("design", {"wave_periods": "individual"}, "[design] wave_periods"),
    ],
)
def test_climate_keys_out_of_range_are_refused_naming_them(table, keys, named):
    sc = caisson.Scenario.from_toml(EXAMPLES / "design_breakwater.toml")
    with pytest.raises(caisson.ScenarioError) as err:
        sc.replace(**{table: keys})
    assert named in str(err.value)


def test_fragility_directions_through_python_are_the_cli(tmp_path):
    sc = caisson.Scenario.from_toml(EXAMPLES / "fragility.toml").replace(
        fragility={
            "storms": 6,
            "significant_heights_m": [9.0, 10.0],
            "storm_duration_h": 0.3,
            "storm_duration_model": "lognormal",
            "storm_duration_cov": 0.5,
            "wave_direction": "uniform",
            "wave_direction_mean_deg": 30.0,
            "wave_direction_spread_deg": 15.0,
        }
    )
    p = tmp_path / "fragility_climate.toml"
    p.write_text(sc.to_toml())
    want = cli_json("fragility", p)
    r = caisson.Fragility(caisson.Scenario.from_toml(p)).run(threads=2)
    assert r.summary == want
    assert want["storm_duration"] == {"kind": "lognormal", "cov": 0.5}
    assert want["wave_direction"]["kind"] == "uniform"
    with pytest.raises(caisson.ScenarioError, match=r"\[fragility\] wave_direction_spread_deg"):
        caisson.Fragility(sc.replace(fragility={"wave_direction_spread_deg": 0.0})).run()


def test_wave_by_wave_periods_through_python_are_the_cli(tmp_path):
    """`[design] wave_periods` through Python: the CLI's design.json, its record, and lives that
    differ from those at T1/3 (same storms, so the same waves; these short lives slide nothing,
    but the simulated waves rotate the caisson differently); `[fragility]` refuses a spectral
    width out of range naming it."""
    sc = caisson.Scenario.from_toml(EXAMPLES / "design_breakwater.toml").replace(design={"life_years": 5})
    lh = sc.replace(design={"wave_periods": "longuet-higgins"})
    p = tmp_path / "periods.toml"
    p.write_text(lh.to_toml())
    want = cli_json("design", p, "--lives", "8")
    stats, lives = caisson.Design(caisson.Scenario.from_toml(p), lives=8).run(threads=2)
    assert stats == want
    assert want["climate"]["wave_periods"] == {"kind": "longuet-higgins", "spectral_width": 0.39}
    base = caisson.Design(sc, lives=8).simulate_lives()
    assert (lives["waves"].to_numpy() == base["waves"].to_numpy()).all()
    assert lives["simulated_waves"].sum() > 0
    assert not lives["max_rotation_rad"].equals(base["max_rotation_rad"])
    fragility = caisson.Scenario.from_toml(EXAMPLES / "fragility.toml").replace(
        fragility={"wave_periods": "longuet-higgins", "period_spectral_width": 0.01}
    )
    with pytest.raises(caisson.ScenarioError, match=r"\[fragility\] period_spectral_width"):
        caisson.Fragility(fragility).run()
