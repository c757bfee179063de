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


def evaluate(scenario, heights_m: Any, period_s: Any = None) -> pd.DataFrame:
    """The loads of ``caisson loads --json`` for many waves at the scenario's site and caisson.

    ``heights_m`` (incident wave heights, m) and ``period_s`` (default: the scenario's
    ``[waves] period_s``) broadcast against each other; one row per wave, in C order. Columns are
    the JSON keys joined by ``.``: ``wave.incident_height_m``, ``regime.regime``,
    ``goda.horizontal_force_kn_per_m``, ``impact.horizontal_force_kn_per_m``, ``safety.sliding``,
    ... (per metre of breakwater; kN, kPa, m). A key that is ``null`` in the JSON is NaN (None for
    text). ``caisson_version`` and ``results_version`` are in ``.attrs``.
    """
    h = np.asarray(heights_m, dtype=np.float64)
    if period_s is None:
        period_s = report(scenario)["wave"]["period_s"]
    h, t = np.broadcast_arrays(h, np.asarray(period_s, dtype=np.float64))
    h = np.ascontiguousarray(h).ravel()
    t = np.ascontiguousarray(t).ravel()
    names, cols = _core.loads_columns(scenario._core, h, t)
    return _frame(names, cols, len(h))


def _frame(names, cols, rows: int) -> pd.DataFrame:
    """A DataFrame of the columns of ``_core`` (numbers: numpy arrays, used without a copy;
    text: (codes, distinct values), code 2^32 − 1 null, as pandas' default text dtype)."""
    data = {}
    for name, col in zip(names, cols):
        if isinstance(col, tuple):
            codes, values = col
            # The distinct values as pandas makes text by default (None: missing), then one
            # vectorised take: the column pandas would make of the strings, faster.
            lookup = pd.Series(list(values) + [None]).array
            col = lookup.take(np.minimum(codes, len(values)).astype(np.intp))
        data[name] = col
    attrs = {}
    for k in ("caisson_version", "results_version"):
        v = data.pop(k)[0] if rows else None
        attrs[k] = v.item() if isinstance(v, np.generic) else v
    frame = pd.DataFrame(data, copy=False)
    frame.attrs.update(attrs)
    return frame
