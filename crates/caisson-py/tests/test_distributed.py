"""A design sharded over a Dask LocalCluster (2 worker processes) and over Ray (2 CPUs), shards
submitted out of order, gives statistics identical to one `caisson design --json` process."""

from __future__ import annotations

import random

import pytest

import caisson
from conftest import cli_json, short_design_toml

LIVES = 40


def shards(n: int, size: int, seed: int) -> list[list[int]]:
    idx = list(range(n))
    random.Random(seed).shuffle(idx)
    return [idx[k : k + size] for k in range(0, n, size)]


def test_dask_local_cluster_shards_equal_one_cli_process(tmp_path):
    distributed = pytest.importorskip("dask.distributed")
    p = short_design_toml(tmp_path, lives=LIVES)
    want = cli_json("design", p)
    design = caisson.Design(caisson.Scenario.from_toml(p))

    def simulate(design: caisson.Design, indices: list[int]):  # local: pickled by value
        return design.simulate_lives(indices)

    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            futures = [client.submit(simulate, design, s, pure=False) for s in shards(LIVES, 6, seed=1)]
            parts = client.gather(futures)
            workers = {w for w in client.who_has(futures).values() for w in w}
    assert sum(len(x) for x in parts) == LIVES
    assert len(workers) >= 1
    assert design.statistics(parts) == want


def test_ray_shards_equal_one_cli_process(tmp_path):
    ray = pytest.importorskip("ray")
    p = short_design_toml(tmp_path, lives=LIVES)
    want = cli_json("design", p)
    design = caisson.Design(caisson.Scenario.from_toml(p))

    def simulate(design: caisson.Design, indices: list[int]):  # local: pickled by value
        return design.simulate_lives(indices)

    ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False)
    try:
        remote = ray.remote(simulate)
        parts = ray.get([remote.remote(design, s) for s in shards(LIVES, 6, seed=2)])
    finally:
        ray.shutdown()
    assert sum(len(x) for x in parts) == LIVES
    assert design.statistics(parts) == want
