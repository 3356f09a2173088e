"""Ali (1977), the K.E.D. results near a toggle: error against conditioning, and the rule that
says so (scene ali1977-conditioning).

A fixed random sample of four-bars that reach a toggle (coupler and follower in line) at some
input angle: link lengths log-uniform over three decades, alp anywhere; for each, input angles
at 10^-13 to 1 deg from the toggle on both sides, and one angle far from it.  At each, the
Case I source deflection (dx, dy, l2 rot: one vector, in) of two engines against the same
equations evaluated in 60 digits (``exact.case1_source``):

- ``float64``: the corrected port (every quirk off);
- ``real4``: the same with the listings' REAL*4 storage of matrices and loads (the arithmetic
  of legacy and of the listing port, without their bugs, so that the 60-digit reference applies).

Each point's relative error is set against its condition (``port.ali1977.conditioning``:
the links' spread over sin^2 of the transmission angle) and the bound the engines use to
warn and to refuse; ``verdict`` is what the engine said (returned, PrecisionWarning,
SingularPositionError, AssemblyError).
"""
from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np
import pandas as pd

from ....errors import LinkageError, PrecisionWarning
from ....port.ali1977.case1 import source_case1
from ....port.ali1977.conditioning import (CONDITION_FACTOR, DOUBLE_UNIT, REAL4_UNIT, STORAGE_FACTOR, condition,
                                           expected_error, spread)
from ....port.ali1977.fourbar import Lengths
from ....port.ali1977.quirks import CORRECTED
from ...csv_output import write_csv
from ...scene import ReportScene
from . import exact
from .tables import GROUP, START

NAME = "ali1977-conditioning"
TITLE = "Ali (1977): the deflections' error near a toggle, against the conditioning the engines report"
ENGINES = {"float64": CORRECTED, "real4": CORRECTED.only("real4_storage", True)}
RPM = 300.0


def toggle_angles(lengths: Lengths) -> list[float]:
    """The input angles (deg, in [0, 180]) where the loop is at a toggle: the crank pin at
    distance l3 + l4 or |l3 - l4| from the follower's pivot."""
    out = []
    for d in (lengths.l3 + lengths.l4, abs(lengths.l3 - lengths.l4)):
        c = (lengths.l1 ** 2 + lengths.l5 ** 2 - d * d) / (2.0 * lengths.l1 * lengths.l5)
        if abs(c) < 0.9999:
            out.append(math.degrees(math.acos(c)))
    return out


def sample(seed: int, count: int) -> list[tuple[Lengths, float, float]]:
    """(lengths, alp in deg, input angle in deg) near the toggles of ``count`` random four-bars."""
    rng = np.random.default_rng(seed)
    points = []
    while len({id(p[0]) for p in points}) < count:
        lengths = Lengths(*np.exp(rng.uniform(math.log(0.1), math.log(100.0), 5)))
        toggles = toggle_angles(lengths)
        if not toggles:
            continue
        star, alp = toggles[rng.integers(len(toggles))], float(rng.uniform(-180.0, 360.0))
        offsets = [*10.0 ** -rng.uniform(0.0, 13.0, 4), float(rng.uniform(1.0, 179.0))]
        points += [(lengths, alp, star + side * off) for off in offsets for side in (1.0, -1.0)]
    return points


def _run(lengths: Lengths, alp: float, deg: float, quirks) -> tuple[np.ndarray | None, str]:
    """(dx, dy, l2 rot) of the engine at one angle, or None, and what it said."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", PrecisionWarning)
        try:
            out = source_case1(np.array([deg]), lengths, alp=math.radians(alp), rpm=RPM, quirks=quirks)
        except LinkageError as exc:
            return None, type(exc).__name__
    verdict = "PrecisionWarning" if any(issubclass(w.category, PrecisionWarning) for w in caught) else "returned"
    return np.array([out["dx"][0], out["dy"][0], lengths.l2 * out["rot"][0]]), verdict


def measure(points) -> pd.DataFrame:
    """One row per point and engine: the geometry, sin(mu), the condition, the bound, the
    measured relative error (NaN where the engine refused) and the verdict."""
    rows = []
    for lengths, alp, deg in points:
        ref = exact.case1_source(deg, lengths, alp_deg=alp)
        if ref is None:
            continue
        truth = np.array([ref["dx"], ref["dy"], lengths.l2 * ref["rot"]])
        link_spread = spread(list(vars(lengths).values()))
        kappa = float(condition([deg], math.pi, [(lengths.l1, lengths.l3, lengths.l4, lengths.l5)], link_spread)[0])
        for engine, quirks in ENGINES.items():
            got, verdict = _run(lengths, alp, deg, quirks)
            error = np.nan if got is None else float(np.linalg.norm(got - truth) / np.linalg.norm(truth))
            rows.append({"l1": lengths.l1, "l2": lengths.l2, "l3": lengths.l3, "l4": lengths.l4, "l5": lengths.l5,
                         "alp_deg": alp, "input_deg": deg, "sin_mu": ref["sin_mu"], "spread": link_spread,
                         "condition": kappa, "engine": engine,
                         "bound": float(expected_error(kappa, link_spread, engine == "real4")),
                         "error": error, "verdict": verdict})
    return pd.DataFrame(rows)


def summary(data: pd.DataFrame) -> pd.DataFrame:
    """Per engine: points, refused, warned, the worst error over its bound, and the silent
    failures (returned without a warning, error beyond half the storage's digits)."""
    rows = []
    for engine, g in data.groupby("engine", sort=False):
        claim = math.sqrt(REAL4_UNIT if engine == "real4" else DOUBLE_UNIT)
        answered = g[g["error"].notna()]
        rows.append({"engine": engine, "points": len(g), "refused": int(g["error"].isna().sum()),
                     "warned": int((g["verdict"] == "PrecisionWarning").sum()),
                     "worst_error_over_bound": float((answered["error"] / answered["bound"]).max()),
                     "silent_failures": int(((answered["verdict"] == "returned") & (answered["error"] > claim)).sum())})
    return pd.DataFrame(rows)


def plot(data: pd.DataFrame, path: Path) -> None:
    """Relative error against condition, one panel per engine, with the bound and the limits."""
    from matplotlib.figure import Figure
    from ...report import save_png
    fig = Figure(figsize=(11, 4.2))
    axes = fig.subplots(1, 2, sharey=True)
    kappa = np.logspace(0, 16, 200)
    for ax, (engine, g) in zip(axes, data.groupby("engine", sort=False)):
        real4 = engine == "real4"
        storage = REAL4_UNIT if real4 else DOUBLE_UNIT
        answered = g[g["error"].notna()]
        floor = np.maximum(answered["error"], 1e-18)
        ax.loglog(answered["condition"], floor, ".", ms=3, alpha=0.5, label="measured (60-digit reference)")
        for link_spread, style in ((1.0, "-"), (100.0, "--")):
            ax.loglog(kappa, expected_error(kappa, link_spread, real4), "k" + style, lw=0.9,
                      label=f"bound, links' spread {link_spread:g}")
        ax.axhline(math.sqrt(storage), color="tab:orange", lw=0.9, label="warning: half the stored digits")
        ax.axhline(1.0, color="tab:red", lw=0.9, label="SingularPositionError")
        ax.set_xlabel("condition: links' spread / sin^2(transmission angle)")
        ax.set_title(f"{engine}: {'REAL*4 storage (the listings)' if real4 else 'IEEE double (corrected port)'}",
                     fontsize=9)
        ax.set_ylim(1e-18, 10.0)
        ax.grid(alpha=0.3, which="both")
    axes[0].set_ylabel("relative error of (dx, dy, l2 rot)")
    axes[1].legend(fontsize=7, loc="lower right")
    save_png(fig, path, left=0.07, right=0.985, bottom=0.14, top=0.92, wspace=0.06)


def run(out_dir: Path, seed: int = 2026, count: int = 60) -> pd.DataFrame:
    """out/ali1977-conditioning/: conditioning.csv (every point), summary.csv, conditioning.png,
    report.md."""
    target = out_dir / NAME
    target.mkdir(parents=True, exist_ok=True)
    data = measure(sample(seed, count))
    table = summary(data)
    write_csv(data, target / "conditioning.csv", "%.9g")
    write_csv(table, target / "summary.csv", "%.6g")
    plot(data, target / "conditioning.png")
    lines = [f"# {TITLE}", "", __doc__.split("\n\n", 1)[1].strip(), "",
             f"Bound: {STORAGE_FACTOR:g} u_s spread + {CONDITION_FACTOR:g} u kappa (u_s the storage's unit "
             "roundoff, u the double's); a PrecisionWarning where it passes sqrt(u_s), a "
             "SingularPositionError where it reaches 1.", "",
             "| engine | points | refused | warned | worst error / bound | silent failures |", "|---|---|---|---|---|---|"]
    lines += [f"| {r.engine} | {r.points} | {r.refused} | {r.warned} | {r.worst_error_over_bound:.3g} | "
              f"{r.silent_failures} |" for r in table.itertuples()]
    lines += ["", "![error against condition](conditioning.png)", ""]
    (target / "report.md").write_text("\n".join(lines))
    return table


def overview(table: pd.DataFrame) -> list[str]:
    return [f"{r.engine}: {r.points} points near toggles, worst error {r.worst_error_over_bound:.2g} of the bound, "
            f"{r.warned} warned, {r.refused} refused, {r.silent_failures} silent failures"
            for r in table.itertuples()]


SCENE = ReportScene(name=NAME, title=TITLE, group=GROUP, start=START, produce=run, overview=overview)
