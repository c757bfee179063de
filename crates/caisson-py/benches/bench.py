"""Benchmarks of the Python layer (BENCHMARKS.md, "Python package"): not tests, nothing asserted.

    .venv/bin/python crates/caisson-py/benches/bench.py [--dask] [--loads]

1. Call overhead of caisson.run on a short scenario (table5_triangle.toml cut to 100 steps, no
   history) against the same run timed inside Rust in the same process.
2. caisson.loads.evaluate on 10^5 heights (wall and CPU, one thread; wall with `threads=2` where
   the build has it; `--loads`: only this, e.g. with PYTHONPATH pointing at another build's
   python/ directory to compare two builds).
3. (--dask) The Dask sweep (examples/python/sweep_dask.py) on 1 and 2 workers.
"""

from __future__ import annotations

import argparse
import inspect
import re
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

import caisson
from caisson import _core

ROOT = Path(__file__).resolve().parents[3]


def best_of(f, repeats: int, number: int) -> float:
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        for _ in range(number):
            f()
        times.append((time.perf_counter() - t0) / number)
    return statistics.median(times)


def timed(f) -> tuple[float, float]:
    """(wall, CPU of this process) seconds of one call."""
    c0, t0 = time.process_time(), time.perf_counter()
    f()
    return time.perf_counter() - t0, time.process_time() - c0


def main() -> None:
    a = argparse.ArgumentParser()
    a.add_argument("--dask", action="store_true")
    a.add_argument("--loads", action="store_true", help="only caisson.loads.evaluate (e.g. to compare two builds)")
    a.add_argument("--sweep-args", default="--lives 480 --years 50 --shard 8 --widths 18 20 22")
    args = a.parse_args()

    if not args.loads:
        sc = caisson.Scenario.from_toml(ROOT / "examples" / "table5_triangle.toml").replace(load={"duration_s": 0.01})
        py = best_of(lambda: caisson.run(sc, history=False), repeats=7, number=300)
        rust = statistics.median(_core._bench_run_s(sc._core, 300) for _ in range(7))
        print(f"caisson.run, 100 steps, no history: Python {py * 1e6:.1f} µs per call, Rust {rust * 1e6:.1f} µs, overhead {(py - rust) * 1e6:.1f} µs")

    pari = caisson.Scenario.from_toml(ROOT / "examples" / "pari_breaking_loads.toml")
    heights = np.linspace(0.01, 0.6, 100_000)
    caisson.loads.evaluate(pari, heights[:1000])
    wall, cpu = zip(*(timed(lambda: caisson.loads.evaluate(pari, heights)) for _ in range(7)))
    t = statistics.median(wall)
    print(f"caisson.loads.evaluate, 1e5 heights, median of 7: {t:.3f} s wall ({t / 1e5 * 1e6:.2f} µs per wave), {statistics.median(cpu):.3f} s CPU")
    if "threads" in inspect.signature(caisson.loads.evaluate).parameters:  # builds after issue 10's second speed-up
        two = statistics.median(timed(lambda: caisson.loads.evaluate(pari, heights, threads=2))[0] for _ in range(7))
        print(f"  threads=2: {two:.3f} s wall")
    if hasattr(_core, "_bench_loads_s"):  # builds after the speed-up
        model = statistics.median(_core._bench_loads_s(pari._core, heights, 0) for _ in range(7))
        report = statistics.median(_core._bench_loads_s(pari._core, heights, 1) for _ in range(7))
        print(f"  inside Rust: the model {model:.3f} s, with the report rows {report:.3f} s (wall)")
    if args.loads:
        return

    if args.dask:
        secs = {}
        for w in (1, 2):
            out = subprocess.run(
                [sys.executable, str(ROOT / "examples/python/sweep_dask.py"), "--workers", str(w), *args.sweep_args.split()],
                capture_output=True, text=True, check=True,
            ).stdout
            secs[w] = float(re.search(r"in ([0-9.]+) s", out).group(1))
            print(f"dask sweep ({args.sweep_args}), {w} worker(s): {secs[w]:.2f} s")
        print(f"speed-up {secs[1] / secs[2]:.2f}, efficiency {secs[1] / secs[2] / 2 * 100:.0f} %")


if __name__ == "__main__":
    main()
