"""Typed results of the drivers: every field documented with its unit (docs/python.md, "Results").

The same quantity has the same name in every kind of result and in the CLI's JSON:
``permanent_sliding_m`` is the sliding a run leaves (a ``[load]`` run's, or the mean over the
realizations of a ``[waves]`` run), ``failure_probability`` the share of failed lives (as in
``size.json``), ``warnings`` a tuple of :class:`ResultWarning`. Each result keeps the CLI's report it
was built from (``summary`` / ``report``: the dict of the command's ``--json``, its keys stable
across results versions), and the design statistics also read as that dict
(``stats["dynamic"]["expected_sliding_m"]``), so code written against the JSON keeps working.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any, Iterator, Optional

import pandas as pd

__all__ = ["ResultWarning", "RunResult", "ModelStatistics", "DesignStatistics", "FragilityResult", "SizeResult"]


@dataclass(frozen=True)
class ResultWarning:  
    """One warning of a result (docs/cli.md, "Warnings"): ``code`` (stable, e.g.
    ``"failed-lives"``), ``message`` (what was found and what to check), ``details``: the other
    keys of its JSON entry (e.g. the realization or life it concerns)."""

    code: str
    message: str
    details: Mapping = field(default_factory=dict)

    @staticmethod
    def all_of(report: Mapping) -> tuple:
        """The warnings of a CLI report (its ``warnings`` list), in order."""
        return tuple(
            ResultWarning(w.get("code", ""), w.get("message", ""), {k: v for k, v in w.items() if k not in ("code", "message")})
            for w in report.get("warnings", [])
        )

    def __str__(self) -> str:
        return f"{self.code}: {self.message}"


@dataclass(frozen=True)
class RunResult:
    """The results of :func:`caisson.run`, of either kind of run.

    Fields (units in the names):

    - ``kind``: ``"load"`` (a ``[load]`` or a force series: one run) or ``"waves"`` (wave trains:
      ``realizations`` runs of ``[waves] waves`` waves each).
    - ``permanent_sliding_m``: the sliding the run leaves, m, shoreward +; for ``"waves"`` the mean
      over the realizations of each realization's total (``summary["sliding_m"]["mean"]``).
    - ``rigid_block_sliding_m``: the rigid block's (Shimosako model) beside it, m, mean over the
      realizations; ``None`` for ``"load"`` (no wave to slide it).
    - ``max_horizontal_reaction_kn``: the largest horizontal base reaction, kN (the effective
      design load), over every realization.
    - ``slip_events``: how many times a slip began (for ``"waves"``: the mean per realization).
    - ``realizations``: one row per realization (``"waves"``: ``sliding_m``,
      ``rigid_block_sliding_m``, ``max_horizontal_reaction_kn``, ``slip_events``,
      ``breaking_waves``, ``steps``); ``None`` for ``"load"``.
    - ``warnings``: tuple of :class:`ResultWarning`.
    - ``summary``: the CLI's ``summary.json`` (``caisson run --json``) as a dict.
    - ``history`` (``"load"``): one row every ``[solver] output_interval_s``, the columns of
      ``history.csv`` (``time_s``, ``ux_m``, ``fx_kn``, ...); ``springs`` (``"load"``): an
      xarray Dataset (dims ``time_s`` × ``spring``; ``normal_kn``, ``shear_kn``, ``uy_m``;
      coordinate ``x_m``); ``waves`` (``"waves"``): one row per wave of every realization.
    """

    kind: str
    permanent_sliding_m: float
    rigid_block_sliding_m: Optional[float]
    max_horizontal_reaction_kn: float
    slip_events: float
    warnings: tuple
    summary: dict
    realizations: Optional[pd.DataFrame] = None
    history: Optional[pd.DataFrame] = None
    springs: Any = None
    waves: Optional[pd.DataFrame] = None

    @staticmethod
    def of_load(summary: dict, history: Optional[pd.DataFrame] = None, springs: Any = None) -> "RunResult":
        return RunResult(
            kind="load",
            permanent_sliding_m=summary["permanent_sliding_m"],
            rigid_block_sliding_m=None,
            max_horizontal_reaction_kn=summary["max_horizontal_reaction_kn"],
            slip_events=summary["slip_events"],
            warnings=ResultWarning.all_of(summary),
            summary=summary,
            history=history,
            springs=springs,
        )

    @staticmethod
    def of_waves(summary: dict, waves: pd.DataFrame) -> "RunResult":
        keys = ("index", "sliding_m", "rigid_block_sliding_m", "max_horizontal_reaction_kn", "slip_events", "breaking_waves", "steps")
        rows = pd.DataFrame([{k: r[k] for k in keys} for r in summary["realizations"]]).rename(columns={"index": "realization"})
        return RunResult(
            kind="waves",
            permanent_sliding_m=summary["sliding_m"]["mean"],
            rigid_block_sliding_m=summary["rigid_block_sliding_m"]["mean"],
            max_horizontal_reaction_kn=summary["max_horizontal_reaction_kn"]["max"],
            slip_events=summary["slip_events"]["mean"],
            warnings=ResultWarning.all_of(summary),
            summary=summary,
            realizations=rows,
            waves=waves,
        )


@dataclass(frozen=True)
class ModelStatistics:
    """One model's statistics over the lives of a design (``design.json``'s ``dynamic`` or
    ``rigid_block``; docs/design.md). Lengths in m; |S| is the distance from the caisson's place
    at the end of a life, a failed life counted at the sliding limit.

    Every estimate comes with its 95 % interval, a ``(low, high)`` tuple under the same name with
    ``_ci95`` (docs/design.md, "Intervals"): means with their standard error too.

    - ``expected_sliding_m``: E|S| (failed lives at the limit); ``expected_sliding_uncapped_m``:
      with every life as simulated, run to its end (the published ESD); each with its standard
      error (``…_standard_error_m``) and interval (``…_ci95_m``); ``expected_sliding_per_year_m``:
      E|S| / life_years (and its ``…_standard_error_m``, ``…_ci95_m``).
    - ``percentiles_m``: ``{"p5": ..., "p50": ..., "p95": ..., "p99": ...}`` of |S|;
      ``percentiles_ci95_m``: their order-statistic intervals (an end ``None`` where the lives are
      too few for it).
    - ``exceedance_probability``: ``{threshold_m: P(|S| > threshold)}``; ``exceedance_ci95``:
      ``{threshold_m: (low, high)}`` (Wilson).
    - ``failure_probability``, ``failure_lives``: the lives that failed (by sliding beyond
      ``[design] failure_sliding_m`` or rotating beyond ``failure_rotation_rad``), with
      ``failure_probability_ci95`` (Wilson); ``failure_probability_by_sliding``,
      ``failure_probability_by_rotation``, ``failure_probability_by_heel_pressure``: by the failing
      wave's mode.
    - ``surviving_lives``, ``surviving_expected_sliding_m`` (with ``…_standard_error_m`` and
      ``…_ci95_m``): the lives that did not fail.
    - ``impulsive``: what the impulsive waves make of the lives (``waves``, ``sliding_m``,
      ``share_of_expected_sliding``, ``share_of_failures``, each with its 95 % interval
      ``…_ci95``, ``failures``; docs/design.md).
    """

    expected_sliding_m: float
    expected_sliding_uncapped_m: float
    expected_sliding_standard_error_m: float
    expected_sliding_uncapped_standard_error_m: float
    expected_sliding_ci95_m: tuple
    expected_sliding_uncapped_ci95_m: tuple
    expected_sliding_per_year_m: float
    expected_sliding_per_year_standard_error_m: float
    expected_sliding_per_year_ci95_m: tuple
    percentiles_m: Mapping
    percentiles_ci95_m: Mapping
    exceedance_probability: Mapping
    exceedance_ci95: Mapping
    failure_probability: float
    failure_probability_ci95: tuple
    failure_lives: int
    failure_probability_by_sliding: float
    failure_probability_by_rotation: float
    failure_probability_by_heel_pressure: float
    surviving_lives: int
    surviving_expected_sliding_m: float
    surviving_expected_sliding_standard_error_m: float
    surviving_expected_sliding_ci95_m: tuple
    impulsive: Mapping

    @staticmethod
    def of(m: Mapping) -> "ModelStatistics":
        f = m["failure"]
        return ModelStatistics(
            expected_sliding_m=m["expected_sliding_m"],
            expected_sliding_uncapped_m=m["expected_sliding_uncapped_m"],
            expected_sliding_standard_error_m=m["expected_sliding_standard_error_m"],
            expected_sliding_uncapped_standard_error_m=m["expected_sliding_uncapped_standard_error_m"],
            expected_sliding_ci95_m=tuple(m["expected_sliding_ci95_m"]),
            expected_sliding_uncapped_ci95_m=tuple(m["expected_sliding_uncapped_ci95_m"]),
            expected_sliding_per_year_m=m["expected_sliding_per_year_m"],
            expected_sliding_per_year_standard_error_m=m["expected_sliding_per_year_standard_error_m"],
            expected_sliding_per_year_ci95_m=tuple(m["expected_sliding_per_year_ci95_m"]),
            percentiles_m=dict(m["percentiles_m"]),
            percentiles_ci95_m={k: tuple(v) for k, v in m["percentiles_ci95_m"].items()},
            exceedance_probability={e["threshold_m"]: e["probability"] for e in m["exceedance_probability"]},
            exceedance_ci95={e["threshold_m"]: tuple(e["ci95"]) for e in m["exceedance_probability"]},
            failure_probability=f["probability"],
            failure_probability_ci95=tuple(f["probability_ci95"]),
            failure_lives=f["lives"],
            failure_probability_by_sliding=f["by_sliding"]["probability"],
            failure_probability_by_rotation=f["by_rotation"]["probability"],
            failure_probability_by_heel_pressure=f["by_heel_pressure"]["probability"],
            surviving_lives=m["surviving"]["lives"],
            surviving_expected_sliding_m=m["surviving"]["expected_sliding_m"],
            surviving_expected_sliding_standard_error_m=m["surviving"]["expected_sliding_standard_error_m"],
            surviving_expected_sliding_ci95_m=tuple(m["surviving"]["expected_sliding_ci95_m"]),
            impulsive=dict(m["impulsive"]),
        )


class _ReadsAsReport(Mapping):
    """A typed result that also reads as the CLI's JSON report it keeps in ``report``: its keys,
    items and ``==`` against that dict (or another result of its kind)."""

    report: dict

    def __getitem__(self, key: str) -> Any:
        return self.report[key]

    def __iter__(self) -> Iterator[str]:
        return iter(self.report)

    def __len__(self) -> int:
        return len(self.report)

    def __eq__(self, other: object) -> bool:
        if isinstance(other, _ReadsAsReport):
            return type(self) is type(other) and self.report == other.report
        return isinstance(other, Mapping) and self.report == dict(other)

    __hash__ = None  # type: ignore[assignment]


@dataclass(frozen=True, eq=False)
class DesignStatistics(_ReadsAsReport):
    """The statistics of a design's lives (``caisson design --json``, docs/design.md):
    ``lives``, ``life_years``; ``dynamic`` and ``rigid_block``: :class:`ModelStatistics`;
    ``waves``, ``simulated_waves`` (the waves drawn and those run through the dynamic model);
    ``heel_pressure_exceedance``: P(q_heel > q_a) of the dynamic model's lives (``allowable_kpa``,
    ``probability``, ``standard_error``, ``lives``, ``exact_from_kpa``, ``largest_kpa``);
    ``warnings``: tuple of :class:`ResultWarning`; ``report``: the dict of ``design.json``;
    ``sampling``: how a stratified design sampled its lives (``pool_lives``, ``simulated_lives``,
    ``strata``), ``None`` when every life was simulated.

    It also reads as that dict (``stats["dynamic"]["failure"]["probability"]``, ``dict(stats)``,
    ``stats == json.load(open("design.json"))``).
    """

    lives: int
    life_years: int
    dynamic: ModelStatistics
    rigid_block: ModelStatistics
    waves: int
    simulated_waves: int
    heel_pressure_exceedance: Mapping
    warnings: tuple
    report: dict
    sampling: Optional[Mapping] = None
    #: ``[design] lives = "auto"``: how many lives it took, the target, the relative errors
    #: reached and whether the target was met (``lives``, ``max_lives``, ``batch_lives``,
    #: ``target_relative_error``, ``expected_sliding_relative_error``,
    #: ``failure_relative_error``, ``failure_probability_upper``, ``met``, ...); ``None`` with a
    #: number of lives.
    precision: Optional[Mapping] = None

    @staticmethod
    def of(report: dict) -> "DesignStatistics":
        return DesignStatistics(
            lives=report["lives"],
            life_years=report["life_years"],
            dynamic=ModelStatistics.of(report["dynamic"]),
            rigid_block=ModelStatistics.of(report["rigid_block"]),
            waves=report["waves"],
            simulated_waves=report["simulated_waves"],
            heel_pressure_exceedance=dict(report["dynamic"]["heel_pressure_exceedance"]),
            warnings=ResultWarning.all_of(report),
            report=report,
            sampling=report.get("sampling"),
            precision=dict(report["precision"]) if "precision" in report else None,
        )

    def __repr__(self) -> str:
        d = self.dynamic
        return (
            f"DesignStatistics(lives={self.lives}, life_years={self.life_years}, "
            f"expected_sliding_m={d.expected_sliding_m:.4g}, failure_probability={d.failure_probability:.4g})"
        )


@dataclass(frozen=True)
class FragilityResult:
    """The results of :meth:`caisson.Fragility.run` (docs/fragility.md).

    - ``levels``: one row per height: ``significant_height_m`` (H1/3 at the structure, the
      intensity measure), ``hmax_m`` (the largest wave of its storms), ``storms``,
      ``mean_sliding_m``, ``max_sliding_m``, ``mean_rigid_block_sliding_m``,
      ``max_rigid_block_sliding_m`` (m), ``rotation_failures``, ``screened_share``,
      ``simulated_waves``, ``goda_sliding_safety_factor``.
    - ``storms``: one row per storm: ``level``, ``significant_height_m``, ``storm``,
      ``sliding_m``, ``rigid_block_sliding_m`` (m), ``max_rotation_rad``.
    - ``fits``: one row per limit and model: ``limit_m`` (the sliding limit, m), ``model``
      (``"dynamic"`` or ``"rigid_block"``), ``fitted``, ``median_significant_height_m`` (θ: the
      H1/3 at which P(S > limit) = 1/2, m; ``median_m`` in ``fragility.json``), ``beta``
      (lognormal standard deviation), ``ln_median_se``, ``beta_se``, ``log_likelihood``.
    - ``warnings``: tuple of :class:`ResultWarning`; ``summary``: the dict of ``fragility.json``.
    """

    summary: dict
    levels: pd.DataFrame
    storms: pd.DataFrame
    fits: pd.DataFrame
    warnings: tuple = ()


def _interval_columns(name: str) -> tuple:
    """The two columns of an interval ``name`` as candidates.csv names them: ``x_ci95_m`` ->
    ``x_ci95_low_m``, ``x_ci95_high_m``; ``x_ci95`` -> ``x_ci95_low``, ``x_ci95_high``."""
    if name.endswith("_m"):
        return (f"{name[:-2]}_low_m", f"{name[:-2]}_high_m")
    return (f"{name}_low", f"{name}_high")


@dataclass(frozen=True, eq=False)
class SizeResult(_ReadsAsReport):
    """The results of :func:`caisson.size` (``caisson size --json``, docs/size.md). Widths in m.

    - ``width_m``: the required width by the dynamic model (``None`` where the search found none
      in the range: ``status`` says why); ``rigid_block_width_m``: the rigid block's;
      ``goda_width_m``: Goda's conventional width (sliding and overturning safety factors under
      the design wave H_max).
    - ``status``, ``rigid_block_status``: ``"found"`` or why not (docs/size.md).
    - ``candidates``: one row per width tried: ``width_m``, ``weight_in_water_kn``, and per model
      (``dynamic_...``, ``rigid_block_...``) ``expected_sliding_m``, ``expected_sliding_standard_error_m``,
      ``expected_sliding_uncapped_m`` (as simulated) and its ``…_standard_error_m``, each 95 %
      interval in two columns as in candidates.csv (``…_ci95_low_m``, ``…_ci95_high_m``; Wilson
      intervals of the probabilities ``…_ci95_low``, ``…_ci95_high``), ``failure_probability``
      (with ``failure_by_sliding_probability``, ``failure_by_rotation_probability``,
      ``failure_by_heel_pressure_probability``), ``exceedance_probability``, ``p50_m``, ``p95_m``,
      ``impulsive_...`` (``waves``, ``sliding_m``, ``share_of_expected_sliding``,
      ``share_of_failures``, each with its interval's ``…_ci95_low``/``…_ci95_high``,
      ``failures``) and ``meets``; ``heel_pressure_exceedance_...``
      (``probability``, ``standard_error``, ...); Goda's safety factors and heel pressure
      (``goda_sliding_safety_factor``, ``goda_overturning_safety_factor``,
      ``goda_heel_pressure_kpa``).
    - ``warnings``: tuple of :class:`ResultWarning`; ``report``: the dict of ``size.json``,
      which the object also reads as.
    """

    width_m: Optional[float]
    rigid_block_width_m: Optional[float]
    goda_width_m: Optional[float]
    status: str
    rigid_block_status: str
    candidates: pd.DataFrame
    warnings: tuple
    report: dict

    @staticmethod
    def of(report: dict) -> "SizeResult":
        rows = []
        for c in report["candidates"]:
            row = {k: v for k, v in c.items() if not isinstance(v, Mapping) and k not in ("dynamic_meets", "rigid_block_meets")}
            for model in ("dynamic", "rigid_block"):
                for k, v in (c.get(model) or {}).items():
                    # A group (the impulsive waves') flattened as candidates.csv has it.
                    if isinstance(v, Mapping):
                        for g, x in v.items():
                            if isinstance(x, (list, tuple)):
                                row.update(zip(_interval_columns(f"{model}_{k}_{g}"), x))
                            else:
                                row[f"{model}_{k}_{g}"] = x
                    elif isinstance(v, (list, tuple)):
                        row.update(zip(_interval_columns(f"{model}_{k}"), v))
                    else:
                        row[f"{model}_{k}"] = v
                row[f"{model}_meets"] = c.get(f"{model}_meets")
            # `[size] lives = "auto"`: the candidate's verdict (precision_lives, precision_met, ...).
            for k, v in (c.get("precision") or {}).items():
                row[f"precision_{k}"] = v
            for k, v in (c.get("heel_pressure_exceedance") or {}).items():
                if isinstance(v, (list, tuple)):
                    row.update(zip(_interval_columns(f"heel_pressure_exceedance_{k}"), v))
                else:
                    row[f"heel_pressure_exceedance_{k}"] = v
            rows.append(row)
        return SizeResult(
            width_m=report["dynamic"].get("width_m"),
            rigid_block_width_m=report["rigid_block"].get("width_m"),
            goda_width_m=report["goda"].get("width_m"),
            status=report["dynamic"]["status"],
            rigid_block_status=report["rigid_block"]["status"],
            candidates=pd.DataFrame(rows),
            warnings=ResultWarning.all_of(report),
            report=report,
        )

    def __repr__(self) -> str:
        return f"SizeResult(width_m={self.width_m}, rigid_block_width_m={self.rigid_block_width_m}, goda_width_m={self.goda_width_m})"
