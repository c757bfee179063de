"""Sizing, and the checkpoints and shards of the CLI, from Python (re-exported by ``caisson``).

Every rule is the library's (Rust): the sizing driver of ``caisson size``, the checkpoint codec
of ``caisson design`` (header, format, results version, fingerprint, the check of every line) and
the merge rules of ``caisson merge`` (each life in one shard, none beyond N, no gap). This module
only reads the files and shapes the results as the rest of the package does.
"""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any, Callable, Optional, Sequence, Union

import pandas as pd

from . import _core
from .results import DesignStatistics, SizeResult

Progress = Optional[Callable[[int, int], Any]]
PathLike = Union[str, os.PathLike]

#: The most bytes a checkpoint file may have (about 2.5 million lives of 400 bytes).
MAX_CHECKPOINT_BYTES = 1 << 30


def size(scenario, *, threads: int = 1, progress: Progress = None) -> SizeResult:
    """The smallest caisson width that meets the scenario's ``[size]`` criterion over the lives of
    its ``[design]`` (``caisson size``, docs/size.md): a :class:`SizeResult`, whose ``report`` is
    the dict of ``size.json``, key for key and bit for bit, warnings included. The caisson must be given by its construction. Raises
    :class:`ScenarioError` for a scenario the CLI refuses (or over the work budget), and
    ``KeyboardInterrupt`` on Ctrl-C (nothing is kept: the CLI's ``--out`` keeps a checkpoint).
    ``progress(done, total)``: lives, ``total`` the most the search may run."""
    return SizeResult.of(json.loads(_core.size(scenario._core, threads, progress)))


def _checkpoint_bytes(path: PathLike) -> tuple:
    """(name, bytes) of a CLI checkpoint: ``path`` itself, or ``path/checkpoint.jsonl`` for a
    directory (an ``--out`` directory or a shard); a regular file of at most 1 GiB."""
    p = Path(path)
    if p.is_dir():
        p = p / "checkpoint.jsonl"
    if not p.is_file():
        raise ValueError(f"{p}: not a checkpoint file (a checkpoint is a regular file written by `caisson design`)")
    if p.stat().st_size > MAX_CHECKPOINT_BYTES:
        raise ValueError(f"{p}: {p.stat().st_size} bytes, more than any checkpoint ({MAX_CHECKPOINT_BYTES} bytes)")
    return str(p), p.read_bytes()


def read_checkpoint(design, path: PathLike) -> pd.DataFrame:
    """The lives of a ``caisson design`` checkpoint (``path``: the file, or the ``--out``
    directory that holds ``checkpoint.jsonl``) of this design's scenario, as
    :meth:`Design.simulate_lives` returns them (sorted by ``life``). Refused (``ValueError``,
    naming the file and the line) as ``--resume`` refuses it: another format, results version or
    fingerprint (another scenario, seed, or a ``--brute-force`` run), an edited or foreign line,
    a life given twice. A last line cut short (the run was stopped while writing it) is left out."""
    name, data = _checkpoint_bytes(path)
    cols = _core.read_design_checkpoint(design.scenario._core, name, data)
    return design._frame(cols)


def resume(design, path: PathLike, *, threads: int = 1, progress: Progress = None) -> tuple:
    """Complete a ``caisson design`` run from its checkpoint: the lives it holds and the others of
    ``design`` simulated here, joined by the rules of ``caisson merge``. Returns (:class:`DesignStatistics`,
    lives DataFrame): what the uninterrupted CLI run reports, bit for bit. The checkpoint is
    read, never written."""
    done = read_checkpoint(design, path)
    have = set(int(i) for i in done["life"])
    todo = [i for i in range(design.lives) if i not in have]
    parts = [done[done["life"] < design.lives]]
    if todo:
        parts.append(design.simulate_lives(todo, threads=threads, progress=progress))
    lives = pd.concat(parts, ignore_index=True).sort_values("life", ignore_index=True)
    return design.statistics(lives), lives


def merge(design, shards: Sequence[PathLike]) -> tuple:
    """Join the shards of a design run (``caisson design --life-range START..END --out SHARD``,
    each a directory or its checkpoint) into lives 0 .. ``design.lives`` − 1, by the rules of
    ``caisson merge``: every shard of this scenario and results version with intact lines, each
    life in exactly one shard, none beyond N, no gap (``ValueError`` naming the shards and the
    lives). Returns (:class:`DesignStatistics`, lives DataFrame): what ``caisson merge`` writes."""
    files = [_checkpoint_bytes(s) for s in shards]
    text, cols = _core.merge_checkpoints(design.scenario._core, files, design.lives)
    return DesignStatistics.of(json.loads(text)), design._frame(cols)
