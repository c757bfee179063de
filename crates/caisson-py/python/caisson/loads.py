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
    data = {}
    for name, col in zip(names, cols):
        if isinstance(col, tuple):  # text: (codes, distinct values); code 2^32 - 1 is null
            codes, values = col
            lookup = np.array(list(values) + [None], dtype=object)
            col = lookup[np.minimum(codes, len(values))]
        data[name] = col
    attrs = {k: data.pop(k)[0] if len(h) else None for k in ("caisson_version", "results_version")}
    frame = pd.DataFrame(data, copy=False)
    frame.attrs.update(attrs)
    return frame
