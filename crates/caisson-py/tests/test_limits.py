"""The work budget from Python (issue 12): `caisson.estimate` and `Design.estimate` give the CLI's
estimates, and the long entry points (`run`, `campaign`, `Design.simulate_lives`, `Fragility.run`)
refuse work over the budget before they start, with the CLI's words, as a `ScenarioError`."""

from __future__ import annotations

import re
import time

import pytest

import caisson
from conftest import EXAMPLES, cli


def load(name: str) -> caisson.Scenario:
    return caisson.Scenario.from_toml(EXAMPLES / name)


def what_it_would_take(message: str) -> str:
    """The estimate in a refusal: from "would take" to "; the budget is ... (docs/cli.md, Limits)"."""
    m = re.search(r"would take (.*); the budget is (.*) \(docs/cli\.md, Limits\)", message)
    assert m, message
    return m.group(1) + " | " + m.group(2)


def test_design_of_ten_million_lives_is_refused_with_the_cli_words(tmp_path):
    big = load("design_breakwater.toml").replace(design={"lives": 10_000_000})
    d = caisson.Design(big)
    with pytest.raises(caisson.ScenarioError) as e:
        d.simulate_lives()
    py = str(e.value)
    assert py.startswith("`Design.simulate_lives` would take about 3.72e11 waves"), py
    assert "indices=" in py
    assert (e.value.value, e.value.allowed) == ("3.72e11 waves", "at most 2e10 waves")
    scenario = tmp_path / "big.toml"
    scenario.write_text(big.to_toml())
    r = cli("design", scenario, check=False)
    assert r.returncode == 2 and r.stderr.startswith("Error: `caisson design` would take"), r.stderr
    # The same estimate and limit in both (only what to change is said in each one's own terms).
    assert what_it_would_take(py) == what_it_would_take(r.stderr), (py, r.stderr)
    est = caisson.estimate(big, "design")
    assert est["over_budget"] == "waves" and est["refusal"] == py


def test_a_shard_of_lives_is_estimated_at_its_own_count_and_runs():
    big = load("design_breakwater.toml").replace(design={"lives": 10_000_000})
    d = caisson.Design(big)
    whole, shard = d.estimate(), d.estimate(range(2))
    assert whole["over_budget"] == "waves" and shard["over_budget"] is None
    assert shard["waves"] == pytest.approx(whole["waves"] * 2 / 10_000_000, rel=1e-12)
    assert shard["basis"].startswith("2 lives × 50 years")
    assert shard == caisson.estimate(big, "design", lives=2)
    lives = d.simulate_lives(range(5, 7))
    assert list(lives["life"]) == [5, 6]


def test_design_lives_beyond_the_cap_are_refused():
    sc = load("design_breakwater.toml")
    for n in (0, 10_000_001, 10**9):
        with pytest.raises(caisson.ScenarioError, match="from 1 to 10000000, as `\\[design\\] lives`"):
            caisson.Design(sc, lives=n)
    assert caisson.Design(sc, lives=10_000_000).lives == 10_000_000


def test_a_run_holding_ten_million_history_rows_is_refused_and_runs_without_them():
    long = load("table5_triangle.toml").replace(load={"duration_s": 10000.0})
    est = caisson.estimate(long)
    assert est["over_budget"] == "memory" and est["disk_bytes"] == 0.0
    assert est["memory_bytes"] == pytest.approx(10000001 * (8 * 42 + 4 + 750))
    start = time.monotonic()
    with pytest.raises(caisson.ScenarioError) as e:
        caisson.run(long)
    assert time.monotonic() - start < 5, "refused before running"
    msg = str(e.value)
    assert "10.2 GiB of results held in memory" in msg and "10000001 history rows held" in msg, msg
    assert "history=False" in msg and e.value.allowed == "at most 4.0 GiB held"
    # Without the history nothing is held: within the budget (1e8 steps; not run here).
    assert caisson.estimate(long, history=False)["over_budget"] is None
    assert caisson.estimate(long, history=False)["memory_bytes"] == 0.0
    # A force series of numpy arrays is estimated on its duration.
    assert caisson.estimate(load("table5_triangle.toml"), duration_s=10000.0)["over_budget"] == "memory"


def test_trains_campaign_and_fragility_over_the_budget_are_refused_before_running():
    trains = load("pari_breaking_loads.toml").replace(waves={"waves": 10000, "realizations": 1000})
    camp = caisson.Scenario.from_toml(
        (EXAMPLES / "pari_breaking_campaign.toml").read_text().replace("waves = 15 ", "waves = 10000 ").replace("realizations = 10", "realizations = 1000"),
        base_dir=EXAMPLES,
    )
    frag = caisson.Scenario.from_toml(
        (EXAMPLES / "fragility.toml").read_text().replace("storms = 100 ", "storms = 1000000 "), base_dir=EXAMPLES
    )
    cases = [
        (lambda: caisson.run(trains), "`caisson.run`", "held in memory", caisson.estimate(trains, "run")),
        (lambda: caisson.campaign(camp), "`caisson.campaign`", "time steps", caisson.estimate(camp, "campaign")),
        (lambda: caisson.Fragility(frag).run(), "`Fragility.run`", "time steps", caisson.estimate(frag, "fragility")),
    ]
    for call, name, what, est in cases:
        start = time.monotonic()
        with pytest.raises(caisson.ScenarioError) as e:
            call()
        assert time.monotonic() - start < 10, f"{name}: refused before running"
        assert str(e.value).startswith(f"{name} would take about ") and what in str(e.value), str(e.value)
        assert est["refusal"] == str(e.value)
    assert len(cases) == 3


@pytest.mark.parametrize(
    "name, what",
    [
        ("table5_triangle.toml", "run"),
        ("pari_breaking_loads.toml", "run"),
        ("pari_breaking_campaign.toml", "campaign"),
        ("design_breakwater.toml", "design"),
        ("fragility.toml", "fragility"),
    ],
)
def test_every_example_is_within_the_budget_and_the_estimate_has_its_keys(name, what):
    est = caisson.estimate(load(name), what)
    keys = {
        "steps", "step_cost", "weighted_steps", "waves", "memory_bytes", "disk_bytes", "simulated_s",
        "simulated_share", "steps_from", "basis", "budget", "over_budget", "refusal",
    }
    assert set(est) == keys
    assert est["over_budget"] is None and est["refusal"] is None
    assert est["budget"] == caisson.BUDGET == {
        "steps": 2e10, "waves": 2e10, "memory_bytes": 4 * 2**30, "disk_bytes": 10 * 2**30,
    }
    assert 0 < est["weighted_steps"] < caisson.BUDGET["steps"] / 90
    assert est["disk_bytes"] == 0.0


def test_estimate_refuses_an_unknown_command():
    with pytest.raises(caisson.ScenarioError) as e:
        caisson.estimate(load("table5_triangle.toml"), "frobnicate")
    assert e.value.key == "what"
