"""`caisson.report`: the calculation note of `caisson report` (docs/report.md), by the CLI's own
exporter: the same report.html byte for byte, from a file or a Scenario, and the CLI's refusals."""

from __future__ import annotations

import caisson
import pytest

from conftest import cli, short_design_toml


def test_the_note_is_the_clis_byte_for_byte(tmp_path, monkeypatch):
    # The note's date from SOURCE_DATE_EPOCH (docs/report.md), so two notes can be compared.
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1764892800")
    p = short_design_toml(tmp_path, lives=40, years=20)
    cli("report", p, "--out", tmp_path / "cli", "--no-pdf", "--threads", "2")
    written = caisson.report(p, tmp_path / "py", threads=2, pdf=False)
    assert written == [str(tmp_path / "py" / "report.html")]
    want = (tmp_path / "cli" / "report.html").read_bytes()
    got = (tmp_path / "py" / "report.html").read_bytes()
    assert len(want) > 10_000 and got == want
    # A Scenario (here changed in memory) is written under its file name: the note of the same
    # file, and the change shows (80 lives instead of 40).
    sc = caisson.Scenario.from_toml(p)
    caisson.report(sc, tmp_path / "same", pdf=False)
    assert (tmp_path / "same" / "report.html").read_bytes() == want
    caisson.report([sc.replace(design={"lives": 80})], tmp_path / "more", pdf=False)
    more = (tmp_path / "more" / "report.html").read_text()
    assert more != want.decode() and "80" in more


def test_the_note_refuses_what_the_cli_refuses(tmp_path):
    missing = tmp_path / "missing.toml"
    refused = cli("report", missing, "--out", tmp_path / "cli", "--no-pdf", check=False)
    assert refused.returncode == 2
    with pytest.raises(caisson.ScenarioError) as e:
        caisson.report(missing, tmp_path / "py", pdf=False)
    assert str(e.value) == refused.stderr.strip().removeprefix("Error: ")
    assert not (tmp_path / "py" / "report.html").exists()
