"""A sweep of caisson widths × lives on Dask (a LocalCluster of 2 worker processes here; the same
code on any cluster: pass its scheduler address with --scheduler, see docs/python.md).

    python examples/python/sweep_dask.py [--quick] [--workers 2] [--scheduler tcp://host:8786]
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import _sweep  # noqa: E402

from dask.distributed import Client, LocalCluster  # noqa: E402


def main() -> None:
    a = _sweep.options(__doc__)
    ds = _sweep.designs(a)
    work = _sweep.tasks(a, ds)
    with LocalCluster(n_workers=a.workers, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, Client(cluster) as client:
        client.submit(sum, [1], pure=False).result()  # workers up before the clock starts
        t0 = _sweep.timer()
        futures = [client.submit(_sweep.simulate, d, idx, pure=False) for _, d, idx in work]
        frames = client.gather(futures)
        seconds = _sweep.timer() - t0
    results = [(b, df) for (b, _, _), df in zip(work, frames)]
    _sweep.report(a, ds, results, seconds, "dask")
    mid = sorted(ds)[len(ds) // 2]
    _sweep.one_caisson_check(ds, [df for b, df in results if b == mid], mid)


if __name__ == "__main__":
    main()
