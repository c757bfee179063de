import os
from typing import Any, Callable, Iterable, Mapping, Optional, Sequence, Union

import pandas as pd
import xarray as xr

from . import loads as loads, waves as waves
from .results import (
    DesignStatistics as DesignStatistics,
    FragilityResult as FragilityResult,
    ModelStatistics as ModelStatistics,
    ResultWarning as ResultWarning,
    RunResult as RunResult,
    SizeResult as SizeResult,
)

__version__: str
RESULTS_VERSION: int
LIVES_OF: str

Progress = Optional[Callable[[int, int], Any]]

class ScenarioError(ValueError):
    key: Optional[str]
    value: Optional[str]
    allowed: Optional[str]

class RunError(RuntimeError): ...

class FitError(ValueError):
    reason: Optional[str]

class Scenario:
    def __init__(self, text: str, *, path: str = ..., base_dir: Union[str, os.PathLike] = ...) -> None: ...
    @classmethod
    def from_toml(cls, source: Union[str, os.PathLike], *, base_dir: Union[str, os.PathLike, None] = ...) -> Scenario: ...
    @classmethod
    def from_dict(cls, d: Mapping[str, Any], *, base_dir: Union[str, os.PathLike] = ...) -> Scenario: ...
    def to_dict(self) -> dict: ...
    def to_toml(self) -> str: ...
    def replace(self, **tables: Optional[Mapping[str, Any]]) -> Scenario: ...
    @property
    def path(self) -> str: ...
    @property
    def base_dir(self) -> str: ...
    @property
    def has_load(self) -> bool: ...
    @property
    def has_waves(self) -> bool: ...
    @property
    def has_campaign(self) -> bool: ...
    @property
    def has_design(self) -> bool: ...
    @property
    def has_fragility(self) -> bool: ...
    @property
    def duration_s(self) -> float: ...

def run(
    scenario: Scenario,
    *,
    t_s: Any = ...,
    fx_kn: Any = ...,
    fy_kn: Any = ...,
    moment_knm: Any = ...,
    duration_s: Optional[float] = ...,
    history: bool = ...,
    threads: int = ...,
    progress: Progress = ...,
) -> RunResult: ...
def estimate(
    scenario: Scenario,
    what: str = ...,
    *,
    lives: Optional[int] = ...,
    history: bool = ...,
    duration_s: Optional[float] = ...,
) -> dict: ...

BUDGET: dict

def spectrum(scenario: Scenario, tr_over_t0: Any, *, threads: int = ..., progress: Progress = ...) -> pd.DataFrame: ...
def campaign(scenario: Scenario, *, damping_mode: Optional[str] = ..., threads: int = ..., progress: Progress = ...) -> xr.Dataset: ...

class Design:
    def __init__(self, scenario: Scenario, *, lives: Optional[int] = ...) -> None: ...
    @property
    def scenario(self) -> Scenario: ...
    @property
    def lives(self) -> int: ...
    @property
    def fingerprint(self) -> str: ...
    def estimate(self, indices: Optional[Iterable[int]] = ...) -> dict: ...
    def simulate_lives(self, indices: Optional[Iterable[int]] = ..., *, threads: int = ..., progress: Progress = ...) -> pd.DataFrame: ...
    def statistics(self, lives: Union[pd.DataFrame, Sequence[pd.DataFrame]]) -> DesignStatistics: ...
    def sample(self, *, threads: int = ...) -> list: ...
    def run(self, *, threads: int = ..., progress: Progress = ...) -> tuple[DesignStatistics, pd.DataFrame]: ...

class Fragility:
    def __init__(self, scenario: Scenario) -> None: ...
    @property
    def scenario(self) -> Scenario: ...
    def run(self, *, threads: int = ..., progress: Progress = ...) -> FragilityResult: ...

def fit_lognormal(im: Any, k: Any, n: Any) -> dict: ...

# Sizing, and the CLI's design checkpoints and shards (module _size, typed in its source).
from ._size import merge as merge, read_checkpoint as read_checkpoint, resume as resume, size as size

def report(
    scenarios: Union[str, os.PathLike, Scenario, Sequence[Union[str, os.PathLike, Scenario]]],
    out: Union[str, os.PathLike],
    *,
    threads: int = 0,
    pdf: bool = True,
) -> list[str]: ...
