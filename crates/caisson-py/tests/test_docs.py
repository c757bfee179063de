"""Every Python snippet of docs/python.md runs as written, as a script from the repository root
(as a reader copies it into a file): the quick start, and the Dask and Ray sweeps, whose work is
under `if __name__ == "__main__":` (without it each worker process would start the script over).
The numbers the quick start's comments quote are checked against what it prints."""

from __future__ import annotations

import re
import subprocess
import sys

import pytest

from conftest import ROOT

SNIPPETS = re.findall(r"```python\n(.*?)```", (ROOT / "docs" / "python.md").read_text(), re.S)


def run_snippet(tmp_path, code: str) -> str:
    script = tmp_path / "snippet.py"
    script.write_text(code)
    r = subprocess.run([sys.executable, str(script)], capture_output=True, text=True, cwd=ROOT, timeout=600)
    assert r.returncode == 0, f"{code}\n--- stdout\n{r.stdout}\n--- stderr\n{r.stderr}"
    return r.stdout


def test_the_page_has_the_three_snippets():
    assert len(SNIPPETS) == 3, [s.splitlines()[0] for s in SNIPPETS]
    assert "caisson.run(" in SNIPPETS[0] and "dask" in SNIPPETS[1] and "ray" in SNIPPETS[2]
    for code in SNIPPETS[1:]:
        assert 'if __name__ == "__main__":' in code


def test_quick_start_runs_and_prints_what_its_comments_say(tmp_path):
    lines = run_snippet(tmp_path, SNIPPETS[0]).splitlines()
    sliding, rigid, reaction = map(float, lines[0].split())
    # The comments: 0.0109 m, 0.0158 m, 2131 kN; the heavier caisson 0.0073 m (README figures).
    assert (round(sliding, 4), round(rigid, 4), round(reaction)) == (0.0109, 0.0158, 2131)
    assert round(float(lines[1]), 4) == 0.0073
    expected, failure = map(float, lines[-1].split())
    assert expected >= 0.0 and 0.0 <= failure <= 1.0


@pytest.mark.parametrize("which, module", [(1, "dask.distributed"), (2, "ray")])
def test_distributed_snippet_runs_as_a_script(tmp_path, which, module):
    pytest.importorskip(module)
    out = run_snippet(tmp_path, SNIPPETS[which]).strip().splitlines()[-1]
    if which == 1:
        table = eval(out, {})  # {18: ..., 20: ..., 22: ...}: printed by the snippet itself
        assert sorted(table) == [18, 20, 22] and all(v >= 0.0 for v in table.values())
    else:
        assert float(out) >= 0.0
