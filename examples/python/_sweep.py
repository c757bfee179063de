"""The sweep shared by sweep_dask.py and sweep_ray.py: caisson widths × lives with common random
numbers (every width sees the same storms: life i draws from stream i of the same seed), and one
caisson's lives sharded. Only picklable objects (Design) and plain index lists travel to workers."""

from __future__ import annotations

import argparse
import pathlib
import tempfile
import time

import pandas as pd

import caisson

EXAMPLES = pathlib.Path(__file__).resolve().parents[1]


def options(description: str) -> argparse.Namespace:
    p = argparse.ArgumentParser(description=description)
    p.add_argument("--widths", type=float, nargs="+", default=[16.0, 18.0, 20.0, 22.0, 24.0], help="caisson widths, m")
    p.add_argument("--lives", type=int, default=200)
    p.add_argument("--years", type=int, default=50)
    p.add_argument("--shard", type=int, default=25, help="lives per task")
    p.add_argument("--workers", type=int, default=2)
    p.add_argument("--quick", action="store_true", help="3 widths × 16 lives of 10 years (CI)")
    p.add_argument("--out", type=pathlib.Path, default=pathlib.Path(tempfile.mkdtemp(prefix="caisson-sweep-")))
    a = p.parse_args()
    if a.quick:
        a.widths, a.lives, a.years, a.shard = [18.0, 20.0, 22.0], 16, 10, 4
    a.out.mkdir(parents=True, exist_ok=True)
    return a


def designs(a: argparse.Namespace) -> dict[float, caisson.Design]:
    """One Design per width; the weight in water grows with the width (same concrete section)."""
    base = caisson.Scenario.from_toml(EXAMPLES / "design_breakwater.toml").replace(
        design={"lives": a.lives, "life_years": a.years}
    )
    w0 = base.to_dict()["caisson"]
    return {
        b: caisson.Design(base.replace(caisson={"width_m": b, "weight_in_water_kn": w0["weight_in_water_kn"] * b / w0["width_m"]}))
        for b in a.widths
    }


def tasks(a: argparse.Namespace, ds: dict[float, caisson.Design]) -> list[tuple[float, caisson.Design, list[int]]]:
    """(width, design, life indices) for every shard, the larger widths first (any order works)."""
    return [(b, d, list(range(k, min(k + a.shard, a.lives)))) for b, d in sorted(ds.items(), reverse=True) for k in range(0, a.lives, a.shard)]


def simulate(design: caisson.Design, indices: list[int]) -> pd.DataFrame:
    return design.simulate_lives(indices)


def report(a: argparse.Namespace, ds: dict[float, caisson.Design], results: list[tuple[float, pd.DataFrame]], seconds: float, engine: str) -> pd.DataFrame:
    rows = []
    for b, d in sorted(ds.items()):
        s = d.statistics([df for w, df in results if w == b])
        rows.append(
            {
                "width_m": b,
                "lives": s["lives"],
                "expected_sliding_m": s["dynamic"]["expected_sliding_m"],
                "p95_sliding_m": s["dynamic"]["percentiles_m"]["p95"],
                "rigid_block_expected_sliding_m": s["rigid_block"]["expected_sliding_m"],
            }
        )
    table = pd.DataFrame(rows)
    print(f"{engine}: {len(ds)} widths × {a.lives} lives of {a.years} years on {a.workers} workers in {seconds:.1f} s")
    print(table.to_string(index=False))
    table.to_csv(a.out / "sweep.csv", index=False)
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6, 3.5))
    ax.plot(table["width_m"], table["expected_sliding_m"], "o-", label="dynamic model")
    ax.plot(table["width_m"], table["rigid_block_expected_sliding_m"], "s--", label="rigid block (Shimosako)")
    ax.set_xlabel("caisson width B (m)")
    ax.set_ylabel(f"expected sliding over {a.years} years (m)")
    ax.legend()
    fig.tight_layout()
    fig.savefig(a.out / "sweep.png", dpi=90)
    print("wrote", a.out / "sweep.csv", "and", a.out / "sweep.png")
    return table


def one_caisson_check(ds: dict[float, caisson.Design], parts: list[pd.DataFrame], width: float) -> dict:
    """The sharded lives of one caisson give exactly the statistics of one process."""
    d = ds[width]
    sharded = d.statistics(parts)
    local = d.statistics(d.simulate_lives(threads=0))
    assert sharded == local, "sharded statistics differ from one process"
    print(f"B = {width} m: {sharded['lives']} lives sharded = one process: expected sliding {sharded['dynamic']['expected_sliding_m']:.5f} m")
    return sharded


def timer() -> float:
    return time.perf_counter()
