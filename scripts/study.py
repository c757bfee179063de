#!/usr/bin/env python3
"""The tables and plots of the study of the breaking-wave load (docs/design.md, "The breaking-wave
load: a study") from the runs of scripts/study.sh.

    python3 scripts/study.py OUT FIGURES

OUT holds the JSON (and the 15 m site's lives.csv) of scripts/study.sh; the markdown tables are
printed, and FIGURES/study_widths.svg (the required widths over Goda's against the depth) and
FIGURES/study_pari_breaking.svg (the PARI breaking campaign's mean sliding against H) are written.
Python's standard library only.
"""

from __future__ import annotations

import csv
import json
import math
import sys
from pathlib import Path

RULES = ["cuomo-2010", "goda-takahashi", "none"]
# The depth series also under `goda-takahashi` with α_qs = 1 on every wave (scripts/study.sh).
SERIES = RULES + ["goda-takahashi-aqs1"]
LABELS = {"goda-takahashi-aqs1": "goda-takahashi, α_qs = 1"}
COLOURS = {"cuomo-2010": "#c0392b", "goda-takahashi": "#1f5fa8", "none": "#2e8b57", "goda-takahashi-aqs1": "#8e44ad"}
WIDE = {"goda-takahashi": 5}
DEPTHS = [10, 15, 20, 25, 30]


def load(path: Path) -> dict:
    return json.loads(path.read_text())


def width(model: dict) -> str:
    """A required width as the table shows it: the width, or where the range ends."""
    status = model["status"]
    if status == "found":
        return f"{model['width_m']:.2f}"
    if status == "at_lower_bound":
        return f"≤ {model['width_m']:.2f}"
    return f"> {model['bracket_m'][0]:.2f}" if model.get("bracket_m") else "not in range"


def interval(model: dict) -> str:
    lo, hi = (model.get("interval_m") or [None, None])[:2]
    show = lambda x, alt: f"{x:.1f}" if x is not None else alt
    return f"{show(lo, '<')}-{show(hi, '>')}"


def ratio(model: dict, goda: float) -> float | None:
    return model["width_m"] / goda if model["status"] == "found" else None


def depth_table(out: Path) -> dict:
    """The depth series: Goda's width and each rule's required widths (and their ratios)."""
    rows = {}
    print("| depth h (m) | Goda's width (m), governs | rule | dynamic model (m) | × Goda | rigid block (m) | × Goda |")
    print("|---|---|---|---|---|---|---|")
    for h in DEPTHS:
        for rule in SERIES:
            r = load(out / f"size_depth_{h}m_{rule}.json")
            g = r["goda"]
            goda = g["width_m"]
            d, b = r["dynamic"], r["rigid_block"]
            rows[(h, rule)] = (goda, ratio(d, goda), ratio(b, goda), d, b)
            rd, rb = ratio(d, goda), ratio(b, goda)
            print(
                f"| {h} | {goda:.2f}, {g['governs']} | {LABELS.get(rule, f'`{rule}`')} | {width(d)} ({interval(d)}) | "
                f"{'–' if rd is None else f'{rd:.2f}'} | {width(b)} ({interval(b)}) | {'–' if rb is None else f'{rb:.2f}'} |"
            )
    return rows


def capped_se(lives_csv: Path, limit_m: float, rotation_rad: float, rigid: bool) -> float:
    """The standard error of E|S| (a failed life at the limit) from lives.csv: s/√n."""
    values = []
    with open(lives_csv) as f:
        for row in csv.DictReader(f):
            if rigid:
                s = abs(float(row["rigid_block_sliding_m"]))
                values.append(min(s, limit_m) if s <= limit_m else limit_m)
            else:
                s = abs(float(row["sliding_m"]))
                failed = float(row["max_excursion_m"]) > limit_m or float(row["max_rotation_rad"]) > rotation_rad
                values.append(limit_m if failed else s)
    n = len(values)
    mean = sum(values) / n
    return math.sqrt(sum((v - mean) ** 2 for v in values) / (n - 1) / n)


def site_table(out: Path) -> None:
    """The 15 m site: the required widths and the lives at Goda's width, per rule."""
    print()
    print("| rule | dynamic model (m) | rigid block (m) | Goda's width (m) | E\\|S\\| at Goda's width, dynamic (m) | rigid block (m) | P(failure), dynamic |")
    print("|---|---|---|---|---|---|---|")
    for rule in RULES:
        r = load(out / f"size_site_15m_{rule}.json")
        d = out / f"design_site_15m_{rule}"
        j = load(d / "design.json")
        limit, rot = j["failure_sliding_m"], j["failure_rotation_rad"]
        se_d = capped_se(d / "lives.csv", limit, rot, False)
        se_b = capped_se(d / "lives.csv", limit, rot, True)
        dyn, rig = j["dynamic"], j["rigid_block"]
        print(
            f"| `{rule}` | {width(r['dynamic'])} ({interval(r['dynamic'])}) | {width(r['rigid_block'])} "
            f"({interval(r['rigid_block'])}) | {r['goda']['width_m']:.2f} | {dyn['expected_sliding_m']:.3f} ± {se_d:.3f} | "
            f"{rig['expected_sliding_m']:.3f} ± {se_b:.3f} | {dyn['failure']['probability']:.3f} |"
        )


def campaign_table(out: Path) -> dict:
    """The PARI breaking campaign: mean sliding per condition, and the seed's F7 and F8."""
    curves = {}
    print()
    for heights in ["varied", "nominal"]:
        print(f"\n{heights} heights: mean total sliding of 10 trains of 15 waves, mm (dynamic model / rigid block)\n")
        conds = None
        table = {}
        for rule in RULES:
            c = load(out / f"campaign_{heights}_{rule}.json")
            for k in c["conditions"]:
                key = (k["weight_in_water_kn"], k["height_m"])
                table.setdefault(key, {})[rule] = (1e3 * k["sliding_m"]["mean"], 1e3 * k["rigid_block_sliding_m"]["mean"])
        weights = sorted({w for w, _ in table})
        hs = sorted({h for _, h in table})
        print("| W' (kN) | H (m) | " + " | ".join(f"`{r}`" for r in RULES) + " |")
        print("|---|---|" + "---|" * len(RULES))
        for w in weights:
            for h in hs:
                if (w, h) in table:
                    cells = " | ".join(f"{table[(w, h)][r][0]:.2f} / {table[(w, h)][r][1]:.2f}" for r in RULES)
                    print(f"| {w} | {h} | {cells} |")
        # F7: sliding falls with W for each H (within 1 µm); F8: the largest mean sliding at
        # 0.524-0.569 m for each W tested at 3 heights or more (analysis/findings.rs, docs/validation.md).
        print()
        for rule in RULES:
            f7 = all(
                table[(w2, h)][rule][0] <= table[(w1, h)][rule][0] + 1e-3
                for h in hs
                for w1, w2 in zip(weights, weights[1:])
                if (w1, h) in table and (w2, h) in table
            )
            peaks = []
            for w in weights:
                row = [(table[(w, h)][rule][0], h) for h in hs if (w, h) in table]
                if len(row) >= 3:
                    best = row[0]
                    for r in row[1:]:
                        best = r if r[0] > best[0] else best
                    peaks.append((w, best[1]))
            f8 = all(0.524 <= h <= 0.569 for _, h in peaks)
            print(
                f"- `{rule}`: F7 (falls with W at every H) {'holds' if f7 else 'does not hold'}; "
                f"F8 (largest at 0.524-0.569 m) {'holds' if f8 else 'does not hold'}: largest at "
                + ", ".join(f"H = {h} m (W' = {w} kN)" for w, h in peaks)
            )
        curves[heights] = (table, weights, hs)
    return curves


# ------------------------------------------------------------------------------------------------
# A small SVG line chart (the project's plots are the CLI's; this one is the study's own).


class Chart:
    def __init__(self, x0, y0, w, h, xr, yr, title, xlabel, ylabel):
        self.x0, self.y0, self.w, self.h = x0, y0, w, h
        self.xr, self.yr = xr, yr
        self.parts = []
        self.title, self.xlabel, self.ylabel = title, xlabel, ylabel

    def px(self, x):
        return self.x0 + (x - self.xr[0]) / (self.xr[1] - self.xr[0]) * self.w

    def py(self, y):
        return self.y0 + self.h - (y - self.yr[0]) / (self.yr[1] - self.yr[0]) * self.h

    def frame(self, xticks, yticks):
        p = self.parts
        p.append(f'<rect x="{self.x0}" y="{self.y0}" width="{self.w}" height="{self.h}" fill="white" stroke="#444"/>')
        for x in xticks:
            X = self.px(x)
            p.append(f'<line x1="{X:.1f}" y1="{self.y0}" x2="{X:.1f}" y2="{self.y0 + self.h}" stroke="#ddd"/>')
            p.append(f'<text x="{X:.1f}" y="{self.y0 + self.h + 16}" text-anchor="middle">{x:g}</text>')
        for y in yticks:
            Y = self.py(y)
            p.append(f'<line x1="{self.x0}" y1="{Y:.1f}" x2="{self.x0 + self.w}" y2="{Y:.1f}" stroke="#ddd"/>')
            p.append(f'<text x="{self.x0 - 6}" y="{Y + 4:.1f}" text-anchor="end">{y:g}</text>')
        p.append(f'<text x="{self.x0 + self.w / 2}" y="{self.y0 - 10}" text-anchor="middle" font-weight="bold">{self.title}</text>')
        p.append(f'<text x="{self.x0 + self.w / 2}" y="{self.y0 + self.h + 36}" text-anchor="middle">{self.xlabel}</text>')
        cx, cy = self.x0 - 44, self.y0 + self.h / 2
        p.append(f'<text x="{cx}" y="{cy}" text-anchor="middle" transform="rotate(-90 {cx} {cy})">{self.ylabel}</text>')

    def line(self, pts, colour, dashed=False, marker="circle", width=2):
        pts = [(x, y) for x, y in pts if y is not None]
        if not pts:
            return
        d = " ".join(f"{self.px(x):.1f},{self.py(y):.1f}" for x, y in pts)
        dash = ' stroke-dasharray="6,4"' if dashed else ""
        self.parts.append(f'<polyline points="{d}" fill="none" stroke="{colour}" stroke-width="{width}"{dash}/>')
        for x, y in pts:
            X, Y = self.px(x), self.py(y)
            if marker == "circle":
                self.parts.append(f'<circle cx="{X:.1f}" cy="{Y:.1f}" r="3.5" fill="{colour}"/>')
            else:
                self.parts.append(f'<rect x="{X - 3.5:.1f}" y="{Y - 3.5:.1f}" width="7" height="7" fill="white" stroke="{colour}" stroke-width="1.5"/>')


def svg(path: Path, width: int, height: int, parts: list) -> None:
    head = (
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
        f'viewBox="0 0 {width} {height}" font-family="DejaVu Sans, Arial, sans-serif" font-size="12">'
        f'<rect width="{width}" height="{height}" fill="white"/>'
    )
    path.write_text(head + "".join(parts) + "</svg>\n")


def legend(parts, x, y, entries):
    for i, (label, colour, dashed, marker) in enumerate(entries):
        Y = y + 18 * i
        dash = ' stroke-dasharray="6,4"' if dashed else ""
        parts.append(f'<line x1="{x}" y1="{Y}" x2="{x + 28}" y2="{Y}" stroke="{colour}" stroke-width="2"{dash}/>')
        if marker is None:
            pass
        elif marker == "circle":
            parts.append(f'<circle cx="{x + 14}" cy="{Y}" r="3.5" fill="{colour}"/>')
        else:
            parts.append(f'<rect x="{x + 10.5}" y="{Y - 3.5}" width="7" height="7" fill="white" stroke="{colour}" stroke-width="1.5"/>')
        parts.append(f'<text x="{x + 36}" y="{Y + 4}">{label}</text>')


def widths_plot(rows: dict, path: Path) -> None:
    ratios = [v for (goda, rd, rb, *_) in rows.values() for v in (rd, rb) if v is not None]
    top = max(2.0, math.ceil(max(ratios) * 4) / 4)
    c = Chart(70, 40, 520, 330, (8, 32), (0, top), "Required width over Goda's width (E|S| ≤ 0.3 m in 50 years)",
              "water depth at the toe h (m)", "required width / Goda's width")
    c.frame(DEPTHS, [k * 0.25 for k in range(int(top / 0.25) + 1)])
    c.parts.append(f'<line x1="{c.px(8)}" y1="{c.py(1):.1f}" x2="{c.px(32)}" y2="{c.py(1):.1f}" stroke="#000" stroke-width="1.5"/>')
    entries = []
    for rule in SERIES:
        col, w = COLOURS[rule], WIDE.get(rule, 2)
        c.line([(h, rows[(h, rule)][1]) for h in DEPTHS], col, False, "circle", w)
        c.line([(h, rows[(h, rule)][2]) for h in DEPTHS], col, True, "square", w)
        name = LABELS.get(rule, rule)
        entries += [(f"{name}: dynamic model", col, False, "circle"), (f"{name}: rigid block", col, True, "square")]
    entries.append(("Goda's width (with α_I)", "#000", False, None))
    legend(c.parts, 610, 60, entries)
    c.parts.append(f'<text x="610" y="{60 + 18 * len(entries) + 10}" fill="#444">goda-takahashi (wide) and none coincide</text>')
    svg(path, 900, 420, c.parts)


def campaign_plot(curves: dict, path: Path) -> None:
    table, weights, hs = curves["varied"]
    parts = []
    top = max(v[r][0] for v in table.values() for r in RULES)
    top = math.ceil(top / 10) * 10 if top > 10 else math.ceil(top)
    dash = {w: i for i, w in enumerate(weights)}
    greys = ["#000000", "#555555", "#888888", "#aaaaaa", "#cccccc"]
    parts.append(
        '<text x="20" y="18" font-weight="bold">PARI breaking campaign (examples/pari_breaking_campaign.toml: '
        'profile seed-2011, 20 % height variability, 10 trains of 15 waves)</text>'
        '<text x="20" y="36">goda-takahashi with a berm B_M = 1.12 m = 0.12 L (the seed gives none); '
        'the seed (Fig. 15) finds the largest sliding at H = 0.524-0.569 m</text>'
    )
    for i, rule in enumerate(RULES):
        c = Chart(70 + i * 300, 76, 240, 260, (0.4, 0.64), (0, top), f"breaking_load = {rule}",
                  "wave height H (m)", "mean total sliding (mm)" if i == 0 else "")
        c.frame([0.428, 0.524, 0.569, 0.619], [top * k / 5 for k in range(6)])
        for w in weights:
            pts = [(h, table[(w, h)][rule][0]) for h in hs if (w, h) in table]
            if len(pts) > 1:
                c.line(pts, greys[dash[w]], False, "circle")
        parts += c.parts
    legend(parts, 980, 96, [(f"W' = {w} kN", greys[dash[w]], False, "circle") for w in weights if sum((w, h) in table for h in hs) > 1])
    svg(path, 1120, 390, parts)


def main() -> None:
    out, figures = Path(sys.argv[1]), Path(sys.argv[2])
    rows = depth_table(out)
    site_table(out)
    curves = campaign_table(out)
    widths_plot(rows, figures / "study_widths.svg")
    campaign_plot(curves, figures / "study_pari_breaking.svg")
    print(f"\nwrote {figures / 'study_widths.svg'} and {figures / 'study_pari_breaking.svg'}")


if __name__ == "__main__":
    main()
