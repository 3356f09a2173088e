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
    bench.md.  A sweep has many settings: ``bench_run.run_bench`` gives it ``repeat // 10`` calls a
    timing, at least 1."""
    name: str
    what: str
    rows: Callable[[int], list[dict]]


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
        lines.append(f"| {name} | {g.positions.iloc[-1]} | {_us(legacy_us)} | {_us(printed)} | {_us(corrected)} | "
                     f"{_us(limit)} ({g.flops_per_position.iloc[0]:.3g}) | {_ratio(printed, legacy_us)} | "
                     f"{_ratio(corrected, legacy_us)} | {_ratio(legacy_us, limit)} | {_ratio(corrected, limit)} | "
                     f"{f'{agree.iloc[0]:.1e}' if len(agree) else ''} |")
        notes += [f"- {name}: {g.note.iloc[0]}."] if isinstance(g.note.iloc[0], str) and g.note.iloc[0] else []
    return lines + [""] + notes


def knob_tables(rows: pd.DataFrame, descriptions: dict[str, str]) -> list[str]:
    """Part 2 as markdown: one table per knob."""
    lines = []
    for name, g in rows.groupby("subject", sort=False):
        lines += [f"### {name}", "", f"{descriptions[name]}. Error unit: {g.error_unit.iloc[0]}; "
                  "* on the Pareto front, = the reference.", "", "| setting | seconds | error | |", "|---|---|---|---|"]
        for r in g.itertuples():
            error = f"{r.error:.2e}" if np.isfinite(r.error) else r.note
            lines.append(f"| {r.setting} | {r.seconds:.3g} | {error} | {'* ' if r.pareto else ''}"
                         f"{'=' if r.reference is True else ''} |")
        lines.append("")
    return lines


def markdown(frame: pd.DataFrame, descriptions: dict[str, str], repeat: int, elapsed: float, png: str) -> str:
    """bench.md: the cost table, the figure, the knobs' tables."""
    lines = ["# linkrepro bench", "",
             f"Best of {repeat} calls each (time.perf_counter; the port's caches cleared before each call), all "
             f"from one run of {elapsed:.0f} s. The machine is shared: read the ratios, measured side by side, "
             "not the seconds.", "", "## Cost per position", "",
             "Microseconds per position (an input angle, a crank position). Limit: the flops per position of the "
             "listing's algorithm, counted by hand (harness/scenes/<thesis>/bench.py: KED_*, NEWTON_*, CSSP_*, CLOSED_LOOP, "
             f"GSC_FORCES; matrix products dense as the listings form them, {TRANSCENDENTAL} flops for a sin, "
             f"cos, atan or sqrt), at {FLOP_RATE / 1e9:g} GFLOP/s (one core's scalar peak: 4 flops a cycle at "
             "2.5 GHz, no SIMD). Last column: the port with the listing's bugs against legacy on the same inputs, "
             "max |difference| / max |legacy|.", ""]
    lines += cost_table(frame[frame.kind == "cost"])
    lines += ["", "## Speed against error, per knob", "",
              "Seconds of one call (every position of the setting); error against the knob's converged "
              "reference. The figure plots them per knob, the Pareto front joined.", "",
              f"![error against time]({png})", ""]
    lines += knob_tables(frame[frame.kind == "knob"], descriptions)
    return "\n".join(lines) + "\n"


def plot(frame: pd.DataFrame, path: Path) -> None:
    """Error against time, one panel per knob, the Pareto front joined; a zero error (the
    reference, or as good) at the panel's floor, a failed setting at its ceiling."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.ticker import NullFormatter
    groups = list(frame[frame.kind == "knob"].groupby("subject", sort=False))
    rows = -(-len(groups) // 3)
    fig, axes = plt.subplots(rows, 3, figsize=(12, 3.4 * rows), squeeze=False)
    for ax, (name, g) in zip(axes.flat, groups):
        error = g.error.astype(float)
        positive = error[np.isfinite(error) & (error > 0)]
        floor, ceiling = (positive.min() / 10, positive.max() * 10) if len(positive) else (1e-16, 1.0)
        shown = error.where(np.isfinite(error), ceiling).clip(lower=floor)
        kinds = [(np.isfinite(error) & (error > 0), "o", "0.6", "setting"),
                 (error <= 0, "v", "C0", "error 0 (the reference)"), (~np.isfinite(error), "x", "k", "failed")]
        for where, marker, colour, label in kinds:
            ax.loglog(g.seconds[where], shown[where], marker, color=colour, ms=5, label=label)
        front = g.seconds[g.pareto.astype(bool)].sort_values().index
        ax.loglog(g.seconds[front], shown[front], "-o", color="C3", ms=5, label="Pareto front")
        for i in front:
            ax.annotate(str(g.setting[i]), (g.seconds[i], shown[i]), fontsize=6, xytext=(3, 3),
                        textcoords="offset points")
        ax.set_xlim(g.seconds.min() / 1.6, g.seconds.max() * 1.6)
        ax.set_ylim(floor / 3, ceiling * 3)
        ax.yaxis.set_minor_formatter(NullFormatter())
        ax.tick_params(axis="x", which="both", labelsize=6, labelrotation=40)
        ax.set_title(name, fontsize=9)
        unit = g.error_unit.iloc[0]
        ax.set_xlabel("wall time of one call (s)")
        ax.set_ylabel("relative error against the reference" if unit == "relative"
                      else f"error against the reference ({unit})")
        ax.grid(alpha=0.3, which="both")
    for ax in list(axes.flat)[len(groups):]:
        ax.axis("off")
    axes.flat[0].legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)
