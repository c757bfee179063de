"""A sweep of caisson widths × lives on Ray (`ray.init(num_cpus=2)` here; on a Ray cluster run it
with RAY_ADDRESS set, see docs/python.md).

    python examples/python/sweep_ray.py [--quick] [--workers 2]
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import _sweep  # noqa: E402

import ray  # noqa: E402


def main() -> None:
    a = _sweep.options(__doc__)
    ds = _sweep.designs(a)
    work = _sweep.tasks(a, ds)
    if os.environ.get("RAY_ADDRESS"):
        ray.init()
    else:
        ray.init(num_cpus=a.workers, include_dashboard=False, log_to_driver=False)
    try:
        simulate = ray.remote(num_cpus=1)(_sweep.simulate)
        t0 = _sweep.timer()
        frames = ray.get([simulate.remote(d, idx) for _, d, idx in work])
        seconds = _sweep.timer() - t0
    finally:
        ray.shutdown()
    results = [(b, df) for (b, _, _), df in zip(work, frames)]
    _sweep.report(a, ds, results, seconds, "ray")
    mid = sorted(ds)[len(ds) // 2]
    _sweep.one_caisson_check(ds, [df for b, df in results if b == mid], mid)


if __name__ == "__main__":
    main()
