"""Wave loads on the caisson (``caisson loads``, docs/waves.md), vectorised over wave heights."""

from __future__ import annotations

import json
from typing import Any, Optional

import numpy as np
import pandas as pd

from . import _core

__all__ = ["evaluate", "report"]


def report(scenario) -> dict:
    """The loads of the scenario's ``[waves]`` wave: the dict of ``caisson loads --json``."""
    return json.loads(_core.loads_report(scenario._core))


def evaluate(scenario, heights_m: Any, period_s: Any = None, *, threads: int = 1) -> pd.DataFrame:
    """The loads of ``caisson loads --json`` for many waves at the scenario's site and caisson.

    ``heights_m`` (m: the scenario's height key, H of regular waves or H1/3 at the toe of an
    irregular sea) and ``period_s`` (default: the scenario's ``[waves] period_s``) broadcast
    against each other; one row per height, in C order, each the ``caisson loads --json`` of the
    scenario with that height: Goda's check under its design wave (H; or H_max of the irregular
    sea, ``design_wave.rule`` and ``goda.design_height_m``, docs/model.md §1.3). Columns are
    the JSON keys joined by ``.``: ``wave.incident_height_m``, ``regime.regime``,
    ``goda.horizontal_force_kn_per_m``, ``impact.horizontal_force_kn_per_m``, ``safety.sliding``,
    ... (per metre of breakwater; kN, kPa, m): numbers as float64 (a ``null`` of the JSON is NaN),
    flags as bool, text (``wave.kind``, ``regime.regime``, ...) as pandas Categoricals.
    ``caisson_version`` and ``results_version`` are in ``.attrs``. ``threads``: 1 (default) this
    thread, 0 one per core, n a local pool of n (the same table on any number); the GIL is
    released while the waves are evaluated.
    """
    h = np.asarray(heights_m, dtype=np.float64)
    if period_s is None:
        period_s = report(scenario)["wave"]["period_s"]
    h, t = np.broadcast_arrays(h, np.asarray(period_s, dtype=np.float64))
    h = np.ascontiguousarray(h).ravel()
    t = np.ascontiguousarray(t).ravel()
    names, cols = _core.loads_columns(scenario._core, h, t, threads)
    return _frame(names, cols)


def _frame(names, cols) -> pd.DataFrame:
    """A DataFrame of the columns of ``_core.loads_columns`` (numbers and flags: numpy arrays,
    used without a copy; text: (int32 codes, distinct values), made a Categorical)."""
    data = {}
    for name, col in zip(names, cols):
        if isinstance(col, tuple):
            codes, values = col
            col = pd.Categorical.from_codes(codes, categories=pd.Index(values, dtype=object))
        data[name] = col
    frame = pd.DataFrame(data, copy=False)
    frame.attrs.update(caisson_version=_core.VERSION, results_version=_core.RESULTS_VERSION)
    return frame
