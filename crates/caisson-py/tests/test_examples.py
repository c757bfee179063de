"""The notebook-style quick start and the distributed sweeps run as a user runs them."""

from __future__ import annotations

import subprocess
import sys

import pytest

from conftest import ROOT


def run_example(tmp_path, name: str, *args: str) -> str:
    r = subprocess.run(
        [sys.executable, str(ROOT / "examples" / "python" / name), "--out", str(tmp_path), *args],
        capture_output=True,
        text=True,
        cwd=ROOT,
        timeout=600,
    )
    assert r.returncode == 0, r.stdout + r.stderr
    return r.stdout


def test_quickstart_runs(tmp_path):
    out = run_example(tmp_path, "quickstart.py")
    assert "permanent sliding" in out and "20 lives" in out
    assert (tmp_path / "quickstart.png").stat().st_size > 1000


@pytest.mark.parametrize("name", ["sweep_dask.py", "sweep_ray.py"])
def test_sweep_examples_run_and_check_their_shards(tmp_path, name):
    pytest.importorskip("dask.distributed" if "dask" in name else "ray")
    out = run_example(tmp_path, name, "--quick")
    assert "sharded = one process" in out
    table = (tmp_path / "sweep.csv").read_text().splitlines()
    assert table[0].startswith("width_m,lives,expected_sliding_m") and len(table) == 4
    assert (tmp_path / "sweep.png").stat().st_size > 1000
