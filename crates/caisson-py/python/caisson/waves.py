"""Linear wave theory, breaking and surf-zone heights, element-wise with numpy broadcasting (like
ufuncs): scalars in, numpy scalars out; arrays in, arrays of the broadcast shape out. SI units."""

from __future__ import annotations

from typing import Any

import numpy as np

from . import _core

__all__ = ["wavelength_m", "breaker_height_m", "surf_zone_heights"]


def _flat(*args: Any):
    arrs = np.broadcast_arrays(*[np.asarray(a, dtype=np.float64) for a in args])
    return arrs[0].shape, [np.ascontiguousarray(a).ravel() for a in arrs]


def _shaped(a: np.ndarray, shape):
    a = a.reshape(shape)
    return a[()] if shape == () else a


def wavelength_m(period_s: Any, depth_m: Any):
    """Linear wavelength L = 2π/k, ω² = g k tanh(k h), m."""
    shape, (t, d) = _flat(period_s, depth_m)
    return _shaped(_core.wavelength_m(t, d), shape)


def breaker_height_m(depth_m: Any, period_s: Any, criterion: str = "miche", *, slope: Any = 0.0, coefficient: float = None):
    """Breaker height H_b at depth h, m (docs/model.md §3): ``"miche"`` (0.142 L tanh(k h)),
    ``"goda"`` (breaker index, ``coefficient`` A = 0.17 and seabed ``slope`` tan θ) or
    ``"mccowan"`` (``coefficient`` γ_b = 0.78 times h)."""
    kinds = {"miche": (0, 0.0), "goda": (1, 0.17), "mccowan": (2, 0.78)}
    if criterion not in kinds:
        raise ValueError(f'criterion = "{criterion}": must be "miche", "goda" or "mccowan"')
    code, default = kinds[criterion]
    shape, (d, t, s) = _flat(depth_m, period_s, slope)
    return _shaped(_core.breaker_height_m(code, d, t, s, default if coefficient is None else float(coefficient)), shape)


def surf_zone_heights(h0_m: Any, period_s: Any, depth_m: Any, slope: Any = 0.0):
    """Goda's (2000) surf-zone H1/3 and H_max, m, at depth h for the deep-water H0' ``h0_m`` and
    period T1/3, seabed slope tan θ (docs/model.md §3.3): returns ``(h13_m, hmax_m)``."""
    shape, (h, t, d, s) = _flat(h0_m, period_s, depth_m, slope)
    a, b = _core.surf_zone_heights(h, t, d, s)
    return _shaped(a, shape), _shaped(b, shape)
