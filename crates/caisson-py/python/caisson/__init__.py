"""caisson: how far a caisson breakwater slides under waves (Python bindings of the Rust engine).

A thin layer: every number is computed by the Rust library (the same code as the ``caisson``
command); this package only assembles its results into typed results (:class:`RunResult`,
:class:`DesignStatistics`, :class:`FragilityResult`: fields with their units, the same name for
the same quantity in every result, docs/python.md "Results"), pandas DataFrames and xarray
Datasets. Units are in every field, key and column name (``sliding_m``, ``fx_kn``); each result
keeps the CLI's JSON report it was built from, with exactly its keys (docs/cli.md,
docs/design.md, docs/fragility.md).

Runs that could take long (``run``, ``campaign``, ``Design.simulate_lives``, ``Fragility.run``)
estimate their work first and raise :class:`ScenarioError` beyond the CLI's budget
(:func:`estimate`, docs/cli.md "Limits").

Objects are validated when built, immutable and picklable. Every run releases the GIL; parallel
drivers run on a local pool of ``threads`` worker threads (default 1, 0 = one per core), never on
a global pool, so Dask and Ray workers can each run one task per core. ``progress(done, total)``
is called from the calling thread about every 0.1 s while work finishes.

>>> import caisson
>>> sc = caisson.Scenario.from_toml("examples/table5_triangle.toml")
>>> r = caisson.run(sc)
>>> r.permanent_sliding_m, r.history[["time_s", "fx_kn", "ux_m"]]
"""

from __future__ import annotations

import json
import os
import re
import sys
from pathlib import Path
from typing import Any, Callable, Iterable, Mapping, Optional, Sequence, Union

import numpy as np
import pandas as pd

from . import _core, _toml
from ._core import FitError, RunError, ScenarioError
from .results import DesignStatistics, FragilityResult, ModelStatistics, ResultWarning, RunResult, SizeResult

__all__ = [
    "Scenario",
    "ScenarioError",
    "RunError",
    "FitError",
    "RunResult",
    "DesignStatistics",
    "ModelStatistics",
    "ResultWarning",
    "SizeResult",
    "run",
    "campaign",
    "spectrum",
    "Design",
    "Fragility",
    "FragilityResult",
    "fit_lognormal",
    "estimate",
    "BUDGET",
    "loads",
    "waves",
    "__version__",
    "RESULTS_VERSION",
    "LIVES_OF",
]

__version__: str = _core.VERSION
#: Raised whenever a change moves any number for the same input; results of different versions
#: are never comparable.
RESULTS_VERSION: int = _core.RESULTS_VERSION

Progress = Optional[Callable[[int, int], Any]]

if sys.version_info >= (3, 11):
    import tomllib as _tomllib
else:  # pragma: no cover
    _tomllib = None


def _looks_like_text(s: str) -> bool:
    return "\n" in s or "=" in s or s.lstrip().startswith("[")


class Scenario:
    """A validated scenario file (docs/scenario.md): immutable, picklable (by its TOML text).

    Build it with :meth:`from_toml` (a path or TOML text) or :meth:`from_dict`; change it with
    :meth:`replace`. Bad input raises :class:`ScenarioError` (a ``ValueError``) whose message is
    the CLI's and whose ``.key``, ``.value`` and ``.allowed`` say what to fix.
    """

    __slots__ = ("_text", "_path", "_base_dir", "_core")

    def __init__(self, text: str, *, path: str = "scenario.toml", base_dir: Union[str, os.PathLike] = ".") -> None:
        core = _core.CoreScenario(text, str(path), str(base_dir))
        object.__setattr__(self, "_text", text)
        object.__setattr__(self, "_path", str(path))
        object.__setattr__(self, "_base_dir", str(base_dir))
        object.__setattr__(self, "_core", core)

    @classmethod
    def from_toml(cls, source: Union[str, os.PathLike], *, base_dir: Union[str, os.PathLike, None] = None) -> "Scenario":
        """A scenario from a TOML file (a path) or TOML text. Relative file names in it (a force
        series) are taken from the file's directory, or from ``base_dir`` (default: the current
        directory for text)."""
        if isinstance(source, os.PathLike) or (isinstance(source, str) and not _looks_like_text(source)):
            p = Path(source)
            # As the CLI reads it: at most 1 MiB, a regular file (never a FIFO or /dev/zero).
            text = _core.read_scenario(str(p))
            return cls(text, path=str(source), base_dir=base_dir if base_dir is not None else (p.parent or Path(".")))
        return cls(str(source), base_dir=base_dir if base_dir is not None else ".")

    @classmethod
    def from_dict(cls, d: Mapping[str, Any], *, base_dir: Union[str, os.PathLike] = ".") -> "Scenario":
        """A scenario from a dictionary of tables, as :meth:`to_dict` gives (``{"caisson":
        {"width_m": 0.78, ...}, ...}``; ``None`` values are left out)."""
        return cls(_toml.dumps(d), base_dir=base_dir)

    def to_dict(self) -> dict:
        """The scenario's tables as written (keys and units of the file)."""
        if _tomllib is None:  # pragma: no cover
            raise RuntimeError("to_dict needs Python 3.11 (tomllib)")
        return _tomllib.loads(self._text)

    def to_toml(self) -> str:
        """The TOML text of the scenario."""
        return self._text

    def replace(self, **tables: Mapping[str, Any]) -> "Scenario":
        """A new scenario with keys of tables changed, e.g. ``sc.replace(caisson={"width_m": 22.0},
        design={"lives": 100})``; a value ``None`` removes the key; a number is taken as the number
        it equals (``lives=10.0`` is 10). Validated again: an error names the key and the value
        given (``replace(caisson={'widht_m': 1.0})``), never a line of the generated TOML."""
        d = self.to_dict()
        for table, keys in tables.items():
            if keys is None:
                d.pop(table, None)
                continue
            if not isinstance(keys, Mapping):
                raise TypeError(
                    f"`{table}` = {keys!r}: must be a dict of the table's keys and values "
                    f"(replace({table}={{'key': value}})), or None to remove the table"
                )
            t = dict(d.get(table, {}))
            for k, v in keys.items():
                if v is None:
                    t.pop(k, None)
                else:
                    t[k] = v
            d[table] = t
        try:
            return Scenario(_toml.dumps(d), path=self._path, base_dir=self._base_dir)
        except ScenarioError as e:
            raise _replace_error(e, tables, self._path) from None

    @property
    def path(self) -> str:
        """The file it was read from (``scenario.toml`` for text)."""
        return self._path

    @property
    def base_dir(self) -> str:
        return self._base_dir

    @property
    def has_load(self) -> bool:
        return self._core.has_load

    @property
    def has_waves(self) -> bool:
        return self._core.has_waves

    @property
    def has_campaign(self) -> bool:
        return self._core.has_campaign

    @property
    def has_design(self) -> bool:
        return self._core.has_design

    @property
    def has_fragility(self) -> bool:
        return self._core.has_fragility

    @property
    def duration_s(self) -> float:
        """Simulated time of a ``[load]`` run, s."""
        return self._core.duration_s

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError("a Scenario is immutable: use replace()")

    def __reduce__(self):
        return (_restore_scenario, (self._text, self._path, self._base_dir))

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Scenario) and (self._text, self._base_dir) == (other._text, other._base_dir)

    def __hash__(self) -> int:
        return hash((self._text, self._base_dir))

    def __repr__(self) -> str:
        tables = [t for t in ("load", "waves", "campaign", "design", "fragility") if getattr(self, f"has_{t}")]
        return f"Scenario({self._path!r}, tables: caisson, foundation, {', '.join(tables)})"


def _replace_error(e: ScenarioError, tables: Mapping[str, Any], path: str) -> ScenarioError:
    """``e`` of a scenario built by :meth:`Scenario.replace`, in the caller's words: the
    message without the place in the generated TOML text, and the change it comes from."""
    message = re.sub(r"^" + re.escape(path) + r" line \d+(, column \d+)?: ", "", str(e))
    message = re.sub(r" \(in `[^`]*`\)$", "", message)
    m = re.match(r"^\[([^\]]+)\](?: (.+))?$", getattr(e, "key", None) or "")
    # The change the error is about: the key, else its table, else every change given.
    given = "replace(" + ", ".join(f"{t}={v!r}" for t, v in tables.items()) + "): "
    if m and m.group(1) in tables and tables[m.group(1)] is not None:
        table, name = m.group(1), m.group(2)
        if name is not None and name in tables[table]:
            given = f"replace({table}={{{name!r}: {tables[table][name]!r}}}): "
        else:
            given = f"replace({table}={tables[table]!r}): "
    out = ScenarioError(given + message.replace("unknown field", "unknown key", 1))
    out.key = getattr(e, "key", None)
    out.value = getattr(e, "value", None)
    out.allowed = getattr(e, "allowed", None)
    return out


def _restore_scenario(text: str, path: str, base_dir: str) -> Scenario:
    return Scenario(text, path=path, base_dir=base_dir)


def _springs_dataset(time_s: np.ndarray, s: dict):
    import xarray as xr

    n = len(s["x_m"])
    return xr.Dataset(
        {
            "normal_kn": (("time_s", "spring"), s["normal_kn"]),
            "shear_kn": (("time_s", "spring"), s["shear_kn"]),
            "uy_m": (("time_s", "spring"), s["uy_m"]),
        },
        coords={"time_s": time_s, "spring": np.arange(1, n + 1), "x_m": ("spring", s["x_m"])},
        attrs={
            "normal_kn": "normal force of each spring, compression +",
            "shear_kn": "shear force, + when it pushes the caisson seaward",
            "uy_m": "vertical displacement of each spring, up +",
            "x_m": "spring position from the base centre, shoreward +",
        },
    )


def _waves_frame(summary: dict) -> pd.DataFrame:
    rows = []
    for r in summary["realizations"]:
        for j, w in enumerate(r["waves"]):
            rows.append(
                {
                    "realization": r["index"],
                    "wave": j,
                    "start_s": w["start_s"],
                    "height_m": w["height_m"],
                    "regime": w["regime"],
                    "rise_time_s": w.get("rise_time_s", np.nan),
                    "sliding_m": w["sliding_m"],
                    "rigid_block_sliding_m": w["rigid_block_sliding_m"],
                    "max_horizontal_reaction_kn": w["max_horizontal_reaction_kn"],
                }
            )
    return pd.DataFrame(rows)


def _array(name: str, v: Any) -> np.ndarray:
    a = np.ascontiguousarray(np.asarray(v, dtype=np.float64))
    if a.ndim != 1:
        raise ScenarioError(f"`{name}`: must be a one-dimensional series")
    return a


def run(
    scenario: Scenario,
    *,
    t_s: Any = None,
    fx_kn: Any = None,
    fy_kn: Any = None,
    moment_knm: Any = None,
    duration_s: Optional[float] = None,
    history: bool = True,
    threads: int = 1,
    progress: Progress = None,
) -> RunResult:
    """One dynamic run (``caisson run``).

    With ``t_s`` (s) and ``fx_kn`` (kN, shoreward +) and optionally ``fy_kn`` (uplift, kN, up +)
    and ``moment_knm`` (kN·m about the base centre, clockwise +), totals on the caisson: that force
    series is run instead of the scenario's ``[load]`` (linear between samples, held outside
    them, as ``[load] kind = "series"``) for ``duration_s`` (default: to the last sample).
    A scenario with ``[waves]`` and no ``[load]`` runs its wave trains (``threads``, ``progress``:
    per realization). See :class:`RunResult`.
    """
    _core.check_threads(threads)
    if t_s is not None or fx_kn is not None:
        if t_s is None or fx_kn is None:
            raise ScenarioError("a force series needs both t_s and fx_kn")
        t = _array("t_s", t_s)
        zeros = np.zeros_like(t)
        series = (
            t,
            _array("fx_kn", fx_kn),
            _array("fy_kn", zeros if fy_kn is None else fy_kn),
            _array("moment_knm", zeros if moment_knm is None else moment_knm),
        )
        return _run_load(scenario, series, duration_s, history)
    if scenario.has_load or not scenario.has_waves:
        return _run_load(scenario, None, duration_s, history)
    summary = json.loads(_core.run_trains(scenario._core, threads, progress))
    return RunResult.of_waves(summary, _waves_frame(summary))


def _run_load(scenario: Scenario, series, duration_s, history: bool) -> RunResult:
    text, cols = _core.run_load(scenario._core, series, duration_s, history)
    summary = json.loads(text)
    if cols is None:
        return RunResult.of_load(summary)
    h, s = cols
    return RunResult.of_load(summary, pd.DataFrame(h), _springs_dataset(h["time_s"], s))


def campaign(
    scenario: Scenario,
    *,
    damping_mode: Optional[str] = None,
    threads: int = 1,
    progress: Progress = None,
):
    """The scenario's ``[campaign]`` (``caisson campaign``) as an ``xarray.Dataset``.

    Dims ``condition`` × ``realization``. Per condition and realization: ``sliding_m``,
    ``rigid_block_sliding_m``, ``max_horizontal_reaction_kn``, ``slip_events``. Per condition:
    ``height_m``, ``weight_in_water_kn``, ``regime``, ``nominal_regime``,
    ``goda_horizontal_force_kn_per_m``, ``goda_uplift_force_kn_per_m``,
    ``impact_horizontal_force_kn_per_m``, ``sliding_safety_factor`` (NaN if undefined) and the
    spreads of ``campaign.csv`` (``sliding_mean_m``, ...). ``attrs["report_json"]`` is the text of
    ``campaign.json``. ``progress``: per realization.
    """
    import xarray as xr

    stem = Path(scenario.path).stem or "campaign"
    report = json.loads(_core.campaign(scenario._core, stem, damping_mode, threads, progress))
    conds = report["conditions"]
    nr = max(len(c["realization_sliding_m"]) for c in conds)

    def per_real(get) -> np.ndarray:
        a = np.full((len(conds), nr), np.nan)
        for i, c in enumerate(conds):
            v = [get(r) for r in c["realizations"]]
            a[i, : len(v)] = v
        return a

    dims = ("condition", "realization")
    data = {
        "sliding_m": (dims, per_real(lambda r: r["sliding_m"])),
        "rigid_block_sliding_m": (dims, per_real(lambda r: r["rigid_block_sliding_m"])),
        "max_horizontal_reaction_kn": (dims, per_real(lambda r: r["max_horizontal_reaction_kn"])),
        "slip_events": (dims, per_real(lambda r: r["slip_events"])),
    }
    col = lambda f: ("condition", np.array([f(c) for c in conds]))  # noqa: E731
    for key in (
        "height_m",
        "weight_in_water_kn",
        "regime",
        "nominal_regime",
        "goda_horizontal_force_kn_per_m",
        "goda_uplift_force_kn_per_m",
        "impact_horizontal_force_kn_per_m",
    ):
        data[key] = col(lambda c, k=key: c[k])
    data["sliding_safety_factor"] = col(lambda c: c.get("sliding_safety_factor", np.nan))
    for name, key, unit in (
        ("sliding", "sliding_m", "m"),
        ("rigid_block", "rigid_block_sliding_m", "m"),
        ("max_horizontal_reaction", "max_horizontal_reaction_kn", "kn"),
    ):
        for stat in ("mean", "min", "max"):
            data[f"{name}_{stat}_{unit}"] = col(lambda c, k=key, s=stat: c[k][s])
    data["slip_events_mean"] = col(lambda c: c["slip_events"]["mean"])
    attrs = {
        "title": report["title"],
        "waves_description": report["waves"]["description"],
        "waves": report["waves"]["waves"],
        "realizations": report["waves"]["realizations"],
        "seed": report["waves"]["seed"],
        "damping_mode": report["damping_mode"],
        "caisson_version": report["caisson_version"],
        "results_version": report["results_version"],
        "report_json": json.dumps(report),
    }
    return xr.Dataset(data, coords={"condition": np.arange(len(conds)), "realization": np.arange(nr)}, attrs=attrs)


def spectrum(scenario: Scenario, tr_over_t0: Any, *, threads: int = 1, progress: Progress = None) -> pd.DataFrame:
    """The shock spectrum of the caisson under the scenario's triangular pulse (``caisson
    spectrum``, docs/cli.md; seed §5.2): the pulse (``[load] kind = "triangle"``, its peak forces
    kept) run with rise times t_r = ``tr_over_t0`` · T0.

    ``tr_over_t0``: ratios t_r/T0 (dimensionless), any order, each from 0.001 to 1000, at most
    10⁸ time steps in all (``caisson spectrum --tr-over-t0 FROM:TO:COUNT`` gives them spaced
    logarithmically). One row per ratio, in the order given, with the columns of
    ``spectrum.csv``: ``tr_over_t0``, ``rise_time_s`` (t_r, s), ``psi`` (Ψ = max |u_x| / (F/K_x)
    of the dynamic model), ``psi_closed_form`` (undamped oscillator), ``permanent_sliding_m``,
    ``shimosako_sliding_m`` and ``rigid_block_sliding_m`` (closed forms, m),
    ``max_horizontal_reaction_kn`` (kN). ``.attrs``: the other keys of ``caisson spectrum
    --json``: ``natural_period_s`` (T0, s), ``peak_horizontal_kn``, ``peak_uplift_kn``,
    ``static_sliding_resistance_kn`` (kN), ``warnings``, ``caisson_version``,
    ``results_version``. ``progress``: per ratio. Bad ratios raise :class:`ScenarioError` with
    ``.key == "tr_over_t0"``.
    """
    r = np.asarray(tr_over_t0, dtype=np.float64)
    if r.ndim > 1:
        raise ScenarioError(f"`tr_over_t0`: must be a number or a one-dimensional array, got shape {r.shape}")
    head, names, cols = _core.spectrum(scenario._core, np.ascontiguousarray(r.ravel()), threads, progress)
    frame = pd.DataFrame(dict(zip(names, cols)), copy=False)
    frame.attrs.update(json.loads(head))
    return frame


def estimate(
    scenario: Scenario,
    what: str = "run",
    *,
    lives: Optional[int] = None,
    history: bool = True,
    duration_s: Optional[float] = None,
) -> dict:
    """The work that ``what`` (``"run"``, ``"campaign"``, ``"design"``, ``"fragility"``) would do on
    the scenario, estimated before it starts as the CLI does (docs/cli.md "Limits"): ``lives``
    for a design (default ``[design] lives``), ``history`` and ``duration_s`` as :func:`run`.

    A dict: ``steps`` (time steps of the dynamic model), ``step_cost`` (a step on n springs in
    steps on 10), ``weighted_steps`` (what the budget counts), ``waves`` (drawn), ``memory_bytes``
    (held until the end), ``disk_bytes`` (0: Python writes no file), ``simulated_s``,
    ``simulated_share``, ``steps_from`` (how the steps were counted), ``basis`` (the count in
    words), ``budget`` (``steps``, ``waves``, ``memory_bytes``, ``disk_bytes``), ``over_budget``
    (``"steps"``, ``"waves"``, ``"memory"`` or None) and ``refusal`` (the message of the
    :class:`ScenarioError` the entry point raises, or None). A pilot run of about 15 ms measures
    adaptive steps; the estimate is deterministic.
    """
    return json.loads(_core.estimate(scenario._core, what, lives, history, duration_s))


#: The work budget of the long entry points (and of the CLI): time steps, waves, bytes held and
#: bytes written (docs/cli.md "Limits").
BUDGET: dict = dict(json.loads(_core.budget_json()))


_LIFE_COLUMNS = tuple(_core.life_columns())

#: The key of ``DataFrame.attrs`` that names the design a frame of lives was simulated by (its
#: fingerprint and results version): ``Design.statistics`` joins only lives of its own design, as
#: ``caisson merge`` joins only shards of its scenario.
LIVES_OF = "caisson_design"


def _lives_of(design: "Design") -> dict:
    return {"fingerprint": design.fingerprint, "results_version": RESULTS_VERSION}


class Design:
    """Performance-based design (``caisson design``, docs/design.md): lives of the scenario's
    ``[design]``, each from its own random stream keyed by its index, so lives can be simulated
    in any order, on any number of machines, and gathered.

    >>> d = caisson.Design(sc)                      # lives = [design] lives, or Design(sc, lives=N)
    >>> part = d.simulate_lives(range(0, 50))       # a DataFrame, one row per life
    >>> d.statistics([part, d.simulate_lives(range(50, 100))])   # == design.json of 100 lives
    """

    __slots__ = ("_scenario", "_lives")

    def __init__(self, scenario: Scenario, *, lives: Optional[int] = None) -> None:
        if not scenario.has_design:
            _core.design_fingerprint_of(scenario._core)  # raises the library's ScenarioError
        n = scenario._core.design_lives if lives is None else int(lives)
        if not 1 <= n <= _core.MAX_LIVES:
            raise ScenarioError(f"`lives` = {n}: must be a whole number from 1 to {_core.MAX_LIVES}, as `[design] lives`")
        object.__setattr__(self, "_scenario", scenario)
        object.__setattr__(self, "_lives", n)

    @property
    def scenario(self) -> Scenario:
        return self._scenario

    @property
    def lives(self) -> int:
        """How many lives the design has (``[design] lives`` unless given)."""
        return self._lives

    @property
    def fingerprint(self) -> str:
        """What every life depends on (the checkpoint fingerprint of ``caisson design``)."""
        return _core.design_fingerprint_of(self._scenario._core)

    def estimate(self, indices: Optional[Iterable[int]] = None) -> dict:
        """The work of :meth:`simulate_lives` on ``indices`` (default: all lives), as
        :func:`estimate`: counted on the number of lives asked for."""
        n = self._lives if indices is None else len(self._indices(indices))
        return estimate(self._scenario, "design", lives=max(n, 1))

    def simulate_lives(self, indices: Optional[Iterable[int]] = None, *, threads: int = 1, progress: Progress = None) -> pd.DataFrame:
        """Simulate lives ``indices`` (default: all, 0 .. lives − 1), in any order: one row per
        life, sorted by ``life``, with the columns of ``lives.csv`` (docs/design.md): ``sliding_m``
        (net, shoreward +), ``shoreward_sliding_m``, ``seaward_sliding_m``, ``max_excursion_m``,
        ``rigid_block_sliding_m``, ``max_storm_sliding_m`` in m; ``waves``, ``simulated_waves``,
        ``screened_waves``, ``rocking_waves``, ``large_rotation_waves``; ``max_rotation_rad`` in
        rad. A life ends at the wave that fails it (docs/design.md, "Failure"). Raises
        :class:`ScenarioError` if the lives asked for are over the work budget (:meth:`estimate`):
        ask for fewer at a time."""
        idx = self.sample() if indices is None else self._indices(indices)
        try:
            cols = _core.design_lives(self._scenario._core, idx, threads, progress)
        except KeyboardInterrupt as e:
            # The lives finished before Ctrl-C, as the CLI keeps them in its checkpoint.
            if isinstance(getattr(e, "lives", None), dict):
                e.lives = self._frame(e.lives)
            raise
        return self._frame(cols)

    def sample(self, *, threads: int = 1) -> list:
        """The lives the design simulates: every life, 0 .. lives − 1, or with ``[design]
        sampling = "stratified"`` the stratified sample of them (docs/design.md, "Stratified
        sampling"), the lives ``caisson design`` simulates."""
        idx = _core.design_sample(self._scenario._core, self._lives, threads)
        return list(range(self._lives)) if idx is None else idx

    @property
    def auto(self) -> Optional[float]:
        """``[design] lives = "auto"``: its target relative error (``lives`` is then the budget,
        ``max_lives``); ``None`` with a number of lives."""
        return self._scenario._core.design_target_relative_error

    def simulate_auto(self, *, threads: int = 1, progress: Progress = None) -> pd.DataFrame:
        """``[design] lives = "auto"`` (docs/design.md, "Lives to a target precision"): lives
        0 .. k − 1 in batches of 500, k the first batch boundary where the relative standard
        errors of E|S| and of P(failure) meet ``target_relative_error``, or the budget
        ``max_lives``: the same lives as ``caisson design`` on any thread count. With ``[design]
        sampling = "stratified"`` the batches are of the pool and the lives returned its sample
        of 0 .. k − 1 (the rule reading the weighted estimates; docs/design.md).
        :meth:`statistics` of them is ``design.json``, with its ``precision``. Shards of
        :meth:`simulate_lives` given to :meth:`statistics` stop at the same k (the rule of
        ``caisson merge``). Raises ``ValueError`` for a scenario with a number of lives."""
        try:
            cols = _core.design_auto(self._scenario._core, threads, progress)
        except KeyboardInterrupt as e:
            if isinstance(getattr(e, "lives", None), dict):
                e.lives = self._frame(e.lives)
            raise
        return self._frame(cols)

    def _frame(self, cols: dict) -> pd.DataFrame:
        """Lives as a DataFrame that names this design (``attrs[LIVES_OF]``)."""
        frame = pd.DataFrame(cols)
        frame.attrs[LIVES_OF] = _lives_of(self)
        return frame

    def _indices(self, indices: Any) -> list:
        """Life indices as a list of ints: whole numbers from 0 to lives − 1, each once."""
        allowed = f"whole numbers from 0 to {self._lives - 1} (the design has {self._lives} lives), each once"
        if isinstance(indices, (str, bytes)) or not isinstance(indices, Iterable):
            raise ScenarioError(f"`indices` = {indices!r}: must be an iterable of life indices, {allowed}")
        out = []
        seen = set()
        for i in indices:
            if isinstance(i, (bool, np.bool_)) or not isinstance(i, (int, np.integer)):
                raise ScenarioError(f"life index {i!r} ({type(i).__name__}): indices must be {allowed}")
            i = int(i)
            if not 0 <= i < self._lives:
                raise ScenarioError(f"life index {i}: indices must be {allowed}")
            if i in seen:
                raise ScenarioError(f"life index {i} is given twice: indices must be {allowed}")
            seen.add(i)
            out.append(i)
        return out

    def statistics(self, lives: Union[pd.DataFrame, Sequence[pd.DataFrame]]) -> DesignStatistics:
        """The statistics of the lives given (one DataFrame or several, e.g. shards from
        workers, in any order): a :class:`DesignStatistics` (typed fields, and the dict of
        ``caisson design --json`` as ``.report``, which it also reads as). The statistics of lives
        0 .. N − 1 are exactly those of ``caisson design`` with N lives. Raises ``ValueError``
        for a life given twice, a missing column (``life`` and those of ``lives.csv``), no lives,
        a non-finite length or a count that is not a whole number ≥ 0, and a gap (lives 0 .. N − 1 must all
        be given, N − 1 the largest life given: the rule of ``caisson merge``), and for lives of
        another design: each frame names the design that simulated it (``attrs[caisson.LIVES_OF]``,
        set by :meth:`simulate_lives`, ``read_checkpoint``, ``resume`` and ``merge``), which must
        be this one (its fingerprint and results version), as ``caisson merge`` refuses a shard of
        another scenario."""
        frames = [lives] if isinstance(lives, pd.DataFrame) else list(lives)
        need = ("life",) + _LIFE_COLUMNS
        ours = _lives_of(self)
        for k, f in enumerate(frames):
            if not isinstance(f, pd.DataFrame):
                raise TypeError(f"the lives must be DataFrames of simulate_lives, got {type(f).__name__}")
            one = len(frames) == 1
            whose = "the lives" if one else f"shard {k} (of {len(frames)})"
            has, names, are, were = ("have", "name", "are", "were") if one else ("has", "names", "is", "was")
            missing = [c for c in need if c not in f.columns]
            if missing:
                raise ValueError(f"{whose} {has} no column {missing[0]!r} (the lives need {', '.join(need)})")
            theirs = f.attrs.get(LIVES_OF)
            if not isinstance(theirs, dict):
                raise ValueError(
                    f"{whose} {names} no design (DataFrame.attrs[{LIVES_OF!r}]): give lives that simulate_lives, "
                    "read_checkpoint, resume or merge of this Design returned (a frame built by hand, or "
                    "concatenated from lives of different designs, names none)"
                )
            if theirs.get("results_version") != ours["results_version"]:
                raise ValueError(
                    f"{whose} {are} of results version {theirs.get('results_version')}, this caisson computes "
                    f"results version {ours['results_version']}: the lives would not match"
                )
            if theirs.get("fingerprint") != ours["fingerprint"]:
                raise ValueError(
                    f"{whose} {were} simulated by another design (fingerprint {theirs.get('fingerprint')}, this "
                    f"design {ours['fingerprint']}: the caisson, foundation, solver, waves, [design] life model "
                    "or seed differ), as `caisson merge` refuses a shard of another scenario"
                )
        frame = pd.concat(frames, ignore_index=True) if frames else pd.DataFrame(columns=list(need))
        if len(frame) == 0:
            raise ValueError("no lives given: the statistics need at least one life (a DataFrame of simulate_lives)")
        life = frame["life"].to_numpy()
        cols = {}
        for c in need:
            v = frame[c].to_numpy()
            real = c.endswith(("_m", "_rad", "_kpa"))  # lengths, rotations, pressures; the rest are counts
            allowed = f"must be a finite number ({c.rsplit('_', 1)[1]})" if real else "must be a whole number ≥ 0"
            if real or v.dtype.kind not in "iu":
                try:
                    v = v.astype(np.float64)
                except (TypeError, ValueError):
                    raise ValueError(f"column {c!r} holds {v.dtype} values: {allowed}") from None
            if real:
                bad = ~np.isfinite(v)
            else:
                bad = v < 0 if v.dtype.kind in "iu" else ~((v >= 0) & (v == np.floor(v)) & np.isfinite(v))
            if bad.any():
                i = int(np.argmax(bad))
                raise ValueError(f"column {c!r} = {v[i]} in row {i} (life {life[i]}): {allowed}")
            cols[c] = v
        beyond = (cols["life"] >= self._lives) | (cols["life"] != np.floor(cols["life"]))
        if beyond.any():
            i = int(np.argmax(beyond))
            raise ValueError(f"life {life[i]} in row {i}: the design has lives 0 to {self._lives - 1}")
        if frame["life"].duplicated().any():
            dup = frame.loc[frame["life"].duplicated(), "life"].iloc[0]
            raise ValueError(f"life {dup} appears more than once")
        life_sorted = np.sort(cols["life"].astype(np.uint64), kind="stable")
        order = np.argsort(cols.pop("life").astype(np.uint64), kind="stable")
        cols = {c: (v[order].astype(np.float64) if c.endswith(("_m", "_rad", "_kpa")) else v[order].astype(np.uint64)).tolist() for c, v in cols.items()}
        # Joined by `caisson merge`'s rules (in Rust): lives 0 .. N − 1, no gap.
        return DesignStatistics.of(
            json.loads(_core.design_statistics(self._scenario._core, cols, life_sorted.tolist(), self._lives))
        )

    def run(self, *, threads: int = 1, progress: Progress = None) -> tuple:
        """All lives at once: (:class:`DesignStatistics`, lives DataFrame); with ``[design] lives
        = "auto"`` the lives :meth:`simulate_auto` runs."""
        if self.auto is not None:
            lives = self.simulate_auto(threads=threads, progress=progress)
            return self.statistics(lives), lives
        lives = self.simulate_lives(threads=threads, progress=progress)
        return self.statistics(lives), lives

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError("a Design is immutable")

    def __reduce__(self):
        return (_restore_design, (self._scenario, self._lives))

    def __repr__(self) -> str:
        return f"Design({self._scenario.path!r}, lives={self._lives})"


def _restore_design(scenario: Scenario, lives: int) -> Design:
    return Design(scenario, lives=lives)


class Fragility:
    """Fragility curves for sliding (``caisson fragility``, docs/fragility.md): for each
    significant height H1/3 at the structure in ``[fragility] significant_heights_m``,
    ``storms`` storms of ``storm_duration_h`` of Rayleigh waves (limited to Goda's design-wave
    H_max of that H1/3) through the dynamic model and the rigid block; the share of storms whose
    sliding exceeds each of ``limits_m``, and a lognormal curve P(S > limit | H1/3) =
    Φ((ln H1/3 − ln θ)/β) fitted to the counts by maximum likelihood. θ (the median, in m of
    H1/3) and β are in :attr:`FragilityResult.fits`.

    >>> f = caisson.Fragility(caisson.Scenario.from_toml("examples/fragility.toml"))
    >>> r = f.run(threads=2)                      # a FragilityResult
    >>> r.fits[["limit_m", "model", "median_significant_height_m", "beta"]]
    """

    __slots__ = ("_scenario",)

    def __init__(self, scenario: Scenario) -> None:
        if not scenario.has_fragility:
            raise ScenarioError(
                "missing key `[fragility]`: Fragility needs a [fragility] table with significant_heights_m (and storms, limits_m, ...)"
            )
        object.__setattr__(self, "_scenario", scenario)

    @property
    def scenario(self) -> Scenario:
        return self._scenario

    def run(self, *, threads: int = 1, progress: Progress = None) -> FragilityResult:
        """Every storm of every height (``progress``: per storm), counts and lognormal fits."""
        name = Path(self._scenario.path).name or "fragility"
        s = json.loads(_core.fragility(self._scenario._core, name, threads, progress))
        levels = pd.DataFrame(
            [
                {k: v for k, v in lv.items() if k not in ("exceedance", "storm_sliding_m", "storm_rigid_block_sliding_m", "storm_max_rotation_rad")}
                for lv in s["levels"]
            ]
        )
        storms = pd.DataFrame(
            [
                {"level": i, "significant_height_m": lv["significant_height_m"], "storm": j, "sliding_m": a, "rigid_block_sliding_m": b, "max_rotation_rad": r}
                for i, lv in enumerate(s["levels"])
                for j, (a, b, r) in enumerate(zip(lv["storm_sliding_m"], lv["storm_rigid_block_sliding_m"], lv["storm_max_rotation_rad"]))
            ]
        )
        fits = pd.DataFrame(
            [{"limit_m": f["limit_m"], "model": m, **f[m]} for f in s["fits"] for m in ("dynamic", "rigid_block")]
        ).rename(columns={"median_m": "median_significant_height_m"})
        return FragilityResult(summary=s, levels=levels, storms=storms, fits=fits, warnings=ResultWarning.all_of(s))

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError("a Fragility is immutable")

    def __reduce__(self):
        return (Fragility, (self._scenario,))


def fit_lognormal(im: Any, k: Any, n: Any) -> dict:
    """Maximum-likelihood lognormal fragility P(IM) = Φ((ln IM − ln θ)/β) from ``k[i]``
    exceedances in ``n[i]`` trials at intensities ``im[i]`` > 0 (docs/fragility.md). Returns
    ``{"median", "beta", "ln_median_se", "beta_se", "log_likelihood", "median_ci95", "beta_ci95"}``
    (median in the unit of IM; the 95 % profile-likelihood intervals as ``[low, high]``, ``None``
    for an end beyond the search bounds); raises :class:`FitError` (``.reason``) when the counts do
    not determine the fit."""
    im_l = [float(x) for x in np.asarray(im, dtype=np.float64).ravel()]
    k_l = [int(x) for x in np.asarray(k).ravel()]
    n_l = [int(x) for x in np.asarray(n).ravel()]
    if any(x < 0 for x in k_l + n_l):
        raise ValueError("counts must be ≥ 0")
    median, beta, se_m, se_b, ll, ci_m, ci_b = _core.fit_lognormal(im_l, k_l, n_l)
    return {
        "median": median,
        "beta": beta,
        "ln_median_se": se_m,
        "beta_se": se_b,
        "log_likelihood": ll,
        "median_ci95": list(ci_m),
        "beta_ci95": list(ci_b),
    }


from . import loads, waves  # noqa: E402  (submodules use the names above)


# Sizing, and the CLI's design checkpoints and shards: the library's driver, codec and merge rules
# (module _size).
from ._size import merge, read_checkpoint, resume, size  # noqa: E402

__all__ += ["size", "read_checkpoint", "resume", "merge"]


def report(scenarios, out: Union[str, os.PathLike], *, threads: int = 0, pdf: bool = True) -> list:
    """The calculation note of ``caisson report`` (docs/report.md): ``report.html`` (self-contained)
    and, where a headless Chromium is found and ``pdf``, ``report.pdf`` (A4) in ``out``, by the
    CLI's own exporter, so the note is the CLI's byte for byte. ``scenarios``: a scenario file,
    a :class:`Scenario`, or a list of them (two or more are set side by side). A
    :class:`Scenario` is written to a temporary TOML file under its own file name (a scenario
    that reads a force series is given as its file). Returns the paths written. Raises
    :class:`ScenarioError` for what the CLI refuses (exit 2) and :class:`RunError` for a run
    that failed. The note's runs cannot be stopped by Ctrl-C from Python."""
    import tempfile

    items = scenarios if isinstance(scenarios, (list, tuple)) else [scenarios]
    with tempfile.TemporaryDirectory(prefix="caisson-report-") as tmp:
        paths = []
        for i, sc in enumerate(items):
            if isinstance(sc, Scenario):
                name = Path(sc.path).name if sc.path else f"scenario_{i + 1}.toml"
                d = Path(tmp) / str(i)
                d.mkdir()
                (d / name).write_text(sc.to_toml())
                paths.append(str(d / name))
            else:
                paths.append(os.fspath(sc))
        return _core.report(paths, os.fspath(out), threads, pdf)


__all__ += ["report"]


def __dir__() -> list:
    """The package's names (``__all__``), not the modules and typing names it imports."""
    return sorted(__all__)
