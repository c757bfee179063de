"""caisson.size against `caisson size` bit for bit; a CLI design checkpoint read, resumed and
merged from Python with the CLI's codec and merge rules (one library implementation)."""

from __future__ import annotations

import json

import pytest

import caisson
from conftest import EXAMPLES, assert_same_json, cli, cli_json, short_design_toml, short_size_toml


def test_size_is_caisson_size_bit_for_bit(tmp_path):
    p = short_size_toml(tmp_path)
    want = cli_json("size", p, "--threads", "2")
    calls = []
    got = caisson.size(caisson.Scenario.from_toml(p), threads=2, progress=lambda a, b: calls.append((a, b)))
    n = assert_same_json(got.report, want)
    assert n > 100 and len(want["candidates"]) >= 4
    # The typed fields are the report's.
    assert (got.width_m, got.rigid_block_width_m, got.goda_width_m) == (
        want["dynamic"].get("width_m"),
        want["rigid_block"].get("width_m"),
        want["goda"].get("width_m"),
    )
    assert len(got.candidates) == len(want["candidates"])
    assert list(got.candidates["width_m"]) == [c["width_m"] for c in want["candidates"]]
    assert list(got.candidates["dynamic_expected_sliding_m"]) == [c["dynamic"]["expected_sliding_m"] for c in want["candidates"]]
    # The intervals in two columns each, as candidates.csv has them.
    for model in ("dynamic", "rigid_block"):
        for key, low, high in (
            ("expected_sliding_ci95_m", "expected_sliding_ci95_low_m", "expected_sliding_ci95_high_m"),
            ("failure_probability_ci95", "failure_probability_ci95_low", "failure_probability_ci95_high"),
        ):
            assert list(got.candidates[f"{model}_{low}"]) == [c[model][key][0] for c in want["candidates"]]
            assert list(got.candidates[f"{model}_{high}"]) == [c[model][key][1] for c in want["candidates"]]
    assert [w.code for w in got.warnings] == [w["code"] for w in want["warnings"]]
    assert calls and calls[-1][0] == want["lives_simulated"]
    # The same answer on one thread.
    assert caisson.size(caisson.Scenario.from_toml(p)) == got


def test_a_stratified_auto_size_is_the_clis(tmp_path):
    """`[design] sampling = "stratified"` with `[size] lives = "auto"`: caisson.size gives the CLI's
    size.json, each candidate with its verdict (the rule read on the weighted estimates)."""
    sc = caisson.Scenario.from_toml(short_size_toml(tmp_path)).replace(
        design={"sampling": "stratified"},
        size={"lives": "auto", "target_relative_error": 0.2, "max_lives": 3000},
    )
    p = tmp_path / "stratified_auto.toml"
    p.write_text(sc.to_toml())
    want = cli_json("size", p, "--threads", "2")
    got = caisson.size(caisson.Scenario.from_toml(p), threads=2)
    n = assert_same_json(got.report, want)
    assert n > 100
    verdicts = [c["precision"] for c in want["candidates"]]
    assert len(verdicts) >= 4 and all(v["lives"] % 500 == 0 or v["lives"] == 3000 for v in verdicts), verdicts


def test_size_refuses_a_scenario_without_size_as_the_cli_does(tmp_path):
    p = EXAMPLES / "design_breakwater.toml"
    refused = cli("size", p, check=False)
    assert refused.returncode == 2 and "missing key `[size]`" in refused.stderr
    with pytest.raises(caisson.ScenarioError, match=r"^missing key `\[size\]`: `caisson.size` needs a \[size\] table"):
        caisson.size(caisson.Scenario.from_toml(p))


def test_a_cli_checkpoint_is_resumed_from_python_as_caisson_design_resume_completes_it(tmp_path):
    p = short_design_toml(tmp_path, lives=30, years=10)
    want = cli_json("design", p)
    out = tmp_path / "stopped"
    stopped = cli("design", p, "--threads", "1", "--stop-after", "11", "--out", out, check=False)
    assert stopped.returncode != 0 and (out / "checkpoint.jsonl").exists()
    d = caisson.Design(caisson.Scenario.from_toml(p))
    kept = caisson.read_checkpoint(d, out)
    assert len(kept) == 11 and list(kept["life"]) == sorted(kept["life"])
    stats, lives = caisson.resume(d, out, threads=2)
    assert assert_same_json(stats.report, want) > 40
    assert list(lives["life"]) == list(range(30))
    # A checkpoint of another scenario is refused, naming the file.
    other = caisson.Design(caisson.Scenario.from_toml(p).replace(design={"seed": 9}))
    with pytest.raises(ValueError, match="checkpoint.jsonl was written for a different scenario"):
        caisson.read_checkpoint(other, out)
    # An edited line is refused with its number.
    cp = out / "checkpoint.jsonl"
    lines = cp.read_text().splitlines(keepends=True)
    lines[3] = lines[3].replace('"waves":', '"waves":1', 1)
    cp.write_text("".join(lines))
    with pytest.raises(ValueError, match=r"line 4 does not match its check"):
        caisson.read_checkpoint(d, out)


def test_cli_shards_merged_in_python_are_caisson_merge(tmp_path):
    p = short_design_toml(tmp_path, lives=20, years=10)
    for r in ("0..7", "7..20"):
        cli("design", p, "--life-range", r, "--out", tmp_path / r)
    cli("merge", p, tmp_path / "7..20", tmp_path / "0..7", "--out", tmp_path / "m")
    want = json.loads((tmp_path / "m" / "design.json").read_text())
    d = caisson.Design(caisson.Scenario.from_toml(p))
    stats, lives = caisson.merge(d, [tmp_path / "7..20", tmp_path / "0..7"])
    assert assert_same_json(stats.report, want) > 40 and len(lives) == 20
    # The merge rules of the CLI: a gap and an overlap are refused, naming the shards.
    with pytest.raises(ValueError, match=r"lives 0\.\.7 are in no shard"):
        caisson.merge(d, [tmp_path / "7..20"])
    with pytest.raises(ValueError, match=r"life 0 is in two shards"):
        caisson.merge(d, [tmp_path / "0..7", tmp_path / "m"])
