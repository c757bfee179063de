"""A small TOML writer for scenario dictionaries (tables of scalars, lists and arrays of tables).

Floats are written with ``repr`` (the shortest text that reads back to the same number), so a
dictionary written here and parsed by the engine gives exactly the numbers it held.
"""

from __future__ import annotations

import json
import math
from typing import Any, Mapping


def _key(k: str) -> str:
    if k and all(c.isalnum() or c in "_-" for c in k):
        return k
    return json.dumps(k)


def _value(v: Any, where: str) -> str:
    if type(v).__module__ == "numpy":
        # numpy scalars and arrays (every pandas cell): their Python values. (np.float64 is a
        # float whose repr is "np.float64(0.9)", which is no TOML.)
        v = v.tolist()
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        # A whole number is written as one (10.0 as 10): a key that wants a whole number takes
        # it, and one that wants a real number reads the same value (exact below 2^53).
        if v.is_integer() and abs(v) < 2.0**53:
            return str(int(v))
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(float(v))
    if isinstance(v, str):
        return json.dumps(v, ensure_ascii=False)
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_value(x, where) for x in v) + "]"
    if isinstance(v, Mapping):
        return "{" + ", ".join(f"{_key(str(k))} = {_value(x, where)}" for k, x in v.items()) + "}"
    raise TypeError(f"{where}: cannot write a {type(v).__name__} to a scenario")


def _is_table_array(v: Any) -> bool:
    return isinstance(v, (list, tuple)) and len(v) > 0 and all(isinstance(x, Mapping) for x in v)


def _table(out: list[str], name: str, d: Mapping[str, Any]) -> None:
    scalars = [(k, v) for k, v in d.items() if v is not None and not isinstance(v, Mapping) and not _is_table_array(v)]
    if name:
        out.append(f"[{name}]")
    for k, v in scalars:
        out.append(f"{_key(str(k))} = {_value(v, f'{name}.{k}' if name else str(k))}")
    if name or scalars:
        out.append("")
    for k, v in d.items():
        sub = f"{name}.{_key(str(k))}" if name else _key(str(k))
        if isinstance(v, Mapping):
            _table(out, sub, v)
        elif _is_table_array(v):
            for item in v:
                out.append(f"[[{sub}]]")
                for kk, vv in item.items():
                    if vv is not None:
                        out.append(f"{_key(str(kk))} = {_value(vv, f'{sub}.{kk}')}")
                out.append("")


def dumps(d: Mapping[str, Any]) -> str:
    """TOML text of a scenario dictionary (``None`` values are left out)."""
    out: list[str] = []
    _table(out, "", d)
    return "\n".join(out) + "\n"
