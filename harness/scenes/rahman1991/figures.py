"""Rahman (1991), figures 5-38 replotted: slider displacement s4 and the 18 joint force/torque
components against crank angle, for each engine and each of the three families of section 3.2
(seed 001, lines 1111-1113), every panel with the ideal planar case (a4 = 0, S1 = 0, alpha4 = 270)
as a thick black line.

  family "a4"     (a4 = 10, 20, 30 in; S1 = 3.5 in; alpha4 = 270):  figs. 5, 8, 11, 14, 16, 18, 21, 24, 27, 30, 33, 36
  family "s1"     (S1 = 3, 6, 9 in; a4 = 30 in; alpha4 = 270):      figs. 6, 9, 12, 15, 17, 19, 22, 25, 28, 31, 34, 37
  family "alpha4" (alpha4 = 232, 270, 310; a4 = 20 in; S1 = 0):     figs. 7, 10, 13, 20, 23, 26, 29, 32, 35, 38

Figs. 5-7 are the displacement; 14-17 are the two pairs of torque figures (no alpha4 member: T1i and
T1j vanish when S1 = 0); the rest are forces. The thesis does not name the component of each figure,
so one PNG per quantity is written and no figure number is claimed for it. The seed prints each
caption under the preceding figure number: read one figure later, the captions agree with the text
(a4 = 30 for the s1 family, a4 = 20 for the alpha4 family, S1 = 3.5 for the a4 family).

Points near the dead centres (about 100 and 300 deg) can reach 1e6 or more; the thesis dropped them.
Here the y-limits are robust (2nd-98th percentile, widened), off-scale points are drawn as
triangles on the panel edge and counted in the panel, and non-converged points are counted in the legend.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib.figure import Figure

from ...report import draw_all, save_png
from .quantities import CONFIGURATION, POSITIONS

IDEAL = {"a4": 0.0, "s1": 0.0, "alpha4_deg": 270.0}
FAMILIES = {"a4": ("a4", [10.0, 20.0, 30.0], {"s1": 3.5, "alpha4_deg": 270.0}),
            "s1": ("s1", [3.0, 6.0, 9.0], {"a4": 30.0, "alpha4_deg": 270.0}),
            "alpha4": ("alpha4_deg", [232.0, 270.0, 310.0], {"a4": 20.0, "s1": 0.0})}
QUANTITIES = ["s4"] + [f"{p}{n}{c}" for p, n in [("F", 1), ("T", 1), ("F", 2), ("F", 3), ("F", 4), ("T", 4)]
                       for c in "ijk"]
LABEL = {"a4": "a4", "s1": "S1", "alpha4_deg": "alpha4"}
UNIT = {column: q.unit for column, q in CONFIGURATION.items()}
COLORS = ["tab:blue", "tab:orange", "tab:green", "tab:red"]


def case_rows(frame: pd.DataFrame) -> dict[tuple, pd.DataFrame]:
    """Each case's rows sorted by crank angle, keyed by (a4, s1, alpha4_deg) rounded to 1e-6."""
    keys = [frame[col].astype(float).round(6) for col in IDEAL]
    return {key: rows.sort_values("crank_deg") for key, rows in frame.groupby(keys, sort=False)}


def select(cases: dict[tuple, pd.DataFrame], where: dict, quantity: str) -> tuple[np.ndarray, np.ndarray, int]:
    """Crank angles and values of one case (NaN where not converged); and how many are not finite."""
    rows = cases.get(tuple(np.round(float(where[col]), 6) for col in IDEAL))
    if rows is None:
        return np.empty(0), np.empty(0), 0
    y = rows[quantity].to_numpy(float).copy()
    y[~rows["converged"].to_numpy(bool)] = np.nan
    return rows["crank_deg"].to_numpy(float), y, int((~np.isfinite(y)).sum())


def robust_limits(values: np.ndarray) -> tuple[float, float] | None:
    """2nd-98th percentile widened by half its span (kept inside the data range), plus a 5% margin."""
    v = values[np.isfinite(values)]
    if v.size == 0:
        return None
    lo, hi = np.percentile(v, [2, 98])
    span = hi - lo
    lo, hi = max(v.min(), lo - 0.5 * span), min(v.max(), hi + 0.5 * span)
    margin = 0.05 * (hi - lo) if hi > lo else max(abs(hi) * 0.1, 1.0)
    return lo - margin, hi + margin


def panel_curves(cases: dict[tuple, pd.DataFrame], family: str, quantity: str) -> tuple[list, list]:
    """One panel's data: curves (x, y, plot style, label), ideal first, and the cases not drawn."""
    col, members, fixed = FAMILIES[family]
    named = [("ideal", "k", IDEAL)] + [(f"{LABEL[col]} = {value:g} {UNIT[col]}", color, {**fixed, col: value})
                                       for color, value in zip(COLORS, members)]
    curves, missing = [], []
    for name, color, where in named:
        x, y, n = select(cases, where, quantity)
        if x.size == 0 or n == x.size:
            missing.append(f"{name}: {'no rows' if x.size == 0 else 'not converged'}")
            continue
        style = dict(color=color, lw=2.5, zorder=1) if name == "ideal" else dict(color=color, lw=1.2, zorder=2)
        curves.append((x, y, style, f"{name} ({n} not converged)" if n else name))
    return curves, missing


def draw_panel(ax, family: str, curves: list, missing: list) -> None:
    """Curves with robust y-limits, off-scale points as edge triangles, a note and a legend."""
    limits = robust_limits(np.concatenate([c[1] for c in curves])) if curves else None
    if limits is not None:  # headroom above the data for the legend and the note
        limits = (limits[0], limits[1] + 0.4 * (limits[1] - limits[0]))
    off = 0
    for x, y, style, label in curves:
        ax.plot(x, y, label=label, **style)
        if limits is None:
            continue
        for sel, edge, marker in [(y < limits[0], limits[0], "v"), (y > limits[1], limits[1], "^")]:
            off += int(sel.sum())
            if sel.any():
                ax.plot(x[sel], np.full(sel.sum(), edge), ls="none", marker=marker, ms=4, color=style["color"],
                        clip_on=False)
    for label in missing:
        ax.plot([], [], ls="none", label=label)
    if limits is not None:
        ax.set_ylim(*limits)
    col, _, fixed = FAMILIES[family]
    fixed_text = ", ".join(f"{LABEL[k]} = {v:g} {UNIT[k]}" for k, v in fixed.items())
    ax.set_title(f"{LABEL[col]} varies ({fixed_text})", fontsize=9)
    note = f"{off} point(s) off-scale,\nshown as edge triangles" if off else "all finite points on scale"
    ax.text(0.02, 0.97, note if limits is not None else "no finite values", transform=ax.transAxes,
            fontsize=7, va="top", color="firebrick" if off else "gray")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=6, loc="upper right")


def draw_figure(quantity: str, panels: dict[str, list], path: Path) -> Path:
    """One PNG: rows = engines, columns = families; panels maps engine -> [(curves, missing)] per family."""
    fig = Figure(figsize=(4.2 * len(FAMILIES), 3.2 * len(panels)))
    axes = fig.subplots(len(panels), len(FAMILIES), squeeze=False, sharex=True)
    axes[0][0].set_xlim(0, 360)
    axes[0][0].set_xticks(range(0, 361, 60))
    for row, (engine, data) in zip(axes, panels.items()):
        for ax, family, (curves, missing) in zip(row, FAMILIES, data):
            draw_panel(ax, family, curves, missing)
        row[0].set_ylabel(f"{engine}\n{POSITIONS[quantity].label}", fontsize=8)
    for ax in axes[-1]:
        ax.set_xlabel(POSITIONS["crank_deg"].label)
    fig.suptitle(f"Rahman (1991) figs. 5-38: {POSITIONS[quantity].words} against crank angle; thick black: the "
                 "ideal planar case", fontsize=10)
    return save_png(fig, path, left=0.09, right=0.977, bottom=0.091, top=0.901, wspace=0.273, hspace=0.251)


def plot_figures(results: dict[str, pd.DataFrame], out_dir: Path) -> list[Path]:
    """One PNG per quantity: rows = engines, columns = families. Returns the paths written."""
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    cases = {engine: case_rows(frame) for engine, frame in results.items()}
    jobs = [(quantity, {engine: [panel_curves(rows, family, quantity) for family in FAMILIES]
                        for engine, rows in cases.items()}, out_dir / f"fig_{quantity}.png")
            for quantity in QUANTITIES]
    return draw_all(draw_figure, jobs)
