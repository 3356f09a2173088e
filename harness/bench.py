"""``linkrepro bench``: speed against error for every scene, from one run.

Two parts, printed as markdown and written to ``--out`` (bench.md, bench.png, bench.csv):

1. **Cost per position** of each computation (a ``Computation``) for legacy (the FORTRAN
   through f2py), the port with the listing's bugs and the port corrected, against a
   flop-count limit: a hand count of the floating-point operations per position of the
   listing's algorithm (good to a factor of two) at ``FLOP_RATE``.  The ratios port/legacy and
   legacy/limit are the result.
2. **Speed against error** for each knob that trades one for the other (a ``Knob``, or a
   ``Sweep`` measured by a study of its own): the error against a converged reference, the
   time, and the Pareto front (the settings no other setting beats in both).

This module is the machine; each thesis's computations, knobs, sweeps and flop counts are
in its ``harness/scenes/<thesis>/bench.py``; ``harness/bench_run.py`` finds them through the
scene registry (``harness.scenes``) and runs them (``run_bench``).

Times: ``time.perf_counter``, best of ``repeat`` calls, the engines of one computation (or
the settings of one knob) taken in turn within each round so that the machine's load falls on
all alike; every ``functools.lru_cache`` of ``linkrepro.port`` is cleared before each call
(a repeat measures the work, not a cache); every result shown is that of a timed call.  Read
the ratios, not the seconds: the machine is shared.  Units: seconds, microseconds (us) per
position, inches and radians for the errors unless a knob says otherwise.  What it is doing
shows on stderr's progress line (``harness/progress``) when stderr is a terminal.
"""
from __future__ import annotations

import sys
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

import numpy as np
import pandas as pd

from . import progress
from .markdown_text import prose

#: the port's package (linkrepro.port), whose caches are cleared before each timed call
PORT = __name__.split(".")[0] + ".port"
ENGINES = ("legacy", "port_printed", "port_corrected")
#: the files the bench writes into its output folder
OUTPUTS = ("bench.md", "bench.png", "bench.csv")
#: the columns of bench.csv, one row per engine of a computation or per setting of a knob
COLUMNS = ["kind", "subject", "setting", "engine", "positions", "seconds", "us_per_position",
           "flops_per_position", "error", "error_unit", "reference", "pareto", "note"]

# ------------------------------------------------------------------ the flop-count limit

#: the rate of the limit (flop/s): one core's scalar peak, 4 double-precision additions and
#: multiplications a cycle (two pipes each, no SIMD, no fused multiply-add: the FORTRAN is built
#: with -ffp-contract=off) at 2.5 GHz.  (At 1 GFLOP/s the CSSP legacy build beats the "limit".)
FLOP_RATE = 1e10
#: flops charged for one sin, cos, atan or sqrt (a libm call)
TRANSCENDENTAL = 20


def mprd(n: int, m: int, l: int) -> int:
    """Flops of an (n x m)(m x l) matrix product formed densely, as MPRD and MULTI do."""
    return 2 * n * m * l


# ------------------------------------------------------------------ timing

def clear_port_caches() -> None:
    """Clear every functools cache of linkrepro.port (so that a repeat does the work again)."""
    for name, module in list(sys.modules.items()):
        if not name.startswith(PORT):
            continue
        for value in list(vars(module).values()):
            if hasattr(value, "cache_clear") and str(getattr(value, "__module__", "")).startswith(name):
                value.cache_clear()


def timed(funcs: dict[str, Callable], repeat: int) -> dict[str, tuple[float, object]]:
    """{name: (best seconds of ``repeat`` calls, the result of the last call)}; each round
    calls every function once, in turn, with the port's caches cleared before each call."""
    best = {name: float("inf") for name in funcs}
    results = {}
    for _ in range(repeat):
        for name, func in funcs.items():
            clear_port_caches()
            start = time.perf_counter()
            results[name] = func()
            best[name] = min(best[name], time.perf_counter() - start)
    return {name: (best[name], results[name]) for name in funcs}


def step(what: str, func: Callable):
    """func(), shown as ``what`` on the progress line (stderr, when it is a terminal)."""
    progress.note("bench", what)
    result = func()
    progress.done("bench")
    return result


# ------------------------------------------------------------------ part 1: cost per position

@dataclass
class Computation:
    """One computation timed on each engine.  ``engines``: name -> call (absent: the engine
    does not exist); ``flops(results)``: the limit's flops per position; ``agreement(legacy,
    port_printed)``: how far the port with the bugs is from legacy (a relative number)."""
    name: str
    positions: int
    engines: dict[str, Callable]
    flops: Callable[[dict], float]
    agreement: Callable | None = None
    legacy_positions: int | None = None     # positions the legacy call solves, if not ``positions``
    note: str = ""


def relative_error(a: np.ndarray, b: np.ndarray) -> float:
    """max |a - b| / max |b|."""
    return float(np.max(np.abs(a - b)) / np.max(np.abs(b)))


def cost_rows(comp: Computation, repeat: int) -> list[dict]:
    """The computation's rows of bench.csv: one per engine and one for the limit."""
    runs = timed(comp.engines, repeat)
    flops = comp.flops({name: result for name, (_, result) in runs.items()})
    rows = []
    for engine in ENGINES:
        if engine not in runs:
            continue
        seconds, result = runs[engine]
        positions = comp.legacy_positions if engine == "legacy" and comp.legacy_positions else comp.positions
        agrees = (comp.agreement(runs["legacy"][1], result)
                  if engine == "port_printed" and comp.agreement and "legacy" in runs else np.nan)
        rows.append(dict(kind="cost", subject=comp.name, engine=engine, positions=positions, seconds=seconds,
                         us_per_position=1e6 * seconds / positions, flops_per_position=flops, error=agrees,
                         error_unit="max |port - legacy| / max |legacy|" if np.isfinite(agrees) else "",
                         note=comp.note))
    rows.append(dict(kind="cost", subject=comp.name, engine="limit", positions=comp.positions,
                     seconds=flops * comp.positions / FLOP_RATE, us_per_position=1e6 * flops / FLOP_RATE,
                     flops_per_position=flops, note=f"{flops:.0f} flops a position at {FLOP_RATE:.0e} flop/s"))
    return rows


# ------------------------------------------------------------------ part 2: knobs

@dataclass
class Knob:
    """Settings of one knob (label -> call), the one taken as converged (``reference``),
    ``error(result, reference_result)`` -> (error, note), np.inf with a note where a setting
    fails, and ``positions(result)``: the positions one call computes."""
    name: str
    engine: str
    unit: str
    what: str
    settings: dict[str, Callable]
    reference: str
    error: Callable[[object, object], tuple[float, str]]
    positions: Callable[[object], int]


def crank_grid(step: float) -> np.ndarray:
    """0, step, ... up to 360 deg."""
    return np.arange(0.0, 360.0 + 1e-9, step)


def step_label(step: float) -> str:
    return f"{step:g} deg"


def knob_rows(knob: Knob, repeat: int) -> list[dict]:
    """The knob's rows of bench.csv, one per setting, with the Pareto front marked."""
    runs = timed(knob.settings, repeat)
    reference = runs[knob.reference][1]
    rows = []
    for label, (seconds, result) in runs.items():
        error, note = knob.error(result, reference)
        positions = knob.positions(result)
        rows.append(dict(kind="knob", subject=knob.name, setting=label, engine=knob.engine, positions=positions,
                         seconds=seconds, us_per_position=1e6 * seconds / positions if positions else np.nan,
                         error=error, error_unit=knob.unit, reference=label == knob.reference, note=note))
    return with_pareto_front(rows)


@dataclass
class Sweep:
    """A knob measured by a study of its own rather than by ``timed``: ``rows(repeat)``, its
    rows of bench.csv (the Pareto front marked, ``with_pareto_front``); ``what``, its description in
    bench.md; ``series``, where given, splits a setting into its series and its point's label (the
    figure draws a line per series).  A sweep has many settings: ``bench_run.run_bench`` gives it
    ``repeat // 10`` calls a timing, at least 1."""
    name: str
    what: str
    rows: Callable[[int], list[dict]]
    series: Callable[[str], tuple[str, str]] | None = None    # setting -> (series, point label), for the figure


def pareto_front(seconds, errors) -> np.ndarray:
    """True for the points no other point beats: none as fast or faster and as accurate or more,
    better in one.  A non-finite error (a failed setting) is never on the front."""
    t, e = np.asarray(seconds, dtype=float), np.asarray(errors, dtype=float)
    ok = np.isfinite(t) & np.isfinite(e)
    front = np.zeros(t.size, dtype=bool)
    for i in np.flatnonzero(ok):
        beaten = ok & (t <= t[i]) & (e <= e[i]) & ((t < t[i]) | (e < e[i]))
        front[i] = not beaten.any()
    return front


def with_pareto_front(rows: list[dict]) -> list[dict]:
    front = pareto_front([r["seconds"] for r in rows], [r["error"] for r in rows])
    return [{**row, "pareto": bool(on)} for row, on in zip(rows, front)]


# ------------------------------------------------------------------ output

def _us(value: float) -> str:
    return "" if not np.isfinite(value) else f"{value:.3g}"


def _ratio(a: float, b: float) -> str:
    return f"{a / b:.3g}" if np.isfinite(a) and np.isfinite(b) and b > 0 else ""


def cost_table(rows: pd.DataFrame) -> list[str]:
    """Part 1 as markdown: one line per computation, then its notes."""
    lines = ["| computation | positions | legacy us | port (bugs) us | port corrected us | limit us (flops) | "
             "port (bugs) / legacy | port corrected / legacy | legacy / limit | port corrected / limit | "
             "port (bugs) vs legacy |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    notes = []
    for name, g in rows.groupby("subject", sort=False):
        us = dict(zip(g.engine, g.us_per_position))
        legacy_us, printed, corrected, limit = (us.get(e, np.nan) for e in (*ENGINES, "limit"))
        agree = g.error[g.engine == "port_printed"].dropna()
        lines.append(f"| {prose(name)} | {g.positions.iloc[-1]} | {_us(legacy_us)} | {_us(printed)} | {_us(corrected)} | "
                     f"{_us(limit)} ({g.flops_per_position.iloc[0]:.3g}) | {_ratio(printed, legacy_us)} | "
                     f"{_ratio(corrected, legacy_us)} | {_ratio(legacy_us, limit)} | {_ratio(corrected, limit)} | "
                     f"{f'{agree.iloc[0]:.1e}' if len(agree) else ''} |")
        notes += [f"- {prose(name)}: {prose(g.note.iloc[0])}."] if isinstance(g.note.iloc[0], str) and g.note.iloc[0] else []
    return lines + [""] + notes


#: a setting on the Pareto front, as knob_tables marks it (an asterisk, escaped: not emphasis)
FRONT = "\\* "


def knob_tables(rows: pd.DataFrame, descriptions: dict[str, str]) -> list[str]:
    """Part 2 as markdown: one table per knob."""
    lines = []
    for name, g in rows.groupby("subject", sort=False):
        lines += [f"### {prose(name)}", "", f"{prose(descriptions[name])}. Error unit: {prose(str(g.error_unit.iloc[0]))}; "
                  f"{FRONT}on the Pareto front, = the reference.", "", "| setting | seconds | error | |", "|---|---|---|---|"]
        for r in g.itertuples():
            error = f"{r.error:.2e}" if np.isfinite(r.error) else prose(str(r.note))
            lines.append(f"| {prose(str(r.setting))} | {r.seconds:.3g} | {error} | {FRONT if r.pareto else ''}"
                         f"{'=' if r.reference is True else ''} |")
        lines.append("")
    return lines


def markdown(frame: pd.DataFrame, descriptions: dict[str, str], repeat: int, elapsed: float, png: str,
             warned: dict[tuple[str, str], int] | None = None) -> str:
    """bench.md: the cost table, the figure, the knobs' tables, and the warnings the engines gave
    (``warned``: (category, message): times; a bench computes settings near the listings' limits,
    where an engine says its answer keeps fewer digits)."""
    lines = ["# linkrepro bench", "",
             f"{'One call' if repeat == 1 else f'Best of {repeat} calls'} each (time.perf_counter; the port's "
             "caches cleared before each call), all "
             f"from one run of {elapsed:.0f} s. The machine is shared: read the ratios, measured side by side, "
             "not the seconds.", "", "## Cost per position", "",
             "Microseconds per position (an input angle, a crank position). Limit: the flops per position of the "
             "listing's algorithm, counted by hand (`harness/scenes/<thesis>/bench.py`: `KED_*`, `NEWTON_*`, `CSSP_*`, "
             f"`CLOSED_LOOP`, `GSC_FORCES`; matrix products dense as the listings form them, {TRANSCENDENTAL} flops for a sin, "
             f"cos, atan or sqrt), at {FLOP_RATE / 1e9:g} GFLOP/s (one core's scalar peak: 4 flops a cycle at "
             "2.5 GHz, no SIMD). Last column: the port with the listing's bugs against legacy on the same inputs, "
             "max |difference| / max |legacy|.", ""]
    lines += cost_table(frame[frame.kind == "cost"])
    lines += ["", "## Speed against error, per knob", "",
              "Seconds of one call (every position of the setting); error against the knob's converged "
              "reference. The figure plots them per knob (those with three settings or more of different errors), the "
              "Pareto front marked; its caption tells the others.", "",
              f"![error against time]({png})", ""]
    lines += knob_tables(frame[frame.kind == "knob"], descriptions)
    if warned:
        lines += ["", "## Warnings the engines gave", "",
                  "Every distinct warning of the run (its category, how many times it was given, its words): "
                  "the times above include the calls that warned.", ""]
        lines += [f"- `{category}` ({times} time{'s' * (times != 1)}): {prose(message)}"
                  for (category, message), times in sorted(warned.items())]
    return "\n".join(lines) + "\n"


# ------------------------------------------------------------------ the figure (bench.png)

#: a knob gets a panel when at least this many of its settings have a finite error, of two values
#: or more (the others, two settings or all alike, are told in the caption and the tables)
PANEL_SETTINGS = 3
#: a sweep's series: colours by the last part of their names, lines by the first ("coupled, 20 deg")
SERIES_COLOURS = ("darkviolet", "tab:green", "tab:blue", "tab:brown", "tab:olive", "tab:cyan")
SERIES_LINES = (dict(ls="-", marker="o", ms=4), dict(ls="--", marker="x", ms=6), dict(ls=":", marker="s", ms=4))
#: the looks: the Pareto front (a band under the points, its settings ringed), a setting, an error 0
#: (at the floor), a failed setting (at the ceiling)
LOOKS = {"band": dict(color="tab:red", lw=6, alpha=0.3, solid_capstyle="round", zorder=1),
         "front": dict(marker="o", ms=10, mfc="none", mec="tab:red", mew=1.5, ls="none", zorder=5),
         "setting": dict(color="0.35", marker="o", ls="none", ms=5, zorder=2),
         "zero": dict(color="k", marker="v", ls="none", ms=7, zorder=4),
         "failed": dict(color="k", marker="X", ls="none", ms=7, zorder=4)}
LOOK_WORDS = {"band": "the Pareto front", "front": "a setting on it", "setting": "a setting",
              "zero": "error 0 (the reference or as good), at the floor", "failed": "failed, at the ceiling"}


def series_of_setting(setting: str) -> tuple[str, str]:
    """A sweep's setting "n = 10, coupled, 20 deg" as (its series "coupled, 20 deg", its point "n = 10")."""
    point, _, series = setting.partition(", ")
    return series, point


def paneled(knobs: pd.DataFrame) -> tuple[list, list]:
    """The knobs (name, rows) that get a panel, and the others (``PANEL_SETTINGS``)."""
    drawn, told = [], []
    for name, g in knobs.groupby("subject", sort=False):
        finite = g.error[np.isfinite(g.error.astype(float))]
        (drawn if len(finite) >= PANEL_SETTINGS and finite.nunique() > 1 else told).append((name, g))
    return drawn, told


def error_label(unit: str) -> str:
    """The error axis in words with its unit; a knob whose error mixes variables of two units says so."""
    if unit == "relative":
        return "relative error against the reference"
    units = [u.strip() for u in unit.split(",")]
    if len(units) == 1:
        return f"error against the reference ({unit})"
    return f"error against the reference\n(each variable's unit: {' or '.join(units)})"


def _time_ticks(ax, low: float, high: float) -> None:
    """Label the log time axis (ms) at the sparsest of 1, 1-3, 1-2-5 per decade that gives two
    ticks or more in the view [low, high] (else at 2-9, every other), as plain numbers."""
    decades = range(int(np.floor(np.log10(low))), int(np.ceil(np.log10(high))) + 1)
    for subs in ((1,), (1, 3), (1, 2, 5), (2, 4, 6, 8)):
        ticks = [m * 10.0 ** e for e in decades for m in subs if low <= m * 10.0 ** e <= high]
        if len(ticks) >= 2:
            break
    ax.set_xticks(ticks, [f"{t:g}" for t in ticks])
    ax.xaxis.set_minor_formatter("")


def _draw_knob(ax, g: pd.DataFrame, series: Callable | None) -> tuple[dict, list, np.ndarray]:
    """One knob's panel: error against time (ms), the front a band under the points; returns its
    legend handles, the points to label (x, y, text; front first) and every point (x, y).  A knob
    with ``series`` (a sweep) has a line per series and labels on the front only; another knob, a
    label on every setting."""
    error, ms = g.error.astype(float), 1e3 * g.seconds.astype(float)
    positive = error[np.isfinite(error) & (error > 0)]
    floor, ceiling = (positive.min() / 10, positive.max() * 10) if len(positive) else (1e-16, 1.0)
    shown = error.where(np.isfinite(error), ceiling).clip(lower=floor)
    front = g.pareto.astype(bool)
    order = ms[front].sort_values().index
    handles = {}
    handles[LOOK_WORDS["band"]], = ax.loglog(ms[order], shown[order], **LOOKS["band"])
    if series:
        names = [series(s) for s in g.setting]
        lasts = list(dict.fromkeys(n[0].rpartition(", ")[2] for n in names))
        firsts = list(dict.fromkeys(n[0].partition(", ")[0] for n in names))
        for label in dict.fromkeys(n[0] for n in names):
            at = [k for k, n in enumerate(names) if n[0] == label]
            style = dict(SERIES_LINES[firsts.index(label.partition(", ")[0]) % len(SERIES_LINES)],
                         color=SERIES_COLOURS[lasts.index(label.rpartition(", ")[2]) % len(SERIES_COLOURS)])
            handles[label], = ax.loglog(ms.iloc[at], shown.iloc[at], lw=1.5, zorder=2, **style)
        text = {i: n[1] for i, n in zip(g.index, names)}
    else:
        text = dict(zip(g.index, g.setting.astype(str)))
        ordinary = np.isfinite(error) & (error > 0)
        handles[LOOK_WORDS["setting"]], = ax.loglog(ms[ordinary], shown[ordinary], **LOOKS["setting"])
    handles[LOOK_WORDS["front"]], = ax.loglog(ms[order], shown[order], **LOOKS["front"])
    for kind, where in (("zero", error <= 0), ("failed", ~np.isfinite(error))):
        if where.any():
            handles[LOOK_WORDS[kind]], = ax.loglog(ms[where], shown[where], **LOOKS[kind])
    low, high = ms.min() / 1.6, ms.max() * 4.0              # room on the right for the labels
    ax.set_xlim(low, high)
    ax.set_ylim(shown.min() / (10 if (error <= 0).any() else 4), shown.max() * 10)
    _time_ticks(ax, low, high)
    ax.yaxis.set_minor_formatter("")
    ax.grid(alpha=0.3, which="major")
    labelled = [*order, *(i for i in g.index if i not in order and not series)]
    return handles, [(ms[i], shown[i], text[i]) for i in labelled], np.column_stack([ms, shown])


# ------------------------------------------------------------------ its point labels

def _spots(px: float, py: float, w: float, h: float, distances: tuple):
    """Lower-left corners of a w x h label around the point (px, py), nearest first: right, left,
    above, below and the four corners, then (farther than the first distance) eight directions
    between them, at each of ``distances`` (display pixels)."""
    for d in distances:
        e = 0.7 * d
        yield from ((px + d, py - h / 2), (px - d - w, py - h / 2), (px - w / 2, py + d), (px - w / 2, py - d - h),
                    (px + e, py + e), (px + e, py - e - h), (px - e - w, py + e), (px - e - w, py - e - h))
        if d > distances[0]:
            for angle in np.radians(np.arange(22.5, 360.0, 45.0)):
                cx, cy = px + d * np.cos(angle), py + d * np.sin(angle)
                yield (cx if cx >= px else cx - w), (cy if cy >= py else cy - h)


#: distances (px) of a label beside its point, and of one joined to it by a thin line
NEAR, FAR = (10.0, 14.0, 19.0), (30.0, 45.0, 60.0, 80.0, 100.0)


def _distance(box: tuple, xy: np.ndarray) -> np.ndarray:
    """Display distance from the box (x0, y0, x1, y1) to each point."""
    dx = np.maximum.reduce([box[0] - xy[:, 0], np.zeros(len(xy)), xy[:, 0] - box[2]])
    dy = np.maximum.reduce([box[1] - xy[:, 1], np.zeros(len(xy)), xy[:, 1] - box[3]])
    return np.hypot(dx, dy)


def _nearest(box: tuple, px: float, py: float, others: np.ndarray) -> bool:
    """Whether a label in ``box`` reads as the point (px, py)'s: no other point nearer the box,
    and every other point farther from its centre."""
    centre = np.array([(box[0] + box[2]) / 2, (box[1] + box[3]) / 2])
    return bool((_distance(box, np.array([[px, py]]))[0] <= _distance(box, others)).all()
                and (np.hypot(*(centre - [px, py])) < np.hypot(*(centre - others).T)).all())


def place_labels(ax, renderer, labels: list[tuple[float, float, str]], points: np.ndarray) -> int:
    """Write each label (9 pt) beside its point (data coordinates) at the first spot (``_spots``)
    inside the axes that covers no curve or point and no label already placed: ``NEAR`` where it
    lies nearer its own point than any other of ``points`` (x, y: the panel's settings), else
    ``FAR``, joined to its point by a thin line that crosses no label; returns how many found no
    spot (left unwritten)."""
    from .figures import _data_points
    inside = ax.get_window_extent(renderer).padded(-2.0)
    data = _data_points(ax)
    markers = ax.transData.transform(points)
    placed, written, missed = [], [], 0
    for x, y, words in labels:
        px, py = ax.transData.transform((x, y))
        if any(text == words and np.hypot(qx - px, qy - py) < 8.0 for qx, qy, text in written):
            continue                                    # the same words at (nearly) the same point
        others = markers[np.hypot(markers[:, 0] - px, markers[:, 1] - py) > 1.0]
        label = ax.text(x, y, words, fontsize=9, ha="left", va="bottom")
        extent = label.get_window_extent(renderer)
        w, h = extent.width, extent.height

        def free(box):
            return (inside.x0 <= box[0] and box[2] <= inside.x1 and inside.y0 <= box[1] and box[3] <= inside.y1
                    and not _hits(box, data, 4.0) and all(_apart(box, other) for other in placed))

        near = (box for box in ((x0, y0, x0 + w, y0 + h) for x0, y0 in _spots(px, py, w, h, NEAR))
                if free(box) and _nearest(box, px, py, others))
        far = (box for box in ((x0, y0, x0 + w, y0 + h) for x0, y0 in _spots(px, py, w, h, FAR))
               if free(box) and _clear_line(px, py, box, placed, others))
        box = next(near, None)
        joined = box is None
        box = next(far, None) if joined else box
        label.remove()
        if box is None:
            missed += 1
            continue
        at = tuple(ax.transData.inverted().transform((px + box[0] - extent.x0, py + box[1] - extent.y0)))
        ax.text(*at, words, fontsize=9, ha="left", va="bottom")
        if joined:
            data = np.concatenate([data, _leader(ax, px, py, box)])
        placed.append(box)
        written.append((px, py, words))
    return missed


def _clear_line(px: float, py: float, box: tuple, placed: list, others: np.ndarray) -> bool:
    """Whether the line from (px, py) to the centre of ``box`` passes through no placed label and
    6 px or more from every other point (sampled every 2 px or less)."""
    centre = np.array([(box[0] + box[2]) / 2, (box[1] + box[3]) / 2])
    t = np.linspace(0.0, 1.0, 100)[:, None]
    line = np.array([px, py]) + t * (centre - np.array([px, py]))
    line = line[np.hypot(line[:, 0] - px, line[:, 1] - py) > 8.0]     # leaving its own point's cluster
    near = (np.hypot(line[:, None, 0] - others[None, :, 0], line[:, None, 1] - others[None, :, 1]) < 6.0).any()
    return not near and not any(_hits(other, line, 1.0) for other in placed)


def _leader(ax, px: float, py: float, box: tuple) -> np.ndarray:
    """Draw a thin line from the point (px, py) towards the nearest edge of the label's ``box``
    (display pixels), clear of both (a patch: no curve of the data); returns its pixels, every 2."""
    from matplotlib.patches import ConnectionPatch
    end = np.array([min(max(px, box[0]), box[2]), min(max(py, box[1]), box[3])])
    start = np.array([px, py])
    length = np.hypot(*(end - start))
    a, b = start + (end - start) * 6.0 / length, end - (end - start) * 2.0 / length
    back = ax.transData.inverted()
    ax.add_artist(ConnectionPatch(tuple(back.transform(a)), tuple(back.transform(b)), "data", color="0.4", lw=0.8))
    return a + np.linspace(0.0, 1.0, max(2, int(length / 2)))[:, None] * (b - a)


def _hits(box: tuple, xy: np.ndarray, pad: float) -> bool:
    return bool(((xy[:, 0] > box[0] - pad) & (xy[:, 0] < box[2] + pad)
                 & (xy[:, 1] > box[1] - pad) & (xy[:, 1] < box[3] + pad)).any())


def _apart(a: tuple, b: tuple, pad: float = 2.0) -> bool:
    return a[2] + pad <= b[0] or b[2] + pad <= a[0] or a[3] + pad <= b[1] or b[3] + pad <= a[1]


def _quoted(setting) -> str:
    """A setting as the caption lists it: quoted where it holds a comma."""
    return f'"{setting}"' if "," in str(setting) else str(setting)


def _error_words(error: float, unit: str) -> str:
    """A setting's error as the caption tells it, with its unit ("in, rad": "(in or rad)")."""
    if not np.isfinite(error):
        return "failed"
    if error == 0 or unit == "relative":
        return f"{'relative ' if unit == 'relative' else ''}error {error:.2g}"
    return f"error {error:.2g} " + (unit if "," not in unit else f"({unit.replace(', ', ' or ')})")


def _told(name: str, g: pd.DataFrame) -> str:
    """A knob without a panel in words: each setting's error and time."""
    return f"{name}: " + ", ".join(f"{_quoted(r.setting)} {_error_words(r.error, r.error_unit)} "
                                   f"({1e3 * r.seconds:.2g} ms)" for r in g.itertuples())


def plot(frame: pd.DataFrame, path: Path, series: dict[str, Callable] | None = None) -> Path:
    """bench.png: error against the wall time of one call, a panel per knob with three settings or
    more of different errors (``paneled``), the Pareto front marked, each setting labelled (a
    sweep's ``series``: setting -> (series, point label), a line per series and the front's
    labels); an error 0 at the panel's floor, a failed setting at its ceiling.  The caption
    names each front and tells the knobs without a panel."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from .figures import MAX_WIDTH_IN, save
    from .report import panel_grid, top_legend
    series = series or {}
    drawn, told = paneled(frame[frame.kind == "knob"])
    across = min(2, max(1, len(drawn)))
    down = max(1, -(-len(drawn) // across))
    fig, margins = panel_grid(MAX_WIDTH_IN, across, down, 2.6, "linkrepro bench: the error of each knob's "
                              "settings against the wall time of one call", legend_rows=2, left=1.05, gap_across=1.0)
    axes = fig.subplots(down, across, squeeze=False)
    fig.subplots_adjust(**margins)
    renderer = FigureCanvasAgg(fig).get_renderer()
    handles, missed, fronts = {}, 0, []
    for ax, (name, g) in zip(axes.flat, drawn):
        drawn_handles, labels, points = _draw_knob(ax, g, series.get(name))
        handles |= drawn_handles
        ax.set_title(name)
        ax.set_xlabel("wall time of one call (ms)")
        ax.set_ylabel(error_label(g.error_unit.iloc[0]))
        missed += place_labels(ax, renderer, labels, points)
        fronts.append(f"{name}: {', '.join(map(_quoted, g.setting[g.pareto.astype(bool)]))}")
    for ax in axes.flat[len(drawn):]:
        ax.set_visible(False)
    looks = [LOOK_WORDS[k] for k in LOOKS if LOOK_WORDS[k] in handles]
    top_legend(fig, {label: handles[label] for label in [*looks, *(h for h in handles if h not in looks)]}, rows=2)
    caption = ("Speed against error, a panel per knob with three settings or more of different errors: each "
               "setting's error against the knob's reference setting (up) and the wall time of one call (across; "
               "this run's, on a shared machine: read the ratios). Each point is a setting, labelled (a sweep of "
               "many settings: a line per series, only the front's points labelled); the Pareto front (the "
               "settings no other beats in both time and error) is a red band through its settings, each ringed; "
               "an error 0 is drawn at the panel's floor, a failed setting at its "
               f"ceiling. The fronts: {'; '.join(fronts) or 'none'}."
               + (f" {missed} labels found no free spot and are left out." if missed else "")
               + (f" Without a panel: {'; '.join(_told(name, g) for name, g in told)}." if told else ""))
    return save(fig, path, caption)
